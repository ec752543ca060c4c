#!/usr/bin/env bash
# Tests of dggvtp-batch: one case per call.
# usage: batch_cases.sh DGGVTP_BATCH DGGVTP NPY_ROWS MESH_DIR MPIEXEC CASE
#   MPIEXEC: the MPI launcher dggvtp-batch was built for, or "none" (built without MPI); the MPI
#   cases then say that they are skipped and pass (exit status 77 tells CTest: skipped).
# The rows are compared with dggvtp's text output bit for bit: npy_rows prints a row as dggvtp
# does (%.17g), which tells every double apart.
set -u
batch=$1 dggvtp=$2 npy_rows=$3 meshes=$4 mpiexec=$5 case=$6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAIL ($case): $*" >&2; exit 1; }
skip() { echo "SKIPPED ($case): $*"; exit 77; }
spot=$meshes/spot.ply lion=$meshes/lion_head.ply

# mpirun as CI runs it: as root, more ranks than cores, no shared-memory single copy (not allowed
# in containers; the ranks exchange a few bytes only)
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
# Under the sanitizers (scripts/run_sanitizers.sh) the processes mpirun starts run without
# LeakSanitizer: Open MPI's allocations kept until exit come from components it has unloaded by
# then (frames without a module, which no suppression can name). AddressSanitizer's other checks
# and UBSan stay on, and the single-process cases (MPI not initialised) still check for leaks.
mpi_environment=(env "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0")
mpi() { # mpi RANKS ARGS...
  local np=$1; shift
  local extra=()
  "$mpiexec" --version 2>/dev/null | grep -Eq "Open MPI|OpenRTE" && extra=(--oversubscribe)
  [ "$(id -u)" -eq 0 ] && "$mpiexec" --version 2>/dev/null | grep -Eq "Open MPI|OpenRTE" && extra+=(--allow-run-as-root)
  "${mpi_environment[@]}" "$mpiexec" "${extra[@]}" -np "$np" "$batch" "$@"
}
need_mpi() {
  [ "$mpiexec" != none ] || skip "dggvtp-batch was built without MPI"
  command -v "$mpiexec" >/dev/null 2>&1 || skip "no MPI launcher ($mpiexec)"
}

# run ARGS...: dggvtp-batch in one process; sets $rc, $err
run() {
  timeout 300 "$batch" "$@" >"$work/.stdout" 2>"$work/.stderr"
  rc=$?
  err=$(cat "$work/.stderr")
  [ "$rc" -lt 124 ] || fail "killed or timed out ($rc): $*; stderr: $err"
}
expect_input_error() { # MESSAGE_PATTERN
  [ "$rc" -eq 2 ] || fail "exit status $rc, expected 2; stderr: $err"
  [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "expected one stderr line, got: $err"
  [[ "$err" == error:* ]] || fail "stderr does not start with error: $err"
  [[ "$err" == *$1* ]] || fail "the error does not say '$1': $err"
  [ ! -e out.npy ] || fail "an output file was written"
}
expect_usage_error() {
  [ "$rc" -eq 1 ] || fail "exit status $rc, expected 1; stderr: $err"
  [[ "$err" == error:* ]] || fail "stderr does not start with error: $err"
}
# same_as_dggvtp NPY MESH "SOURCES" [DGGVTP OPTIONS]: row k of NPY is dggvtp's output for source k
same_as_dggvtp() {
  local npy=$1 mesh=$2 sources=$3; shift 3
  local k=0 s
  for s in $sources; do
    "$dggvtp" "$mesh" --source "$s" --output "d$s.txt" --quiet "$@" || fail "dggvtp failed on source $s"
    "$npy_rows" "$npy" "$k" > "r$k.txt" || fail "$npy is not a valid .npy file"
    cmp -s "d$s.txt" "r$k.txt" || fail "row $k (source $s) differs from dggvtp $*: $(diff "d$s.txt" "r$k.txt" | head -4)"
    k=$((k + 1))
  done
}
expect_shape() { # NPY "ROWS COLUMNS DTYPE"
  local shape
  shape=$("$npy_rows" "$1") || fail "$1 is not a valid .npy file"
  [ "$shape" = "$2" ] || fail "$1: shape $shape, expected $2"
}
json_field() { sed -n "s/.*\"$2\": \([0-9.e+-]*\).*/\1/p" "$1"; }
# wait_until_stopped PID: until the process is stopped (state T), at most 60 s; fails if it ends
wait_until_stopped() {
  local i
  for ((i = 0; i < 1200; ++i)); do
    [ "$(awk '{ print $3 }' "/proc/$1/stat" 2>/dev/null)" = T ] && return 0
    kill -0 "$1" 2>/dev/null || return 1
    sleep 0.05
  done
  return 1
}
# records CHECKPOINT RANK: the number of rows RANK recorded as done
records() { cat "$1/done.$2" 2>/dev/null | wc -l; }
# The kills are the test hook's (DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=K, and _RANK=R): the process
# kills itself with SIGKILL right after its K-th row is durable and recorded, so a test knows
# what the kill left, whatever the speed of the machine (rows become durable every second, and a
# kill from outside races that timer).
# grid: OBJ of a bumpy 5 x 4 grid of vertices, 24 triangles: the smallest mesh worth a run
grid() {
  awk 'BEGIN { for (i = 0; i < 20; ++i) print "v", i % 5, int(i / 5), (i % 3) * 0.1
               for (y = 0; y < 3; ++y) for (x = 0; x < 4; ++x) { a = y * 5 + x + 1
                 print "f", a, a + 1, a + 6; print "f", a, a + 6, a + 5 } }'
}
# lion_head, 60 sources spread over the mesh, in a shuffled order: a few seconds of work
lion_sources() { awk 'BEGIN { for (i = 0; i < 60; ++i) print (i * 4099) % 8356 }'; }

