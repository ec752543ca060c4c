/*!
\ingroup PkgDGGVTP3Concepts
\cgalConcept

The geometric traits of `CGAL::DGG_VTP_3::Geodesic_distance_solver`. It is deliberately tiny:
the propagation reads each point's Cartesian coordinates once, in the constructor, and does all
its geometry (edge lengths, unfolding of triangles onto the plane) in `FT` with internal structs.
The test suite compiles an archetype with exactly the members the solvers need, so this page
cannot drift from what the code needs; `compute_isolines()` needs two more. The traits must be default constructible when the named parameter
`geom_traits` is not given.

\cgalHasModel All models of `Kernel` (e.g. `CGAL::Exact_predicates_inexact_constructions_kernel`,
`CGAL::Simple_cartesian<float>`).
*/
class DGGVTPTraits_3
{
public:
  /// The number type of the coordinates and of the results (the propagation runs in it, but at
  /// least in `double`): `float`, `double`, `long double`, `CGAL::Gmpfr`, or an exact type with
  /// square roots (`CGAL::Algebraic_structure_traits<FT>::Is_exact` and `Sqrt`, e.g. `CORE::Expr`).
  /// Only a square root is asked beyond a field: no angles, no trigonometry.
  typedef unspecified_type FT;
  /// Function objects returning a Cartesian coordinate of the value type of the vertex point map
  /// (`FT operator()(const Point&) const`).
  typedef unspecified_type Compute_x_3;
  typedef unspecified_type Compute_y_3;
  typedef unspecified_type Compute_z_3;

  Compute_x_3 compute_x_3_object() const;
  Compute_y_3 compute_y_3_object() const;
  Compute_z_3 compute_z_3_object() const;

  /// \name For `CGAL::DGG_VTP_3::compute_isolines()` only
  /// The solvers do not use these; `compute_isolines()` places each isoline point on its edge.
  /// @{

  /// The point type of the isolines' points, the value type of the vertex point map.
  typedef unspecified_type Point_3;
  /// A function object `Point_3 operator()(const Point_3& p, const FT& w, const Point_3& q) const`
  /// returning the point w p + (1 - w) q, as `Kernel::ConstructBarycenter_3` does.
  typedef unspecified_type Construct_barycenter_3;

  Construct_barycenter_3 construct_barycenter_3_object() const;

  /// @}
};
