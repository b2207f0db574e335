/// bench_replication.cpp: what replicating many entities costs per frame. A
/// benchmark, not a test.
///
/// 100 000 entities with mixed DIS models as games use them: 45% FPW, 40% RVW, 8% RPB, 7% RVB
/// (every rotating one with a non-zero angular velocity), positions within 1 km, updates
/// between 0 and 0.25 s old. One iteration is one frame.
///
///   BM_Replication/Batch      predictDeadReckoningBatch over the 100 000 (one call)
///   BM_Replication/Prepared   extrapolateDeadReckoning over the same 100 000, prepared once
///                             with prepareDeadReckoning (not timed: once per update, not
///                             per frame), extrapolation limit 0.25 s
///   BM_Replication/Prepared/FPW, /RVW, /RPB, /RVB  the same with every entity on one model
///   BM_Replication/SoA        DeadReckoningBatch::extrapolate over the same 100 000 (the
///                             updates set once, not timed), limit 0.25 s: the fast path,
///                             with the widest instruction set this machine runs (the label:
///                             AVX2 or baseline; every one gives the same bytes)
///   BM_Replication/SoA/Baseline, /SoA/Cold/Baseline  the mix, hot and cold, with the baseline
///                             instruction set (what a processor without AVX2 runs)
///   BM_Replication/SoA/FPW, /RVW, /RPB, /RVB      the same with every entity on one model
///   BM_Replication/SoA/Cold   BM_Replication/SoA (mix) with the data evicted before every frame
///                             (a read of a buffer twice the last-level cache, not timed), as a
///                             server sees it: the entities come from memory. Counters: the
///                             bytes the frame moves per entity (read and written, from the
///                             batch's layout) and the lower bound they set at the measured
///                             bandwidth
///   BM_Replication/MemoryRead, /MemoryWrite  streaming bandwidth of one thread over a buffer
///                             twice the last-level cache (bytes_per_second: the lines moved
///                             between memory and the core; a written line is read and written
///                             back, so it counts twice)
///   BM_Replication/PlainLoop  the loop a game writes without dead reckoning models: p + v t
///                             over the same arrays (velocity and orientation copied)
///   BM_Replication/Receivers  DeadReckoningReceiver::sample for 10 000 receivers (PVB, each
///                             in the middle of a correction); a receiver holds its
///                             interpolation ring (sizeof in the counter), so 100 000 would
///                             need ~300 MB: the time scales linearly.
/// The time column is per frame; items_per_second counts entities (receivers).
/// Target: under 1 ms per frame. scripts/bench.sh --replication prints the times and the
/// ratios to PlainLoop from one run's medians.

#include "bench_scenes.h"
#include "replication_batch.h"

#include <foresight/foresight.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

using namespace foresight;
using foresight_bench::Random;

constexpr std::size_t kEntityCount = 100000;
constexpr std::size_t kReceiverCount = 10000;
constexpr double kNow = 3600.0;  // [s], an hour into the session

struct Entities {
    std::vector<DeadReckoningState> states;
    std::vector<double> timestamps;
    std::vector<PreparedDeadReckoning> prepared;
};

DeadReckoningAlgorithm mixedAlgorithm(float u) {
    if (u < 0.45f) return DeadReckoningAlgorithm::Fpw;
    if (u < 0.85f) return DeadReckoningAlgorithm::Rvw;
    if (u < 0.93f) return DeadReckoningAlgorithm::Rpb;
    return DeadReckoningAlgorithm::Rvb;
}