case $case in
usage)
  run "$spot" --output out.npy; expect_usage_error
  run "$spot" --sources all; expect_usage_error
  run "$spot" --sources fps:x --output out.npy; expect_usage_error
  run "$spot" --sources fps:0 --output out.npy; expect_usage_error
  run "$spot" --sources all --output out.npy --dtype float16; expect_usage_error
  run "$spot" --sources all --output - ; expect_usage_error
  run "$spot" --sources all --output out.npy --exact --epsilon 1e-3; expect_usage_error
  run --help; [ "$rc" -eq 0 ] && grep -q "fps:K" .stdout || fail "--help"
  ;;
bad_source_lists)
  printf '1 2 3000\n' > range.txt
  run "$spot" --sources range.txt --output out.npy; expect_input_error "out of range"
  printf '4\n7 4\n' > twice.txt
  run "$spot" --sources twice.txt --output out.npy; expect_input_error "listed twice"
  printf ' \n\n' > empty.txt
  run "$spot" --sources empty.txt --output out.npy; expect_input_error "empty"
  printf '1 -2\n' > negative.txt
  run "$spot" --sources negative.txt --output out.npy; expect_input_error "not a vertex index"
  printf '1 2.5\n' > fraction.txt
  run "$spot" --sources fraction.txt --output out.npy; expect_input_error "not a vertex index"
  run "$spot" --sources missing.txt --output out.npy; expect_input_error "cannot read the source list"
  run "$spot" --sources fps:2931 --output out.npy; expect_input_error "more sources than"
  [ -z "$(ls -A)" ] || [ "$(ls | grep -v '\.txt$')" = "" ] || fail "files left behind: $(ls)"
  ;;
rows_equal_dggvtp)
  # exact and DGG-VTP, double and float, float64 and float32: each row is dggvtp's output
  printf '17 0 2929 1000\n5' > s.txt
  run "$spot" --sources s.txt --output out.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  expect_shape out.npy "5 2930 float64"; same_as_dggvtp out.npy "$spot" "17 0 2929 1000 5"
  run "$lion" --sources s.txt --output out.npy --epsilon 1e-5 --quiet; [ "$rc" -eq 0 ] || fail "$err"
  expect_shape out.npy "5 8356 float64"; same_as_dggvtp out.npy "$lion" "17 0 2929 1000 5" --epsilon 1e-5
  run "$lion" --sources s.txt --output out.npy --precision float --dtype float32 --quiet; [ "$rc" -eq 0 ] || fail "$err"
  expect_shape out.npy "5 8356 float32"; same_as_dggvtp out.npy "$lion" "17 0 2929 1000 5" --precision float
  [ ! -e out.npy.checkpoint ] || fail "the checkpoint was left behind"
  ;;
all_sources_and_threads)
  # --sources all on a small mesh: row v is vertex v's field; any thread count, the same bytes
  grid > grid.obj
  run grid.obj --sources all --output one.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  expect_shape one.npy "20 20 float64"; same_as_dggvtp one.npy grid.obj "$(seq 0 19)"
  lion_sources > l.txt
  run "$lion" --sources l.txt --output t1.npy --threads 1 --quiet; [ "$rc" -eq 0 ] || fail "$err"
  run "$lion" --sources l.txt --output t2.npy --threads 2 --stats s2.json --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s t1.npy t2.npy || fail "2 threads do not give the bytes of 1"
  same_as_dggvtp t2.npy "$lion" "$(head -3 l.txt)"
  # every stage timed, with its threads (the preparation's and the rows' as TBB allows: 1 or 2)
  for key in seconds_load seconds_repair seconds_prepare seconds_compute seconds_write seconds_total; do
    grep -q "\"$key\": [0-9]" s2.json || fail "stats lack $key: $(cat s2.json)"
  done
  grep -Eq '"threads_per_stage": \{"load": 1, "repair": 1, "prepare": [12], "compute": [12], "write": 1\}' s2.json \
    || fail "stats: threads per stage: $(cat s2.json)"
  ;;
