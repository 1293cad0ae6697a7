#!/bin/sh
# Builds the fuzz targets (the glTF loader's, the G-buffer manifest reader's) with clang in their own
# build folder and fuzzes one of them for a bounded time over its seed corpus.
# Usage: run_fuzz.sh SOURCE_ROOT BUILD_DIR [SECONDS] [TARGET]   (TARGET gltf_fuzz, the default, or manifest_fuzz)
set -eu
src=$1
build=$2
seconds=${3:-30}
target=${4:-gltf_fuzz}
fuzzdir="$src/tests/fuzz"
case "$target" in
    gltf_fuzz) seeds="$fuzzdir/corpus" dict="$fuzzdir/gltf.dict" ;;
    manifest_fuzz) seeds="$fuzzdir/manifest_corpus" dict="$fuzzdir/manifest.dict" ;;
    *) echo "run_fuzz.sh: no fuzz target $target" >&2; exit 2 ;;
esac

die() { echo "$target: $*" >&2; exit 1; }

# Missing tools are a failure, not a skip: the suite promises a fuzzed loader.
cxx=$(command -v clang++ || true)
[ -n "$cxx" ] || die "clang++ not found; install the Debian packages clang and libclang-rt-14-dev (or the libclang-rt-dev matching your clang)"
cc=$(command -v clang || true)
mkdir -p "$build"
probe="$build/probe.cpp"
printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' > "$probe"
"$cxx" -fsanitize=fuzzer,address,undefined "$probe" -o "$build/probe" 2> "$build/probe.log" ||
    die "clang++ cannot link -fsanitize=fuzzer,address,undefined (see $build/probe.log); install libclang-rt-14-dev (the libFuzzer and sanitizer runtimes for $("$cxx" --version | head -n 1))"

cmake -S "$fuzzdir" -B "$build/cmake" -DCMAKE_CXX_COMPILER="$cxx" ${cc:+-DCMAKE_C_COMPILER="$cc"} \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo > "$build/configure.log" 2>&1 ||
    { cat "$build/configure.log" >&2; die "configuring the fuzz build failed"; }
cmake --build "$build/cmake" -j2 || die "building the fuzz targets failed"

# New inputs go to a scratch corpus in the build folder; the seed corpus in the source tree is read only.
mkdir -p "$build/corpus-$target" "$build/artifacts-$target"
cd "$build"
export LSAN_OPTIONS="suppressions=$fuzzdir/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
"$build/cmake/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -dict="$dict" -artifact_prefix="$build/artifacts-$target/" "$build/corpus-$target" "$seeds"
