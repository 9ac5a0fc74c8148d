#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer and UBSan) into
# build-fuzz/ and runs each for SECONDS (default 60) from the seed corpora
# in fuzz/corpus/. A crash leaves its input as build-fuzz/crash-*; turn it
# into a regression test. Usage: bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
command -v clang++ >/dev/null || apt-get install -y --no-install-recommends clang
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEYESTREAM_FUZZ=ON \
  -DEYESTREAM_TESTS=OFF -DEYESTREAM_BENCH=OFF >/dev/null
cmake --build build-fuzz --target gaze_fuzz config_fuzz report_fuzz
for target in gaze config report; do
  mkdir -p "build-fuzz/corpus-$target"
  echo "fuzzing $target for $seconds s"
  (cd build-fuzz && "./fuzz/${target}_fuzz" -max_total_time="$seconds" -max_len=4096 -print_final_stats=1 \
    "corpus-$target" "../fuzz/corpus/$target" 2>&1 | tail -4)
done
