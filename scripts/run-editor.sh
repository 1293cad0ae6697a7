#!/usr/bin/env bash
# Quick start 1: installs what is missing, builds the editor alone (not the tests; Dear ImGui with
# docking is vendored under third_party/, nothing is fetched), and opens the editor on the default scene.
#
#   scripts/run-editor.sh [editor arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
[ "${1:-}" = --debian-imgui ] && shift  # accepted and ignored, as scripts/build.sh does
scripts/install-deps.sh
scripts/build.sh --target gbuffer-lab
build="$(scripts/build.sh --print-build-dir)"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "No display is available for the editor window; render headlessly instead: $build/gbuffer-lab render --out out/"
  exit 1
fi
exec "$build/gbuffer-lab" "$@"