threads_default_is_every_core)
  # without --threads: every core (--stats: threads 0; the preparation and the rows on the cores),
  # the bytes of --threads 1; under mpirun, the ranks of a machine share its cores
  lion_sources | head -6 > l.txt
  run "$lion" --sources l.txt --output t1.npy --threads 1 --epsilon 1e-3 --quiet; [ "$rc" -eq 0 ] || fail "$err"
  run "$lion" --sources l.txt --output t.npy --epsilon 1e-3 --stats s.json --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s t1.npy t.npy || fail "the default does not give the bytes of --threads 1"
  n=$(nproc)
  grep -q '"threads": 0,' s.json || fail "stats: the default --threads is not 0: $(cat s.json)"
  grep -Fq "\"prepare\": $n, \"compute\": $n," s.json || fail "stats: the default is not the $n cores: $(cat s.json)"
  "$batch" --help | grep -A1 -- "--threads T" | grep -q "0 = all cores (the default" || fail "--help does not say the default"
  if [ "$mpiexec" != none ] && command -v "$mpiexec" >/dev/null 2>&1; then
    mpi 2 "$lion" --sources l.txt --output m.npy --epsilon 1e-3 --stats m.json --quiet > mpi.log 2>&1 ||
      fail "mpirun -np 2: $(cat mpi.log)"
    cmp -s t1.npy m.npy || fail "2 ranks with the default threads: other bytes"
    share=$((n / 2)); [ "$share" -ge 1 ] || share=1
    compute=$(grep -o '"compute": [0-9]*' m.json | grep -o '[0-9]*$')
    [ "$compute" -ge 1 ] && [ "$compute" -le "$share" ] ||
      fail "2 ranks on one machine of $n cores: $compute threads each, not at most $share: $(cat m.json)"
  else
    echo "the default under MPI skipped: no MPI"
  fi
  ;;
mpi_ranks_and_threads)
  # R = 1, 2, 3 ranks x 1, 2 threads: the bytes of one process, which are dggvtp's rows
  need_mpi
  lion_sources | head -24 > l.txt
  run "$lion" --sources l.txt --output ref.npy --epsilon 1e-6 --quiet; [ "$rc" -eq 0 ] || fail "$err"
  same_as_dggvtp ref.npy "$lion" "$(cat l.txt)" --epsilon 1e-6
  for ranks in 1 2 3; do
    for threads in 1 2; do
      mpi "$ranks" "$lion" --sources l.txt --output "m$ranks$threads.npy" --epsilon 1e-6 --threads "$threads" \
        --stats "s$ranks$threads.json" --quiet > mpi.log 2>&1 || fail "mpirun -np $ranks, $threads threads: $(cat mpi.log)"
      cmp -s ref.npy "m$ranks$threads.npy" || fail "$ranks ranks x $threads threads: other bytes"
      grep -q "\"ranks\": $ranks," "s$ranks$threads.json" || fail "not $ranks ranks: $(cat "s$ranks$threads.json")"
      echo "$ranks ranks x $threads threads: identical bytes"
    done
  done
  ;;
kill_and_resume)
  # one process killed (SIGKILL) after 7 durable rows, run again: only the 53 missing rows, the same bytes
  lion_sources > l.txt
  run "$lion" --sources l.txt --output ref.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=7 "$batch" "$lion" --sources l.txt --output out.npy --quiet 2>/dev/null
  rc=$?
  [ "$rc" -eq 137 ] || fail "exit status $rc, expected 137 (killed by SIGKILL after 7 rows)"
  [ ! -e out.npy ] || fail "the killed run left an output file"
  [ "$(records out.npy.checkpoint 0)" -eq 7 ] || fail "$(records out.npy.checkpoint 0) rows recorded, expected 7"
  # a torn last record (the kill came while appending) is ignored
  printf '5' >> out.npy.checkpoint/done.0
  run "$lion" --sources l.txt --output out.npy --stats st.json --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s ref.npy out.npy || fail "the resumed run wrote other bytes"
  resumed=$(json_field st.json rows_resumed) computed=$(json_field st.json rows_computed)
  [ "$resumed" -eq 7 ] && [ "$computed" -eq 53 ] || fail "resumed $resumed + computed $computed rows, expected 7 + 53"
  echo "killed after $resumed rows, resumed with $computed"
  [ ! -e out.npy.checkpoint ] || fail "the checkpoint was left behind"
  ;;
