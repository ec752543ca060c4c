#!/usr/bin/env bash
# Builds the tests that run threads with GCC's ThreadSanitizer in build-tsan/ and runs them: the
# library's threaded test cases (test_DGG_VTP_3_threads: concurrency, query reuse, threads on meshes
# with copies, parallel preparation), dggvtp and dggvtp-batch with threads (cli.threads_*,
# batch.*threads*, batch.farthest_point_sampling, batch.local_distance_matrix, batch.error_bounds).
# Not the Python module: its threads= runs the same library code, and the TSan runtime preloaded into
# the uninstrumented python3 died in NumPy's import (SEGV inside TSan) before any test ran.
#
# TSan sees the synchronisation of code it instruments only: TBB's scheduler, in Debian's
# libtbb.so, would hide the start and end of every parallel loop, and each would be reported as
# a race. So oneTBB is built from Debian's source package of the installed version, with
# -fsanitize=thread (build-tsan/onetbb, a minute), and put before Debian's at run time. Its
# allocator too: libtbb opens libtbbmalloc.so.2 by name and takes its memory from it, and
# Debian's, whose free lists TSan cannot see, made an arena freed by a worker and the next arena
# the main thread built at the same address look like a race (CI, concurrency test, 8 threads).
# Suppressions (scripts/tsan.supp) cover only what lies outside the project, each with its reason.
# Assertions are on (no -DNDEBUG): the scheduler checks that no message is left between patches.
# dggvtp-batch is built without MPI (its MPI cases report themselves skipped): Open MPI's ranks
# under TSan hung without using the CPU (batch.farthest_point_sampling, batch.local_distance_matrix);
# the Release and AddressSanitizer runs have the MPI cases.
# usage: scripts/run_thread_sanitizer.sh [extra ctest arguments, e.g. -R concurrency]
# Any report fails the test that triggered it (halt_on_error).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
# dpkg-source, which apt-get source runs
if ! dpkg -s dpkg-dev >/dev/null 2>&1; then
  [ "$(id -u)" -eq 0 ] || { echo "error: missing Debian package dpkg-dev and not root: install it or run as root" >&2; exit 1; }
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends dpkg-dev >/dev/null
fi
root=$PWD
mkdir -p build-tsan

# oneTBB, the installed version, from Debian's sources (apt-get source needs a deb-src entry)
tbb_version=$(dpkg-query -W -f '${Version}' libtbb-dev)
tbb_lib=$root/build-tsan/onetbb/lib
if [ ! -e "$tbb_lib/libtbb.so.12" ] || [ ! -e "$tbb_lib/libtbbmalloc.so.2" ] || [ "$(cat build-tsan/onetbb/version 2>/dev/null)" != "$tbb_version" ]; then
  rm -rf build-tsan/onetbb && mkdir -p build-tsan/onetbb/src
  sources=/etc/apt/sources.list.d/dggvtp-deb-src.sources
  if ! apt-get source --print-uris -qq onetbb="$tbb_version" >/dev/null 2>&1; then
    if [ "$(id -u)" -ne 0 ]; then
      echo "error: apt-get source onetbb needs a deb-src entry in APT's sources; add one or run as root" >&2
      exit 1
    fi
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources > "$sources"
    apt-get update -qq
  fi
  (cd build-tsan/onetbb/src && apt-get source -qq onetbb="$tbb_version" >/dev/null 2>&1) \
    || { echo "error: apt-get source onetbb=$tbb_version failed" >&2; exit 1; }
  rm -f "$sources"
  tbb_source=$(find build-tsan/onetbb/src -maxdepth 1 -type d -name 'onetbb-*' | head -n 1)
  cmake -S "$tbb_source" -B build-tsan/onetbb/build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=g++ \
        -DCMAKE_CXX_FLAGS="-O1 -g1" -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF -DTBB_SANITIZE=thread >/dev/null
  cmake --build build-tsan/onetbb/build -j2 --target tbb tbbmalloc >/dev/null
  mkdir -p "$tbb_lib"
  built=$(dirname "$(find build-tsan/onetbb/build -name 'libtbb.so.12' | head -n 1)")
  cp -P "$built"/libtbb.so* "$built"/libtbbmalloc.so* "$tbb_lib"/
  echo "$tbb_version" > build-tsan/onetbb/version
fi

flags="-fsanitize=thread -fno-omit-frame-pointer"
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
      -DCMAKE_CXX_COMPILER=g++ -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" \
      -DCMAKE_SHARED_LINKER_FLAGS="$flags" -DDGG_VTP_3_THREAD_TESTS_ONLY=ON -DDGG_VTP_3_TEST_FEWER_CONFIGURATIONS=ON -DDGG_VTP_3_WITH_MPI=OFF \
      -DDGG_VTP_3_BUILD_BENCHMARKS=OFF -DDGG_VTP_3_BUILD_EXAMPLES=OFF -DDGG_VTP_3_BUILD_PYTHON=OFF >/dev/null
cmake --build build-tsan -j2 --target test_DGG_VTP_3_threads dggvtp dggvtp-batch npy_rows

export LD_LIBRARY_PATH=$tbb_lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export TSAN_OPTIONS="halt_on_error=1 abort_on_error=1 second_deadlock_stack=1 suppressions=$root/scripts/tsan.supp"
export DGG_VTP_3_TEST_RUNS=2 # see test_threads_with_copies.cpp
# the instrumented TBB must be the one loaded
# (ldd's output read whole first: grep -q may exit before ldd has written all, and pipefail would
# then fail the check with ldd's SIGPIPE)
libraries=$(ldd build-tsan/bin/test_DGG_VTP_3_threads)
grep -q "$tbb_lib/libtbb.so" <<<"$libraries" \
  || { echo "error: test_DGG_VTP_3_threads does not load $tbb_lib/libtbb.so" >&2; exit 1; }
tests='^DGG_VTP_3\.(concurrency|query_reuse|threads_with_copies|parallel_preparation)/'
tests+='|^cli\.threads_|^batch\.(all_sources_and_threads|farthest_point_sampling|local_distance_matrix|error_bounds)$'
# the typed cases in double only: float input runs the same threads
ctest --test-dir build-tsan --output-on-failure -j2 --timeout 900 -R "$tests" -E '<Sm_f>$' --no-tests=error "$@"
