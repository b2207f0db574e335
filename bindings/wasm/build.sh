#!/bin/sh
# Builds the WebAssembly package alone: dist/foresight_core.mjs next to index.mjs, as npm
# publishes it (`npm run build`). Needs emscripten (emcc), node, CMake and GLM's headers; the
# build tree is bindings/wasm/obj/ (or $1). The full CMake build does the same in its build tree
# (bindings/wasm/CMakeLists.txt) and runs the tests there.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
build=${1:-$here/obj}
cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFORESIGHT_BUILD_TESTS=OFF \
    -DFORESIGHT_BUILD_TOOLS=OFF -DFORESIGHT_BUILD_BENCHMARKS=OFF -DFORESIGHT_BUILD_C_API=OFF \
    -DFORESIGHT_BUILD_VIEWER=OFF -DFORESIGHT_WITH_EMBREE=OFF -DFORESIGHT_WITH_BULLET=OFF \
    -DFORESIGHT_INSTALL=OFF -DFORESIGHT_BUILD_WASM=ON
cmake --build "$build" --target foresight_wasm
test -f "$build/bindings/wasm/package/dist/foresight_core.mjs" || {
    echo "build.sh: no module was built (is emcc on the PATH? see the CMake output above)" >&2
    exit 1
}
mkdir -p "$here/dist"
cp "$build/bindings/wasm/package/dist/foresight_core.mjs" "$here/dist/"
echo "built $here/dist/foresight_core.mjs"
