#!/usr/bin/env bash
# Builds everything with GCC under AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/
# (-O1 -g1, assertions off as in a release: one test file took 536 s to compile at -O2 -g, 381 s
# at -O2 -g1 and 176 s at -O1 -g1, and line tables are all a sanitizer report needs) and runs the
# whole test suite with CTest (not the Python module: an instrumented module cannot be loaded into an uninstrumented python3),
# but for the tests that only run a compiler or check files (labels compile_only, cmake_package,
# documentation) and the examples, which call the library as the tests do: the Release run of
# scripts/run_tests.sh has them, and leaving them out here keeps CI's build within its time.
# For the same reason: fewer configurations (DGG_VTP_3_TEST_FEWER_CONFIGURATIONS: Surface_mesh, no
# MPFR; see test_utilities.h); not the cases that run threads, which scripts/run_thread_sanitizer.sh
# runs under ThreadSanitizer (DGG_VTP_3_LEAVE_THREADS_TO_TSAN: but for query_reuse, whose heap
# overflow AddressSanitizer found); and not the cases whose cost is numerical thoroughness over code
# the other cases run: the adversary's sweeps, MPFR at 150 bits, every source of pinion, MPI ranks
# (the one-process batch cases run the same code): 678 of the 1624 s of this run's tests before.
# usage: scripts/run_sanitizers.sh [extra ctest arguments, e.g. -R cli]
# Any sanitizer report fails the test that triggered it (-fno-sanitize-recover=all, halt_on_error).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh

# float-cast-overflow is not in GCC's undefined (it is in clang's): a NaN cast to an integer was
# found by the fuzzer only
flags="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDGG_VTP_3_REQUIRE_ALL_TESTS=ON -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DCMAKE_CXX_COMPILER=g++ \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" \
      -DDGG_VTP_3_BUILD_BENCHMARKS=OFF -DDGG_VTP_3_BUILD_PYTHON=OFF -DDGG_VTP_3_BUILD_EXAMPLES=OFF \
      -DDGG_VTP_3_TEST_FEWER_CONFIGURATIONS=ON -DDGG_VTP_3_LEAVE_THREADS_TO_TSAN=ON >/dev/null
cmake --build build-asan -j2

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# sanitized runs take 2-4 times longer than Release ones
threaded='^cli\.threads_|^batch\.all_sources_and_threads$' # the library's are not built
thorough='^adversary\.|^DGG_VTP_3\.number_types/gmpfr_computes|^DGG_VTP_3\.lower_bounds/every_source|^batch\.mpi_'
ctest --test-dir build-asan --output-on-failure -j2 --timeout 1200 -LE 'compile_only|cmake_package|documentation' \
      -E "$threaded|$thorough" "$@"
