#!/usr/bin/env bash
# Installs the Debian packages gbuffer-lab builds and tests with (bookworm). Skips apt when all are present.
# Dear ImGui and ImPlot are not among them: they are vendored under third_party/.
set -euo pipefail

# libx11-dev is only recommended by libglfw3-dev (and recommends are not installed below); the UI tests'
# drag-and-drop program, tests/support/xdnd_drop.c, is built with it. apitrace and apitrace-tracers
# (apitrace, eglretrace) are what `gbuffer-lab capture` runs; its test needs them.
packages=(
  cmake g++ make ninja-build pkg-config mold
  libglfw3-dev libx11-dev libglm-dev libtinygltf-dev libopenimageio-dev libepoxy-dev libdraco-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libcli11-dev nlohmann-json3-dev
  xvfb xauth xdotool x11-apps
  clang libclang-rt-14-dev clang-format
  glslang-tools fonts-dejavu-core
  # The browser's image files (renderer/image/image_io_stb.cpp), tested natively: stb, tinyexr, zlib.
  libstb-dev libtinyexr-dev zlib1g-dev
  apitrace apitrace-tracers
  # A compiler cache: .ci/run builds through it when it is installed.
  ccache
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
