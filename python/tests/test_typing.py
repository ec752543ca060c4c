"""Typed (PEP 561): py.typed and the stubs beside the module, the stubs' signatures the runtime's
(names, kinds, defaults), real types in the signatures help() shows, and mypy (when installed)
checks a program against the stubs and finds its mistakes."""
import ast
import inspect
import pathlib
import subprocess
import sys

import pytest

import dggvtp
from conftest import needs_mypy

PACKAGE = pathlib.Path(dggvtp.__file__).parent


def test_layout():
    for name in ("__init__.py", "__init__.pyi", "_dggvtp.pyi", "py.typed"):
        assert (PACKAGE / name).is_file(), name
    assert pathlib.Path(dggvtp._dggvtp.__file__).parent == PACKAGE


def stub_functions(name):
    """{qualified name: ast arguments} of the functions of a stub (the first overload of each)"""
    tree = ast.parse((PACKAGE / name).read_text())
    found = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            found.setdefault(node.name, node.args)
        elif isinstance(node, ast.ClassDef):
            for f in node.body:
                if isinstance(f, ast.FunctionDef) and not any(
                        isinstance(d, ast.Name) and d.id == "property" for d in f.decorator_list):
                    found.setdefault(f"{node.name}.{f.name}", f.args)
    return found


def runtime_signature(function):
    """the signature on the first line of a pybind11 docstring (or of a function written in Python,
    the former spellings), as ast arguments"""
    if inspect.isfunction(function) and not hasattr(function, "__wrapped__"):
        header = f"{function.__name__}{inspect.signature(function)}".split(" -> ")[0]
        header = header.replace("=inf", "=float('inf')")
    else:
        header = function.__doc__.split("\n")[0].split(" -> ")[0]
    return ast.parse(f"def {header}: ...").body[0].args


def parameters(args):
    """names, kinds and defaults (as source text) of ast arguments, without self"""
    positional = [a.arg for a in args.args]
    defaults = [None] * (len(args.args) - len(args.defaults)) + [ast.unparse(d) for d in args.defaults]
    out = [(n, "positional", d) for n, d in zip(positional, defaults) if n != "self"]
    out += [(a.arg, "keyword", None if d is None else ast.unparse(d)) for a, d in zip(args.kwonlyargs, args.kw_defaults)]
    return out


def same_default(stub, runtime):
    return stub == runtime or stub == "..." or (stub, runtime) in {("0.0", "0.0"), ("'double'", "'double'")}


def test_threads_default_to_every_core():
    # threads=0 (all cores) wherever a function takes threads: the result is the same bits for any number
    found = 0
    for name, args in stub_functions("_dggvtp.pyi").items():
        target = dggvtp._dggvtp
        for part in name.split("."):
            target = getattr(target, part)
        for n, _, default in parameters(runtime_signature(target)):
            if n == "threads":
                assert default == "0", (name, default)
                found += 1
    assert found >= 10, found


@pytest.mark.parametrize("name", sorted(stub_functions("_dggvtp.pyi")))
def test_stub_is_the_runtime(name):
    target = dggvtp._dggvtp
    for part in name.split("."):
        target = getattr(target, part)
    stub, runtime = parameters(stub_functions("_dggvtp.pyi")[name]), parameters(runtime_signature(target))
    assert [(n, k) for n, k, _ in stub] == [(n, k) for n, k, _ in runtime], name
    for (n, _, s), (_, _, r) in zip(stub, runtime):
        assert same_default(s, r), (name, n, s, r)


def test_every_runtime_function_has_a_stub():
    stubs = stub_functions("_dggvtp.pyi")
    names = {n for n in dir(dggvtp._dggvtp) if not n.startswith("_") and callable(getattr(dggvtp._dggvtp, n))}
    names |= {f"GeodesicSolver.{n}" for n, v in vars(dggvtp.GeodesicSolver).items()
              if not n.startswith("_") and callable(v)}
    names.discard("InputError")
    assert names <= set(stubs) | {"GeodesicSolver"}, names - set(stubs)


def test_geodesic_distances_takes_the_options_of_distances():
    one_call = parameters(stub_functions("__init__.pyi")["geodesic_distances"])
    distances = parameters(stub_functions("_dggvtp.pyi")["GeodesicSolver.distances"])
    init = parameters(stub_functions("_dggvtp.pyi")["GeodesicSolver.__init__"])
    assert {n for n, _, _ in one_call} == {n for n, _, _ in distances + init}
    assert list(inspect.signature(dggvtp.geodesic_distances).parameters)[:3] == ["V", "F", "sources"]


def test_signatures_give_real_types():
    for f in (dggvtp.read_mesh, dggvtp.GeodesicSolver.__init__, dggvtp.GeodesicSolver.distances,
              dggvtp.GeodesicSolver.local_distance_matrix, dggvtp.GeodesicSolver.distances_and_paths,
              dggvtp.GeodesicSolver.target_distances, dggvtp.GeodesicSolver.geodesic_path):
        first = f.__doc__.split("\n")[0]
        assert ": object" not in first and "-> object" not in first, first
        assert "ArrayLike" in first or "PathLike" in first, first


PROGRAM = '''
import numpy as np
import dggvtp
V, F = dggvtp.read_mesh("mesh.ply")
solver = dggvtp.GeodesicSolver(V, F, repair=True)
d: np.ndarray = solver.distances([0, 1], face_points=([3], [[0.2, 0.3, 0.5]]), epsilon=1e-3)
d2, labels = solver.distances(0, return_labels=True)
lengths, paths = solver.distances_and_paths(0, targets=[5])
n: int = solver.num_vertices + len(paths) + int(lengths[0])
M = solver.local_distance_matrix(0.1, threads=2)
e = dggvtp.geodesic_distances(V, F, 0, max_distance=1.0)
version: str = dggvtp.__version__
'''


@needs_mypy
def test_mypy_checks_a_program(tmp_path):
    (tmp_path / "good.py").write_text(PROGRAM)
    (tmp_path / "bad.py").write_text(PROGRAM + "solver.local_distance_matrix(0.1, epsilom=1e-3)\nk: str = solver.num_faces\n")
    run = lambda name: subprocess.run([sys.executable, "-m", "mypy", "--ignore-missing-imports", "--no-incremental",
                                       "--cache-dir", str(tmp_path / "cache"), str(tmp_path / name)],
                                      capture_output=True, text=True, cwd=tmp_path)
    good = run("good.py")
    assert good.returncode == 0, good.stdout
    bad = run("bad.py")
    assert bad.returncode == 1 and 'Unexpected keyword argument "epsilom"' in bad.stdout, bad.stdout
    assert 'Incompatible types in assignment (expression has type "int", variable has type "str")' in bad.stdout


@needs_mypy
def test_stubtest(tmp_path):
    # mypy's own comparison of the stubs with the module (it cannot read pybind11's signatures:
    # test_stub_is_the_runtime does)
    (tmp_path / "mypy.ini").write_text("[mypy]\nignore_missing_imports = True\n")
    result = subprocess.run([sys.executable, "-m", "mypy.stubtest", "dggvtp", "--mypy-config-file", tmp_path / "mypy.ini",
                             "--allowlist", pathlib.Path(__file__).parent / "stubtest_allowlist.txt"],
                            capture_output=True, text=True, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
