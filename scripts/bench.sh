#!/usr/bin/env bash
# Builds the release build (build/), runs the benchmarks with repetitions, and prints how the
# exact methods compare with the reference article's loops, from the medians of that one run:
#   exact projectile / stepped loop       target <= 1.1
#   exact vehicle / 4-iteration loop      target <= 1.0
#
# Usage: scripts/bench.sh [benchmark options...], e.g. --benchmark_filter=Vehicle
#        scripts/bench.sh --instructions   (instruction counts under callgrind instead of times)
#        scripts/bench.sh --planning [benchmark options...]   throw planning on the demo level
#            (bench/bench_planning.cpp, Embree backend): ms per plan, target < 5; success rate
#        scripts/bench.sh --replication [benchmark options...]   dead reckoning for 100 000
#            entities per frame (bench/bench_replication.cpp): predictDeadReckoningBatch, the
#            prepared forms (extrapolateDeadReckoning, DeadReckoningBatch: mix and per model)
#            against a plain p + v t loop, ms per frame (target < 1) and ratios; receivers;
#            DeadReckoningBatch with the data evicted before each frame (cold, target <= 1 ms)
#            against the memory bandwidth measured in the same run
#        scripts/bench.sh --aim [benchmark options...]   aimProjectile per call
#            (bench/bench_aim.cpp): ns per call, accelerating target under 1000
#        scripts/bench.sh --c-api [benchmark options...]   the C API (the bindings' way in)
#            against the C++ call it wraps (bench/bench_c_api.cpp): a projectile prediction,
#            target C / C++ <= 1.5, and predictLinear (the bare cost of the boundary)
#        scripts/bench.sh --output [benchmark options...]   `foresight predict`'s JSON output
#            (bench/bench_output.cpp): writing 1 000 projectile results with trajectories (the
#            streamed writer, and the former whole-document writer) against predicting them,
#            target streamed / predicting <= 2, also timed in turns (BM_Output/Turns, with its
#            spread); then the CLI's peak memory (max RSS) for 1 000 and 4 000 such predictions,
#            which must not grow with the output
#        scripts/bench.sh --worlds [benchmark options...]
#            the collision worlds (bench/bench_worlds.cpp, needs the Embree and Bullet
#            backends): segment casts per second on a mesh of a million triangles through
#            EmbreeWorld (castSegment, and castSegments for many at once), bare native Embree and
#            Bullet's rayTest; targets: castSegment within 1.2x the time of a bare native
#            rtcIntersect1, castSegments >= 5x Bullet's rayTest per ray; predictions per second
#            on the demo level per world; the BVH build times; then the same targets timed in
#            turns within one benchmark (BM_Turns), with their spread. Progress goes to stderr on a
#            terminal only; the build's output is shown only if it fails.
# The JSON results go to build/bench.json (--worlds: build/bench_worlds.json; FORESIGHT_BENCH_OUT
# overrides, relative to the repository root). With FORESIGHT_BENCH_STRICT=1 a missed target
# makes the script fail (timings are noisy: off by default). FORESIGHT_BENCH_BUILD_DIR=DIR
# (--worlds only) builds and runs an already configured tree DIR instead of build/.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

