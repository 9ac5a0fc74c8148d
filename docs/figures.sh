#!/usr/bin/env bash
# Regenerates every picture in docs/ and every figure the docs quote from a
# command, with the project's own commands, so the docs cannot drift:
#
#   bash docs/figures.sh            regenerate: pictures into docs/, quoted numbers rewritten in place
#   bash docs/figures.sh --check    regenerate into a scratch folder and compare (CTest runs this):
#                                   each quoted number within its stated tolerance (docs/figures.map),
#                                   each picture within CIEDE2000 (eyestream compare)
#   add --bench                     rerun `eyestream bench` too, with 4K and the peers (about 20 minutes,
#                                   and /usr/bin/time for peak memory; timing: never in --check)
#
# Timings are quoted as measured; --check reads them but does not judge them
# (a noisy machine is not a failure). The bench's table and the figures
# derived from it are checked against the committed docs/bench.csv, and
# the peers' figures against docs/bench-peers.txt.
# Environment: EYESTREAM (the program, default build/eyestream), FIGURES_DIR
# (scratch folder, default out/figures).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=update bench=no
for a in "$@"; do
  case "$a" in
    --check) mode=check ;;
    --bench) bench=yes ;;
    *) echo "usage: docs/figures.sh [--check] [--bench]" >&2; exit 2 ;;
  esac
done
es=${EYESTREAM:-build/eyestream}
es=$(realpath "$es")
work=${FIGURES_DIR:-out/figures}
if [ "$bench" = yes ] && [ ! -x /usr/bin/time ]; then
  echo "docs/figures.sh: --bench needs /usr/bin/time (Debian: time) for the runs' peak memory" >&2
  exit 2
fi
rm -rf "$work" && mkdir -p "$work/pictures"
values="$work/values.txt"
: > "$values"
value() { echo "$1 $2" >> "$values"; }
command -v ffmpeg > /dev/null || { echo "docs/figures.sh: needs ffmpeg (scripts/install-deps.sh installs it)" >&2; exit 77; }

# The flash and its afterimage (README): frames 16, 20, 30, 45, 70 and 110
# of the flash sample at 30 fps without glare (which would veil the disc), each cropped to the 200x160 around the
# flash, side by side, each with 4 px of white on its right.
"$es" sample -q flash -o "$work/flash"
"$es" run -q -i "$work/flash/frames/%05d.exr" -g "$work/flash/gaze.csv" -o "$work/flash/out/%05d.png" --end-frame 111 --no-glare
inputs=() chain="" labels=""
for i in 0 1 2 3 4 5; do
  f=(16 20 30 45 70 110); inputs+=(-i "$(printf "$work/flash/out/%05d.png" "${f[$i]}")")
  chain+="[$i:v]crop=200:160:220:100,pad=204:160:0:0:white,format=rgb24[p$i];" labels+="[p$i]"
done
ffmpeg -v error -y "${inputs[@]}" -filter_complex "${chain}${labels}hstack=inputs=6" "$work/pictures/flash-afterimage.png"

# The new samples through the wave-optics lines (model.md): the sun
# through leaves and the shaped lamps' beacon at 0, 1/3, 2/3 and 1 s,
# each frame cropped to 320x180.
for s in dappled-sunlight shaped-lamps; do
  "$es" sample -q $s -o "$work/$s" --duration 1.05
  "$es" run -q -i "$work/$s/frames" -g "$work/$s/gaze.csv" -o "$work/$s/out/%05d.png" --flare-model wave
done
inputs=() chain=""
for i in 0 1 2 3; do
  inputs+=(-i "$(printf "$work/dappled-sunlight/out/%05d.png" $((i * 10)))")
  inputs+=(-i "$(printf "$work/shaped-lamps/out/%05d.png" $((i * 10)))")
  chain+="[$((2 * i)):v]crop=320:180:160:0,format=rgb24[d$i];[$((2 * i + 1)):v]crop=320:180:300:90,format=rgb24[l$i];"
done
ffmpeg -v error -y "${inputs[@]}" -filter_complex \
  "${chain}[d0][d1][d2][d3]hstack=inputs=4[top];[l0][l1][l2][l3]hstack=inputs=4[bottom];[top][bottom]vstack" \
  "$work/pictures/wave-lines.png"