error_bounds)
  # issue 45: --error-bounds, a second .npy whose row k is dggvtp --source s --error-bounds, bit for
  # bit; checkpointed with the rows (a kill and a resume give the same bytes), over MPI ranks too
  lion_sources > l.txt
  run "$lion" --sources l.txt --epsilon 1e-2 --output ref.npy --error-bounds ref_b.npy --threads 2 --quiet
  [ "$rc" -eq 0 ] || fail "$err"
  expect_shape ref_b.npy "60 8356 float64"
  run "$lion" --sources l.txt --epsilon 1e-2 --output plain.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s ref.npy plain.npy || fail "the rows changed with --error-bounds"
  k=0
  for s in $(head -3 l.txt); do
    "$dggvtp" "$lion" --source "$s" --epsilon 1e-2 --error-bounds "b$s.txt" --quiet || fail "dggvtp failed on source $s"
    "$npy_rows" ref_b.npy "$k" > "rb$k.txt" || fail "ref_b.npy is not a valid .npy file"
    cmp -s "b$s.txt" "rb$k.txt" || fail "bounds row $k (source $s) differ from dggvtp --error-bounds"
    k=$((k + 1))
  done
  DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=7 "$batch" "$lion" --sources l.txt --epsilon 1e-2 --output out.npy \
    --error-bounds out_b.npy --quiet 2>/dev/null
  [ "$?" -eq 137 ] || fail "not killed after 7 rows"
  [ ! -e out.npy ] && [ ! -e out_b.npy ] || fail "the killed run left an output file"
  run "$lion" --sources l.txt --epsilon 1e-2 --output out.npy --quiet; expect_input_error "error_bounds 'yes' there, none now"
  run "$lion" --sources l.txt --epsilon 1e-2 --output out.npy --error-bounds out_b.npy --stats st.json --quiet
  [ "$rc" -eq 0 ] || fail "$err"
  cmp -s ref.npy out.npy && cmp -s ref_b.npy out_b.npy || fail "the resumed run wrote other bytes"
  [ "$(json_field st.json rows_resumed)" -eq 7 ] || fail "resumed $(json_field st.json rows_resumed) rows, expected 7"
  [ ! -e out.npy.checkpoint ] || fail "the checkpoint was left behind"
  run "$lion" --sources fps:4 --epsilon 1e-1 --output f.npy --error-bounds fb.npy --sources-output fs.txt --quiet
  [ "$rc" -eq 0 ] || fail "$err"
  same_as_dggvtp f.npy "$lion" "$(cat fs.txt)" --epsilon 1e-1
  run "$lion" --sources all --output out.npz --max-distance 0.1 --error-bounds b.npy; expect_usage_error
  run "$lion" --sources all --output out.npy --error-bounds out.npy; expect_usage_error
  if [ "$mpiexec" != none ] && command -v "$mpiexec" >/dev/null 2>&1; then
    mpi 2 "$lion" --sources l.txt --epsilon 1e-2 --output m.npy --error-bounds m_b.npy --quiet > mpi.log 2>&1 ||
      fail "mpirun: $(cat mpi.log)"
    cmp -s ref.npy m.npy && cmp -s ref_b.npy m_b.npy || fail "2 ranks: other bytes"
  fi
  ;;
mpi_kill_one_rank_and_resume)
  # rank 1 of 3 killed (SIGKILL) after 3 durable rows of its 20, the job run again on 2 ranks: the
  # same bytes, at least rank 1's other 17 rows computed again
  need_mpi
  lion_sources > l.txt
  run "$lion" --sources l.txt --output ref.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=3 DGGVTP_BATCH_TEST_KILL_RANK=1 \
    mpi 3 "$lion" --sources l.txt --output out.npy --quiet > mpi.log 2>&1 &&
    fail "the launcher reported success after a rank was killed"
  [ ! -e out.npy ] || fail "the killed run left an output file"
  [ "$(records out.npy.checkpoint 1)" -eq 3 ] || fail "rank 1 recorded $(records out.npy.checkpoint 1) rows, expected 3: $(cat mpi.log)"
  mpi 2 "$lion" --sources l.txt --output out.npy --stats st.json --quiet > mpi.log 2>&1 || fail "resume: $(cat mpi.log)"
  cmp -s ref.npy out.npy || fail "the resumed run wrote other bytes"
  resumed=$(json_field st.json rows_resumed) computed=$(json_field st.json rows_computed)
  [ "$resumed" -ge 3 ] && [ "$computed" -ge 17 ] && [ $((resumed + computed)) -eq 60 ] ||
    fail "resumed $resumed + computed $computed rows, expected >= 3 + >= 17, 60 in all"
  echo "rank 1 killed after 3 rows, $resumed recorded in all, resumed with $computed"
  ;;
resume_refuses_another_command)
  lion_sources > l.txt
  # the first run stops itself (SIGSTOP) after 3 durable rows, its checkpoint locked: the second
  # one comes while it holds it, whatever the speed of the machine
  DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=3 DGGVTP_BATCH_TEST_KILL_SIGNAL=STOP \
    "$batch" "$lion" --sources l.txt --output out.npy --epsilon 1e-6 --quiet 2>/dev/null &
  pid=$!
  wait_until_stopped "$pid" || fail "the first run did not stop after 3 rows"
  [ "$(records out.npy.checkpoint 0)" -eq 3 ] || fail "$(records out.npy.checkpoint 0) rows recorded, expected 3"
  # a second run on the checkpoint while the first holds it
  run "$lion" --sources l.txt --output out.npy --epsilon 1e-6 --quiet; expect_input_error "another dggvtp-batch is running"
  kill -9 "$pid"; wait "$pid" 2>/dev/null
  run "$lion" --sources l.txt --output out.npy --epsilon 1e-5 --quiet
  expect_input_error "epsilon '1e-06' there, '1e-05' now"
  [[ "$err" == *"belongs to another command"* ]] || fail "unclear refusal: $err"
  head -59 l.txt > fewer.txt
  run "$lion" --sources fewer.txt --output out.npy --epsilon 1e-6 --quiet; expect_input_error "sources"
  run "$lion" --sources l.txt --output out.npy --epsilon 1e-6 --dtype float32 --quiet; expect_input_error "dtype"
  run "$spot" --sources l.txt --output out.npy --epsilon 1e-6 --quiet; expect_input_error "out of range"
  run "$meshes/bunny.ply" --sources l.txt --output out.npy --epsilon 1e-6 --quiet; expect_input_error "mesh '"
  run "$lion" --sources l.txt --output out.npy --epsilon 1e-6 --precision float --quiet; expect_input_error "precision"
  # the same command still finishes it
  run "$lion" --sources l.txt --output out.npy --epsilon 1e-6 --quiet; [ "$rc" -eq 0 ] || fail "$err"
  same_as_dggvtp out.npy "$lion" "$(head -2 l.txt)" --epsilon 1e-6
  # a directory that is not a checkpoint is left alone
  rm out.npy
  mkdir notes && echo keep > notes/mine.txt
  run "$spot" --sources fps:2 --output o2.npy --checkpoint notes --quiet; expect_input_error "not a dggvtp-batch checkpoint"
  [ -f notes/mine.txt ] || fail "a user file was removed"
  ;;
