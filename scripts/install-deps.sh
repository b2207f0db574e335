#!/usr/bin/env bash
# Installs the Debian packages foresight needs to build, test and benchmark, when missing, then
# the npm packages of the HTML viewer (viewer/node_modules) and of the engine harnesses
# (tests/engines/node_modules: Jolt, PhysX, Rapier and ammo.js builds, each from its lock file).
#
# Idempotent and silent when everything is present: it only asks dpkg which packages are
# missing, and runs `apt-get update && apt-get install` for those alone (as root, or through
# sudo); `npm ci` runs only when viewer/node_modules is missing or older than the lock file,
# with PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 (the browser tests drive Debian's chromium, never a
# downloaded one). Set FORESIGHT_SKIP_DEPS=1 to skip the check (e.g. on a non-Debian machine where the
# dependencies were installed another way).
set -euo pipefail

if [[ "${FORESIGHT_SKIP_DEPS:-0}" == "1" ]]; then
    exit 0
fi

# Build tools (clang-14 and its runtime libraries for the libFuzzer harnesses, scripts/fuzz.sh;
# clang-format-14 for the layout check of scripts/test.sh),
# then libraries, then the HTML viewer's: Node.js and npm to bundle it (only when
# `node`/`npm` are not already on PATH, e.g. from nodesource) and chromium for its browser tests;
# then the real engines the engine-matched predictions are tested against: headless Godot 3 and
# Box2D (Bullet is already among the libraries; the wasm engines come from npm); then the language
# bindings' toolchains (bindings/): Debian's Python with pip, venv, pybind11, NumPy and pytest;
# mono for C#; emscripten for WebAssembly.
# Keep in sync with CONTRIBUTING.md.
packages=(
    cmake ninja-build g++ pkg-config
    clang-14 libclang-rt-14-dev clang-format-14
    libglm-dev nlohmann-json3-dev libcli11-dev libfmt-dev libtinyobjloader-dev libtinygltf-dev
    libembree-dev libbullet-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    chromium
    godot3-server libbox2d-dev
    python3 python3-dev python3-pip python3-venv python3-pybind11 pybind11-dev python3-numpy python3-pytest
    mono-devel emscripten
)
if ! command -v node >/dev/null 2>&1; then packages+=(nodejs); fi
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi

# DIR/node_modules (npm ci), when missing or older than DIR/package-lock.json.
root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
install_npm_modules() {
    local dir=$1
    if [[ ! -f "$dir/package-lock.json" ]]; then
        return 0
    fi
    if [[ -f "$dir/node_modules/.package-lock.json" &&
        ! "$dir/package-lock.json" -nt "$dir/node_modules/.package-lock.json" ]]; then
        return 0
    fi
    echo "install-deps: installing npm packages (npm ci in ${dir#"$root_dir"/})"
    if ! (cd "$dir" &&
        PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error >/dev/null); then
        echo "install-deps: npm ci failed in $dir (is the npm registry reachable?)" >&2
        exit 1
    fi
}
install_viewer_modules() {
    install_npm_modules "$root_dir/viewer"
    install_npm_modules "$root_dir/tests/engines"
}

if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "install-deps: dpkg-query not found (not a Debian-based system?)." >&2
    echo "install-deps: install these yourself, then rerun with FORESIGHT_SKIP_DEPS=1:" >&2
    echo "  ${packages[*]}" >&2
    exit 1
fi

missing=()
for package in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null || true)
    if [[ "$status" != "installed" ]]; then
        missing+=("$package")
    fi
done

if ((${#missing[@]} == 0)); then
    install_viewer_modules
    exit 0
fi

echo "install-deps: installing missing packages: ${missing[*]}"
if [[ "$(id -u)" == "0" ]]; then
    sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
else
    echo "install-deps: not root and sudo is not available; as root, run:" >&2
    echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
fi

# sudo resets the environment: pass DEBIAN_FRONTEND through env (no prompts in CI).
apt_get=("${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get)
if ! "${apt_get[@]}" update -qq ||
    ! "${apt_get[@]}" install -y -qq --no-install-recommends "${missing[@]}"; then
    echo "install-deps: apt-get failed to install: ${missing[*]}" >&2
    exit 1
fi
install_viewer_modules
echo "install-deps: done"
