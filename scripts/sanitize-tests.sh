#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan and runs it under ctest.
#
#   scripts/sanitize-tests.sh            every CPU test and the GL binaries of asan_gl_binaries (below), but
#                                        the tests of plain_only
#   scripts/sanitize-tests.sh --all      every target built, every registered test, UI tests under Xvfb included
#   scripts/sanitize-tests.sh -R session extra ctest arguments are passed on
#   scripts/sanitize-tests.sh --build-only configures and builds, runs nothing (.ci/run builds beside the
#                                        plain tests, then runs this script again: its build is then a no-op)
#
# Environment: GBL_ASAN_BUILD_DIR (default build-asan), JOBS (default: number of cores).
# Any sanitizer report fails the test that produced it: UBSan is built with
# -fno-sanitize-recover, ASan aborts on the first error, LeakSanitizer fails the process at exit.
# tests/lsan.supp silences leaks inside third-party libraries only (Mesa, LLVM, EGL/GLX loaders,
# fontconfig); a leak with a project frame on top is never suppressed there.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${GBL_ASAN_BUILD_DIR:-$root/build-asan}"
jobs="${JOBS:-$(nproc)}"
labels='cpu|gl'
all=0
build_only=0
ctest_args=()
for arg in "$@"; do
    case "$arg" in
        --all) labels=''; all=1 ;;
        --build-only) build_only=1 ;;
        *) ctest_args+=("$arg") ;;
    esac
done

start=$(date +%s)
# The sanitizer runtimes are linked statically so that LD_PRELOAD (below) can name the GL driver
# alone: with a shared ASan runtime it would have to be preloaded as well, into every process
# (bash, xauth and Xvfb under xvfb-run included), whose own leaks would then fail the tests.
# Warnings are errors here as in scripts/build.sh (issue 45), but for -Wmaybe-uninitialized, which GCC's
# flow analysis over instrumented code reports inside libstdc++'s <regex> where the plain build does
# not (CMakeLists.txt, gbl_warnings): it is printed, and does not stop the build.
# -O1 -g1 rather than RelWithDebInfo's -O2 -g: line tables are all a sanitizer report's stack needs,
# and an instrumented file then compiles in about 55 % of the time (tests/many_lights_gl_test.cpp:
# 14.4 s against 8.0 s on one core here), which is most of CI's time in this script.
# Ninja for a new folder, as scripts/build.sh says why.
generator=()
if [[ ! -f "$build/CMakeCache.txt" ]] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S "$root" -B "$build" "${generator[@]}" -DGBL_SANITIZE=ON -DGBL_WERROR=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    "-DCMAKE_EXE_LINKER_FLAGS=-static-libasan -static-libubsan" -DGBL_CPU_TESTS_PER_BINARY=ON >/dev/null
# The GL test binaries run here: those whose host code goes past render() and a read-back (files,
# sessions, the command line, viewers and their tools, glTF scenes, the shader checks, the edge-case
# scenes). The others (renderer_shading_gl_test among them) compare shaded pixels with the CPU's math
# over the same host path, which instrumentation does not change; they run in scripts/test.sh's plain
# build, and are not even built here (CI on a fresh clone, 2 cores: this script took 2223 s of CI's 3198
# with every GL test).
asan_gl_binaries=(headless_context_gl_test renderer_gl_test gl_error_check_gl_test shader_checks_gl_test
  viewer_export_gl_test viewer_tools_gl_test lit_pin_gl_test viewport_tools_gl_test render_cli_gl_test
  compare_cli_gl_test session_cli_gl_test gltf_render_gl_test gltf_render_random_gl_test gltf_features_gl_test
  bench_cli_gl_test lessons_cli_gl_test edge_scenes_gl_test)
# The subset is built as the dependencies of one target (GBL_BUILD_SET, CMakeLists.txt): given as
# separate --target goals, Makefiles build them one after another, and a one-source test target
# leaves the second core idle (this build had a core idle 45 % of its time so).
set_list=""
targets=()
if [[ "$all" == 0 ]]; then
    set_list="gbuffer-lab"
    # ui_gbuffer's drag-and-drop program, where tests/CMakeLists.txt builds it (X11's headers installed).
    if [[ -f /usr/include/X11/Xlib.h ]]; then set_list+=";xdnd_drop"; fi
    for name in "${asan_gl_binaries[@]}"; do set_list+=";$name"; done
    for f in "$root"/tests/*_test.cpp; do
        name=$(basename "$f" .cpp)
        [[ "$name" == *_gl_test ]] || set_list+=";$name"
    done
    targets=(--target gbl_build_set)
fi
cmake -S "$root" -B "$build" "-DGBL_BUILD_SET=$set_list" >/dev/null
cmake --build "$build" -j"$jobs" "${targets[@]}"
built=$(date +%s)
if [[ "$build_only" == 1 ]]; then
    echo "sanitize-tests: build $((built - start)) s (--build-only)"
    exit 0
fi

# detect_leaks: on by default on x86-64 Linux, stated so the intent is visible.
# abort_on_error=0 + exitcode: the test fails with a report instead of a core dump.
export ASAN_OPTIONS="detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1:abort_on_error=0:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=1:${LSAN_OPTIONS:-}"
# Mesa's shader cache, emptied at the start of every run so that timings do not depend on history, but
# kept within the run: the GL test processes build the same programs, and under the sanitizers building
# them is most of a process's time (LightingPassMatchesCpuEquation, when renderer_gl_test held it: 12.4 s
# with the cache disabled, 4.2 s from a cache another process filled). .ci/run seeds it with the cache the
# plain tests filled in the same CI run (GBL_SHADER_CACHE_SEED): the same driver builds the same
# programs from the same sources there, so this run starts with them (EdgeScenes.sizes alone, on this
# 2-core machine: 77.6 s from an empty cache, 30.8 s from the plain run's).
export MESA_SHADER_CACHE_DIR="$build/mesa-shader-cache"
rm -rf "$MESA_SHADER_CACHE_DIR"
if [[ -n "${GBL_SHADER_CACHE_SEED:-}" && -d "$GBL_SHADER_CACHE_SEED" ]]; then
    cp -r "$GBL_SHADER_CACHE_SEED" "$MESA_SHADER_CACHE_DIR"
fi
unset MESA_SHADER_CACHE_DISABLE
# EGL and GLX dlopen Mesa's driver and dlclose it before exit; its globals are then unmapped and
# the blocks they pointed to look leaked (2 x 56 bytes per process, with no symbol since the module
# is gone). Preloading the driver keeps it mapped, so LeakSanitizer sees those blocks as reachable
# and no suppression is needed.
driver=$(ls /usr/lib/*/dri/swrast_dri.so /usr/lib/dri/swrast_dri.so 2>/dev/null | head -n 1 || true)
if [[ -n "$driver" ]]; then
    export LD_PRELOAD="$driver${LD_PRELOAD:+ $LD_PRELOAD}"