// The 100 000 entities; `only` puts every one on that model (Static: the mix), with the same
// random positions, velocities and ages.
Entities makeEntities(DeadReckoningAlgorithm only) {
    Entities r;
    r.states.resize(kEntityCount);
    r.timestamps.resize(kEntityCount);
    r.prepared.resize(kEntityCount);
    Random random(6);
    for (std::size_t i = 0; i < kEntityCount; ++i) {
        DeadReckoningState& s = r.states[i];
        const DeadReckoningAlgorithm mixed = mixedAlgorithm(random.uniform(0.0f, 1.0f));
        s.algorithm = only == DeadReckoningAlgorithm::Static ? mixed : only;
        s.position = RVec3(random.uniform(-1000, 1000), random.uniform(0, 50), random.uniform(-1000, 1000));
        s.velocity = Vec3(random.uniform(-10, 10), random.uniform(-1, 1), random.uniform(-10, 10));
        s.acceleration = Vec3(random.uniform(-3, 3), random.uniform(-9.81f, 0), random.uniform(-3, 3));
        s.orientation = glm::angleAxis(random.uniform(-3.14f, 3.14f), Vec3(0, 1, 0));
        const Vec3 w(random.uniform(-0.2f, 0.2f), random.uniform(-2, 2), random.uniform(-0.2f, 0.2f));
        if (deadReckoningRotates(s.algorithm)) s.angularVelocity = w;
        r.timestamps[i] = kNow - static_cast<double>(random.uniform(0.0f, 0.25f));
        if (prepareDeadReckoning(s, r.timestamps[i], r.prepared[i]) != Status::Ok) r.prepared.clear();
    }
    return r;
}

const Entities& entities(DeadReckoningAlgorithm only = DeadReckoningAlgorithm::Static) {
    static const Entities mixed = makeEntities(DeadReckoningAlgorithm::Static);
    static const Entities fpw = makeEntities(DeadReckoningAlgorithm::Fpw);
    static const Entities rvw = makeEntities(DeadReckoningAlgorithm::Rvw);
    static const Entities rpb = makeEntities(DeadReckoningAlgorithm::Rpb);
    static const Entities rvb = makeEntities(DeadReckoningAlgorithm::Rvb);
    switch (only) {
        case DeadReckoningAlgorithm::Fpw:
            return fpw;
        case DeadReckoningAlgorithm::Rvw:
            return rvw;
        case DeadReckoningAlgorithm::Rpb:
            return rpb;
        case DeadReckoningAlgorithm::Rvb:
            return rvb;
        default:
            return mixed;
    }
}

