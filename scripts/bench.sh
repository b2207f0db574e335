#!/usr/bin/env bash
# Builds the release build (build/), runs the benchmarks with repetitions, and prints how the
# exact methods compare with the reference article's loops, from the medians of that one run:
#   exact projectile / stepped loop       target <= 1.1
#   exact vehicle / 4-iteration loop      target <= 1.0
#
# Usage: scripts/bench.sh [benchmark options...], e.g. --benchmark_filter=Vehicle
#        scripts/bench.sh --instructions   (instruction counts under callgrind instead of times)
# The JSON results go to build/bench.json (FORESIGHT_BENCH_OUT overrides, relative to the
# repository root). With FORESIGHT_BENCH_STRICT=1 a missed target makes the script fail
# (timings are noisy: off by default).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

if [[ "${1:-}" == "--instructions" ]]; then
    # Instruction counts under callgrind: the same every run, whatever else the machine does.
    if ! command -v valgrind >/dev/null 2>&1; then
        echo "bench.sh: --instructions needs valgrind (apt-get install valgrind)" >&2
        exit 1
    fi
    ./scripts/build.sh --target foresight_count_instructions
    count() { # CASE [FRICTION] -> instructions
        valgrind --tool=callgrind --callgrind-out-file=/dev/null \
            build/bench/foresight_count_instructions "$@" 2>&1 >/dev/null |
            sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'
    }
    echo "Instruction counts (callgrind), same inputs as the timing benchmark:"
    for friction in 0 0.4; do
        stepped=$(count projectile-stepped "$friction")
        exact=$(count projectile-exact "$friction")
        awk -v s="$stepped" -v e="$exact" -v f="$friction" 'BEGIN {
            printf "  projectile, friction %-3s  stepped %d  exact %d  ratio %.3fx (target <= 1.1x)\n", f, s, e, e / s }'
    done
    iterative=$(count vehicle-iterative4)
    exact=$(count vehicle-exact)
    awk -v s="$iterative" -v e="$exact" 'BEGIN {
        printf "  vehicle                   4 iterations %d  exact %d  ratio %.3fx (target <= 1.0x)\n", s, e, e / s }'
    exit 0
fi

./scripts/build.sh --target foresight_bench

out=${FORESIGHT_BENCH_OUT:-build/bench.json}
./build/bench/foresight_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_out="$out" --benchmark_out_format=json "$@"

# Lines "run_name median_cpu_time" from the JSON (all times in the same unit: ns by default).
medians() {
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$out" <<'PY'
import json, sys
with open(sys.argv[1]) as f:
    for b in json.load(f)["benchmarks"]:
        if b.get("aggregate_name") == "median" and "cpu_time" in b:
            print(b["run_name"], b["cpu_time"])
PY
    else
        # Google Benchmark writes one "key": value per line; good enough without a JSON parser.
        awk '
            /"name":/ { name = $2; gsub(/[",]/, "", name) }
            /"cpu_time":/ && name ~ /_median$/ {
                value = $2; gsub(/,/, "", value); sub(/_median$/, "", name); print name, value
            }' "$out"
    fi
}

echo ""
echo "Ratios of median CPU times (this run, $out):"
medians | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
    { time[$1] = $2 }
    function report(label, exact, reference, target,    ratio) {
        if (!(exact in time) || !(reference in time) || time[reference] <= 0) {
            printf "  %-40s not measured (filtered out?)\n", label
            return
        }
        ratio = time[exact] / time[reference]
        printf "  %-40s %5.2fx  (target <= %.1fx: %s)\n", label, ratio, target,
               ratio <= target ? "met" : "MISSED"
        if (ratio > target) missed = 1
    }
    END {
        report("exact projectile / stepped loop", "BM_Projectile/Exact", "BM_Projectile/Stepped", 1.1)
        report("  the same with friction 0.4", "BM_Projectile/ExactFriction", "BM_Projectile/SteppedFriction", 1.1)
        report("exact vehicle / 4-iteration loop", "BM_Vehicle/Exact", "BM_Vehicle/Iterative4", 1.0)
        if (missed && strict == 1) exit 1
    }'
