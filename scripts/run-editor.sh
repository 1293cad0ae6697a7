#!/usr/bin/env bash
# Quick start 1: installs what is missing, builds the editor alone (not the tests; with a docking ImGui when one can be had, see
# scripts/build.sh), and opens the editor on the default scene.
#
#   scripts/run-editor.sh [--imgui-dir PATH | --debian-imgui] [editor arguments...]
#
# GBL_IMGUI_DIR=PATH names a docking-branch checkout as --imgui-dir does.
set -euo pipefail
cd "$(dirname "$0")/.."
build_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --imgui-dir) [ $# -ge 2 ] || { echo "run-editor.sh: --imgui-dir needs a folder" >&2; exit 2; }
                 build_args+=("$1" "$2"); shift 2 ;;
    --imgui-dir=*|--debian-imgui) build_args+=("$1"); shift ;;
    *) break ;;
  esac
done
scripts/install-deps.sh
scripts/build.sh "${build_args[@]}" --target gbuffer-lab
build="$(scripts/build.sh --print-build-dir "${build_args[@]}")"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "No display is available for the editor window; render headlessly instead: $build/gbuffer-lab render --out out/"
  exit 1
fi
exec "$build/gbuffer-lab" "$@"
