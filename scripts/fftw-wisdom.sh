#!/bin/bash
# Remakes glare/fftw_wisdom.txt, the FFTW plans shipped with eyestream
# (glare/fftw_planner.hpp): runs each preset on two frames of the night city
# at 720p, 1080p and 4K with EYESTREAM_FFTW_WISDOM_OUT set, so that every
# transform the glare engines make is planned by measuring and recorded.
# Run it on an idle machine of the kind the program will run on, from the
# repository's top, after scripts/build.sh; then rebuild. Takes some minutes.
set -euo pipefail
bin=${BIN:-build/eyestream}
out=$(pwd)/glare/fftw_wisdom.txt
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
rm -f "$scratch/wisdom.txt"
for size in 1280x720 1920x1080 3840x2160; do
  w=${size%x*} h=${size#*x}
  "$bin" sample -q night-city -o "$scratch/scene" -y --width "$w" --height "$h" --duration 0.07
  for preset in fast balanced reference; do
    echo "fftw-wisdom: $size $preset" >&2
    rm -rf "$scratch/out" && mkdir -p "$scratch/out"
    EYESTREAM_FFTW_WISDOM_OUT="$scratch/wisdom.txt" "$bin" run -q -y --quality "$preset" \
      -i "$scratch/scene/frames/%05d.exr" -g "$scratch/scene/gaze.csv" -o "$scratch/out/%05d.exr"
  done
done
cp "$scratch/wisdom.txt" "$out"
echo "fftw-wisdom: wrote $out ($(grep -c '^  (' "$out") plans)" >&2
