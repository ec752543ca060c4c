"""What users coming from gdist, pygeodesic and potpourri3d expect (issue 44): Ctrl-C stops a long
call, targets by position, short TypeErrors, paths either way, a pair's distance and path, the
targets' labels, warnings at the caller's line, pickle and copy, and the small things."""
import copy
import multiprocessing
import os
import pathlib
import pickle
import subprocess
import sys
import textwrap
import warnings

import numpy as np
import pytest

import dggvtp
from conftest import grid, mesh, needs, needs_mypy

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def bunny():
    V, F = dggvtp.read_mesh(mesh("bunny.ply"))
    return V, F, dggvtp.GeodesicSolver(V, F)


# ---- 1. Ctrl-C ------------------------------------------------------------------------------

CHILD = textwrap.dedent('''
    import os, sys
    import numpy as np
    import dggvtp
    V, F = dggvtp.read_mesh(sys.argv[1])
    solver = dggvtp.GeodesicSolver(V, F)
    calls = {
        # about 70 s (260 MB) and 54 s (60 MB) on one thread of a 2026 laptop core
        "local_distance_matrix": lambda: solver.local_distance_matrix(0.1, threads=int(sys.argv[3])),
        "distances_from_each": lambda: solver.distances_from_each(np.arange(200), threads=int(sys.argv[3])),
    }
    try:
        calls[sys.argv[2]]()
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted", flush=True)
        del os.environ["DGGVTP_TEST_SIGINT_AT_CHECK"]  # the test hook: for the call above only
        d = solver.distances(0)            # the solver is ready for the next call
        print("usable", bool(np.isfinite(d).all() and d[0] == 0), flush=True)
''')


# the hook is compiled into the module of a test build only (DGGVTP_PYTHON_TEST_HOOKS): not into the
# one pip installs (tests/pip_install.py runs this suite on it, where these tests are skipped)
@needs(getattr(dggvtp._dggvtp, "_test_hooks", False), "the module has no test hooks (a build without BUILD_TESTING)")
@pytest.mark.parametrize("call, threads", [("local_distance_matrix", 1), ("local_distance_matrix", 2),
                                           ("distances_from_each", 1)])
def test_ctrl_c_interrupts_a_long_call(tmp_path, call, threads):
    # Each of these calls takes 10 s or more on the bunny (one thread) and checks for signals
    # hundreds of times; SIGINT at its 5th check (the module's test hook, not a clock: a signal from
    # outside races the call) must end it there with KeyboardInterrupt, and leave the solver usable.
    # Without the check in the call, Python would raise the KeyboardInterrupt when the call returns.
    script = tmp_path / "child.py"
    script.write_text(CHILD)
    result = subprocess.run([sys.executable, str(script), mesh("bunny.ply"), call, str(threads)],
                            capture_output=True, text=True, timeout=300,
                            env=dict(os.environ, DGGVTP_TEST_SIGINT_AT_CHECK="5"))
    assert result.stdout.split("\n")[:2] == ["interrupted", "usable True"], (result.stdout, result.stderr)
    assert "dggvtp test hook: SIGINT at check 5, 5 checks in the call" in result.stderr, result.stderr
    assert result.returncode == 0


# ---- 2. targets by position, short TypeErrors --------------------------------------------------

def test_targets_by_position():
    V, F = grid(6)
    s = dggvtp.GeodesicSolver(V, F)
    assert np.array_equal(s.target_distances([1], [2]), s.target_distances(sources=[1], targets=[2]))
    assert np.array_equal(s.geodesic_path(14, 22), s.geodesic_path(sources=14, target=22))
    lengths, paths = s.distances_and_paths(0, [5, 7])
    assert len(paths) == 2 and lengths.shape == (2,)


def short(error):
    text = str(error.value)
    assert len(text) <= 400 and text.count("\n") <= 3, text
    return text


