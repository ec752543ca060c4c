#!/usr/bin/env bash
# Installs what is missing, builds everything (Release) in build/ and runs all the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
# a build folder the demo configured (its packages only) is configured again from scratch, its
# compiled files kept: what it did not find then is there now
if [ -f build/CMakeCache.txt ] && ! grep -q '^DGG_VTP_3_REQUIRE_ALL_TESTS:BOOL=ON$' build/CMakeCache.txt; then
  rm build/CMakeCache.txt
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDGG_VTP_3_REQUIRE_ALL_TESTS=ON
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2
