#!/usr/bin/env bash
# Copyright (c) 2026 The DGG-VTP for CGAL authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Times `dggvtp --exact` on a large generated mesh (default bunny_1M: 1,018,010 vertices).
# The mesh is generated once by make_large.sh (next to this script; compiles a helper the first
# time, ~45 s) from the repository's data/meshes into OUT_DIR: never commit generated meshes.
#
# usage: large_mesh.sh [TARGET [REPEAT [dggvtp options...]]]
#   TARGET   a make_large.sh target: bunny_1M (default), bunny_4M, bunny_flat_aniso_1M, blade_aniso_2M, terrain_2M
#   REPEAT   number of runs (default 3); the median propagation time is reported
#   options  passed to dggvtp instead of the default --exact (e.g. --source 509005, --epsilon 1e-6)
# environment:
#   OUT_DIR     where the generated meshes go             (default: ${TMPDIR:-/tmp}/large_meshes)
#   BUILD       build directory holding bin/dggvtp        (default: <repo>/build)
#   DGGVTP      path of dggvtp                            (default: $BUILD/bin/dggvtp)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${OUT_DIR:-${TMPDIR:-/tmp}/large_meshes}
build=${BUILD:-$repo/build}
dggvtp=${DGGVTP:-$build/bin/dggvtp}
target=${1:-bunny_1M}
repeat=${2:-3}
[ $# -gt 0 ] && shift
[ $# -gt 0 ] && shift
options=("$@")
[ ${#options[@]} -gt 0 ] || options=(--exact)
# one thread unless the options say otherwise (dggvtp's default is every core)
[[ " ${options[*]} " == *" --threads "* || " ${options[*]} " == *" --threads="* ]] || options+=(--threads 1)

[ -x "$dggvtp" ] || { echo "error: $dggvtp is not an executable (set BUILD or DGGVTP)" >&2; exit 1; }
mesh=$out/$target.ply
if [ -f "$mesh" ]; then
  echo "[large_mesh] using existing $mesh" >&2
else
  bash "$repo/benchmark/DGG_VTP_3/make_large.sh" "$out" "$target" >&2
fi

stats_dir=$(mktemp -d "${TMPDIR:-/tmp}/large_mesh.XXXXXX")
trap 'rm -rf "$stats_dir"' EXIT
for i in $(seq "$repeat"); do
  "$dggvtp" "$mesh" --quiet "${options[@]}" --stats "$stats_dir/run$i.json"
  python3 - "$stats_dir/run$i.json" "$i" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"[large_mesh] run {sys.argv[2]}: propagate {s['seconds_propagate']:.2f} s (load {s['seconds_load']:.2f} s, "
      f"prepare {s['seconds_prepare']:.2f} s), windows {s['windows_created']} (peak {s['windows_peak']}), "
      f"peak RSS {s['peak_rss_mb']:.0f} MB", file=sys.stderr)
PY
done

rev="commit $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?')"
[ -z "$(git -C "$repo" status --porcelain -- include loader cli 2>/dev/null)" ] || rev="$rev + uncommitted changes in include/, loader/ or cli/"
python3 - "$target" "${options[*]}" "$rev" "$stats_dir"/run*.json <<'PY'
import datetime, json, os, statistics, sys
target, options, rev, files = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
runs = [json.load(open(f)) for f in files]
med = lambda key: statistics.median(r[key] for r in runs)
cpu = next((l.split(':', 1)[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')), '?')
r0 = runs[0]
print(f"{datetime.datetime.now():%Y-%m-%d %H:%M}, {cpu}, {os.cpu_count()} logical cores; "
      f"{rev}; dggvtp {options}, median of {len(runs)} runs")
print()
print('| mesh | vertices | faces | source | propagate (s) | load (s) | prepare (s) | windows created | windows peak '
      '| pseudo-sources | vertices reached | peak RSS (MB) |')
print('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
print(f"| {target} | {r0['vertices']} | {r0['faces']} | {r0['source']} | {med('seconds_propagate'):.2f} "
      f"| {med('seconds_load'):.2f} | {med('seconds_prepare'):.2f} | {r0['windows_created']} | {r0['windows_peak']} "
      f"| {r0['pseudo_sources']} | {r0['vertices_reached']} | {med('peak_rss_mb'):.0f} |")
PY
