#!/usr/bin/env bash
# The README's second command: installs the dependencies, builds and runs
# the test suite (CTest over GoogleTest). With --sanitize, the same suite
# built with AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh "$@"
dir=build costs=tests/costs/release.txt
[ "${1:-}" = "--sanitize" ] && dir=build-asan costs=tests/costs/sanitize.txt
# A build that has not run its tests yet schedules them by the recorded
# times (longest first) rather than in declaration order, which left the
# five-minute docs check to start last on a fresh clone.
mkdir -p "$dir/Testing/Temporary"
[ -f "$dir/Testing/Temporary/CTestCostData.txt" ] || grep -v '^#' "$costs" > "$dir/Testing/Temporary/CTestCostData.txt"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan-suppressions.txt  # libx265's own leaks
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)"
