#!/usr/bin/env bash
# Builds the libFuzzer harnesses of fuzz/ (build-fuzz/, clang-14, address + undefined
# sanitizers) and runs each for a bounded time. fuzz/README.md describes them.
#
#   scripts/fuzz.sh [SECONDS-PER-HARNESS] [HARNESS...]
#
#   SECONDS-PER-HARNESS  default 60 (scripts/test.sh uses 10; a long run: scripts/fuzz.sh 3600)
#   HARNESS              scenario aim plan danger netsim_csv netsim_options obj gltf glb predict
#                        (default: all of them)
#
# Each harness first replays its reproducers of past findings (fuzz/regressions/<harness>/),
# then fuzzes from its seeds (fuzz/corpus/<harness>/, read only) plus what earlier runs found
# (build-fuzz/fuzz-corpus/<harness>/, where new inputs go), with its dictionary when there is
# one (fuzz/dict/). Limits: -rss_limit_mb=2048, -timeout=10 (seconds per input).
# A crash, leak, sanitizer report, timeout or out-of-memory input is kept in
# build-fuzz/fuzz-findings/<harness>/ and the script exits 1 after running the others; the
# log of each run is build-fuzz/fuzz-logs/<harness>.log. Progress goes to standard error.
#
# Environment: FORESIGHT_JOBS (build parallelism, default: every core), CC/CXX (default
# clang-14/clang++-14), FORESIGHT_FUZZ_BUILD_DIR (default build-fuzz).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

all_harnesses=(scenario aim plan danger netsim_csv netsim_options obj gltf glb predict)
seconds=${1:-60}
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || ((seconds < 1)); then
    echo "fuzz.sh: SECONDS-PER-HARNESS must be a positive integer, got '$seconds'" >&2
    exit 2
fi
shift || true
harnesses=("$@")
if ((${#harnesses[@]} == 0)); then harnesses=("${all_harnesses[@]}"); fi
for h in "${harnesses[@]}"; do
    if [[ ! -d "fuzz/corpus/$h" ]]; then
        echo "fuzz.sh: unknown harness '$h' (expected one of: ${all_harnesses[*]})" >&2
        exit 2
    fi
done

build=${FORESIGHT_FUZZ_BUILD_DIR:-build-fuzz}
jobs=${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}
start=$SECONDS
log() { echo "fuzz.sh: [$((SECONDS - start)) s] $*" >&2; }

# A build tree of its own: every target is instrumented. -O1 with line tables: the usual
# libFuzzer trade-off between speed, build time and readable stacks.
if [[ ! -f "$build/CMakeCache.txt" ]]; then
    log "configuring $build/"
    CC=${CC:-clang-14} CXX=${CXX:-clang++-14} cmake -S . -B "$build" -G Ninja --log-level=WARNING \
        -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" \
        -DFORESIGHT_BUILD_FUZZERS=ON -DFORESIGHT_BUILD_TESTS=OFF -DFORESIGHT_BUILD_BENCHMARKS=OFF \
        -DFORESIGHT_BUILD_VIEWER=OFF -DFORESIGHT_WITH_BULLET=OFF >&2
fi
log "building the harnesses in $build/ (-j$jobs)"
cmake --build "$build" --target foresight_fuzzers --parallel "$jobs" >&2

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

failed=()
for h in "${harnesses[@]}"; do
    binary="$build/fuzz/fuzz_$h"
    if [[ ! -x "$binary" ]]; then
        # fuzz_gltf and fuzz_glb need the Embree backend.
        log "$h: not built (see the CMake warnings), skipped"
        continue
    fi
    corpus="$build/fuzz-corpus/$h"
    findings="$build/fuzz-findings/$h"
    logfile="$build/fuzz-logs/$h.log"
    mkdir -p "$corpus" "$findings" "$(dirname "$logfile")"
    options=(-rss_limit_mb=2048 -timeout=10 -artifact_prefix="$findings/" -close_fd_mask=1)
    dict="fuzz/dict/$h.dict"
    case $h in scenario | aim | plan | danger) dict=fuzz/dict/json.dict ;; esac
    if [[ -f "$dict" ]]; then options+=(-dict="$dict"); fi

    if compgen -G "fuzz/regressions/$h/*" >/dev/null; then
        log "$h: replaying fuzz/regressions/$h/"
        if ! "$binary" "${options[@]}" fuzz/regressions/"$h"/* >"$logfile.regressions" 2>&1; then
            log "$h: a reproducer of fuzz/regressions/$h/ fails again (log: $logfile.regressions)"
            tail -n 30 "$logfile.regressions" >&2
            failed+=("$h (regression)")
            continue
        fi
    fi

    log "$h: fuzzing for $seconds s"
    status=0
    "$binary" "${options[@]}" -max_total_time="$seconds" -print_final_stats=1 \
        "$corpus" "fuzz/corpus/$h" >"$logfile" 2>&1 || status=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$logfile" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$logfile" | tail -n 1)
    cov=$(grep -oE 'cov: [0-9]+' "$logfile" | tail -n 1 || true)
    if ((status != 0)); then
        log "$h: FINDING (exit status $status), kept in $findings/; log: $logfile"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|foresight fuzz:|artifact_prefix|Test unit written)' "$logfile" | head -n 10 >&2 || true
        failed+=("$h")
    else
        log "$h: ok, ${runs:-?} inputs, ${rate:-?} exec/s, ${cov:-cov ?}"
    fi
done

if ((${#failed[@]} > 0)); then
    log "findings in: ${failed[*]}"
    exit 1
fi
log "every harness ran without a finding"
