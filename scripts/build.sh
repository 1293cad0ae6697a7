#!/usr/bin/env bash
# Configures and builds gbuffer-lab (the Quick start commands share this), against a docking-branch
# Dear ImGui when one can be had, else against Debian's ImGui 1.86 (tiled windows, no docking).
#
#   scripts/build.sh [--imgui-dir PATH | --debian-imgui] [--print-build-dir] [--target NAME] [extra cmake arguments]
#
# --target NAME builds that target only (scripts/run-editor.sh builds gbuffer-lab, not the tests);
# every caller configures the folder the same way, so the editor's build and the tests' share it.
#
# Which ImGui, first that applies:
#   --debian-imgui             Debian's 1.86 into build/ (what scripts/test.sh and CI use: no network)
#   --imgui-dir PATH           a docking-branch checkout, built into build-dock/
#   GBL_IMGUI_DIR=PATH         the same, from the environment
#   imgui-docking/             the pinned tag below, cloned there once when the network allows
#                              (GBL_IMGUI_FETCH=0 skips the attempt, GBL_IMGUI_URL names a mirror) and
#                              checked against the pinned commit
#   otherwise                  Debian's 1.86 into build/
# One line on stdout says which ImGui was used and why. --print-build-dir prints only the build folder
# that choice leads to, without fetching or building (scripts/run-editor.sh uses it).
set -euo pipefail
cd "$(dirname "$0")/.."

imgui_tag="v1.92.9b-docking"
imgui_commit="b48d1afbe8ee8b238e2961dc363a949dd7304e23"
imgui_url="${GBL_IMGUI_URL:-https://github.com/ocornut/imgui.git}"  # a mirror may stand in; the commit is checked anyway
fetched_dir="imgui-docking"

imgui_dir="${GBL_IMGUI_DIR:-}"
imgui_from="GBL_IMGUI_DIR"
debian=0
print_only=0
targets=()
# Warnings are errors in this build (the editor's, the tests' and CI's), though not by default in
# CMakeLists.txt; a -DGBL_WERROR=OFF among the arguments comes later and wins.
cmake_args=(-DGBL_WERROR=ON)
while [ $# -gt 0 ]; do
  case "$1" in
    --imgui-dir) [ $# -ge 2 ] || { echo "build.sh: --imgui-dir needs a folder" >&2; exit 2; }
                 imgui_dir="$2"; imgui_from="--imgui-dir"; shift 2 ;;
    --imgui-dir=*) imgui_dir="${1#*=}"; imgui_from="--imgui-dir"; shift ;;
    --debian-imgui) debian=1; shift ;;
    --print-build-dir) print_only=1; shift ;;
    --target) [ $# -ge 2 ] || { echo "build.sh: --target needs a name" >&2; exit 2; }
              targets+=(--target "$2"); shift 2 ;;
    *) cmake_args+=("$1"); shift ;;
  esac
done

# Why a folder is not a usable docking-branch ImGui; empty when it is.
docking_problem() {
  local dir="$1"
  [ -d "$dir" ] || { echo "$dir does not exist"; return; }
  [ -f "$dir/imgui.cpp" ] && [ -f "$dir/backends/imgui_impl_glfw.cpp" ] && [ -f "$dir/backends/imgui_impl_opengl3.cpp" ] ||
    { echo "$dir has no imgui.cpp with GLFW and OpenGL3 backends"; return; }
  grep -q '^#define IMGUI_HAS_DOCK' "$dir/imgui.h" || { echo "$dir is not the docking branch (imgui.h lacks IMGUI_HAS_DOCK)"; return; }
}

imgui_version() { sed -n 's/^#define IMGUI_VERSION  *"\(.*\)"/\1/p' "$1/imgui.h"; }

# Why the fetched checkout is not the pinned commit; empty when it is.
pinned_problem() {
  local head
  head="$(git -C "$fetched_dir" rev-parse HEAD 2>/dev/null || true)"
  [ "$head" = "$imgui_commit" ] || echo "$fetched_dir/ is at ${head:-no git commit}, not the pinned $imgui_tag commit $imgui_commit"
}

# Clones the pinned tag into imgui-docking/ within a few seconds, or leaves nothing behind and says why.
fetch_pinned() {
  command -v git >/dev/null || { echo "git is not installed"; return; }
  local log
  if ! log="$(GIT_TERMINAL_PROMPT=0 timeout 20 git -c advice.detachedHead=false clone --quiet --depth 1 \
                --branch "$imgui_tag" "$imgui_url" "$fetched_dir" 2>&1)"; then
    rm -rf "$fetched_dir"
    echo "fetching $imgui_tag from $imgui_url failed: $(printf '%s' "${log:-timed out after 20 s}" | tail -n 1)"
    return
  fi
  local problem
  problem="$(pinned_problem)"
  if [ -n "$problem" ]; then
    rm -rf "$fetched_dir"
    echo "refusing the fetched copy: $problem"
  fi
}

# The choice: sets dir (empty for Debian's ImGui) and says why in one line.
dir="" why=""
if [ "$debian" = 1 ]; then
  why="Debian's ImGui (--debian-imgui)"
elif [ -n "$imgui_dir" ]; then
  problem="$(docking_problem "$imgui_dir")"
  if [ -z "$problem" ]; then
    dir="$(cd "$imgui_dir" && pwd)"
    why="docking ImGui $(imgui_version "$dir") from $imgui_from=$imgui_dir"
  else
    why="Debian's ImGui 1.86 without docking: $imgui_from names no docking ImGui ($problem)"
  fi
else
  problem=""
  if [ -d "$fetched_dir" ]; then
    problem="$(pinned_problem)"
  elif [ "$print_only" = 1 ]; then
    problem="no $fetched_dir/ checkout"
  elif [ "${GBL_IMGUI_FETCH:-1}" = 0 ]; then
    problem="no $fetched_dir/ checkout and GBL_IMGUI_FETCH=0"
  else
    problem="$(fetch_pinned)"
  fi
  if [ -z "$problem" ] && [ -z "$(docking_problem "$fetched_dir")" ]; then
    dir="$PWD/$fetched_dir"
    why="docking ImGui $(imgui_version "$dir") from $fetched_dir/ (pinned $imgui_tag, commit ${imgui_commit:0:12})"
  else
    why="Debian's ImGui 1.86 without docking: ${problem:-$fetched_dir/ is not a docking ImGui}"
  fi
fi

if [ -n "$dir" ]; then build="build-dock"; imgui_arg=("-DIMGUI_DIR=$dir"); else build="build"; imgui_arg=("-UIMGUI_DIR"); fi
if [ "$print_only" = 1 ]; then echo "$build"; exit 0; fi

echo "gbuffer-lab: $why -> $build/"
# Ninja when it is installed and the folder is new (a folder keeps the generator it was configured with):
# it compiles a target's sources while the libraries it links are still being built, where CMake's
# Makefiles finish each target before starting the next, and the chain of libraries left a core idle.
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
# -g1: line tables, which a crash's backtrace needs, without the full debug info (variables, types) that
# made the optimised build about 28 % slower to compile here (ui/session's first unity batch: 22-24 s
# against 15-18 s). For a debugger's view of locals, configure a Debug build of your own.
cmake -S . -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
    "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "${imgui_arg[@]}" "${cmake_args[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" "${targets[@]}"
