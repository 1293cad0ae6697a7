#!/usr/bin/env bash
# Quick start 1: installs what is missing, builds, and opens the editor on the default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "No display is available for the editor window; render headlessly instead: build/gbuffer-lab render --out out/"
  exit 1
fi
exec build/gbuffer-lab "$@"
