"""One version: the macros of <CGAL/DGG_VTP_3/version.h> (what CMake reads, DGGVTP_VERSION here),
dggvtp.__version__ (compiled from them), the programs' --version and the installed metadata."""
import importlib.metadata
import os
import re
import subprocess

import pytest

import dggvtp
from conftest import BATCH, CLI, needs_batch, needs_cli


def test_version_is_a_version():
    assert re.fullmatch(r"[0-9]+\.[0-9]+\.[0-9]+", dggvtp.__version__)


@pytest.mark.skipif("DGGVTP_VERSION" not in os.environ, reason="no CMake project version given (DGGVTP_VERSION)")
def test_the_cmake_project_version():
    assert dggvtp.__version__ == os.environ["DGGVTP_VERSION"]


@needs_cli
@needs_batch
def test_the_programs_version():
    for program, name in ((CLI, "dggvtp"), (BATCH, "dggvtp-batch")):
        out = subprocess.run([program, "--version"], check=True, capture_output=True, text=True).stdout
        assert out.startswith(f"{name} {dggvtp.__version__} (DGG-VTP for CGAL), CGAL "), out


def test_the_installed_metadata():
    try:
        installed = importlib.metadata.version("dggvtp")
    except importlib.metadata.PackageNotFoundError:
        pytest.skip("dggvtp is not installed (imported from the build tree)")
    assert installed == dggvtp.__version__
