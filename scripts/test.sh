#!/usr/bin/env bash
# Quick start 2: installs what is missing, builds, and runs every test (CPU, headless GL, UI under Xvfb).
# Tests always build against Debian's ImGui into build/ and never touch the network, so CI is deterministic.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh --debian-imgui
# GL tests render with llvmpipe on the CPU: two at a time keeps both cores busy.
ctest --test-dir build --output-on-failure -j2 --timeout 600
