#!/usr/bin/env bash
# run_godot.sh CASES.json OUT.json
#
# Runs the "godot3" (GodotPhysics) and "godot3-bullet" (Godot 3's Bullet backend) cases of a case
# file in Godot 3 (Debian's godot3-server, headless) and writes the result file; both formats are
# in ../README.md. Cases for other engines are listed in the result's "skipped".
#
# Godot reads the physics tick rate and the physics server once at start-up, from the project:
# this script makes a throw-away project in a temporary folder (never in the repository) for each
# (physics_fps = round(1 / timestep), engine) group, from project.godot.in, and runs harness.gd
# in it as a script MainLoop with --fixed-fps (one physics tick per frame, no real-time wait).
# Godot itself also plans the groups and merges the results (no other interpreter needed).
#
# Environment: GODOT (default godot3-server), FORESIGHT_GODOT_TIMEOUT (seconds per Godot run,
# default 120). Exit status 0 on success; 1 with a message on stderr otherwise.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
godot=${GODOT:-godot3-server}
limit=${FORESIGHT_GODOT_TIMEOUT:-120}

die() {
    echo "run_godot.sh: $*" >&2
    exit 1
}

if (($# != 2)); then
    echo "usage: run_godot.sh CASES.json OUT.json" >&2
    exit 2
fi
[[ -f "$1" ]] || die "case file not found: $1"
cases=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out_dir=$(cd "$(dirname "$2")" 2>/dev/null && pwd) || die "output folder not found: $(dirname "$2")"
out=$out_dir/$(basename "$2")
command -v "$godot" >/dev/null 2>&1 || die "'$godot' not found (apt-get install godot3-server)"
command -v timeout >/dev/null 2>&1 || die "'timeout' not found (coreutils)"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/foresight-godot.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# Godot's user and config folders (user://, editor settings) go to the temporary folder too.
export HOME=$tmp/home XDG_DATA_HOME=$tmp/home/data XDG_CONFIG_HOME=$tmp/home/config \
    XDG_CACHE_HOME=$tmp/home/cache
mkdir -p "$HOME"

# make_project DIR FPS ENGINE: a project folder holding project.godot and harness.gd.
make_project() {
    mkdir -p "$1"
    sed -e "s/@FPS@/$2/" -e "s/@ENGINE@/$3/" "$here/project.godot.in" >"$1/project.godot"
    cp "$here/harness.gd" "$1/harness.gd"
}

# godot_run DIR LOG FIXED_FPS [VAR=VALUE...]: runs harness.gd in project DIR; fails with the log
# when Godot fails, times out, or the harness reports an error.
godot_run() {
    local dir=$1 log=$2 fps=$3
    shift 3
    local status=0
    # LANG: Godot 3 complains about the 'C' locale (harmless, but noise in a failure log).
    env -u LC_ALL LANG=en_US.UTF-8 "$@" timeout --kill-after=5 "$limit" \
        "$godot" --path "$dir" --fixed-fps "$fps" -s res://harness.gd >"$log" 2>&1 || status=$?
    if ((status == 124 || status == 137)); then
        cat "$log" >&2
        die "Godot did not finish within $limit s ($dir)"
    fi
    # Godot prints a GDScript error and may still exit 0: look for it as well.
    if ((status != 0)) || grep -qE '^(FORESIGHT_ERROR|SCRIPT ERROR)' "$log"; then
        cat "$log" >&2
        die "Godot failed (exit status $status) in $dir"
    fi
}

# 1. The groups.
make_project "$tmp/plan" 60 GodotPhysics
godot_run "$tmp/plan" "$tmp/plan.log" 60 FORESIGHT_MODE=plan FORESIGHT_CASES="$cases"
grep -q '^Godot Engine v3\.' "$tmp/plan.log" || {
    cat "$tmp/plan.log" >&2
    die "'$godot' is not Godot 3"
}
mapfile -t groups < <(sed -n 's/^FORESIGHT_GROUP //p' "$tmp/plan.log")

# 2. One Godot run per group.
parts=()
n=0
for group in "${groups[@]}"; do
    read -r fps engine <<<"$group"
    case $engine in
        godot3) server=GodotPhysics ;;
        godot3-bullet) server=Bullet ;;
        *) die "unexpected engine '$engine' in the plan" ;;
    esac
    n=$((n + 1))
    dir=$tmp/run$n
    make_project "$dir" "$fps" "$server"
    godot_run "$dir" "$tmp/run$n.log" "$fps" FORESIGHT_MODE=run FORESIGHT_CASES="$cases" \
        FORESIGHT_OUT="$tmp/part$n.txt" FORESIGHT_FPS="$fps" FORESIGHT_ENGINE="$engine"
    [[ -s "$tmp/part$n.txt" ]] || {
        cat "$tmp/run$n.log" >&2
        die "Godot wrote no results for $engine at $fps Hz"
    }
    parts+=("$tmp/part$n.txt")
done

# 3. The result file, in case-file order.
rm -f "$out"
parts_list=$(
    IFS=:
    echo "${parts[*]-}"
)
godot_run "$tmp/plan" "$tmp/merge.log" 60 FORESIGHT_MODE=merge FORESIGHT_CASES="$cases" \
    FORESIGHT_PARTS="$parts_list" FORESIGHT_OUT="$out"
[[ -s "$out" ]] || {
    cat "$tmp/merge.log" >&2
    die "Godot wrote no result file"
}
