"""What the contract is in float (issue 43, item 3): a float mesh is propagated in double (the
library's Computation_FT), so every accuracy is kept down to double's margin, on the surface the
float coordinates make, and the distances are rounded once to float: each within [exact (1 - 6e-8),
exact (1 + epsilon) (1 + 6e-8)] of the double exact mode on the same coordinates; and an accuracy
below float's own rounding (1e-7 < 1.5e-5) is not the exact mode (the manual said it was)."""
import numpy as np
import pytest

import dggvtp
from conftest import mesh

HALF_ULP = 2.0 ** -24   # float's rounding, relative


@pytest.mark.parametrize("name", ["pinion.ply", "spot.ply"])
def test_float_within_the_contract(name):
    V, F = dggvtp.read_mesh(mesh(name))
    V = V.astype(np.float32).astype(np.float64)   # the surface the float solver sees
    double = dggvtp.GeodesicSolver(V, F)
    single = dggvtp.GeodesicSolver(V, F, precision="float")
    for source in (0, len(V) // 2):
        exact = double.distances(source)
        reached = exact > 0
        for epsilon in (0.0, 1e-7, 1e-5, 1e-3, 1e-1):
            d = single.distances(source, epsilon=epsilon)
            assert np.array_equal(d, d.astype(np.float32)), "float results are float values"
            ratio = d[reached] / exact[reached]
            assert ratio.min() >= 1 - HALF_ULP - 1e-12, (epsilon, ratio.min())
            assert ratio.max() <= (1 + epsilon) * (1 + HALF_ULP) + 1e-12, (epsilon, ratio.max())
            if epsilon == 0:
                # the exact mode in float is the double exact mode rounded once
                assert np.array_equal(d, exact.astype(np.float32).astype(np.float64))
            elif epsilon <= 1e-5 and name == "spot.ply" and source == 0:
                # DGG-VTP's rules, not the exact ones (spot, source 0: 7 vertices differ at 1e-7)
                assert np.any(d != single.distances(source))
