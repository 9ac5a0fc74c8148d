#!/usr/bin/env bash
# The README's second command: installs the dependencies, builds and runs
# the test suite (CTest over GoogleTest). With --sanitize, the same suite
# built with AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh "$@"
dir=build
[ "${1:-}" = "--sanitize" ] && dir=build-asan
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan-suppressions.txt  # libx265's own leaks
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)"