def test_type_errors_are_short():
    V, F = grid(30)  # arrays whose repr pybind11 would have printed whole
    s = dggvtp.GeodesicSolver(V, F)
    with pytest.raises(TypeError) as e:
        s.distances(0, epsilon="a")
    assert "epsilon must be a float, not 'a'" in short(e)
    with pytest.raises(TypeError) as e:
        s.target_distances(0, 5, epsilom=1e-3)
    assert "unexpected keyword argument 'epsilom'" in short(e)
    with pytest.raises(TypeError) as e:
        s.local_distance_matrix()
    assert "max_distance" in short(e)
    with pytest.raises(TypeError) as e:
        dggvtp.GeodesicSolver(V, F, precision=1)
    assert "precision must be a str" in short(e)
    with pytest.raises(TypeError) as e:
        dggvtp.GeodesicSolver(V, F, "double", "float")
    assert "too many positional arguments" in short(e)
    with pytest.raises(TypeError) as e:
        s.distances()
    assert "missing required argument: 'sources'" in short(e)
    with pytest.raises(TypeError) as e:
        s.distances(0, threads=1.5)
    assert "threads must be an int" in short(e)
    with pytest.raises(TypeError) as e:
        dggvtp.read_mesh(mesh("spot.ply"), repair="yes")
    assert "repair must be a bool" in short(e)
    # NumPy scalars are numbers
    assert np.array_equal(s.distances(0, epsilon=np.float32(1e-3), threads=np.int64(1)),
                          s.distances(0, epsilon=float(np.float32(1e-3))))


# ---- 3. paths either way, a pair, labels ------------------------------------------------------

def test_path_order_pair_and_labels(bunny):
    V, F, s = bunny
    forth = s.geodesic_path(14, 2200)                      # from the source, by default
    back = s.geodesic_path(14, 2200, source_first=False)
    assert np.array_equal(forth, back[::-1])
    assert np.array_equal(forth[0], V[14]) and np.array_equal(forth[-1], V[2200])
    lengths, paths = s.distances_and_paths(14, [2200, 300])  # values first, as (distance, path)
    assert np.array_equal(paths[0], forth)
    lengths_back, paths_back = s.distances_and_paths(14, [2200, 300], source_first=False)
    assert np.array_equal(paths_back[0], back) and np.array_equal(lengths_back, lengths)
    distance, path = s.distance_and_path(14, 2200)
    assert isinstance(distance, float) and np.array_equal(path, forth)
    assert distance == lengths[0]
    assert distance == pytest.approx(s.target_distances(14, 2200)[0], rel=1e-14)
    distance, path = s.distance_and_path(14, 2200, source_first=False, epsilon=1e-2)
    assert np.array_equal(path[0], V[2200])
    d, labels = s.target_distances([14, 3000], [2200, 14, 3000], return_labels=True)
    field, field_labels = s.distances([14, 3000], return_labels=True)
    assert np.array_equal(d, field[[2200, 14, 3000]]) and np.array_equal(labels, field_labels[[2200, 14, 3000]])
    assert labels.dtype == np.int64 and list(labels[1:]) == [0, 1]
    d, labels = s.target_distances(14, None, target_points=[V[2200] + 1e-9, V[14]], return_labels=True)
    assert list(labels) == [0, 0] and d[1] == 0
    with pytest.raises(ValueError, match="one source vertex and one target vertex"):
        s.distance_and_path([1, 2], 3)


def test_unreachable_labels_and_pair():
    V, F = grid(3)
    V2 = np.vstack([V, V + [5, 0, 0]])
    F2 = np.vstack([F, F + len(V)])
    s = dggvtp.GeodesicSolver(V2, F2)
    with pytest.warns(RuntimeWarning, match="unreachable"):
        d, labels = s.target_distances(0, [1, len(V)], return_labels=True)
    assert np.isinf(d[1]) and list(labels) == [0, -1]
    d, labels = s.target_distances(0, [1, 15], max_distance=0.5, return_labels=True)
    assert np.isinf(d[1]) and labels[1] == -1
    with pytest.warns(RuntimeWarning):
        distance, path = s.distance_and_path(0, len(V))
    assert np.isinf(distance) and path.shape == (0, 3)


# ---- 5. the small things ------------------------------------------------------------------------

def test_distances_from_each_needs_sources():
    V, F = grid(4)
    s = dggvtp.GeodesicSolver(V, F)
    with pytest.raises(ValueError, match="range"):
        s.distances_from_each(None)
    assert s.distances_from_each(range(s.num_vertices)).shape == (25, 25)


def test_warnings_point_at_the_caller():
    import dggvtp.gdist
    V, F = grid(3)
    V2 = np.vstack([V, V + [5, 0, 0]])
    F2 = np.vstack([F, F + len(V)])
    for call in (lambda: dggvtp.geodesic_distances(V2, F2, 0),
                 lambda: dggvtp.GeodesicSolver(V2, F2).distances(0),
                 lambda: dggvtp.gdist.compute_gdist(V2, F2)):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            call()
        assert [pathlib.Path(w.filename).name for w in caught] == ["test_switching.py"], \
            [(w.filename, str(w.message)) for w in caught]


