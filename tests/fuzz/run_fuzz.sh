#!/bin/sh
# Builds the glTF loader fuzz target with clang in its own build folder and fuzzes it for a
# bounded time over the seed corpus. Usage: run_fuzz.sh SOURCE_ROOT BUILD_DIR [SECONDS]
set -eu
src=$1
build=$2
seconds=${3:-30}
fuzzdir="$src/tests/fuzz"

die() { echo "gltf_fuzz: $*" >&2; exit 1; }

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
cmake --build "$build/cmake" -j2 || die "building the fuzz target failed"

# New inputs go to a scratch corpus in the build folder; the seed corpus in the source tree is read only.
mkdir -p "$build/corpus" "$build/artifacts"
cd "$build"
export LSAN_OPTIONS="suppressions=$fuzzdir/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
"$build/cmake/gltf_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -dict="$fuzzdir/gltf.dict" -artifact_prefix="$build/artifacts/" "$build/corpus" "$fuzzdir/corpus"
