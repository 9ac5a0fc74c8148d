#!/usr/bin/env bash
# The README's first command: installs the dependencies, builds, generates
# the built-in night-drive sample and filters it to out/demo.mp4.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh --target eyestream
build/eyestream sample -y night-drive -o out/night-drive
build/eyestream run -y -i out/night-drive/frames/%05d.exr -g out/night-drive/gaze.csv -o out/demo.mp4
echo "demo: out/demo.mp4 is ready to watch"
