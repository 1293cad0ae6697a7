#!/usr/bin/env bash
# Configures and builds gbuffer-lab (the Quick start commands share this) into build/, with the Dear
# ImGui (docking) and ImPlot vendored under third_party/: no network, the same ImGui everywhere.
#
#   scripts/build.sh [--print-build-dir] [--target NAME] [extra cmake arguments]
#
# --target NAME builds that target only (scripts/run-editor.sh builds gbuffer-lab, not the tests);
# every caller configures the folder the same way, so the editor's build and the tests' share it.
# --print-build-dir prints the build folder without building (scripts/run-editor.sh uses it).
# --debian-imgui is accepted and ignored: it chose Debian's ImGui 1.86 before ImGui was vendored.
set -euo pipefail
cd "$(dirname "$0")/.."

print_only=0
targets=()
# Warnings are errors in this build (the editor's, the tests' and CI's), though not by default in
# CMakeLists.txt; a -DGBL_WERROR=OFF among the arguments comes later and wins.
cmake_args=(-DGBL_WERROR=ON)
while [ $# -gt 0 ]; do
  case "$1" in
    --debian-imgui) shift ;;
    --print-build-dir) print_only=1; shift ;;
    --target) [ $# -ge 2 ] || { echo "build.sh: --target needs a name" >&2; exit 2; }
              targets+=(--target "$2"); shift 2 ;;
    *) cmake_args+=("$1"); shift ;;
  esac
done

build="build"
if [ "$print_only" = 1 ]; then echo "$build"; exit 0; fi

# Ninja when it is installed and the folder is new (a folder keeps the generator it was configured with):
# it compiles a target's sources while the libraries it links are still being built, where CMake's
# Makefiles finish each target before starting the next, and the chain of libraries left a core idle.
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
# -g1: line tables, which a crash's backtrace needs, without the full debug info (variables, types) that
# made the optimised build about 28 % slower to compile here (ui/session's first unity batch: 22-24 s
# against 15-18 s). For a debugger's view of locals, configure a Debug build of your own.
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
    "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "${cmake_args[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" "${targets[@]}"