# medians JSON [FIELD]: lines "run_name value" of FIELD (cpu_time by default, in the benchmark's
# time unit) of the median aggregates in Google Benchmark's JSON output.
medians() {
    local json=$1 field=${2:-cpu_time}
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$json" "$field" <<'PY'
import json, sys
with open(sys.argv[1]) as f:
    for b in json.load(f)["benchmarks"]:
        if b.get("aggregate_name") == "median" and sys.argv[2] in b:
            print(b["run_name"], b[sys.argv[2]])
PY
    else
        # Google Benchmark writes one "key": value per line; good enough without a JSON parser.
        awk -v field="\"$field\":" '
            /"name":/ { name = $2; gsub(/[",]/, "", name) }
            $1 == field && name ~ /_median$/ {
                value = $2; gsub(/,/, "", value); sub(/_median$/, "", name); print name, value
            }' "$json"
    fi
}

# spreads JSON [FIELD]: lines "run_name median cv" of FIELD (cpu_time by default): the median and
# the coefficient of variation (a fraction) of the repetitions in Google Benchmark's JSON output.
spreads() {
    local json=$1 field=${2:-cpu_time}
    if command -v python3 >/dev/null 2>&1; then
        python3 - "$json" "$field" <<'PY'
import json, sys
median, cv = {}, {}
with open(sys.argv[1]) as f:
    for b in json.load(f)["benchmarks"]:
        if sys.argv[2] in b:
            if b.get("aggregate_name") == "median":
                median[b["run_name"]] = b[sys.argv[2]]
            elif b.get("aggregate_name") == "cv":
                cv[b["run_name"]] = b[sys.argv[2]]
for name, value in median.items():
    print(name, value, cv.get(name, 0))
PY
    else
        awk -v field="\"$field\":" '
            /"name":/ { name = $2; gsub(/[",]/, "", name) }
            $1 == field && name ~ /_(median|cv)$/ {
                value = $2; gsub(/,/, "", value)
                base = name; sub(/_(median|cv)$/, "", base)
                if (name ~ /_median$/) { median[base] = value; order[++n] = base } else cv[base] = value
            }
            END { for (i = 1; i <= n; ++i) print order[i], median[order[i]], (order[i] in cv ? cv[order[i]] : 0) }' "$json"
    fi
}

if [[ "${1:-}" == "--aim" ]]; then
    # Firing solutions (bench/bench_aim.cpp): ns per aimProjectile call, the median of this run's
    # repetitions and their spread (coefficient of variation).
    shift
    dir=${FORESIGHT_BENCH_BUILD_DIR:-build}
    out=${FORESIGHT_BENCH_OUT:-$dir/bench_aim.json}
    if [[ "$dir" == build ]]; then
        ./scripts/build.sh --target foresight_bench_aim >/dev/null
    else
        cmake --build "$dir" --parallel "${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}" \
            --target foresight_bench_aim >/dev/null
    fi
    "$dir/bench/foresight_bench_aim" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_out="$out" --benchmark_out_format=json "$@" >/dev/null
    echo "aimProjectile per call, 256 random problems per case, median of this run's repetitions ($out):"
    spreads "$out" items_per_second | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        {
            ns = 1e9 / $2; name = $1; sub(/^BM_Aim\//, "", name)
            printf "  %-20s %8.0f ns per call  (spread %4.1f%%)\n", name, ns, 100 * $3
            if (name == "AcceleratingTarget") { accelerating = ns; seen = 1 }
        }
        END {
            if (!seen) { print "  accelerating target: not measured (filtered out?)"; exit 0 }
            printf "  %-20s %s\n", "target: AcceleratingTarget < 1000 ns", (accelerating < 1000 ? "met" : "MISSED")
            if (accelerating >= 1000 && strict == 1) exit 1
        }'
    exit 0
fi

if [[ "${1:-}" == "--c-api" ]]; then
    # The C API against the C++ call (bench/bench_c_api.cpp): time ratios of this run's medians.
    shift
    dir=${FORESIGHT_BENCH_BUILD_DIR:-build}
    out=${FORESIGHT_BENCH_OUT:-$dir/bench_c_api.json}
    if [[ "$dir" == build ]]; then
        ./scripts/build.sh --target foresight_bench_c_api >/dev/null
    else
        cmake --build "$dir" --parallel "${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}" \
            --target foresight_bench_c_api >/dev/null
    fi
    "$dir/bench/foresight_bench_c_api" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_out="$out" --benchmark_out_format=json "$@" >/dev/null
    echo "the C API against the C++ call, CPU time, median of this run's repetitions ($out):"
    spreads "$out" | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        { time[$1] = $2; cv[$1] = $3 }
        END {
            split("Projectile Linear", kinds, " ")
            for (i = 1; i <= 2; ++i) {
                cpp = "BM_CallOverhead/" kinds[i] "/Cpp"; c = "BM_CallOverhead/" kinds[i] "/C"
                if (!(cpp in time) || !(c in time)) continue
                printf "  %-10s C / C++ = %5.2f  (spread %4.1f%% and %4.1f%%)\n", kinds[i], time[c] / time[cpp], 100 * cv[c], 100 * cv[cpp]
                if (kinds[i] == "Projectile") { ratio = time[c] / time[cpp]; seen = 1 }
            }
            if (!seen) { print "  projectile: not measured (filtered out?)"; exit 0 }
            printf "  target: Projectile C / C++ <= 1.5: %s\n", (ratio <= 1.5 ? "met" : "MISSED")
            if (ratio > 1.5 && strict == 1) exit 1
        }'
    exit 0
fi

if [[ "${1:-}" == "--worlds" ]]; then
    shift
    progress() { if [[ -t 2 ]]; then echo "bench.sh: $*" >&2; fi; }
    dir=${FORESIGHT_BENCH_BUILD_DIR:-build}
    out=${FORESIGHT_BENCH_OUT:-$dir/bench_worlds.json}
    log=$(mktemp "${TMPDIR:-/tmp}/foresight-bench-worlds.XXXXXX")
    trap 'rm -f "$log"' EXIT
    progress "building foresight_bench_worlds in $dir/"
    if [[ "$dir" == build ]]; then
        build=(./scripts/build.sh --target foresight_bench_worlds)
    else
        build=(cmake --build "$dir" --parallel "${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}"
            --target foresight_bench_worlds)
    fi
    if ! "${build[@]}" >"$log" 2>&1; then
        cat "$log" >&2
        echo "bench.sh: building foresight_bench_worlds in $dir/ failed (above); the target exists only" \
            "with both backends (FORESIGHT_WITH_EMBREE, FORESIGHT_WITH_BULLET)" >&2
        exit 1
    fi
    progress "running $dir/bench/foresight_bench_worlds, 5 repetitions (about two minutes)"
    # The program's own lines (mesh, BVH builds, agreement of the worlds) go to stderr: kept
    # for the summary. The repetitions of the benchmarks are interleaved in random order, so
    # that a change of load on a shared machine weighs on every ratio's two sides alike.
    if ! "$dir/bench/foresight_bench_worlds" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_enable_random_interleaving=true \
        --benchmark_out="$out" --benchmark_out_format=json "$@" 2>"$log"; then
        cat "$log" >&2
        echo "bench.sh: foresight_bench_worlds failed (above)" >&2
        exit 1
    fi

    echo ""
    echo "Collision worlds, medians of this run ($out); one thread:"
    echo "  Builds and checks:"
    sed -n 's/^foresight_bench_worlds: /    /p' "$log"
    medians "$out" items_per_second | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        { rate[$1] = $2 }
        function human(x) {
            if (x >= 1e6) return sprintf("%.3gM", x / 1e6)
            if (x >= 1e3) return sprintf("%.3gk", x / 1e3)
            return sprintf("%.3g", x)
        }
        function show(label, name) {
            if (name in rate) printf "    %-48s %10s/s\n", label, human(rate[name])
            else printf "    %-48s %10s\n", label, "not measured"
        }
        # rate[a] / rate[b] (at least target), or with `time` set the time of a over the time of
        # b (their rates inverted; at most target). Target 0: for information.
        function compare(label, a, b, target, time,    r, met) {
            if (!(a in rate) || !(b in rate) || rate[a] <= 0 || rate[b] <= 0) {
                printf "  %-50s not measured (filtered out?)\n", label
                return
            }
            r = time ? rate[b] / rate[a] : rate[a] / rate[b]
            if (target <= 0) {
                printf "  %-50s %6.2fx\n", label, r
                return
            }
            met = time ? r <= target : r >= target
            printf "  %-50s %6.2fx  (target %s %gx: %s)\n", label, r, (time ? "<=" : ">="), target, (met ? "met" : "MISSED")
            if (!met) missed = 1
        }
        function ratio(label, a, b, target) { compare(label, a, b, target, 0) }
        function timeRatio(label, a, b, target) { compare(label, a, b, target, 1) }
        END {
            print "  Segment casts on the million-triangle mesh (radius 0):"
            show("EmbreeWorld::castSegment", "BM_Cast/Embree")
            show("EmbreeWorld::castSegments (4096 at once)", "BM_Cast/EmbreeBatch")
            show("Bullet btCollisionWorld::rayTest", "BM_Cast/BulletRayTest")
            show("BulletWorld::castSegment (the adapter)", "BM_Cast/BulletWorld")
            show("native Embree triangles, rtcIntersect1 (info)", "BM_Cast/EmbreeNative")
            show("  the same, Embree default scene flags (info)", "BM_Cast/EmbreeNativeDefault")
            show("Embree user geometry, float test (info)", "BM_Cast/EmbreeUserFloat")
            ratio("EmbreeWorld castSegments / Bullet rayTest", "BM_Cast/EmbreeBatch", "BM_Cast/BulletRayTest", 5)
            ratio("EmbreeWorld castSegment / Bullet rayTest", "BM_Cast/Embree", "BM_Cast/BulletRayTest", 5)
            timeRatio("castSegment time / native rtcIntersect1 time", "BM_Cast/Embree", "BM_Cast/EmbreeNative", 1.2)
            timeRatio("castSegments time / native time (info)", "BM_Cast/EmbreeBatch", "BM_Cast/EmbreeNative", 0)
            ratio("native Embree triangles / Bullet rayTest (info)", "BM_Cast/EmbreeNative", "BM_Cast/BulletRayTest", 0)
            print "  Sphere sweeps, radius 0.1 m (information):"
            show("EmbreeWorld::castSegment", "BM_Sweep/Embree")
            show("Bullet convexSweepTest", "BM_Sweep/BulletConvexSweep")
            show("BulletWorld::castSegment", "BM_Sweep/BulletWorld")
            print "  Projectile predictions on the demo level (3 s at 50 Hz, 64 throws):"
            split("Embree Bullet Static Callback", worlds, " ")
            split("EmbreeWorld BulletWorld StaticWorld(brute-force) CallbackWorld(castSegment-only)", labels, " ")
            for (i = 1; i <= 4; ++i)
                for (m = 0; m < 2; ++m) {
                    method = m == 0 ? "Exact" : "Stepped"
                    show(labels[i] " " method, "BM_DemoLevel/" worlds[i] "/" method)
                }
            ratio("Exact: EmbreeWorld / BulletWorld", "BM_DemoLevel/Embree/Exact", "BM_DemoLevel/Bullet/Exact", 0)
            ratio("Stepped: EmbreeWorld / BulletWorld", "BM_DemoLevel/Embree/Stepped", "BM_DemoLevel/Bullet/Stepped", 0)
            timeRatio("Exact / Stepped time, EmbreeWorld", "BM_DemoLevel/Embree/Exact", "BM_DemoLevel/Embree/Stepped", 0.5)
            timeRatio("Exact / Stepped time, StaticWorld", "BM_DemoLevel/Static/Exact", "BM_DemoLevel/Static/Stepped", 0.5)
            timeRatio("Exact / Stepped time, callback world", "BM_DemoLevel/Callback/Exact", "BM_DemoLevel/Callback/Stepped", 1.0)
            timeRatio("Exact / Stepped time, BulletWorld (info)", "BM_DemoLevel/Bullet/Exact", "BM_DemoLevel/Bullet/Stepped", 0)
            if (missed && strict == 1) exit 1
        }' || missedAny=1
    # The same targets timed in turns within one benchmark (BM_Turns: the parts share the load
    # and the caches; each part starts after another that read other data): median and spread.
    echo "  Timed in turns (median of the repetitions, coefficient of variation):"
    for counter in castSegment/native rayTest/castSegment rayTest/castSegments exact/stepped bulletStep/predict; do
        spreads "$out" "$counter" | sed "s|^|$counter |"
    done | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        # $1 counter, $2 benchmark, $3 median, $4 coefficient of variation; the targets of
        # bench_worlds.cpp: at most ("<=") or at least (">=") so many times.
        {
            if ($1 == "castSegment/native") { rel = "<="; t = 1.2 }
            else if ($1 ~ /^rayTest/) { rel = ">="; t = 5 }
            else if ($1 == "bulletStep/predict") { rel = ">="; t = 20 }
            else if ($2 ~ /Callback/) { rel = "<="; t = 1 }
            else { rel = "<="; t = 0.5 }
            met = rel == "<=" ? $3 <= t : $3 >= t
            printf "    %-28s %-22s %6.2fx  (spread %4.1f %%; target %s %gx: %s)\n", $2, $1, $3, 100 * $4, rel, t,
                   (met ? "met" : "MISSED")
            if (!met) missed = 1
        }
        END { if (missed && strict == 1) exit 1 }' || missedAny=1
    [[ -n "${missedAny:-}" ]] && exit 1
    exit 0
fi

if [[ "${1:-}" == "--output" ]]; then
    shift
    dir=${FORESIGHT_BENCH_BUILD_DIR:-build}
    out=${FORESIGHT_BENCH_OUT:-$dir/bench_output.json}
    if [[ "$dir" == build ]]; then
        ./scripts/build.sh --target foresight_bench_output >/dev/null
        ./scripts/build.sh --target foresight_cli >/dev/null
    else
        cmake --build "$dir" --parallel "${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}" \
            --target foresight_bench_output foresight_cli >/dev/null
    fi
    "$dir/bench/foresight_bench_output" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_out="$out" --benchmark_out_format=json "$@" >/dev/null
    echo "foresight predict's output, 1 000 projectiles with trajectories, medians of this run ($out):"
    medians "$out" | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        { time[$1] = $2 }
        END {
            p = "BM_Output/Predict"; s = "BM_Output/Stream"; d = "BM_Output/Document"
            if (!(p in time) || !(s in time)) { print "  not measured (filtered out?)"; exit 0 }
            printf "  %-44s %8.1f ms\n", "predicting (runScenario, trajectories kept)", time[p]
            printf "  %-44s %8.1f ms  %5.2fx predicting (target <= 2x: %s)\n", "writing, streamed (foresight predict)",
                   time[s], time[s] / time[p], (time[s] / time[p] <= 2 ? "met" : "MISSED")
            if (d in time)
                printf "  %-44s %8.1f ms  %5.2fx predicting\n", "writing, whole document (the former writer)",
                       time[d], time[d] / time[p]
        }'
    # The target timed in turns (BM_Output/Turns: predicting and writing share the load): the
    # median and spread of the ratio; the strict mode goes by this one.
    spreads "$out" stream/predict | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        $1 == "BM_Output/Turns" {
            found = 1
            printf "  %-44s          %5.2fx predicting (spread %.1f %%; target <= 2x: %s)\n",
                   "writing / predicting, timed in turns", $2, 100 * $3, ($2 <= 2 ? "met" : "MISSED")
            if ($2 > 2 && strict == 1) exit 1
        }
        END { if (!found) print "  in turns: not measured (filtered out?)" }'
    # Peak memory of the CLI itself: the same throws, 1 000 and 4 000 of them.
    peak() { # FILE -> "max RSS in KiB" of `foresight predict FILE`, output to /dev/null
        if [[ -x /usr/bin/time ]]; then
            /usr/bin/time -f %M "$dir/foresight" predict "$1" 2>&1 >/dev/null | tail -n 1
        elif command -v python3 >/dev/null 2>&1; then
            python3 - "$dir/foresight" "$1" <<'PY'
import resource, subprocess, sys
subprocess.run([sys.argv[1], "predict", sys.argv[2]], stdout=subprocess.DEVNULL, check=True)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
PY
        else
            echo "?"
        fi
    }
    scenario=$(mktemp "${TMPDIR:-/tmp}/foresight-bench-output.XXXXXX")
    trap 'rm -f "$scenario"' EXIT
    echo "  Peak memory of \`foresight predict\` (max RSS; output to /dev/null):"
    for count in 1000 4000; do
        "$dir/bench/foresight_bench_output" --scenario "$count" >"$scenario"
        bytes=$("$dir/foresight" predict "$scenario" | wc -c)
        kib=$(peak "$scenario")
        awk -v n="$count" -v b="$bytes" -v k="$kib" 'BEGIN {
            printf "    %5d predictions: %6.1f MB of JSON, peak %6.1f MiB\n", n, b / 1e6, k / 1024 }'
    done
    exit 0
fi

if [[ "${1:-}" == "--planning" ]]; then
    # Throw planning on the demo level (bench/bench_planning.cpp, needs the Embree backend):
    # plans per second, ms per plan (target < 5 for BM_Plan/Courtyard) and the success rate.
    shift
    dir=${FORESIGHT_BENCH_BUILD_DIR:-build}
    out=${FORESIGHT_BENCH_OUT:-$dir/bench_planning.json}
    if [[ "$dir" == build ]]; then
        ./scripts/build.sh --target foresight_bench_planning >/dev/null
    else
        cmake --build "$dir" --parallel "${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}" \
            --target foresight_bench_planning >/dev/null
    fi
    "$dir/bench/foresight_bench_planning" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_out="$out" --benchmark_out_format=json "$@" >/dev/null
    echo "Throw planning on the demo level, medians of this run ($out):"
    medians "$out" items_per_second | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        { ms = 1000 / $2; printf "  %-22s %8.3f ms per plan\n", $1, ms
          if ($1 ~ /Courtyard/ && ms >= 5) missed = 1 }
        END { if (missed) { print "  target missed: BM_Plan/Courtyard >= 5 ms per plan"; if (strict == 1) exit 1 } }'
    medians "$out" success | awk '{ printf "  %-22s %8.1f%% of the pairs get a plan\n", $1, 100 * $2 }'
    exit 0
fi

if [[ "${1:-}" == "--replication" ]]; then
    # Replication (bench/bench_replication.cpp): one frame of 100 000 entities through
    # predictDeadReckoningBatch, the prepared forms and a plain p + v t loop, this run's medians.
    shift
    dir=${FORESIGHT_BENCH_BUILD_DIR:-build}
    out=${FORESIGHT_BENCH_OUT:-$dir/bench_replication.json}
    if [[ "$dir" == build ]]; then
        ./scripts/build.sh --target foresight_bench_replication >/dev/null
    else
        cmake --build "$dir" --parallel "${FORESIGHT_JOBS:-$(nproc 2>/dev/null || echo 2)}" \
            --target foresight_bench_replication >/dev/null
    fi
    "$dir/bench/foresight_bench_replication" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
        --benchmark_out="$out" --benchmark_out_format=json "$@" >/dev/null
    echo "Replication, 100 000 entities per frame, medians of this run ($out); one thread:"
    { medians "$out" bytes/entity | sed 's/^/bytes /'; medians "$out" label | sed 's/^/label /'
        spreads "$out" items_per_second
        spreads "$out" bytes_per_second | sed 's/^/bandwidth /'; } | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
        $1 == "bytes" { bytes[$2] = $3; next }
        $1 == "label" { gsub(/"/, "", $3); label[$2] = $3; next }
        $1 == "bandwidth" { bandwidth[$2] = $3; bandwidthSpread[$2] = $4; next }
        { rate[$1] = $2; spread[$1] = $3 }
        function ms(name) { return 1e8 / rate[name] }  # ms per frame of 100 000
        function row(label, name) {
            if (name in rate)
                printf "  %-46s %8.3f ms per frame  %6.2fx the plain loop\n", label, ms(name), ms(name) / p
        }
        END {
            plain = "BM_Replication/PlainLoop"; soa = "BM_Replication/SoA"; receivers = "BM_Replication/Receivers"
            if (!(plain in rate)) { print "  not measured (filtered out?)"; exit 0 }
            p = ms(plain)
            printf "  %-46s %8.3f ms per frame\n", "plain loop p + v t (the reference)", p
            row("predictDeadReckoningBatch (mix, bit-identical)", "BM_Replication/Batch")
            row("extrapolateDeadReckoning (mix, prepared AoS)", "BM_Replication/Prepared/1")
            row("DeadReckoningBatch::extrapolate (mix, SoA)", soa "/1")
            row("  all FPW", soa "/FPW/2")
            row("  all RVW", soa "/RVW/4")
            row("  all RPB", soa "/RPB/7")
            row("  all RVB", soa "/RVB/8")
            if ((soa "/1") in rate)
                printf "  %-46s %s\n", "target: DeadReckoningBatch (mix) < 1 ms", (ms(soa "/1") < 1 ? "met" : "MISSED")
            cold = "BM_Replication/SoA/Cold/iterations:200"
            read = "BM_Replication/MemoryRead/iterations:20"; write = "BM_Replication/MemoryWrite/iterations:20"
            if (cold in rate) {
                printf "  %-46s %8.3f ms per frame  (spread %4.1f%%)  %s\n", "DeadReckoningBatch (mix), hot cache",
                       ms(soa "/1"), 100 * spread[soa "/1"], label[soa "/1"]
                printf "  %-46s %8.3f ms per frame  (spread %4.1f%%)  %.2fx hot  %s\n",
                       "DeadReckoningBatch (mix), cold (data evicted)", ms(cold), 100 * spread[cold], ms(cold) / ms(soa "/1"),
                       label[cold]
                if (read in bandwidth && write in bandwidth) {
                    printf "  %-46s %8.2f GB/s read, %.2f GB/s write (spread %.1f%%, %.1f%%)\n",
                           "memory bandwidth, one thread", bandwidth[read] / 1e9, bandwidth[write] / 1e9,
                           100 * bandwidthSpread[read], 100 * bandwidthSpread[write]
                    printf "  %-46s %8.0f bytes per entity: %.3f ms per frame at the read bandwidth\n",
                           "lower bound for the cold frame", bytes[cold], bytes[cold] * 1e5 / bandwidth[read] * 1e3
                }
                printf "  %-46s %s\n", "target: cold <= 1 ms", (ms(cold) <= 1 ? "met" : "MISSED")
                baseHot = soa "/Baseline/1"; baseCold = "BM_Replication/SoA/Cold/Baseline/iterations:200"
                if (label[soa "/1"] != "baseline" && baseHot in rate && baseCold in rate)
                    printf "  %-46s %8.3f ms hot, %.3f ms cold (without AVX2)\n",
                           "the same with the baseline instruction set", ms(baseHot), ms(baseCold)
            }
            if (receivers in rate)
                printf "  %-46s %8.1f ns per receiver (%.2f ms for 100 000)\n", "DeadReckoningReceiver::sample (PVB)",
                       1e9 / rate[receivers], 1e8 / rate[receivers]
            if ((soa "/1") in rate && ms(soa "/1") >= 1 && strict == 1) exit 1
            if (cold in rate && ms(cold) > 1 && strict == 1) exit 1
        }'
    exit 0
fi

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

echo ""
echo "Ratios of median CPU times (this run, $out):"
medians "$out" | awk -v strict="${FORESIGHT_BENCH_STRICT:-0}" '
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
