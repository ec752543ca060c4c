"""The CTest python_pip_install: the install commands of doc/python.md, run as they are written, in a clean
copy of the repository (what a clone of it has: the files git tracks or would, and no build/), in a
temporary directory, offline; after each pip install, the installed package is imported outside
the source tree and computes a field, and its version, metadata and type information are checked;
at the end the pytest suite runs on the installed package, without dggvtp (the CLI).

usage: /usr/bin/python3 pip_install.py SOURCE_DIR VERSION   (VERSION: the CMake project's)
The commands are the ``` block after the line `<!-- the install commands, run by the test
python_pip_install -->` of doc/python.md. With ccache installed, CCACHE_BASEDIR makes the compiles of
one run the cache of the next (the copy is somewhere else each time).
"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

source, version = pathlib.Path(sys.argv[1]).resolve(), sys.argv[2]
MARKER = "<!-- the install commands, run by the test python_pip_install -->"


def fail(message):
    sys.exit(f"FAIL (python_pip_install): {message}")


DOCUMENT = "doc/python.md"  # its section "Install"


def readme_commands():
    lines = (source / DOCUMENT).read_text().split("\n")
    if MARKER not in lines:
        fail(f"{DOCUMENT} has no line {MARKER!r} before the install commands")
    start = lines.index(MARKER) + 1
    if not lines[start].startswith("```"):
        fail(f"{DOCUMENT}: the install commands' ``` block must follow the marker line")
    end = lines.index("```", start + 1)
    commands = [line.split("#")[0].strip() for line in lines[start + 1:end]]
    return [c for c in commands if c]


def clean_copy(to):
    """the files a clone has: tracked, or not ignored (the working tree's, uncommitted changes too)"""
    listed = subprocess.run(["git", "-C", source, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                            capture_output=True, check=True).stdout.decode().split("\0")
    for name in filter(None, listed):
        if (source / name).is_file():  # not deleted, not a submodule
            (to / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source / name, to / name)
    if (to / "build").exists():
        fail("the copy has a build/ directory")


CHECK = r"""
import importlib.metadata, pathlib, sys
import numpy as np
import dggvtp
package = pathlib.Path(dggvtp.__file__).parent
assert pathlib.Path(sys.prefix) in package.parents, f"dggvtp imported from {package}, not from the venv {sys.prefix}"
for name in ("py.typed", "__init__.pyi", "_dggvtp.pyi"):
    assert (package / name).is_file(), f"{name} is not installed beside the module"
assert list(package.glob("_dggvtp*.so")), "the extension module is not in the package directory"
# the test hooks of python/src/interrupt.h are compiled into the test build's module only
assert dggvtp._dggvtp._test_hooks is False, "the installed module has the test hooks (DGGVTP_PYTHON_TEST_HOOKS)"
for so in package.glob("_dggvtp*.so"):
    assert b"DGGVTP_TEST_SIGINT_AT_CHECK" not in so.read_bytes(), f"{so} reads DGGVTP_TEST_SIGINT_AT_CHECK"
assert dggvtp.__version__ == importlib.metadata.version("dggvtp") == sys.argv[2], (
    dggvtp.__version__, importlib.metadata.version("dggvtp"), sys.argv[2])
requires = importlib.metadata.requires("dggvtp")
assert sorted(requires) == ["numpy", "scipy"], requires
V, F = dggvtp.read_mesh(sys.argv[1])
d = dggvtp.GeodesicSolver(V, F).distances(0)
assert d.shape == (len(V),) and d[0] == 0 and np.all(np.isfinite(d)) and d.max() > 0
print(f"  {package}: dggvtp {dggvtp.__version__}, a field of {len(d)} vertices, farthest {d.max():.6f}")
"""


def main():
    commands = readme_commands()
    if not any("pip install" in c for c in commands):
        fail(f"no pip install among the commands of {DOCUMENT}: {commands}")
    with tempfile.TemporaryDirectory(prefix="dggvtp_pip_") as tmp:
        tmp = pathlib.Path(tmp)
        clone, outside = tmp / "clone", tmp / "outside"
        clone.mkdir()
        outside.mkdir()
        clean_copy(clone)
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "DGGVTP_", "VIRTUAL_ENV", "PIP_"))}
        env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", CCACHE_BASEDIR=str(clone),
                   PYTHONDONTWRITEBYTECODE="1")
        python = None
        for command in commands:
            t0 = time.monotonic()
            print(f"$ {command}", flush=True)
            if subprocess.run(["bash", "-c", command], cwd=clone, env=env).returncode != 0:
                fail(f"the command of {DOCUMENT} failed: {command}")
            print(f"  ({time.monotonic() - t0:.0f} s)", flush=True)
            if "venv" in command and " -m venv " in command:
                python = clone / command.split()[-1] / "bin" / "python"
            if "pip install" in command:
                if python is None:
                    fail("pip install before a venv is made")
                if subprocess.run([python, "-c", CHECK, clone / "data" / "meshes" / "spot.ply", version],
                                  cwd=outside, env=env).returncode != 0:
                    fail(f"the package installed by `{command}` does not work")
        # the suite on the installed package, without the CLI: the tests that need it are skipped
        t0 = time.monotonic()
        suite = subprocess.run([python, "-m", "pytest", "-q", "-rs", "-p", "no:cacheprovider", clone / "python" / "tests"],
                               cwd=outside, env=env)
        print(f"  pytest on the installed package: {time.monotonic() - t0:.0f} s", flush=True)
        if suite.returncode != 0:
            fail("the pytest suite fails on the installed package")


main()
