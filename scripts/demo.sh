#!/usr/bin/env bash
# The README's first command: builds foresight (release, in build/) and runs the CLI's demo.
# Arguments are passed to `foresight demo`, e.g. `./scripts/demo.sh --help`. The demo runs in
# the caller's directory, so relative paths in the arguments mean what the caller expects.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

"$root/scripts/build.sh" --target foresight_cli
exec "$root/build/foresight" demo "$@"
