#!/usr/bin/env bash
# Configures and builds the release build in build/ (the CLI ends up at build/foresight).
#   scripts/build.sh [--target TARGET] [CMAKE-CONFIGURE-ARGS...]
# e.g. `scripts/build.sh --target foresight_cli` or `scripts/build.sh -DFORESIGHT_WERROR=ON`.
# Without --target everything is built (library, CLI, tests, benchmarks).
# Used by demo.sh, bench.sh and the Makefile; installs missing dependencies first.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

target=()
if [[ "${1:-}" == "--target" ]]; then
    target=(--target "${2:?build.sh: --target needs a target name}")
    shift 2
fi

./scripts/install-deps.sh

build_dir=build
jobs=${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}

configure=(cmake -S . -B "$build_dir" --log-level=WARNING -DCMAKE_BUILD_TYPE=Release "$@")
# A build tree keeps the generator it was made with: ask for Ninja only in a new one.
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
    configure+=(-G Ninja)
fi
if ! "${configure[@]}"; then
    echo "build.sh: configuring $build_dir/ failed (see above)" >&2
    exit 1
fi
if ! cmake --build "$build_dir" --parallel "$jobs" "${target[@]}"; then
    echo "build.sh: building $build_dir/ failed (see above)" >&2
    exit 1
fi
