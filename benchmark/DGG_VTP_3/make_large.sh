#!/usr/bin/env bash
# Copyright (c) 2026 The DGG-VTP for CGAL authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Deterministically generate large benchmark meshes from the repository's small meshes in data/meshes/
# (terrain_2M: from terrain_jacksboro.ply, itself rebuilt by make_terrain_jacksboro.py from
# python-matplotlib-data's DEM into OUT_DIR the first time).
#
# usage: make_large.sh [OUT_DIR] [TARGET ...]
#   OUT_DIR  where to write the .ply files (default: ${TMPDIR:-/tmp}/large_meshes; keep them out of git)
#   TARGET   any of: bunny_1M bunny_4M bunny_flat_aniso_1M blade_aniso_2M terrain_2M  (default: all)
#
# Needs g++ and CGAL/Boost/Eigen headers (Debian: libcgal-dev); terrain_2M also needs Python 3 with NumPy
# (PYTHON, default python3, else /usr/bin/python3) and python-matplotlib-data. make_large.cpp (next to
# this script) is compiled once into ${MAKE_LARGE_BUILD_DIR:-${TMPDIR:-/tmp}/make_large_build} and reused
# while it is newer than the source.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
src="$here/make_large.cpp"
meshes="$repo/data/meshes"
out="${1:-${TMPDIR:-/tmp}/large_meshes}"
[ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(bunny_1M bunny_4M bunny_flat_aniso_1M blade_aniso_2M terrain_2M)

build="${MAKE_LARGE_BUILD_DIR:-${TMPDIR:-/tmp}/make_large_build}"
bin="$build/make_large"
mkdir -p "$build" "$out"
if [ ! -x "$bin" ] || [ "$src" -nt "$bin" ]; then
  echo "[make_large] compiling $src (about 20-60 s)"
  g++ -O2 -std=c++17 -DNDEBUG -DCGAL_NDEBUG "$src" -o "$bin.tmp" -lgmp -lmpfr
  mv "$bin.tmp" "$bin"
fi

run() {  # name input ops...
  local name="$1" in="$2"; shift 2
  local t0=$SECONDS
  echo "[make_large] $name: $(basename "$in") $*"
  "$bin" "$in" "$out/$name.ply" "$@"
  echo "[make_large] $name done in $((SECONDS - t0)) s"
}

terrain() {  # the 138,632-vertex terrain is not stored in the repository: rebuilt once into OUT_DIR
  local t="$out/terrain_jacksboro.ply" py="${PYTHON:-python3}"
  if [ ! -f "$t" ]; then
    # NumPy is needed: fall back on the system's python3 when the one on PATH (a venv) lacks it
    [ -n "${PYTHON:-}" ] || "$py" -c 'import numpy' 2>/dev/null || py=/usr/bin/python3
    "$py" "$here/make_terrain_jacksboro.py" "$t" >&2 || return 1
  fi
  echo "$t"
}

for t in "${targets[@]}"; do
  case "$t" in
    # closed genus-0 smooth model: bunny (37,706 V) -> 3 sqrt(3) steps -> 1,018,010 V / 2,036,016 F
    bunny_1M) run bunny_1M "$meshes/bunny.ply" --sqrt3 3 ;;
    # 1 Loop step + 3 sqrt(3) steps -> 4,072,034 V / 8,144,064 F (about 155 MB)
    bunny_4M) run bunny_4M "$meshes/bunny.ply" --loop 1 --sqrt3 3 ;;
    # the 1M bunny squashed along z by 100x: many needle-like triangles (aspect ratio max ~160)
    bunny_flat_aniso_1M) run bunny_flat_aniso_1M "$meshes/bunny.ply" --sqrt3 3 --scale 1 1 0.01 ;;
    # skinny-triangle CAD blade (8,231 V) -> 4 midpoint steps -> ~2.1M V; triangle shapes are kept
    # exactly (aspect ratio p95 ~35, max ~70) and so is the surface, hence every geodesic distance
    blade_aniso_2M) run blade_aniso_2M "$meshes/blade.ply" --midpoint 4 --double ;;
    # real height field (138,632 V) -> 2 midpoint steps -> ~2.2M V, same polyhedral surface
    # (midpoint targets are written with double coordinates: float would move the midpoints off
    #  the original edges by ~1e-7 and change the geodesic distances at that level)
    terrain_2M) in=$(terrain); run terrain_2M "$in" --midpoint 2 --double ;;
    *) echo "unknown target: $t" >&2; exit 2 ;;
  esac
done
ls -l "$out"