farthest_point_sampling)
  run "$lion" --sources fps:6 --output fps.npy --sources-output chosen.txt --quiet; [ "$rc" -eq 0 ] || fail "$err"
  expect_shape fps.npy "6 8356 float64"
  [ "$(head -1 chosen.txt)" = 0 ] || fail "fps does not start at vertex 0"
  [ "$(sort -u chosen.txt | wc -l)" -eq 6 ] || fail "fps chose a vertex twice"
  same_as_dggvtp fps.npy "$lion" "$(cat chosen.txt)"
  # each source is the vertex farthest from the ones before it (smallest index on ties)
  for k in 1 2 3 4 5; do
    paste $(for j in $(seq 0 $((k - 1))); do echo "r$j.txt"; done) |
      awk '{ m = $1; for (i = 2; i <= NF; ++i) if ($i + 0 < m + 0) m = $i; print NR - 1, m }' |
      sort -k2,2gr -k1,1n | head -1 | cut -d' ' -f1 > expected
    [ "$(cat expected)" = "$(sed -n "$((k + 1))p" chosen.txt)" ] ||
      fail "source $k is $(sed -n "$((k + 1))p" chosen.txt), the farthest vertex is $(cat expected)"
  done
  run "$lion" --sources fps:6 --output fps2.npy --threads 2 --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s fps.npy fps2.npy || fail "fps on 2 threads: other bytes"
  # --first-sample N: the samples of dggvtp --fps K --first-sample N (the library's first_sample)
  run "$lion" --sources fps:6 --first-sample 17 --epsilon 1e-2 --output f17.npy --sources-output c17.txt --quiet
  [ "$rc" -eq 0 ] || fail "$err"
  "$dggvtp" "$lion" --fps 6 --first-sample 17 --epsilon 1e-2 --quiet > d17.txt || fail "dggvtp --fps --first-sample"
  cmp -s c17.txt d17.txt || fail "--first-sample 17: not dggvtp's samples: $(cat c17.txt) / $(cat d17.txt)"
  [ "$(head -1 c17.txt)" = 17 ] || fail "fps does not start at --first-sample 17"
  run "$lion" --sources fps:6 --first-sample 0 --output f0.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s fps.npy f0.npy || fail "--first-sample 0 is not the default"
  run "$lion" --sources chosen.txt --first-sample 3 --output o.npy; expect_usage_error
  run "$lion" --sources fps:6 --first-sample 8356 --output out.npy; expect_input_error "--first-sample 8356 is out of range"
  # the sources chosen first: a local distance matrix of them, and the sampling timed
  run "$lion" --sources fps:6 --output fps.npz --max-distance 0.05 --sources-output chosen_local.txt --stats fs.json \
    --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s chosen.txt chosen_local.txt || fail "fps with --max-distance chose other sources"
  grep -q '"seconds_sample": [0-9]' fs.json || fail "stats lack seconds_sample: $(cat fs.json)"
  if [ "$mpiexec" != none ] && command -v "$mpiexec" >/dev/null 2>&1; then
    mpi 2 "$lion" --sources fps:6 --output fps3.npy --sources-output chosen3.txt --quiet > mpi.log 2>&1 ||
      fail "mpirun fps: $(cat mpi.log)"
    cmp -s fps.npy fps3.npy && cmp -s chosen.txt chosen3.txt || fail "fps on 2 ranks: other bytes"
  else
    echo "fps under MPI skipped: no MPI"
  fi
  ;;
farthest_point_sampling_resumes)
  run "$lion" --sources fps:40 --output ref.npy --sources-output ref.txt --quiet; [ "$rc" -eq 0 ] || fail "$err"
  DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=5 "$batch" "$lion" --sources fps:40 --output out.npy --quiet 2>/dev/null
  rc=$?
  [ "$rc" -eq 137 ] || fail "exit status $rc, expected 137 (killed by SIGKILL after 5 rows)"
  ls out.npy.checkpoint/done.* > /dev/null 2>&1 || fail "no rows recorded before the kill"
  run "$lion" --sources fps:40 --output out.npy --sources-output out.txt --stats st.json --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s ref.npy out.npy && cmp -s ref.txt out.txt || fail "the resumed fps run differs"
  [ "$(json_field st.json rows_resumed)" -eq 5 ] || fail "$(json_field st.json rows_resumed) rows resumed, expected 5"
  ;;
