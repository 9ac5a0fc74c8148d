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
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DEYESTREAM_SANITIZE=ON -DEYESTREAM_BENCH=OFF)
fi
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
[ -f "$dir/CMakeCache.txt" ] || cmake -S . -B "$dir" "${generator[@]}" "${flags[@]}" >/dev/null
cmake --build "$dir" -j "$(nproc)" "$@"
