#!/usr/bin/env bash
# Builds gbuffer-lab for the browser (WebGL2, Emscripten) into build-web/ (issue 29):
# index.html (ours, app/web/index.html), gbuffer-lab.js and gbuffer-lab.wasm. Serve with
#   python3 -m http.server -d build-web
# Toolchain and libraries come from Debian, as scripts/install-deps.sh installs the native ones;
# Dear ImGui and ImPlot are the ones vendored under third_party/, as in the native build.
# Environment: BUILD_TYPE (Release), JOBS (1).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/build-web"
jobs="${JOBS:-1}"
build_type="${BUILD_TYPE:-Release}"
start=$(date +%s)

# 1. Packages: the toolchain, the header-only libraries, stb_image (OpenImageIO does not build for the
#    web), and chromium for tests/web/browser_test.py.
packages=(emscripten libglm-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev libstb-dev fonts-dejavu-core chromium cmake make)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -ne 0 ]; then
  echo "Installing: ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# 2. Configure and build. -O2's JavaScript optimiser needs acorn from Debian's node modules.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
emcmake cmake -S "$root" -B "$out" -DCMAKE_BUILD_TYPE="$build_type" -DGBL_BUILD_TESTS=OFF
emmake make -C "$out" -j"$jobs" gbuffer-lab-web
cp "$root/app/web/index.html" "$out/index.html"
echo "Built $out (index.html, gbuffer-lab.js, gbuffer-lab.wasm, gbuffer-lab.data) in $(( $(date +%s) - start )) s"
echo "Serve with: python3 -m http.server -d $out"
