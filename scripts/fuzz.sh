#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer and UBSan) into
# build-fuzz/ and runs each from the seed corpora in fuzz/corpus/: the gaze,
# config and report readers, the EXR, video, .hdr/.pfm/PNG and raw-stream
# readers, and the checkpoint reader with its validation. A crash fails the
# script and leaves its input as build-fuzz/crash-*; turn it into a
# regression test and a seed.
# Usage: bash scripts/fuzz.sh [SECONDS]  each target for SECONDS (60)
#        bash scripts/fuzz.sh ci         each target for a fixed number of
#                                        inputs from seed 1 (under a minute
#                                        each here), so the work does not
#                                        depend on the machine's speed; the
#                                        seed corpora, regression inputs
#                                        included, always run first
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-60}
targets=(gaze config report exr video float_image raw checkpoint)
# The EXR and video readers run at about 6 and 80 inputs a second here
# (whole decodes): 200 and 2500 of them (about half a minute each; 400 and
# 5000 until the fourteenth session, when CI came within 3 minutes of its
# 45) keep CI within its bound; `bash scripts/fuzz.sh 600` gives them longer.
declare -A ci_runs=([gaze]=400000 [config]=600000 [report]=300000 [exr]=200 [video]=2500 [float_image]=20000
                    [raw]=500000 [checkpoint]=1000)
command -v clang++ >/dev/null || apt-get install -y -qq --no-install-recommends clang >/dev/null
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEYESTREAM_FUZZ=ON \
  -DEYESTREAM_TESTS=OFF -DEYESTREAM_BENCH=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]/%/_fuzz}"
for target in "${targets[@]}"; do
  length=4096
  [ "$target" = checkpoint ] && length=65536  # its seed is a whole 32x18 run's state
  if [ "$mode" = ci ]; then
    budget=(-runs="${ci_runs[$target]}" -seed=1)
    corpus="corpus-ci-$target"
    rm -rf "build-fuzz/$corpus"
    echo "fuzzing $target: ${ci_runs[$target]} inputs from seed 1"
  else
    budget=(-max_total_time="$mode")
    corpus="corpus-$target"
    echo "fuzzing $target for $mode s"
  fi
  mkdir -p "build-fuzz/$corpus"
  (cd build-fuzz && "./fuzz/${target}_fuzz" "${budget[@]}" -max_len="$length" -print_final_stats=1 \
    "$corpus" "../fuzz/corpus/$target" 2>&1 | grep -E "^(stat::(number_of_executed_units|new_units_added|average_exec_per_sec)|==[0-9]+==ERROR|SUMMARY)")
done