void BM_Batch(benchmark::State& state) {
    const Entities& e = entities();
    std::vector<DeadReckoningResult> out(kEntityCount);
    std::size_t refused = 0;
    for (auto _ : state) {
        refused += predictDeadReckoningBatch(e.states, e.timestamps, kNow, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    if (refused != 0) state.SkipWithError("entities were refused");
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

// Argument: the model of every entity (DIS value), or 1 (STATIC) for the mix.
void BM_Prepared(benchmark::State& state) {
    const Entities& e = entities(static_cast<DeadReckoningAlgorithm>(state.range(0)));
    if (e.prepared.size() != kEntityCount) {
        state.SkipWithError("prepareDeadReckoning refused an entity");
        return;
    }
    std::vector<DeadReckoningResult> out(kEntityCount);
    std::size_t refused = 0;
    for (auto _ : state) {
        refused += extrapolateDeadReckoning(e.prepared, kNow, 0.25f, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    if (refused != 0) state.SkipWithError("entities were refused");
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

// The instruction set a batch benchmark runs: the widest this machine has, or the baseline (what
// a processor without AVX2 runs) when `baseline`.
detail::BatchSimd batchSimd(bool baseline) {
    return baseline ? detail::BatchSimd::Baseline : detail::BatchAccess::best();
}
const char* simdLabel(detail::BatchSimd simd) { return simd == detail::BatchSimd::Avx2 ? "AVX2" : "baseline"; }

// Argument: as BM_Prepared.
template <bool kBaseline>
void BM_SoA(benchmark::State& state) {
    const Entities& e = entities(static_cast<DeadReckoningAlgorithm>(state.range(0)));
    if (e.prepared.size() != kEntityCount) {
        state.SkipWithError("prepareDeadReckoning refused an entity");
        return;
    }
    DeadReckoningBatch batch(kEntityCount);
    for (std::size_t i = 0; i < kEntityCount; ++i) (void)batch.set(i, e.prepared[i]);
    std::vector<DeadReckoningResult> out(kEntityCount);
    const detail::BatchSimd simd = batchSimd(kBaseline);
    std::size_t refused = 0;
    for (auto _ : state) {
        refused += detail::BatchAccess::extrapolate(batch, simd, kNow, 0.25f, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    if (refused != 0) state.SkipWithError("entities were refused");
    state.SetLabel(simdLabel(simd));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

// The last-level cache as Google Benchmark reads it (32 MiB when it reports none).
std::size_t lastLevelCacheBytes() {
    std::size_t largest = 0;
    for (const auto& cache : benchmark::CPUInfo::Get().caches)
        largest = std::max(largest, static_cast<std::size_t>(cache.size));
    return largest > 0 ? largest : std::size_t(32) << 20;
}

// A buffer twice the last-level cache, written once (so that its pages are real, not the shared
// zero page); reading it evicts whatever the cache held.
std::vector<std::uint64_t>& evictionBuffer() {
    static std::vector<std::uint64_t> buffer(2 * lastLevelCacheBytes() / sizeof(std::uint64_t), 1);
    return buffer;
}

// One load per 64-byte line: the core brings in every line as fast as memory delivers them
// (loading every word measured 25% slower here: bound by the loads, not by memory).
std::uint64_t readAll(const std::vector<std::uint64_t>& buffer) {
    constexpr std::size_t kWordsPerLine = 64 / sizeof(std::uint64_t);
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < buffer.size(); i += kWordsPerLine) sum += buffer[i];
    return sum;
}

// Bytes one frame of DeadReckoningBatch::extrapolate moves per entity for the mix, from the
// layout in src/replication.cpp (Real is 4 bytes in the float build, 8 in the double build).
// Pass 1 reads every entity's position (3 Real), velocity and acceleration (2 x 12) and
// timestamp (8), and writes its result: a written line is read first and written back later (no
// streaming stores), so the result counts twice. The entities that neither turn nor are
// body-axis have their number (4) and fixed orientation (16) read; pass 2 reads a turning
// entity's number (4), orientation and axis term (2 x 16), timestamp and half rate (2 x 8);
// pass 3 a body-axis entity's number (4), position (3 Real), velocity, acceleration and axis
// (3 x 12), orientation and axis term (2 x 16), timestamp and half rate (2 x 8). Their rewrites
// of results just written hit the cache (4 MB) and are not counted.
double batchBytesPerEntity(double turningShare, double bodyShare) {
    const double real = sizeof(Real);
    const double pass1 = 3 * real + 2 * 12 + 8 + 2 * static_cast<double>(sizeof(DeadReckoningResult));
    const double fixed = 4 + 16;
    const double pass2 = 4 + 2 * 16 + 2 * 8;
    const double pass3 = 4 + 3 * real + 3 * 12 + 2 * 16 + 2 * 8;
    return pass1 + (1.0 - turningShare - bodyShare) * fixed + turningShare * pass2 + bodyShare * pass3;
}

template <bool kBaseline>
void BM_SoACold(benchmark::State& state) {
    const Entities& e = entities();
    if (e.prepared.size() != kEntityCount) {
        state.SkipWithError("prepareDeadReckoning refused an entity");
        return;
    }
    DeadReckoningBatch batch(kEntityCount);
    std::size_t turning = 0, body = 0;
    for (std::size_t i = 0; i < kEntityCount; ++i) {
        (void)batch.set(i, e.prepared[i]);
        turning += deadReckoningRotates(e.states[i].algorithm) && !deadReckoningInBodyAxes(e.states[i].algorithm);
        body += deadReckoningInBodyAxes(e.states[i].algorithm);
    }
    std::vector<DeadReckoningResult> out(kEntityCount);
    const std::vector<std::uint64_t>& eviction = evictionBuffer();
    const detail::BatchSimd simd = batchSimd(kBaseline);
    std::size_t refused = 0;
    std::uint64_t sink = 0;
    for (auto _ : state) {
        state.PauseTiming();
        sink += readAll(eviction);
        state.ResumeTiming();
        refused += detail::BatchAccess::extrapolate(batch, simd, kNow, 0.25f, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    benchmark::DoNotOptimize(sink);
    if (refused != 0) state.SkipWithError("entities were refused");
    state.SetLabel(simdLabel(simd));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
    const double bytes =
        batchBytesPerEntity(static_cast<double>(turning) / kEntityCount, static_cast<double>(body) / kEntityCount);
    state.counters["bytes/entity"] = bytes;
    state.SetBytesProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * bytes * kEntityCount));
}

void BM_MemoryRead(benchmark::State& state) {
    const std::vector<std::uint64_t>& buffer = evictionBuffer();
    std::uint64_t sink = 0;
    for (auto _ : state) {
        sink += readAll(buffer);
        benchmark::ClobberMemory();
    }
    benchmark::DoNotOptimize(sink);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(buffer.size() * sizeof(std::uint64_t)));
}

// Writes every byte once (the lines are read first: two bytes of traffic per byte written,
// as the batch's stores; bytes_per_second counts the traffic).
void BM_MemoryWrite(benchmark::State& state) {
    std::vector<std::uint64_t>& buffer = evictionBuffer();
    std::uint64_t value = 2;
    for (auto _ : state) {
        std::fill(buffer.begin(), buffer.end(), value++);
        benchmark::DoNotOptimize(buffer.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(2 * buffer.size() * sizeof(std::uint64_t)));
}

void BM_PlainLoop(benchmark::State& state) {
    const Entities& e = entities();
    std::vector<DeadReckoningResult> out(kEntityCount);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kEntityCount; ++i) {
            const DeadReckoningState& s = e.states[i];
            const Real age = static_cast<Real>(kNow - e.timestamps[i]);
            out[i].position = s.position + RVec3(s.velocity) * age;
            out[i].velocity = s.velocity;
            out[i].orientation = s.orientation;
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

void BM_Receivers(benchmark::State& state) {
    const Entities& e = entities();
    std::vector<DeadReckoningReceiver> receivers(kReceiverCount);
    for (std::size_t i = 0; i < kReceiverCount; ++i) {
        // An update 0.1 s before now, then a disagreeing one now: a correction in progress.
        DeadReckoningState corrected = e.states[i];
        corrected.position += RVec3(0.3f, 0.0f, -0.2f);
        if (receivers[i].receive(kNow - 0.2, e.states[i], kNow - 0.2) != UpdateOutcome::Snapped ||
            receivers[i].receive(kNow - 0.05, corrected, kNow - 0.05) != UpdateOutcome::Accepted) {
            state.SkipWithError("a receiver refused its updates");
            return;
        }
    }
    double time = kNow;
    for (auto _ : state) {
        for (DeadReckoningReceiver& r : receivers) {
            ReceivedPose pose;
            if (r.sample(time, pose) != Status::Ok) {
                state.SkipWithError("sample failed");
                return;
            }
            benchmark::DoNotOptimize(pose);
        }
        time += 1e-6;  // stays inside the blend
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kReceiverCount));
    state.counters["bytes/receiver"] = static_cast<double>(sizeof(DeadReckoningReceiver));
}

BENCHMARK(BM_Batch)->Name("BM_Replication/Batch")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared")->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/FPW")->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/RVW")->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/RPB")->Arg(7)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/RVB")->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SoA, false)->Name("BM_Replication/SoA")->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SoA, false)->Name("BM_Replication/SoA/FPW")->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SoA, false)->Name("BM_Replication/SoA/RVW")->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SoA, false)->Name("BM_Replication/SoA/RPB")->Arg(7)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SoA, false)->Name("BM_Replication/SoA/RVB")->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SoA, true)->Name("BM_Replication/SoA/Baseline")->Arg(1)->Unit(benchmark::kMicrosecond);
// Fixed iteration counts: every frame pays for an untimed read of the eviction buffer.
BENCHMARK_TEMPLATE(BM_SoACold, false)->Name("BM_Replication/SoA/Cold")->Iterations(200)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SoACold, true)
    ->Name("BM_Replication/SoA/Cold/Baseline")
    ->Iterations(200)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MemoryRead)->Name("BM_Replication/MemoryRead")->Iterations(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MemoryWrite)->Name("BM_Replication/MemoryWrite")->Iterations(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlainLoop)->Name("BM_Replication/PlainLoop")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Receivers)->Name("BM_Replication/Receivers")->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
