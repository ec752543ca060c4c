"""Shared by the tests: the bundled meshes, and dggvtp (the command-line program) to compare with.

CTest sets DGGVTP_DATA (data/meshes) and DGGVTP_CLI (the dggvtp built with the module)."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

DATA = pathlib.Path(os.environ.get("DGGVTP_DATA", pathlib.Path(__file__).resolve().parents[2] / "data" / "meshes"))
CLI_DATA = pathlib.Path(__file__).resolve().parents[2] / "test" / "DGG_VTP_3_cli" / "data"  # repairs, polygons
CLI = os.environ.get("DGGVTP_CLI")
MESHES = sorted(p.name for p in DATA.glob("*.ply"))

needs_cli = pytest.mark.skipif(not CLI or not os.path.exists(CLI), reason="dggvtp not built (DGGVTP_CLI)")


def mesh(name):
    return str(DATA / name)


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
