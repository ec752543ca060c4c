#!/usr/bin/env bash
# Installs what building dggvtp needs if it is missing (scripts/install_dependencies.sh --cli: the
# compiler, CMake, CGAL, Boost's headers, TBB, fast_float; the test command installs the rest),
# builds dggvtp and computes exact geodesic distances on a bundled mesh, into a text file and into
# a PLY of the mesh that a viewer colours by distance.
# usage: scripts/demo.sh [MESH [dggvtp options...]]   (default: data/meshes/bunny.ply, source 0)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh --cli
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target dggvtp >/dev/null
mesh=${1:-data/meshes/bunny.ply}
shift || true
build/bin/dggvtp "$mesh" --source 0 --output build/demo_distances.txt --stats build/demo_stats.json "$@"
# the same field on the mesh, for a viewer (a second propagation: a fraction of a second on the bunny)
build/bin/dggvtp "$mesh" --source 0 --output build/demo_distances.ply --quiet "$@"
echo "distances: build/demo_distances.txt (one line per vertex), statistics: build/demo_stats.json"
echo "the mesh with the distances: build/demo_distances.ply (MeshLab: open it, then Filters > Color"
echo "  Creation and Processing > Colorize by vertex Quality; for ParaView, --output FILE.vtk instead)"
