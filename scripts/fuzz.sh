#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer and UBSan) into
# build-fuzz/ and runs each for SECONDS (default 60) from the seed corpora
# in fuzz/corpus/: the gaze, config and report readers, the EXR, video,
# .hdr/.pfm and raw-stream readers, and the checkpoint reader with its
# validation. A crash fails the script and leaves its input as
# build-fuzz/crash-*; turn it into a regression test.
# Usage: bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
targets=(gaze config report exr video float_image raw checkpoint)
command -v clang++ >/dev/null || apt-get install -y -qq --no-install-recommends clang >/dev/null
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEYESTREAM_FUZZ=ON \
  -DEYESTREAM_TESTS=OFF -DEYESTREAM_BENCH=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]/%/_fuzz}"
for target in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus-$target"
  echo "fuzzing $target for $seconds s"
  length=4096
  [ "$target" = checkpoint ] && length=65536  # its seed is a whole 32x18 run's state
  (cd build-fuzz && "./fuzz/${target}_fuzz" -max_total_time="$seconds" -max_len="$length" -print_final_stats=1 \
    "corpus-$target" "../fuzz/corpus/$target" 2>&1 | tail -4)
done
