"""Shared by the tests: the bundled meshes, and dggvtp (the command-line program) to compare with.

The suite runs on the package wherever it is imported from (the build tree, PYTHONPATH=build/python,
or an installed one). CTest sets DGGVTP_DATA (data/meshes), and DGGVTP_CLI and DGGVTP_BATCH (the
programs built with the module): the tests that compare with them are marked needs_cli and skipped
without them. With DGGVTP_REQUIRE_ALL=1 (CTest's setting under DGG_VTP_3_REQUIRE_ALL_TESTS, as CI
runs it) a missing program or tool fails the file instead: CI requires every test."""
import importlib.util
import os
import pathlib
import subprocess

import numpy as np
import pytest

DATA = pathlib.Path(os.environ.get("DGGVTP_DATA", pathlib.Path(__file__).resolve().parents[2] / "data" / "meshes"))
CLI_DATA = pathlib.Path(__file__).resolve().parents[2] / "test" / "DGG_VTP_3_cli" / "data"  # repairs, polygons
CLI = os.environ.get("DGGVTP_CLI")
BATCH = os.environ.get("DGGVTP_BATCH")
MESHES = sorted(p.name for p in DATA.glob("*.ply"))

REQUIRE_ALL = os.environ.get("DGGVTP_REQUIRE_ALL") == "1"


def needs(present, reason):
    """a mark that skips a test when `present` is false, or, with DGGVTP_REQUIRE_ALL=1, an error"""
    if REQUIRE_ALL and not present:
        raise RuntimeError(f"{reason}: every test is required (DGGVTP_REQUIRE_ALL=1)")
    return pytest.mark.skipif(not present, reason=reason)


needs_cli = needs(bool(CLI) and os.path.exists(CLI), "dggvtp not built (DGGVTP_CLI)")
needs_batch = needs(bool(BATCH) and os.path.exists(BATCH), "dggvtp-batch not built (DGGVTP_BATCH)")
needs_mypy = needs(importlib.util.find_spec("mypy") is not None, "mypy is not installed (python3-mypy)")


def pytest_configure(config):
    # the package's own DeprecationWarnings (its former spellings) fail a test that does not expect
    # them (pytest.warns): the tests use the current API, test_deprecations.py the former one
    config.addinivalue_line("filterwarnings", r"error:.*(is deprecated|is keyword-only):DeprecationWarning")


def mesh(name):
    return str(DATA / name)


def same_bits(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def grid(n, size=1.0):
    """A flat (n + 1) x (n + 1) grid of the square [0, size]^2 in the plane z = 0, two triangles a
    cell: geodesic distances there are Euclidean."""
    x, y = np.meshgrid(np.linspace(0, size, n + 1), np.linspace(0, size, n + 1))
    V = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    i = np.arange(n * (n + 1)).reshape(n, n + 1)[:, :n].ravel()
    F = np.concatenate([np.column_stack([i, i + 1, i + n + 2]), np.column_stack([i, i + n + 2, i + n + 1])])
    return V, F


def run_cli(tmp_path, mesh_path, *options, labels=False):
    """dggvtp's distances (and labels) as .npy, read back"""
    out = tmp_path / "d.npy"
    command = [CLI, mesh_path, *map(str, options), "--output", out, "--output-format", "npy", "--quiet"]
    if labels:
        command += ["--labels", tmp_path / "l.npy"]
    subprocess.run(command, check=True)
    d = np.load(out)
    return (d, np.load(tmp_path / "l.npy")) if labels else d


def run_cli_lines(mesh_path, *options):
    """dggvtp's lines on stdout (targets, then path lengths) as floats"""
    result = subprocess.run([CLI, mesh_path, *map(str, options), "--quiet"], check=True, capture_output=True, text=True)
    return [float(line) for line in result.stdout.split()]