progress)
  run "$spot" --sources fps:3 --output out.npy --progress
  [ "$rc" -eq 0 ] || fail "$err"
  printf '%s\n' "$err" | grep -q "dggvtp-batch: 3/3 rows (100.0%)" || fail "no progress line: $err"
  run "$spot" --sources fps:3 --output out.npy
  [ -z "$err" ] || fail "progress without --progress nor a terminal: $err"
  ;;
exit_code_table)
  # one rule for every option: 1 = wrong whatever the mesh (unknown option, missing value, not a
  # number, negative, NaN, contradiction), 2 = wrong for this mesh or these files (out of range,
  # unreadable or refused file, unwritable output); MESH is a 20-vertex grid, W/ a missing directory
  grid > grid.obj
  printf '1 2\n' > s.txt; printf '1 20\n' > range.txt; printf '1 -2\n' > negative.txt
  while read -r expected args; do
    [ -n "$expected" ] && [ "${expected:0:1}" != "#" ] || continue
    rm -rf o.npy o.npy.checkpoint cp so.txt st.json
    words=(); for w in $args; do w=${w/#MESH/grid.obj}; words+=("${w/#W\//$work/missing/}"); done
    run "${words[@]}"
    [ "$rc" -eq "$expected" ] || fail "$args: exit status $rc, expected $expected; stderr: $err"
    if [ "$expected" -ne 0 ]; then
      [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] && [[ "$err" == error:* ]] || fail "$args: not one error: line: $err"
      [ ! -e o.npy ] && [ ! -e o.npy.checkpoint ] || fail "$args: files left behind"
    fi
  done <<'TABLE'
0 MESH --sources s.txt --output o.npy
0 MESH --sources all --output o.npy
0 MESH --sources fps:2 --output o.npy
1
1 MESH MESH --sources s.txt --output o.npy
2 W/none.ply --sources s.txt --output o.npy
1 MESH --frobnicate --sources s.txt --output o.npy
1 MESH --output o.npy
1 MESH --output o.npy --sources
1 MESH --sources fps:x --output o.npy
1 MESH --sources fps:-1 --output o.npy
1 MESH --sources fps:0 --output o.npy
2 MESH --sources fps:21 --output o.npy
0 MESH --sources fps:2 --first-sample 5 --output o.npy
1 MESH --sources s.txt --first-sample 5 --output o.npy
1 MESH --sources fps:2 --first-sample -1 --output o.npy
1 MESH --sources fps:2 --first-sample --output o.npy
2 MESH --sources fps:2 --first-sample 20 --output o.npy
2 MESH --sources W/none.txt --output o.npy
2 MESH --sources range.txt --output o.npy
2 MESH --sources negative.txt --output o.npy
1 MESH --sources s.txt
1 MESH --sources s.txt --output
1 MESH --sources s.txt --output -
2 MESH --sources s.txt --output W/o.npy
0 MESH --sources s.txt --output o.npy --dtype float32
1 MESH --sources s.txt --output o.npy --dtype float16
1 MESH --sources s.txt --output o.npy --dtype
0 MESH --sources s.txt --output o.npy --exact
1 MESH --sources s.txt --output o.npy --exact --epsilon 1e-3
0 MESH --sources s.txt --output o.npy --epsilon 1e-3
1 MESH --sources s.txt --output o.npy --epsilon -1
1 MESH --sources s.txt --output o.npy --epsilon 2
1 MESH --sources s.txt --output o.npy --epsilon nan
1 MESH --sources s.txt --output o.npy --epsilon inf
1 MESH --sources s.txt --output o.npy --epsilon abc
1 MESH --sources s.txt --output o.npy --epsilon
0 MESH --sources s.txt --output o.npy --precision float
1 MESH --sources s.txt --output o.npy --precision half
1 MESH --sources s.txt --output o.npy --precision
0 MESH --sources s.txt --output o.npy --threads 2
1 MESH --sources s.txt --output o.npy --threads -1
1 MESH --sources s.txt --output o.npy --threads two
1 MESH --sources s.txt --output o.npy --threads 5000
1 MESH --sources s.txt --output o.npy --threads
0 MESH --sources s.txt --output o.npy --checkpoint cp
2 MESH --sources s.txt --output o.npy --checkpoint W/cp
1 MESH --sources s.txt --output o.npy --checkpoint
0 MESH --sources s.txt --output o.npy --sources-output so.txt
2 MESH --sources s.txt --output o.npy --sources-output W/so.txt
1 MESH --sources s.txt --output o.npy --sources-output
0 MESH --sources s.txt --output o.npy --stats st.json
2 MESH --sources s.txt --output o.npy --stats W/st.json
1 MESH --sources s.txt --output o.npy --stats
0 MESH --sources s.txt --output o.npy --progress
0 MESH --sources s.txt --output o.npy --quiet
0 --help
0 -h
0 MESH -s s.txt -o o.npy
0 MESH --sources=s.txt --output=o.npy
0 MESH --sources=fps:2 --output=o.npy --dtype=f4
1 MESH --sources= --output o.npy
1 MESH --sources s.txt --output=
1 MESH --sources s.txt --output o.npy --quiet=1
1 MESH --source s.txt --output o.npy
1 MESH --sources s.txt --outptu o.npy
TABLE
  ;;
outputs_checked_before_loading)
  # an output that cannot be written is refused before the mesh is read: the error names it, not
  # the (missing) mesh, and nothing is left behind
  printf '1 2\n' > s.txt
  for args in "--output $work/missing/o.npy" "--output o.npy --checkpoint $work/missing/cp" \
              "--output o.npy --sources-output $work/missing/s.txt" "--output o.npy --stats $work/missing/st.json"; do
    run "$work/none.ply" --sources s.txt $args; expect_input_error "$work/missing/"
    [[ "$err" == *"cannot write --"* ]] || fail "$args: the error does not name the option: $err"
    [ "$(ls)" = s.txt ] || fail "$args: files left behind: $(ls)"
  done
  ;;
