#!/usr/bin/env bash
# Configures and builds eyestream into build/ (or build-asan/ with
# --sanitize: AddressSanitizer + UndefinedBehaviorSanitizer). Extra
# arguments are passed to `cmake --build` (e.g. --target eyestream).
set -euo pipefail
cd "$(dirname "$0")/.."

dir=build
flags=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  dir=build-asan
  # -O1 -g1: line numbers in reports, and a build that keeps CI within its time.
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DEYESTREAM_SANITIZE=ON
         -DEYESTREAM_BENCH=OFF)
fi
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
[ -f "$dir/CMakeCache.txt" ] || cmake -S . -B "$dir" "${generator[@]}" "${flags[@]}" >/dev/null
cmake --build "$dir" -j "$(nproc)" "$@"
