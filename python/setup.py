"""Builds the extension module dggvtp with the project's CMake (target dggvtp_python) for the
interpreter that runs pip, and puts it into the wheel.

CMake, not pybind11's setup helpers: Debian's pybind11-dev ships the headers and the CMake
package only (its Python package, python3-pybind11, is another one), and the module needs what
the CMake build already finds and sets (CGAL, TBB, fast_float, the loader's include path).
Offline: pip install ./python --no-build-isolation (setuptools and wheel from Debian)."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent.parent  # the repository: the CMake project


class CMake_extension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMake_build(build_ext):
    def build_extension(self, extension):
        target = pathlib.Path(self.get_ext_fullpath(extension.name)).resolve()
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}", "-DBUILD_TESTING=OFF",
                     "-DDGG_VTP_3_BUILD_CLI=OFF", "-DDGG_VTP_3_BUILD_EXAMPLES=OFF",
                     "-DDGG_VTP_3_BUILD_BENCHMARKS=OFF"]
        if shutil.which("ccache"):  # a module compiled by the CMake build is not compiled again
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "dggvtp_python", "-j", jobs], check=True)
        built = list((build / "python").glob("dggvtp*" + pathlib.Path(target).suffix))
        if len(built) != 1:
            raise RuntimeError(f"the CMake build did not make the module dggvtp (found {built}): "
                               "are pybind11 and NumPy found for " + sys.executable + "?")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[CMake_extension("dggvtp")], cmdclass={"build_ext": CMake_build}, packages=[], py_modules=[])
