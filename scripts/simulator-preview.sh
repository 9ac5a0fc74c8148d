#!/usr/bin/env bash
# One command for driving-simulator users: generates the 20 s night-drive-long
# sample and renders it for a 25- and a 75-year-old driver side by side with
# the gaze and a timecode burned in, plus the per-frame report, its JSON
# summary and its charts:
#   out/night-drive-long/preview.mp4, report.csv, report.json, report.png
# Assumes the build exists (bash scripts/demo.sh or scripts/build.sh first).
# EYESTREAM and PREVIEW_DIR name another program or folder (docs/figures.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
es=${EYESTREAM:-build/eyestream}
dir=${PREVIEW_DIR:-out/night-drive-long}
"$es" sample -y night-drive-long -o "$dir/scene"
"$es" run -y -i "$dir/scene/frames/%05d.exr" -g "$dir/scene/gaze.csv" -o "$dir/preview.mp4" \
  --viewers 25,75 --gaze-overlay --timecode \
  --report "$dir/report.csv" --target-mask "$dir/scene/target" "$@"
echo "simulator preview: $dir/preview.mp4; report: $dir/report.csv, report.json, report.png"