fi

status=0
# Two at a time as in scripts/test.sh: llvmpipe renders on the CPU, the instrumented code adds ~2x.
# The glTF loader's CPU tests run in a second pass with full (slow) unwinding on malloc: the one
# third-party leak they meet (tests/lsan.supp) is only recognisable with the whole stack, since
# the fast unwinder stops in libstdc++. GL tests never get slow unwinding: it stalls inside the
# driver's threads.
run_ctest() { ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 1200 "$@" "${ctest_args[@]}" || status=$?; }
# Tests left to scripts/test.sh's plain build: what they check does not change under instrumentation,
# and their size makes them the slowest here (CI on a fresh clone, 2 cores: 106 s, 70 s and 144 s
# against 10 s, 14 s and 24 s plain). The two limit tests build and parse a 262,145-light session to
# reach one size check; ui_layout_fits measures where ImGui places text. The code they run is run
# here by smaller inputs: every other session test, and every other UI test.
# ui_lessons too: it scrolls the Lessons window with the wheel to reach each button, and at the
# instrumented build's frame times (its run took 225 s against 31 s plain on CI) a button it had
# scrolled into view had left it again when clicked; the lesson code it drives runs here through
# lessons_cli_gl_test, lesson_file_test, lesson_steps_test and lesson_predict_test.
# Also left to the plain build: the reference compiler's run over the shaders (an external program),
# the edge-case scenes' second and third fresh processes (the first of each runs here), and the 29 s render
# of every shared glTF model (the loader's own tests run here, and GltfRender's others render models).
# ui_teaching and ui_frame_window too (107 s and 82 s here under the sanitizers, 24 s and 22 s plain): the
# editor they drive runs here under ui_real_input, ui_editor, ui_layout_combo, ui_recovery, ui_gltf,
# ui_long_frame and ui_session, and the Frame window's model under frame_diagram_test.
# ui_first_window, ui_dock_drag, ui_plot_drag and ui_overview too (28 s, 49 s, 36 s and 27 s here under the
# sanitizers): the window's first size, the docking drags, the plot's tooltip and the overview's
# grid; the editor code around them runs here under the UI tests named above.
# ui_capture too: the program it captures (tests/capture_target's deferred_demo, under apitrace) is not
# among this build's targets; the capture's child process and its errors run here under program_capture_test.
plain_only='^(ui_capture|ui_teaching|ui_frame_window|ui_first_window|ui_dock_drag|ui_plot_drag|ui_overview|Session\.TooManyLightsAreRefusedWithTheLimit|SessionCli\.SessionWithMoreLightsThanTheLimitIsRefused|ui_layout_fits|ui_lessons|ShaderCompile\..*|EdgeScenes\.(sizes\.)?run[2-9]|GltfRender\.EveryModelRendersWithNonEmptyAttachments)$'
# The CPU tests are one ctest test per executable here (GBL_CPU_TESTS_PER_BINARY, tests/CMakeLists.txt):
# the executable's name selects, and GTEST_FILTER leaves out plain_only's single CPU test.
gltf_cpu='^gltf_(loader|features)_test$'
cpu_filter='-Session.TooManyLightsAreRefusedWithTheLimit'
if [[ -n "$labels" ]]; then
    # Binaries this script did not build register as NAME_NOT_BUILT: not run.
    run_ctest -L 'gl' -E "_NOT_BUILT\$|$plain_only"
    GTEST_FILTER="$cpu_filter" run_ctest -L 'cpu' -E "$gltf_cpu|^shader_compile_test\$"
else
    run_ctest -E "^Gltf|$gltf_cpu"
    run_ctest -L 'gl|ui|fuzz' -R '^Gltf'
fi
LSAN_OPTIONS="$LSAN_OPTIONS:fast_unwind_on_malloc=0" run_ctest -L 'cpu' -R "$gltf_cpu"
end=$(date +%s)
echo "sanitize-tests: build $((built - start)) s, tests $((end - built)) s, total $((end - start)) s, ctest exit $status"
exit $status
