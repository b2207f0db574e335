#!/usr/bin/env bash
# The README's test command: builds and tests everything CI checks, and stops at the first
# failure with a message saying which step failed.
#
#   0. layout       every tracked C++ file as clang-format-14 lays it out (.clang-format)
#   1. build/       release build, warnings as errors; ctest
#   2. install      `cmake --install build` into a temporary prefix; the standalone project in
#                   examples/ is configured against it with find_package(foresight CONFIG),
#                   built with warnings as errors, and run. Then the two other ways a game adds
#                   foresight, tests/consumers/add_subdirectory and tests/consumers/fetch_content
#                   (FetchContent with SOURCE_DIR: no network), each configured with the library
#                   alone, built with warnings as errors and run; they fail if foresight changes
#                   the parent's CMAKE_BUILD_TYPE or builds its tests, tools or backends
#   3. benchmark    build/bench/foresight_bench, foresight_bench_aim and foresight_bench_c_api,
#                   very briefly (a smoke test, not a measurement),
#                   and build/bench/foresight_bench_worlds when the backends are built
#   4. build-asan/  debug build with AddressSanitizer + UndefinedBehaviorSanitizer, warnings as
#                   errors, no benchmarks, no browser tests (the same JavaScript as in build/);
#                   ctest, halting on the first sanitizer report
#   5. build-fuzz/  the libFuzzer harnesses of fuzz/ (clang-14, address + undefined sanitizers),
#                   each run for FORESIGHT_FUZZ_SECONDS (default 5) seconds by scripts/fuzz.sh,
#                   which fails on any finding (kept in build-fuzz/fuzz-findings/)
#
# Each configuration is built once, with every core (FORESIGHT_JOBS overrides the count).
# Cheap checks run first so that a failure shows up early.
# Why sequential builds with -j2 rather than both at once with -j1: ninja keeps both cores
# over 90% busy, so overlapping the two builds would save only seconds and interleave the logs.
# Why Debug for the sanitizer build: -O0 compiles faster than RelWithDebInfo, and GCC 12 at
# -O2 with sanitizers reports false -Wrestrict errors inside std::string.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

jobs=${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}
start=$SECONDS
current="installing dependencies"
tmp=""

on_exit() {
    local status=$?
    if [[ -n "$tmp" ]]; then rm -rf "$tmp"; fi
    if ((status != 0)); then
        echo "" >&2
        echo "test.sh: FAILED while $current (exit status $status, after $((SECONDS - start)) s)" >&2
    fi
    exit "$status"
}
trap on_exit EXIT

# step DESCRIPTION: prints a progress line and remembers what is running for the failure message.
step() {
    current=$1
    echo ""
    echo "==> [$((SECONDS - start)) s] $current"
}

# configure_and_build DIR CMAKE-ARGS...: a Ninja build tree in DIR (reused if it exists).
configure_and_build() {
    local dir=$1
    shift
    local configure=(cmake -S . -B "$dir" --log-level=WARNING "$@")
    # A build tree keeps the generator it was made with: ask for Ninja only in a new one.
    if [[ ! -f "$dir/CMakeCache.txt" ]]; then configure+=(-G Ninja); fi
    "${configure[@]}"
    cmake --build "$dir" --parallel "$jobs"
}

# The engine oracle test (tests/engine_oracle_test.cpp) fails instead of skipping when a real
# engine's runtime is missing: CI compares against all of them.
export FORESIGHT_REQUIRE_ENGINES=1

run_ctest() {
    ctest --test-dir "$1" --output-on-failure --no-tests=error --timeout 300 --parallel "$jobs"
}

step "installing dependencies"
./scripts/install-deps.sh

step "checking the C++ layout (clang-format-14 with .clang-format)"
# Every tracked C++ file as clang-format lays it out; the diff names the files to format with
# `clang-format-14 -i FILE`.
mapfile -t cpp_files < <(git ls-files '*.cpp' '*.h' '*.inc' 2>/dev/null || find include src backends tools tests bench examples fuzz -name '*.cpp' -o -name '*.h' -o -name '*.inc')
if ! clang-format-14 --dry-run --Werror "${cpp_files[@]}"; then
    echo "test.sh: C++ files differ from .clang-format's layout (above); run clang-format-14 -i on them" >&2
    exit 1
fi

step "building build/ (Release, -Werror)"
configure_and_build build -DCMAKE_BUILD_TYPE=Release -DFORESIGHT_WERROR=ON -DFORESIGHT_SANITIZE= \
    -DFORESIGHT_DOUBLE_PRECISION=OFF -DFORESIGHT_BUILD_TESTS=ON -DFORESIGHT_BUILD_TOOLS=ON \
    -DFORESIGHT_BUILD_BENCHMARKS=ON

step "testing build/"
# The viewer's browser tests must be there: install-deps.sh installs Node.js, npm ci and chromium.
# (The list is read whole first: `ctest -N | grep -q` under pipefail fails when grep stops
# reading before ctest has written its last line.)
registered=$(ctest --test-dir build -N)
if ! grep -q 'viewer\.demo_page' <<<"$registered"; then
    echo "test.sh: the viewer's browser tests are not registered in build/ (Node.js, viewer/node_modules or chromium missing?)" >&2
    exit 1
fi
# The language bindings must be there too: install-deps.sh installs Python with pybind11 and
# NumPy, mono and emscripten, and CMake registers each binding's tests when it finds them.
for binding in python_pytest csharp_binding wasm.api; do
    if ! grep -q "$binding" <<<"$registered"; then
        echo "test.sh: the $binding tests are not registered in build/ (a binding's toolchain missing? see bindings/)" >&2
        exit 1
    fi
