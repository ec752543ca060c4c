"""One version: the macros of <CGAL/DGG_VTP_3/version.h> (what CMake reads, DGGVTP_VERSION here),
dggvtp.__version__ (compiled from them), the programs' --version and the installed metadata."""
import importlib.metadata
import os
import pathlib
import re
import subprocess
import sys

import dggvtp
from conftest import BATCH, CLI, needs, needs_batch, needs_cli


def test_version_is_a_version():
    assert re.fullmatch(r"[0-9]+\.[0-9]+\.[0-9]+", dggvtp.__version__)


@needs("DGGVTP_VERSION" in os.environ, "no CMake project version given (DGGVTP_VERSION)")
def test_the_cmake_project_version():
    assert dggvtp.__version__ == os.environ["DGGVTP_VERSION"]


@needs_cli
@needs_batch
def test_the_programs_version():
    for program, name in ((CLI, "dggvtp"), (BATCH, "dggvtp-batch")):
        out = subprocess.run([program, "--version"], check=True, capture_output=True, text=True).stdout
        assert out.startswith(f"{name} {dggvtp.__version__} (DGG-VTP for CGAL), CGAL "), out


def test_the_installed_metadata():
    # installed (python_pip_install runs this suite on the package pip installed): its metadata;
    # imported from the build tree (CTest): the version that setup.py gives pip to write there
    try:
        installed = importlib.metadata.version("dggvtp")
    except importlib.metadata.PackageNotFoundError:
        setup = pathlib.Path(__file__).resolve().parents[1] / "setup.py"
        result = subprocess.run([sys.executable, setup.name, "--version"], cwd=setup.parent,
                                capture_output=True, text=True, timeout=120)
        assert result.returncode == 0, result.stderr
        installed = result.stdout.split()[-1]
    assert installed == dggvtp.__version__