# The 70-year-old's PSF in the dark (model.md).
"$es" psf -o "$work/psf.exr" --width 200 --height 150 --fov-deg 9.17 --adaptation -3 --viewer-age 70 > "$work/psf.txt"
cp "$work/psf.png" "$work/pictures/psf-halo.png"
value psf.pupil_mm "$(awk '/^pupil/ {print $2}' "$work/psf.txt")"
for r in 0.05 1 10; do value "psf.within_$r" "$(awk -v r="$r" '$3 == r {sub(",", "", $5); print $5}' "$work/psf.txt")"; done

# The wave-optics PSF of a night pupil (6 mm), an open eye beside one
# squinting (the upper lid 1.5 mm above the pupil's centre), the central
# 300x300 of each (model.md).
for lid in open squint; do
  extra=(); [ $lid = squint ] && extra=(--eyelid-mrd1 1.5)
  "$es" psf -o "$work/lid-$lid.exr" --width 300 --height 300 --fov-deg 9 --adaptation -2 --flare-model wave "${extra[@]}" > /dev/null
done
ffmpeg -v error -y -i "$work/lid-open.png" -i "$work/lid-squint.png" -filter_complex \
  "[0:v]crop=300:300:(iw-300)/2:(ih-300)/2,pad=304:300:0:0:white,format=rgb24[a];[1:v]crop=300:300:(iw-300)/2:(ih-300)/2,format=rgb24[b];[a][b]hstack" \
  "$work/pictures/eyelid-psf.png"

# The tone-curve family (model.md).
"$es" curves -o "$work/pictures/tone-curves.png"

# The simulator preview: two drivers, the report's summary and charts (simulator.md).
EYESTREAM="$es" PREVIEW_DIR="$work/preview" bash scripts/simulator-preview.sh > "$work/preview.txt" 2>&1
cp "$work/preview/report.png" "$work/pictures/night-drive-long-report.png"
python3 - "$work/preview/report.json" "$work/preview.txt" >> "$values" << 'EOF'
import json, re, sys
summary = json.load(open(sys.argv[1]))
for v in summary["viewers"]:
    age = int(v["viewer_age_years"])
    print(f"sim.{age}.veil_max {v['veil_cd_m2']['max']}")
    print(f"sim.{age}.veil_mean {v['veil_cd_m2']['mean']}")
    print(f"sim.{age}.ti_max {v['ti_percent_max']}")
    print(f"sim.{age}.contrast_veiled_min {v['target_abs_contrast_veiled_min']}")
    print(f"sim.contrast_min {v['target_abs_contrast_min']}")
    print(f"sim.frames_with_target {v['frames_with_target']}")
done = re.search(r"(\d+) frames in ([0-9.]+) s \(([0-9.]+) fps\)", open(sys.argv[2]).read())
print(f"sim.seconds {done.group(2)}\nsim.fps {done.group(3)}")
EOF

# HDR10's measured light level (usage.md): a 160x90 night drive.
"$es" sample -q night-drive -o "$work/hdr10" --width 160 --height 90 --duration 0.5
"$es" run -q -i "$work/hdr10/frames" -g "$work/hdr10/gaze.csv" -o "$work/hdr10/hdr.mp4" --hdr10 --display-peak 1000 --crf 0
ffprobe -v error -select_streams v:0 -show_entries stream_side_data=max_content,max_average -of default=nw=1 \
  "$work/hdr10/hdr.mp4" | sed 's/^max_content=/hdr10.maxcll /; s/^max_average=/hdr10.maxfall /' >> "$values"

# The 45-frame 1080p night city (performance.md, README): each preset's p99
# CIEDE2000 against reference over all frames and on its worst frame; with
# --bench also the end-to-end times of `fast` and `balanced` to H.264.
"$es" sample -q night-city -o "$work/city" --width 1920 --height 1080 --duration 1.5
# Uncompressed: ZIP would spend most of these runs' time writing and reading.
for q in reference balanced fast; do
  "$es" run -q -i "$work/city/frames/%05d.exr" -g "$work/city/gaze.csv" -o "$work/city/$q/%05d.exr" --quality $q \
    --exr-compression none
done
for q in balanced fast; do
  "$es" compare --metric de99 --fail 100 --warn 100 --json "$work/city/$q.json" \
    "$work/city/reference/%05d.exr" "$work/city/$q/%05d.exr" > /dev/null
  python3 -c "import json, sys; c = json.load(open(sys.argv[1]))
