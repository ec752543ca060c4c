#!/usr/bin/env bash
# Copyright (c) 2026 The DGG-VTP for CGAL authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# dggvtp-batch on one mesh: 1 rank x 1 thread against 1 rank x T threads and R ranks x 1 thread
# (mpirun), the same sources, the configurations alternating; median wall time of REPEAT runs (the whole command: load, solver,
# rows, output), speed-up against 1 x 1, peak RSS of each rank and CPU seconds of all ranks
# (from --stats), and a check that every run wrote the same bytes. Prints a Markdown table
# (benchmark README, Table 10). On a machine where other work competes for the cores, the CPU seconds
# tell whether the work grew with the ranks and threads or only had to wait for a core.
#
# usage: batch_scaling.sh [MESH [SOURCES [REPEAT [EPSILON]]]]
#   MESH     default: cat_190k.ply (190,856 vertices), made once from the repository's benchmark/DGG_VTP_3/meshes/cat.ply
#            by make_large's --sqrt3 3 (make_large.cpp, next to this script) into OUT_DIR (never commit it)
#   SOURCES  number of sources (default 32), vertices (i * 7919) mod V, i = 0..SOURCES-1
#   REPEAT   runs per configuration (default 3)
#   EPSILON  default 1e-6
# environment:
#   CONFIGS     "RANKSxTHREADS ..." (default "1x1 1x2 2x1")
#   OUT_DIR     where the generated mesh goes                          (default: ${TMPDIR:-/tmp}/large_meshes)
#   BUILD       build directory holding bin/dggvtp-batch               (default: <repo>/build)
#   MPIEXEC     the MPI launcher                                        (default: mpirun)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${OUT_DIR:-${TMPDIR:-/tmp}/large_meshes}
build=${BUILD:-$repo/build}
batch=$build/bin/dggvtp-batch
mpiexec=${MPIEXEC:-mpirun}
configs=${CONFIGS:-1x1 1x2 2x1}
mesh=${1:-$out/cat_190k.ply}
sources=${2:-32}
repeat=${3:-3}
epsilon=${4:-1e-6}

[ -x "$batch" ] || { echo "error: $batch is not an executable (set BUILD)" >&2; exit 1; }
if [ ! -f "$mesh" ]; then
  [ "$(basename "$mesh")" = cat_190k.ply ] || { echo "error: $mesh not found" >&2; exit 1; }
  tool=${MAKE_LARGE_BUILD_DIR:-${TMPDIR:-/tmp}/make_large_build}/make_large
  if [ ! -x "$tool" ] || [ "$repo/benchmark/DGG_VTP_3/make_large.cpp" -nt "$tool" ]; then
    mkdir -p "$(dirname "$tool")"
    echo "[batch_scaling] compiling make_large (about 20-60 s)" >&2
    g++ -O2 -std=c++17 -DNDEBUG -DCGAL_NDEBUG "$repo/benchmark/DGG_VTP_3/make_large.cpp" -o "$tool.tmp" -lgmp -lmpfr
    mv "$tool.tmp" "$tool"
  fi
  mkdir -p "$out"
  "$tool" "$repo/benchmark/DGG_VTP_3/meshes/cat.ply" "$mesh" --sqrt3 3 >&2
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/batch_scaling.XXXXXX")
trap 'rm -rf "$work"' EXIT
vertices=$(grep -a -m1 '^element vertex' "$mesh" | awk '{ print $3 }')
awk -v n="$sources" -v v="$vertices" 'BEGIN { for (i = 0; i < n; ++i) print (i * 7919) % v }' > "$work/sources.txt"
launcher=("$mpiexec")
if "$mpiexec" --version 2>/dev/null | grep -Eq "Open MPI|OpenRTE"; then
  launcher+=(--oversubscribe --bind-to none)
  [ "$(id -u)" -eq 0 ] && launcher+=(--allow-run-as-root)
  export OMPI_MCA_btl_vader_single_copy_mechanism=none
fi

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
echo "[batch_scaling] $mesh: $vertices vertices, $sources sources, epsilon $epsilon, $repeat runs per configuration" >&2
echo "[batch_scaling] load average before: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores" >&2
declare -A wall rss cpu
# the configurations alternate within each round, so that all see the same machine noise
for ((run = 1; run <= repeat; ++run)); do
  for config in $configs; do
    ranks=${config%x*} threads=${config#*x}
    rm -f "$work/out.npy"
    command=("$batch" "$mesh" --sources "$work/sources.txt" --epsilon "$epsilon" --threads "$threads"
             --output "$work/out.npy" --stats "$work/stats.json" --quiet)
    [ "$ranks" -gt 1 ] && command=("${launcher[@]}" -np "$ranks" "${command[@]}")
    start=$(date +%s.%N)
    "${command[@]}"
    end=$(date +%s.%N)
    seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
    echo "$seconds" >> "$work/times.$config"
    if [ -f "$work/reference.npy" ]; then
      cmp -s "$work/reference.npy" "$work/out.npy" || { echo "error: $config run $run wrote other bytes" >&2; exit 1; }
    else
      mv "$work/out.npy" "$work/reference.npy"
    fi
    rss[$config]=$(sed -n 's/.*"peak_rss_mb": \[\([^]]*\)\].*/\1/p' "$work/stats.json")
    sed -n 's/.*"cpu_seconds": \[\([^]]*\)\].*/\1/p' "$work/stats.json" |
      tr ',' '\n' | awk '{ s += $1 } END { print s }' >> "$work/cpu.$config"
    printf '[batch_scaling] round %d, %s: %.1f s, CPU %.1f s, peak RSS per rank %s MB, load %s\n' "$run" "$config" \
      "$seconds" "$(tail -1 "$work/cpu.$config")" "${rss[$config]}" "$(cut -d' ' -f1 /proc/loadavg)" >&2
  done
done
for config in $configs; do
  wall[$config]=$(median < "$work/times.$config")
  cpu[$config]=$(median < "$work/cpu.$config")
done
echo "[batch_scaling] load average after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2

echo "| ranks x threads | wall time (median of $repeat) | speed-up vs 1 x 1 | CPU seconds, all ranks | peak RSS per rank |"
echo "|---|---:|---:|---:|---|"
base=${wall[1x1]:-}
for config in $configs; do
  speedup=-
  [ -n "$base" ] && speedup=$(awk -v a="$base" -v b="${wall[$config]}" 'BEGIN { printf "%.2fx", a / b }')
  printf '| %s | %.1f s | %s | %.1f | %s MB |\n' "${config/x/ x }" "${wall[$config]}" "$speedup" "${cpu[$config]}" \
    "${rss[$config]}"
done
echo "(all runs wrote the same bytes)"
