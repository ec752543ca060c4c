"""Builds the package dggvtp: the extension module dggvtp._dggvtp with the project's CMake (target
dggvtp_python) for the interpreter that runs pip, and src/dggvtp/'s Python files, stubs and py.typed
(under src/, so that a script or a shell in python/ does not import this folder, which has no
compiled module, in place of the package).

CMake, not pybind11's setup helpers: Debian's pybind11-dev ships the headers and the CMake
package only (its Python package, python3-pybind11, is another one), and the module needs what
the CMake build already finds and sets (CGAL, TBB, fast_float, the loader library).
The metadata is here, for both ways in (pip install . runs this file too), and the version is the
project's one: the macros of <CGAL/DGG_VTP_3/version.h>, read as CMakeLists.txt reads them.
Offline, with Debian's setuptools: pip install --no-build-isolation . (or ./python)."""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent  # python/
ROOT = HERE.parent  # the repository: the CMake project


def project_version():
    header = (ROOT / "include" / "CGAL" / "DGG_VTP_3" / "version.h").read_text()
    numbers = [re.search(rf"^#define DGG_VTP_3_VERSION_{part} +([0-9]+)$", header, re.M)
               for part in ("MAJOR", "MINOR", "PATCH")]
    if not all(numbers):
        raise RuntimeError("include/CGAL/DGG_VTP_3/version.h has no DGG_VTP_3_VERSION_MAJOR, _MINOR and _PATCH")
    return ".".join(n.group(1) for n in numbers)


class CMake_extension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMake_build(build_ext):
    def build_extension(self, extension):
        target = pathlib.Path(self.get_ext_fullpath(extension.name)).resolve()
        # one build directory whichever way in (. or ./python): the second install compiles nothing
        build = ROOT / "build" / f"pip-{sys.implementation.cache_tag}"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}", "-DBUILD_TESTING=OFF",
                     "-DDGG_VTP_3_BUILD_CLI=OFF", "-DDGG_VTP_3_BUILD_EXAMPLES=OFF",
                     "-DDGG_VTP_3_BUILD_BENCHMARKS=OFF"]
        if shutil.which("ccache"):  # a module compiled before, here or in another clone, is not compiled again
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "dggvtp_python", "-j", jobs], check=True)
        built = list((build / "python" / "dggvtp").glob("_dggvtp*" + target.suffix))
        if len(built) != 1:
            raise RuntimeError(f"the CMake build did not make the module dggvtp._dggvtp (found {built}): "
                               "are pybind11 and NumPy found for " + sys.executable + "?")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    name="dggvtp",
    version=project_version(),
    description="Exact and accuracy-controlled geodesic distances on triangle meshes (DGG-VTP for CGAL)",
    long_description=(ROOT / "README.md").read_text(encoding="utf-8"),
    long_description_content_type="text/markdown",
    license="GPL-3.0-or-later",
    python_requires=">=3.8",
    install_requires=["numpy", "scipy"],
    packages=["dggvtp"],
    package_dir={"dggvtp": os.path.relpath(HERE / "src" / "dggvtp")},  # from the directory pip runs this in
    package_data={"dggvtp": ["py.typed", "*.pyi"]},
    include_package_data=False,
    ext_modules=[CMake_extension("dggvtp._dggvtp")],
    cmdclass={"build_ext": CMake_build},
    zip_safe=False,
)