def test_reorientation_is_not_a_warning():
    V, F = grid(3)
    F = F.copy()
    F[0] = F[0][::-1]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s = dggvtp.GeodesicSolver(V, F)
    assert len(s.repairs) == 1 and s.repairs[0].startswith("reoriented")


def rows_of(solver):
    return solver.distances_from_each([0, 3])


def test_pickle_and_copy(bunny):
    V, F, s = bunny
    for t in (pickle.loads(pickle.dumps(s)), copy.deepcopy(s), copy.copy(s)):
        assert isinstance(t, dggvtp.GeodesicSolver) and t is not s
        assert np.array_equal(t.distances(7, epsilon=1e-3), s.distances(7, epsilon=1e-3))
    f = dggvtp.GeodesicSolver(V, F, precision="float", repair=True)
    g = pickle.loads(pickle.dumps(f))
    assert g.precision == "float" and np.array_equal(g.distances(5), f.distances(5))
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        rows = pool.map(rows_of, [s, s])
    assert np.array_equal(rows[0], s.distances_from_each([0, 3])) and np.array_equal(rows[1], rows[0])


def test_docstrings():
    first = dggvtp.GeodesicSolver.__doc__.split("\n")[0]
    assert "*, precision=\"double\"" in first and "threads=0" in first, first
    doc = dggvtp.GeodesicSolver.distances_and_paths.__doc__
    assert "summed lengths" in doc and "source_first" in doc and "from the source to the target" in doc
    assert "potpourri3d" in doc and "pygeodesic" in doc
    assert "threads=1" in dggvtp.__doc__ and "pool" in dggvtp.__doc__  # how to cap the threads in a pool


def test_gitignore_covers_the_readme_install():
    ignored = (ROOT / ".gitignore").read_text().split()
    for path in ("/venv/", "/python/build/", "*.egg-info/"):
        assert path in ignored, path


MYPY_PROGRAM = '''
from typing import Literal
import numpy as np
import dggvtp
import dggvtp.gdist as gdist
V, F = dggvtp.read_mesh("mesh.ply")
precision: Literal["double", "float"] = "float"
labelled: bool = bool(len(V) > 3)
s = dggvtp.GeodesicSolver(V, F, precision=precision, repair=False, threads=1)
d = s.distances(0, epsilon=np.float32(1e-3), max_distance=np.float64(2.0))
either = s.distances(0, return_labels=labelled)
d2, labels = s.distances([0, 1], return_labels=True)
t = s.target_distances(0, [1, 2])
t2, tl = s.target_distances(0, [1, 2], return_labels=True)
t3 = s.target_distances(0, [1], return_labels=labelled)
rows = s.distances_from_each([0, 1], threads=2)
M = s.local_distance_matrix(0.1, symmetric=True, format="csc")
lengths, paths = s.distances_and_paths(0, [5], source_first=False)
p = s.geodesic_path(0, 5)
distance, path = s.distance_and_path(0, 5)
samples, sd, sl, sb = s.farthest_point_sampling(4, first_sample=2, return_distances=True, return_labels=True,
                                                return_bounds=True)
d3, l3 = s.distances(None, points=[[0.0, 0.0, 0.0]], prior_distances=d2, prior_labels=labels, return_labels=True)
total: float = distance + float(lengths[0]) + float(p[0, 0]) + float(path[0, 0])
e = dggvtp.geodesic_distances(V, F, 0, precision=precision, return_labels=labelled)
g = gdist.compute_gdist(V, F, np.array([0], np.int32), None, None, False, epsilon=1e-4)
L = gdist.local_gdist_matrix(V, F, 0.1)
P = gdist.distance_matrix_of_selected_points(V, F, [1, 2, 3], max_distance=None)
n: int = s.num_vertices + s.num_faces + L.shape[0] + P.shape[0] + len(g)
r: list = s.repairs
kind: str = s.precision
try:
    dggvtp.GeodesicSolver(V, F[:0])
except dggvtp.InputError as error:
    message: str = str(error)
version: str = dggvtp.__version__
'''


@needs_mypy
def test_mypy_on_a_program_using_every_public_function(tmp_path):
    (tmp_path / "program.py").write_text(MYPY_PROGRAM)
    result = subprocess.run([sys.executable, "-m", "mypy", "--ignore-missing-imports", "--no-incremental",
                             "--cache-dir", str(tmp_path / "cache"), str(tmp_path / "program.py")],
                            capture_output=True, text=True, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
