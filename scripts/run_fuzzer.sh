#!/usr/bin/env bash
# Builds the libFuzzer target test/DGG_VTP_3_fuzz (clang, -fsanitize=fuzzer,address,undefined) in
# build-fuzz/ and fuzzes dggvtp's loader and the propagation for a bounded time.
# usage: scripts/run_fuzzer.sh [SECONDS]   (default 60)
# Installs clang and its sanitizer runtimes with apt-get if missing (as root). The corpus grows in
# build-fuzz/corpus (not in the repository); the seeds stay in test/DGG_VTP_3_fuzz/seed_corpus.
# Exit status: 0 if no crash, hang, leak or sanitizer report; otherwise libFuzzer's (the input
# that failed is saved as build-fuzz/crash-*, timeout-* or oom-*).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "usage: $0 [SECONDS]" >&2; exit 1; }

bash scripts/install_dependencies.sh
packages=(clang libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "error: missing Debian packages (${missing[*]}) and not root: install them or run as root" >&2
    exit 1
  fi
  echo "installing: ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
      -DDGG_VTP_3_BUILD_FUZZER=ON -DDGG_VTP_3_BUILD_EXAMPLES=OFF -DDGG_VTP_3_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-fuzz -j2 --target fuzz_dggvtp

mkdir -p build-fuzz/corpus
cd build-fuzz
# -max_len: small meshes keep each run fast; -timeout: a run over 10 s is a hang;
# -rss_limit_mb: a single input may not take more than 2 GB (libFuzzer's default, said aloud)
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0 \
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ./bin/fuzz_dggvtp corpus ../test/DGG_VTP_3_fuzz/seed_corpus \
    -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