done
run_ctest build

step "installing build/ into a temporary prefix and building examples/ against it"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/foresight-test.XXXXXX")
cmake --install build --prefix "$tmp/prefix" >/dev/null
for notice in LICENSE THIRD_PARTY_NOTICES.md; do
    if [[ ! -f "$tmp/prefix/share/doc/foresight/$notice" ]]; then
        echo "test.sh: cmake --install did not install share/doc/foresight/$notice" >&2
        exit 1
    fi
done
# The installed package must not point back into the source or build tree.
if grep -rl --include='*.cmake' -e "$root" "$tmp/prefix"; then
    echo "test.sh: the installed CMake package refers to $root (files above)" >&2
    exit 1
fi
cmake -S examples -B "$tmp/example" -G Ninja --log-level=WARNING -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$tmp/prefix" \
    -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror"
found=$(sed -n 's/^foresight_DIR:PATH=//p' "$tmp/example/CMakeCache.txt")
if [[ "$found" != "$tmp/prefix/"* ]]; then
    echo "test.sh: examples/ found foresight in '$found', not in the temporary prefix" >&2
    exit 1
fi
cmake --build "$tmp/example" --parallel "$jobs"

step "running the examples (hello_prediction, c_example, and hello_embree / hello_bullet when those backends are built)"
"$tmp/example/hello_prediction"
if grep -q '^FORESIGHT_BUILD_C_API:BOOL=ON' build/CMakeCache.txt; then
    if [[ ! -x "$tmp/example/c_example" ]]; then
        echo "test.sh: the installed package has no foresight::foresight_c although build/ has it" >&2
        exit 1
    fi
    "$tmp/example/c_example"
fi
if grep -q '^FORESIGHT_WITH_EMBREE:BOOL=ON' build/CMakeCache.txt; then
    if [[ ! -x "$tmp/example/hello_embree" ]]; then
        echo "test.sh: the installed package has no foresight::embree although build/ has it" >&2
        exit 1
    fi
    "$tmp/example/hello_embree"
fi
if grep -q '^FORESIGHT_WITH_BULLET:BOOL=ON' build/CMakeCache.txt; then
    if [[ ! -x "$tmp/example/hello_bullet" ]]; then
        echo "test.sh: the installed package has no foresight::bullet although build/ has it" >&2
        exit 1
    fi
    "$tmp/example/hello_bullet"
fi

# The consumers compile the library themselves (about a minute each on two cores): one with no
# build type, one with Debug, the cheapest builds; their CMakeLists.txt check that the build
# type they set (or left empty) is still theirs after adding foresight.
consumer_flags="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror"
step "building and running tests/consumers/add_subdirectory (foresight added with add_subdirectory)"
cmake -S tests/consumers/add_subdirectory -B "$tmp/consumer-add-subdirectory" -G Ninja --log-level=WARNING \
    -DFORESIGHT_SOURCE_DIR="$root" -DCMAKE_CXX_FLAGS="$consumer_flags"
cmake --build "$tmp/consumer-add-subdirectory" --parallel "$jobs"
"$tmp/consumer-add-subdirectory/consumer_add_subdirectory"

step "building and running tests/consumers/fetch_content (foresight added with FetchContent, offline)"
cmake -S tests/consumers/fetch_content -B "$tmp/consumer-fetch-content" -G Ninja --log-level=WARNING \
    -DCMAKE_BUILD_TYPE=Debug -DFETCHCONTENT_FULLY_DISCONNECTED=ON \
    -DFORESIGHT_SOURCE_DIR="$root" -DCMAKE_CXX_FLAGS="$consumer_flags"
cmake --build "$tmp/consumer-fetch-content" --parallel "$jobs"
"$tmp/consumer-fetch-content/consumer_fetch_content"

step "benchmark smoke test (build/bench/foresight_bench, not a measurement)"
./build/bench/foresight_bench --benchmark_min_time=0.01
./build/bench/foresight_bench_aim --benchmark_min_time=0.01
if [[ -x build/bench/foresight_bench_c_api ]]; then
    ./build/bench/foresight_bench_c_api --benchmark_min_time=0.01
fi
# Built with both the Embree and Bullet backends; about 8 s (the million-triangle mesh's BVHs),
# and it fails if the worlds disagree on a cast.
if [[ -x build/bench/foresight_bench_worlds ]]; then
    step "collision worlds benchmark smoke test (build/bench/foresight_bench_worlds, not a measurement)"
    ./build/bench/foresight_bench_worlds --benchmark_min_time=0.01
fi

step "building build-asan/ (Debug, address + undefined sanitizers, -Werror)"
configure_and_build build-asan -DCMAKE_BUILD_TYPE=Debug -DFORESIGHT_WERROR=ON \
    -DFORESIGHT_SANITIZE=address,undefined -DFORESIGHT_DOUBLE_PRECISION=OFF \
    -DFORESIGHT_BUILD_TESTS=ON -DFORESIGHT_BUILD_TOOLS=ON -DFORESIGHT_BUILD_BENCHMARKS=OFF \
    -DFORESIGHT_BROWSER_TESTS=OFF

step "testing build-asan/ (sanitizers halt on the first error)"
ASAN_OPTIONS=halt_on_error=1:abort_on_error=0:detect_leaks=1:strict_string_checks=1 \
    UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    run_ctest build-asan

step "fuzzing (scripts/fuzz.sh: build-fuzz/, ${FORESIGHT_FUZZ_SECONDS:-5} s per harness)"
./scripts/fuzz.sh "${FORESIGHT_FUZZ_SECONDS:-5}"

current="finishing"
echo ""
echo "==> [$((SECONDS - start)) s] all checks passed"