errors_name_the_users_paths)
  # the default checkpoint is a path the user never typed: its errors name --output too
  touch out.npy.checkpoint
  run "$spot" --sources fps:2 --output out.npy; expect_input_error "--output 'out.npy'"
  rm out.npy.checkpoint
  lion_sources > l.txt
  DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=2 "$batch" "$lion" --sources l.txt --output out.npy --quiet 2>/dev/null
  [ "$?" -eq 137 ] || fail "the run was not killed"
  run "$lion" --sources l.txt --output out.npy --epsilon 1e-5; expect_input_error "belongs to another command"
  [[ "$err" == *"--output 'out.npy'"* ]] || fail "the error does not name --output: $err"
  ;;
refuses_output_larger_than_free_space)
  # DGGVTP_BATCH_TEST_FREE_BYTES (tests only) stands for the file system's free space: spot with
  # --sources all is 2930 x 2930 x 8 bytes + a 128-byte header = 68679328 bytes
  DGGVTP_BATCH_TEST_FREE_BYTES=68679327 run "$spot" --sources all --output out.npy
  expect_input_error "needs 68679328 bytes (65.5 MiB) on the file system of '.', which has 68679327 bytes (65.5 MiB) free"
  [[ "$err" == *"--output 'out.npy' (2930 rows x 2930 columns x 8 bytes"* ]] || fail "the size is not explained: $err"
  [ ! -e out.npy.checkpoint ] || fail "a checkpoint was left behind"
  # just enough room (the 20-vertex grid: 20 x 20 x 8 + 128 = 3328 bytes)
  grid > grid.obj
  DGGVTP_BATCH_TEST_FREE_BYTES=3327 run grid.obj --sources all --output out.npy; expect_input_error "needs 3328 bytes"
  DGGVTP_BATCH_TEST_FREE_BYTES=3328 run grid.obj --sources all --output out.npy; [ "$rc" -eq 0 ] || fail "$err"
  expect_shape out.npy "20 20 float64"
  # resuming needs room for the rows still to write only
  rm out.npy
  DGGVTP_BATCH_TEST_KILL_AFTER_ROWS=10 "$batch" "$spot" --sources all --output out.npy --quiet 2>/dev/null
  [ "$?" -eq 137 ] || fail "the run was not killed"
  DGGVTP_BATCH_TEST_FREE_BYTES=1000 run "$spot" --sources all --output out.npy
  expect_input_error "the rows still to write of --output 'out.npy'"
  [ -e out.npy.checkpoint ] || fail "the checkpoint was removed"
  ;;
version_and_repeated_options)  # issue 30
  run --version
  [ "$rc" -eq 0 ] || fail "--version: exit status $rc"
  grep -Eq '^dggvtp-batch [0-9]+\.[0-9]+.* CGAL [0-9]+\.[0-9]+' "$work/.stdout" || fail "--version: $(cat "$work/.stdout")"
  for args in "--dtype f4 --dtype f8" "--sources all --sources 0" "--epsilon 0.1 --epsilon 0.2" "--threads 1 --threads 2"; do
    run "$spot" --output out.npy $args; expect_usage_error
    [[ "$err" == *"more than once"* ]] || fail "$args: $err"
    [ ! -e out.npy ] || fail "$args wrote a file"
  done
  echo 0 > one.txt
  run "$spot" --sources one.txt --output out.npy --quiet
  [ "$rc" -eq 0 ] || fail "one of each option: exit status $rc: $err"
  ;;
option_spellings)  # issue 30: -s, -o, --opt=value; an unknown option names the nearest known one
  grid > grid.obj
  run grid.obj --sources fps:3 --output ref.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  run grid.obj -s fps:3 -o short.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  run grid.obj --sources=fps:3 --output=equals.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  cmp -s ref.npy short.npy && cmp -s ref.npy equals.npy || fail "the spellings give other bytes"
  for pair in --source:--sources --sourcse:--sources --outptu:--output --dtpye:--dtype -checkpoint:--checkpoint; do
    run grid.obj "${pair%%:*}" x --sources all --output o.npy; expect_usage_error
    [ "$err" = "error: unknown option ${pair%%:*} (did you mean ${pair##*:}?) (see dggvtp-batch --help)" ] || fail "${pair%%:*}: $err"
  done
  run grid.obj --frobnicate --sources all --output o.npy; expect_usage_error
  [[ "$err" != *"did you mean"* ]] || fail "a suggestion for --frobnicate: $err"
  run grid.obj --sources all --output o.npy --progress=yes; expect_usage_error
  [[ "$err" == *"--progress takes no value"* ]] || fail "$err"
  [ ! -e o.npy ] || fail "a refused command wrote o.npy"
  ;;
