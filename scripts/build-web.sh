#!/usr/bin/env bash
# Builds gbuffer-lab for the browser (WebGL2, Emscripten) in build-web/ (issue 29) and publishes the
# page's four files into build-web/site/ (issue 50): index.html (ours, app/web/index.html),
# gbuffer-lab.js, gbuffer-lab.wasm and gbuffer-lab.data. Serve with
#   python3 -m http.server -d build-web/site
# Toolchain and libraries come from Debian, as scripts/install-deps.sh installs the native ones;
# Dear ImGui and ImPlot are the ones vendored under third_party/, as in the native build; zlib's sources
# (for tinyexr in the browser) come from Debian's source package, fetched under build-web/ with a private
# apt configuration (the system's sources lists are not touched). Nothing else third-party is used.
# Environment: BUILD_TYPE (Release), JOBS (1).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/build-web"
jobs="${JOBS:-1}"
build_type="${BUILD_TYPE:-Release}"
start=$(date +%s)

# 1. Packages: the toolchain, the header-only libraries, stb_image (OpenImageIO does not build for the
#    web), tinyexr, dpkg-dev for `apt-get source`, and chromium for tests/web/browser_test.py.
packages=(emscripten libglm-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev libstb-dev libtinyexr-dev fonts-dejavu-core dpkg-dev chromium cmake make)
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

# 2. zlib for tinyexr's ZIP-compressed EXR (renderer/image), from Debian's zlib source package:
#    Emscripten's own zlib port would download its sources while building (cmake/web.cmake).
zlib_dir="$("$root/scripts/debian-source.sh" zlib "$out/third_party")"
echo "zlib sources: $zlib_dir"

# 3. Configure and build. -O2's JavaScript optimiser needs acorn from Debian's node modules.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
emcmake cmake -S "$root" -B "$out" -DCMAKE_BUILD_TYPE="$build_type" -DGBL_BUILD_TESTS=OFF \
    -DGBL_WEB_ZLIB_DIR="$zlib_dir"
emmake make -C "$out" -j"$jobs" gbuffer-lab-web
cp "$root/app/web/index.html" "$out/index.html"

# 4. The site (issue 50): only what the page loads, in a folder of its own, so that serving it or
#    copying it to a course page publishes nothing of the build (object files, CMakeCache.txt, the
#    apt lists and ImGui's sources above). WEB_SITE_DIR puts it elsewhere.
site="${WEB_SITE_DIR:-$out/site}"
rm -rf "$site"
mkdir -p "$site"
cp "$root/app/web/index.html" "$site/index.html"
cp "$out/gbuffer-lab.js" "$out/gbuffer-lab.wasm" "$out/gbuffer-lab.data" "$site/"
size_kb=$(du -sk "$site" | cut -f1)
gzip_kb=$(( $(cat "$site"/* | gzip -9 | wc -c) / 1024 ))
echo "Built in $(( $(date +%s) - start )) s; the site: $site (index.html, gbuffer-lab.js, gbuffer-lab.wasm, gbuffer-lab.data: ${size_kb} KB, ${gzip_kb} KB gzipped)"
echo "Serve with: python3 -m http.server -d $site"
