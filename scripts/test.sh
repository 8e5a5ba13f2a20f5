#!/usr/bin/env bash
# Command 2 of the README: build everything with warnings as errors and run every test
# tier (unit, verification, regression, restart), the unit tier again under AddressSanitizer +
# UndefinedBehaviorSanitizer, and the clang-format check.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh --test
jobs=$(nproc)

echo "== format check"
scripts/check_format.sh

echo "== build (Release, -Werror)"
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=Release -DSLAMSPH_WERROR=ON >/dev/null
cmake --build build-test -j"$jobs"

echo "== tests: unit, verification, regression"
(cd build-test && ctest --output-on-failure -j"$jobs" -L "unit|verification|regression|restart" --timeout 900)

echo "== unit tier under ASan + UBSan"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DSLAMSPH_WERROR=ON -DSLAMSPH_SANITIZE=ON \
  -DSLAMSPH_BENCH=OFF >/dev/null
cmake --build build-asan -j"$jobs" --target unit_tests
(cd build-asan && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j"$jobs" -L unit --timeout 600)
