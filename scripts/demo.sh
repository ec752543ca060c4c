#!/usr/bin/env bash
# Installs what is missing, builds dggvtp and computes exact geodesic distances on a bundled mesh.
# usage: scripts/demo.sh [MESH [dggvtp options...]]   (default: data/meshes/bunny.ply, source 0)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 --target dggvtp >/dev/null
mesh=${1:-data/meshes/bunny.ply}
shift || true
build/bin/dggvtp "$mesh" --source 0 --output build/demo_distances.txt --stats build/demo_stats.json "$@"
echo "distances: build/demo_distances.txt (one line per vertex), statistics: build/demo_stats.json"
