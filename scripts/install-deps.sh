#!/usr/bin/env bash
# Installs the Debian 12 packages Strata builds, tests and runs with; installs only what is missing,
# so running it again is cheap. Needs root or sudo the first time something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git          # toolchain
  libglfw3-dev                                  # windows (viewer only; the core renders into framebuffers)
  libglm-dev                                    # vector maths
  libgdal-dev gdal-bin                          # rasters in, PNG out
  libproj-dev proj-data                         # projections; proj-data ships the EGM96 geoid the demo uses
  libopencolorio-dev                            # colour management
  libyaml-cpp-dev                               # pipelines
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri  # EGL headless contexts; Mesa llvmpipe without a GPU
  libepoxy-dev                                  # GL function loader (behind sdk/include/strata/gl.hpp)
  libcli11-dev                                  # command-line parsing
  libimgui-dev                                  # viewer panels
  libgtest-dev libgmock-dev libbenchmark-dev    # tests and benchmarks
  libchealpix-dev                               # HEALPix's own C library: the tests' reference for pixel indices
  libzstd-dev                                   # geometry.bdam's patches compressed on disk
  libmeshoptimizer-dev                          # geometry.bdam: patches simplified, ordered for the vertex cache
  zlib1g-dev                                    # geometry.bdam's face files: CRC-32 of each record
  xvfb xauth                                    # window tests without a display
  libxtst-dev                                   # window tests send keys and pointer events (XTest)
  xplanet-images                                # the Earth image the demo drapes, and the Earth at night
  stellarium-data                               # the Moon's map and normal map (pipelines/moon.yaml)
  doxygen                                       # the SDK's API reference (target sdk-reference)
  clang-format-14                               # the format check (scripts/check-format.sh)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