unreachable_warns)  # issue 30: rows with inf are counted in a warning, even with --quiet
  # triangles 0 1 2 and 4 5 6, vertex 3 alone
  printf 'OFF\n7 2 0\n0 0 0\n1 0 0\n0 1 0\n5 5 5\n10 0 0\n11 0 0\n10 1 0\n3 0 1 2\n3 4 5 6\n' > u.off
  for q in "" --quiet; do
    run u.off --sources all --output o.npy $q; [ "$rc" -eq 0 ] || fail "$err"
    printf '%s\n' "$err" | grep -qx "warning: 7 of the 7 rows computed leave vertices unreachable (inf), up to 6 of 7 in a row: in other connected components than the row's source, or used by no face" ||
      fail "no count of the rows with unreachable vertices ($q): $err"
    rm o.npy
  done
  printf '0 5\n' > two.txt
  run u.off --sources two.txt --output o.npy --quiet --threads 2; [ "$rc" -eq 0 ] || fail "$err"
  [[ "$err" == "warning: 2 of the 2 rows computed leave vertices unreachable (inf), up to 4 of 7 in a row"* ]] || fail "$err"
  run u.off --sources fps:2 --output f.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  [[ "$err" == "warning: 2 of the 2 rows computed"* ]] || fail "fps: $err"
  run "$spot" --sources fps:2 --output s.npy --quiet; [ "$rc" -eq 0 ] || fail "$err"
  [ -z "$err" ] || fail "a warning on a connected mesh: $err"
  ;;
local_distance_matrix)  # issue 36: --max-distance, a sparse .npz that scipy.sparse.load_npz reads
  python=/usr/bin/python3
  [ -x "$python" ] || python=python3
  "$python" -c "import scipy.sparse" 2>/dev/null || skip "no Python with SciPy to read the .npz"
  printf '5 100 2000 7\n' > s.txt
  for dtype in float64 float32; do
    run "$spot" --sources s.txt --max-distance 0.1 --dtype $dtype --output m.npz --threads 2 --quiet
    [ "$rc" -eq 0 ] || fail "$err"
    [ ! -e m.npz.checkpoint ] || fail "a checkpoint directory was left"
    # each row, as dggvtp prints a field, is dggvtp --source N --max-distance 0.1 (in the dtype)
    "$python" - m.npz $dtype 5 100 2000 7 <<'PY' || fail "m.npz ($dtype) is not a valid sparse .npz"
import sys, zipfile
import numpy as np, scipy.sparse
path, dtype, sources = sys.argv[1], sys.argv[2], sys.argv[3:]
assert zipfile.ZipFile(path).testzip() is None
M = scipy.sparse.load_npz(path)
assert isinstance(M, scipy.sparse.csr_matrix) and M.shape == (len(sources), 2930), M
assert M.data.dtype == np.dtype(dtype) and M.indices.dtype == np.int32 and M.has_sorted_indices
for k, s in enumerate(sources):
    row = np.full(2930, np.inf)
    row[M.indices[M.indptr[k]:M.indptr[k + 1]]] = M.data[M.indptr[k]:M.indptr[k + 1]]
    with open(f"r{s}.txt", "w") as f:
        f.write("".join("%.17g\n" % x for x in row))
PY
    for s in 5 100 2000 7; do
      "$dggvtp" "$spot" --source $s --max-distance 0.1 --quiet --output d.npy || fail "dggvtp failed on source $s"
      "$python" -c "import numpy as np, sys; d = np.load('d.npy').astype('$dtype').astype(float); print(''.join('%.17g\n' % x for x in d), end='')" > d$s.txt
      cmp -s d$s.txt r$s.txt || fail "row of source $s ($dtype) differs from dggvtp --max-distance: $(diff d$s.txt r$s.txt | head -4)"
    done
  done
  # what does not combine with it: usage errors, and no output
  for args in "--output m.npy" "--output m.npz --checkpoint c" "--output m.npz --max-distance 0.2" \
              "--output m.npz --sources fps:2"; do
    rm -f m.npz
    run "$spot" --sources s.txt --max-distance 0.1 $args; expect_usage_error
    [ ! -e m.npz ] && [ ! -e c ] || fail "$args: an output was written"
  done
  for bad in -1 inf nan x; do
    run "$spot" --sources all --max-distance $bad --output m.npz; expect_usage_error
    [[ "$err" == *"--max-distance must be a finite number >= 0"* || "$err" == *"invalid value"* ]] || fail "$bad: $err"
  done
  if [ "$mpiexec" != none ] && command -v "$mpiexec" >/dev/null 2>&1; then
    mpi 2 "$spot" --sources all --max-distance 0.1 --output m.npz >/dev/null 2>"$work/.stderr"; rc=$?
    err=$(cat "$work/.stderr")
    [ "$rc" -eq 1 ] && [[ "$err" == *"--max-distance runs in one process"* ]] || fail "under mpirun -np 2: $rc $err"
  fi
  ;;
*)
  fail "unknown case"
  ;;
esac
exit 0
