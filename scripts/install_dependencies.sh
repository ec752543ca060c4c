#!/usr/bin/env bash
# Installs the Debian packages the project needs, if any is missing (as root, or through sudo).
# usage: scripts/install_dependencies.sh [--benchmark]   (--benchmark adds python3; the Python module's
# packages, matplotlib among them, are in the default list: the test command builds and tests it)
set -euo pipefail
# python3-scipy: local_distance_matrix's result, and the meshes of the adversary's tests;
# python3-venv, python3-pip: the README's install (the test python_pip_install); python3-mypy: the
# check of the stubs; ccache: that test compiles the module again, which ccache makes seconds
# after the first run
packages=(g++ cmake make libcgal-dev libgmp-dev libmpfr-dev libboost-dev libboost-graph-dev
          libboost-test-dev libeigen3-dev libtbb-dev libfast-float-dev libopenmpi-dev openmpi-bin
          pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest python3-matplotlib python3-setuptools
          python3-venv python3-pip python3-mypy ccache git doxygen strace)
if [ "${1:-}" = "--benchmark" ]; then
  packages+=(python3 python3-matplotlib)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "error: missing Debian packages (${missing[*]}) and not root: install them or run as root" >&2
  exit 1
fi
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
