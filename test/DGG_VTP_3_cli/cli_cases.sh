#!/usr/bin/env bash
# Command-line tests of dggvtp: one case per call, named after the input class it guards.
# usage: cli_cases.sh DGGVTP DATA_DIR MESH_DIR CASE
set -u
bin=$1 data=$2 meshes=$3 case=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL ($case): $*" >&2; exit 1; }

# run ARGS...: sets $rc, $out (stdout) and $err (stderr)
run() {
  "$bin" "$@" >"$work/stdout" 2>"$work/stderr"
  rc=$?
  out=$(cat "$work/stdout")
  err=$(cat "$work/stderr")
}
expect_rc() { [ "$rc" -eq "$1" ] || fail "exit status $rc, expected $1; stderr: $err"; }
# bad input: exit 2, exactly one line on stderr, starting with error:, no output file left behind
expect_input_error() {
  expect_rc 2
  [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "expected one stderr line, got: $err"
  [[ "$err" == error:* ]] || fail "stderr does not start with error: $err"
  [ ! -e "$work/d.txt" ] || fail "an output file was written"
  [ -z "$(ls "$work" | grep tmp-)" ] || fail "a temporary file was left behind"
}
expect_usage_error() {
  expect_rc 1
  [[ "$err" == error:* ]] || fail "stderr does not start with error: $err"
}
# lines FILE EXPECTED...: the distances, compared to 1e-12 relative (inf exactly)
expect_lines() {
  local file=$1; shift
  local expected="$*"
  awk -v expected="$expected" 'BEGIN { n = split(expected, e, " ") }
    { ++i; if (i > n) { print "extra line " i; bad = 1; next }
      if (e[i] == "inf" || $1 == "inf") { if ($1 != e[i]) { print "line " i ": " $1 " != " e[i]; bad = 1 } }
      else { d = $1 - e[i]; if (d < 0) d = -d; if (d > 1e-12 * (e[i] < 0 ? -e[i] : e[i]) + 1e-300) { print "line " i ": " $1 " != " e[i]; bad = 1 } } }
    END { if (i != n) { print i " lines, expected " n; bad = 1 } exit bad }' "$file" || fail "unexpected distances in $file"
}

spot=$meshes/spot.ply
case $case in
  help)
    run --help; expect_rc 0
    [[ "$out" == usage:\ dggvtp* ]] || fail "no usage text"
    [[ "$out" == *"Input policy"* ]] || fail "the help does not state the input policy" ;;
  no_mesh) run; expect_usage_error ;;
  unknown_option) run "$spot" --frobnicate; expect_usage_error ;;
  missing_value) run "$spot" --source; expect_usage_error ;;
  bad_numbers)
    for args in "--source -1" "--source 1x" "--epsilon -1" "--epsilon nan" "--epsilon abc" "--threads two" "--precision half"; do
      run "$spot" $args; expect_usage_error
    done ;;
  exact_and_epsilon_conflict) run "$spot" --exact --epsilon 1e-4; expect_usage_error ;;
  spot_output_and_stats)
    run "$spot" --output "$work/d.txt" --stats "$work/s.json"; expect_rc 0
    [ "$(wc -l < "$work/d.txt")" -eq 2930 ] || fail "not one line per vertex"
    [ "$(head -1 "$work/d.txt")" = 0 ] || fail "the source is not at 0"
    grep -q -v '^[0-9.e+-]*$' "$work/d.txt" && fail "a distance is not a finite number"
    for key in vertices faces source epsilon precision threads seconds_load seconds_propagate \
               windows_created windows_peak pseudo_sources vertices_popped vertices_reached peak_rss_mb; do
      grep -q "\"$key\":" "$work/s.json" || fail "stats lack $key"
    done
    grep -q '"vertices": 2930,' "$work/s.json" || fail "stats: wrong vertex count"
    [[ "$out" == *"reached 2930 of 2930"* ]] || fail "no summary" ;;
  output_to_stdout)
    run "$spot" --source 5 --output -; expect_rc 0
    [ "$(printf '%s\n' "$out" | wc -l)" -eq 2930 ] || fail "stdout is not one line per vertex"
    [ "$(printf '%s\n' "$out" | sed -n 6p)" = 0 ] || fail "the source is not at 0"
    [[ "$err" == *"dggvtp:"* ]] || fail "the summary should go to stderr" ;;
  epsilon_within_contract)
    run "$spot" --quiet --output "$work/exact.txt"; expect_rc 0
    for e in 1e-4 1e-6; do
      run "$spot" --quiet --epsilon $e --output "$work/approx.txt"; expect_rc 0
      paste "$work/approx.txt" "$work/exact.txt" | awk -v e=$e '$2 > 0 { r = ($1 - $2) / $2; if (r > e || r < -1e-12) { print NR, r; bad = 1 } } END { exit bad }' \
        || fail "epsilon $e: a distance outside the contract"
    done ;;
  float_precision)
    run "$spot" --quiet --output "$work/double.txt"; expect_rc 0
    run "$spot" --quiet --precision float --output "$work/float.txt"; expect_rc 0
    paste "$work/float.txt" "$work/double.txt" | awk '$2 > 0 { r = ($1 - $2) / $2; if (r < 0) r = -r; if (r > 1e-5) { print NR, r; bad = 1 } } END { exit bad }' \
      || fail "float distances differ from double by more than 1e-5" ;;
  two_components_and_isolated_vertex)
    run "$data/two_components_and_isolated_vertex.off" --quiet --output "$work/d.txt"; expect_rc 0
    expect_lines "$work/d.txt" 0 1 1 inf inf inf inf ;;
  isolated_source)
    run "$data/two_components_and_isolated_vertex.off" --quiet --source 3 --output "$work/d.txt"; expect_rc 0
    expect_lines "$work/d.txt" inf inf inf 0 inf inf inf ;;
  quad_is_triangulated)
    run "$data/quad.off" --output "$work/d.txt"; expect_rc 0
    [[ "$err" == warning:*triangulated* ]] || fail "no warning about the triangulation: $err"
    expect_lines "$work/d.txt" 0 1 1.4142135623730951 1 ;;
  non_manifold_vertex_is_kept)
    run "$data/non_manifold_vertex.off" --output "$work/d.txt"; expect_rc 0
    [[ "$err" == warning:*non-manifold* ]] || fail "no warning about the non-manifold vertex: $err"
    expect_lines "$work/d.txt" 0 1 1 1 1 ;;
  inconsistent_orientation_is_fixed)
    run "$data/inconsistent_orientation.off" --quiet --output "$work/d.txt"; expect_rc 0
    expect_lines "$work/d.txt" 0 1 1 1.4142135623730951 ;;
  source_out_of_range)
    run "$spot" --source 2930 --output "$work/d.txt"; expect_input_error
    [[ "$err" == *"out of range"* ]] || fail "$err" ;;
  missing_file) run "$work/none.off" --output "$work/d.txt"; expect_input_error ;;
  empty_file) run "$data/empty.off" --output "$work/d.txt"; expect_input_error ;;
  garbage_file) run "$data/garbage.off" --output "$work/d.txt"; expect_input_error ;;
  truncated_file) run "$data/truncated.off" --output "$work/d.txt"; expect_input_error ;;
  unsupported_format) run "$data/not_a_mesh.xyz" --output "$work/d.txt"; expect_input_error ;;
  nan_coordinate) run "$data/nan_coordinate.off" --output "$work/d.txt"; expect_input_error ;;
  zero_area_face) run "$data/zero_area_face.off" --output "$work/d.txt"; expect_input_error ;;
  face_repeating_a_vertex) run "$data/face_repeating_a_vertex.off" --output "$work/d.txt"; expect_input_error ;;
  error_keeps_existing_output)
    echo keep > "$work/kept.txt"
    run "$spot" --source 99999 --output "$work/kept.txt"; expect_rc 2
    [ "$(cat "$work/kept.txt")" = keep ] || fail "the existing output file was touched"
    [ -z "$(ls "$work" | grep tmp-)" ] || fail "a temporary file was left behind" ;;
  output_to_device)
    run "$spot" --quiet --output /dev/null --stats /dev/null; expect_rc 0
    [ -c /dev/null ] || fail "/dev/null was replaced by a file" ;;
  empty_output_name) run "$spot" --output ""; expect_usage_error ;;
  *) fail "unknown case" ;;
esac
echo "ok ($case)"
