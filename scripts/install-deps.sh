#!/usr/bin/env bash
# Installs eyestream's build and test dependencies from Debian's archive.
# Idempotent: packages already present are left alone. Needs root (or sudo).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git time
  libopencv-core-dev libopencv-imgproc-dev
  libopencv-imgcodecs-dev  # the tests only: an independent PNG, Radiance and PFM codec to check the program's own
  libpng-dev  # PNG pictures: OpenCV's codecs would bring about 70 more libraries into every start (io/png_file.hpp)
  libopenexr-dev
  libtiff-dev  # float TIFF stills (half floats, alpha), which OpenCV's reader refuses
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev
  libeigen3-dev libfftw3-dev
  libdeflate-dev  # inflates OpenEXR's ZIP blocks ten times faster than zlib (io/zlib_uncompress.cpp)
  libcli11-dev nlohmann-json3-dev
  libxxhash-dev  # the glare stage knows a still scene's last frame by its XXH3 digest, not a 25 MB copy (pipeline/memory/frame_digest.hpp)
  libgtest-dev libgmock-dev libbenchmark-dev
  zlib1g-dev  # uncompress's declaration (io/zlib_uncompress.cpp); the tests check PNG chunk CRCs with zlib (an independent CRC-32)
  python3-dev pybind11-dev python3-numpy  # the Python module (python/) and its tests
  ffmpeg  # the tests cross-check HDR video luminance with its zscale filter (zimg), an independent decoder
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: installed ${#missing[@]} packages"
