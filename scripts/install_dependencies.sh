#!/usr/bin/env bash
# Installs the Debian packages the project needs, if any is missing (as root, or through sudo).
# usage: scripts/install_dependencies.sh [--cli] [--benchmark] [--list]
#   (none)       everything the test command builds and runs (scripts/run_tests.sh): the library's
#                tests, the programs with MPI, the Python module and its checks, the manual
#   --cli        only what building dggvtp and dggvtp-batch (without MPI) needs: the demo's
#                (scripts/demo.sh); test docs.demo_installs_what_the_cli_needs checks the list
#                against the files the build of dggvtp reads
#   --benchmark  adds python3 and python3-matplotlib (the benchmarks' scripts)
#   --list       prints the packages, one a line, and installs nothing
set -euo pipefail
# the programs: a compiler, CMake and make, CGAL (header only, with GMP and MPFR), Boost's headers,
# TBB (--threads) and fast_float (the loader's number parsing)
cli=(g++ cmake make libcgal-dev libgmp-dev libmpfr-dev libboost-dev libtbb-dev libfast-float-dev)
# the rest of the test command: Boost.Graph (benchmarks) and Boost.Test, Eigen (README's C++ blocks),
# MPI (dggvtp-batch's ranks), the Python module (pybind11, NumPy, SciPy: local_distance_matrix's
# result and the adversary's meshes, pytest, matplotlib: the example), python3-venv and python3-pip
# (the README's install, test python_pip_install), python3-mypy (the stubs), ccache (that test
# compiles the module again, in seconds after the first run), git, doxygen (the manual) and strace
# (cli.mesh_read_once)
rest=(libboost-graph-dev libboost-test-dev libeigen3-dev libopenmpi-dev openmpi-bin
      pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest python3-matplotlib python3-setuptools
      python3-venv python3-pip python3-mypy ccache git doxygen strace)
packages=("${cli[@]}" "${rest[@]}")
list=false
for option in "$@"; do
  case $option in
    --cli) packages=("${cli[@]}") ;;
    --benchmark) extra=(python3 python3-matplotlib) ;;
    --list) list=true ;;
    *) echo "error: unknown option $option (usage: $0 [--cli] [--benchmark] [--list])" >&2; exit 1 ;;
  esac
done
packages+=(${extra[@]+"${extra[@]}"})
if $list; then
  printf '%s\n' "${packages[@]}"
  exit 0
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