print('city45.$q.p99', c['overall']['de2000_p99']); print('city45.$q.worst', max(f['de2000_p99'] for f in c['frames']))" \
    "$work/city/$q.json" >> "$values"
done
rm -rf "$work"/city/reference "$work"/city/balanced "$work"/city/fast
if [ "$bench" = yes ]; then
  for q in fast balanced; do
    /usr/bin/time -o "$work/city/$q.rss" -f "%M" \
      "$es" run -i "$work/city/frames/%05d.exr" -g "$work/city/gaze.csv" -o "$work/city/$q.mp4" --quality $q 2>&1 |
      sed -n 's/.* frames in \([0-9.]*\) s .*/city45.'$q'.seconds \1/p' >> "$values"
    awk -v q=$q '{ printf "city45.%s.peak_mib %.0f\n", q, $1 / 1024 }' "$work/city/$q.rss" >> "$values"
  done
fi

# Figures the test suite prints (usage.md, model.md): the presets' error
# bounds at 256x144, the wave lines' correlations through the command
# line and the squinting lid's streak, from the tests built beside the
# program.
tests="$(dirname "$es")/tests/eyestream_tests"
[ -x "$tests" ] || { echo "docs/figures.sh: needs $tests (bash scripts/build.sh)" >&2; exit 2; }
"$tests" --gtest_filter='QualityPresets.EachPresetStaysWithinItsErrorBoundAgainstReference' 2>&1 |
  sed -n 's/^\([a-z-]*\), \([a-z]*\): p99 CIEDE2000 \([0-9.]*\)$/presets.\1.\2 \3/p' >> "$values"
"$tests" --gtest_filter='WavePsf.LinesFollowThePupilAndTheLightAndRepeatForTheSameState' 2>&1 |
  sed -n 's/^correlation: pupil 4.0 to 3.5 mm \([0-9.]*\), light moved 4 deg \([0-9.]*\), one frame later \([0-9.]*\)$/wave.pupil \1\nwave.light \2\nwave.frame \3/p' >> "$values"
"$tests" --gtest_filter='Eyelid.ASquintingLidAndItsLashesStreakAlongTheAxes' 2>&1 |
  sed -n 's/^seed \([0-9]*\): modulation along the axes over the diagonals, open \([0-9.]*\), squinting (MRD1 1.5 mm) \([0-9.]*\)$/lid.\1.open \2\nlid.\1.squint \3/p' >> "$values"
"$tests" --gtest_filter='WaveLinesCli.*' 2>&1 |
  sed -n 's/^\([0-9]*\) px: lines at 0.5 s, 30 against 60 frames\/s \([0-9.]*\); at 0.5 against 1.5 s \([0-9.]*\)$/wave.\1.rates \2\nwave.\1.second \3/p' >> "$values"

# The bench (performance.md, README): only when asked.
if [ "$bench" = yes ]; then
  "$es" bench -y --sizes 720p,1080p,4k --frames 24 --csv "$work/bench.csv" --png "$work/pictures/bench.png"
  # The peers beside `fast` on the same 1080p frames (docs/bench-peers.txt).
  "$es" bench -q --sizes 1080p --presets fast --frames 24 --no-skip-study --peers | sed -n '/^peer /,$p' \
    > "$work/bench-peers.txt"
  [ "$mode" = update ] && cp "$work/bench.csv" docs/bench.csv
  # Kept only when every peer ran (a machine without them keeps the last).
  if [ "$mode" = update ] && ! grep -q skipped "$work/bench-peers.txt"; then
    cp "$work/bench-peers.txt" docs/bench-peers.txt
  fi
fi

if [ "$mode" = update ]; then
  cp "$work"/pictures/*.png docs/
  FIGURES_BENCH=$bench python3 docs/figures.py update "$values"
  echo "docs/figures.sh: pictures and quoted figures regenerated (values in $values)"
else
  failed=0
  python3 docs/figures.py check "$values" || failed=1
  for p in "$work"/pictures/*.png; do
    [ "$(basename "$p")" = bench.png ] && continue
    "$es" compare --metric de99 --warn 1 --fail 2 "docs/$(basename "$p")" "$p" > "$work/compare.txt" 2>&1 ||
      { echo "docs/$(basename "$p") differs from what its command draws now:"; cat "$work/compare.txt"; failed=1; }
  done
  [ $failed = 0 ] && echo "docs/figures.sh: every picture matches its command"
  exit $failed
fi
