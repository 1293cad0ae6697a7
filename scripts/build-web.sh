#!/usr/bin/env bash
# Builds gbuffer-lab for the browser (WebGL2, Emscripten) into build-web/ (issue 29):
# index.html (ours, app/web/index.html), gbuffer-lab.js and gbuffer-lab.wasm. Serve with
#   python3 -m http.server -d build-web
# Toolchain and libraries come from Debian, as scripts/install-deps.sh installs the native ones;
# Dear ImGui's and zlib's sources come from Debian's source packages, fetched under build-web/ with a private
# apt configuration (the system's sources lists are not touched). Nothing third-party is committed.
# Environment: BUILD_TYPE (Release), JOBS (1), IMGUI_DIR (a checkout to use instead of the source package).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/build-web"
jobs="${JOBS:-1}"
build_type="${BUILD_TYPE:-Release}"
start=$(date +%s)

# 1. Packages: the toolchain, the header-only libraries, stb_image (OpenImageIO does not build for the
#    web), dpkg-dev for `apt-get source`, and chromium for tests/web/browser_test.py.
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

# 2. Dear ImGui's sources (1.86, the version of the native build's libimgui-dev) from Debian's source
#    package, with a deb-src entry for the archive this machine's apt already uses.
imgui_dir="${IMGUI_DIR:-}"
if [ -z "$imgui_dir" ]; then
  src="$out/third_party"
  imgui_dir="$(ls -d "$src"/imgui-*/ 2>/dev/null | head -1 || true)"
  if [ -z "$imgui_dir" ] || [ ! -f "$imgui_dir/imgui.cpp" ]; then
    apt_dir="$out/apt"
    mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/sources.list.d" "$src"
    # The archive and suite of the machine's own (deb822 or one-line) sources.
    uri="$(grep -hE '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -1 | awk '{print $2}' || true)"
    suite="$(grep -hE '^Suites:' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -1 | awk '{print $2}' || true)"
    if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
      read -r uri suite < <(awk '$1=="deb" {for (i=2;i<=NF;i++) if ($i ~ /^[a-z]+:\/\//) {print $i, $(i+1); exit}}' /etc/apt/sources.list)
    fi
    uri="${uri:-http://deb.debian.org/debian}"
    suite="${suite:-bookworm}"
    echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $uri $suite main" > "$apt_dir/sources.list"
    apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o "Dir::Etc::SourceParts=$apt_dir/sources.list.d"
              -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache" -o "Debug::NoLocking=1")
    apt-get -qq "${apt_opts[@]}" update
    (cd "$src" && apt-get -qq "${apt_opts[@]}" source imgui)
    imgui_dir="$(ls -d "$src"/imgui-*/ | head -1)"
  fi
fi
imgui_dir="${imgui_dir%/}"
echo "Dear ImGui sources: $imgui_dir"

# 2b. zlib for tinyexr's ZIP-compressed EXR (renderer/image), from Debian's zlib source package:
#     Emscripten's own zlib port would download its sources while building (cmake/web.cmake).
zlib_dir="$("$root/scripts/debian-source.sh" zlib "$out/third_party")"
echo "zlib sources: $zlib_dir"

# 3. Configure and build. -O2's JavaScript optimiser needs acorn from Debian's node modules.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
emcmake cmake -S "$root" -B "$out" -DCMAKE_BUILD_TYPE="$build_type" -DIMGUI_DIR="$imgui_dir" -DGBL_BUILD_TESTS=OFF \
    -DGBL_WEB_ZLIB_DIR="$zlib_dir"
emmake make -C "$out" -j"$jobs" gbuffer-lab-web
cp "$root/app/web/index.html" "$out/index.html"
echo "Built $out (index.html, gbuffer-lab.js, gbuffer-lab.wasm, gbuffer-lab.data) in $(( $(date +%s) - start )) s"
echo "Serve with: python3 -m http.server -d $out"
