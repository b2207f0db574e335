/// bench_c_api.cpp: what calling through the C API (foresight_c.h, the shared library that the
/// C#, wasm and other bindings call) costs next to calling the C++ library directly.
///
/// Pairs that run the same inputs, so their times compare directly:
///   BM_CallOverhead/Projectile/Cpp vs .../C   the bench arena's 64 grenade throws, 3 s fuse,
///                                             Exact method, friction 0.4, the trajectory into
///                                             a buffer allocated once (the per-frame use)
///   BM_CallOverhead/Linear/Cpp vs .../C       64 characters, predictLinear (the smallest call:
///                                             the bare cost of crossing the boundary)
/// Target: the C projectile call within 1.5x of the C++ one. scripts/bench.sh --c-api runs
/// repetitions and prints the ratios.

#include "bench_scenes.h"

#include <foresight/foresight.h>
#include <foresight/foresight_c.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace {

using namespace foresight;
using namespace foresight_bench;

struct WorldDeleter {
    void operator()(fs_world* world) const { fs_world_destroy(world); }
};
using CWorld = std::unique_ptr<fs_world, WorldDeleter>;

/// makeArena()'s shapes (bench_scenes.h), added through the C API in the same order.
CWorld makeCArena() {
    CWorld world(fs_world_create());
    if (!world) return world;
    bool ok = true;
    const fs_plane planes[] = {
        {{0, 1, 0}, 0, 0}, {{1, 0, 0}, 0, -20}, {{-1, 0, 0}, 0, -20}, {{0, 0, 1}, 0, -20}, {{0, 0, -1}, 0, -20}};
    for (const fs_plane& plane : planes) ok &= fs_world_add_plane(world.get(), &plane, nullptr) == FS_STATUS_OK;
    Random random(7);
    for (int i = 0; i < 6; ++i) {
        fs_box crate{};
        crate.center = {random.uniform(-12, 12), 0.75f, random.uniform(-12, 12)};
        crate.half_extents = {random.uniform(0.5f, 2), 0.75f, random.uniform(0.5f, 2)};
        const Quat q = glm::angleAxis(random.uniform(0, kPi), Vec3(0, 1, 0));
        crate.orientation = {q.x, q.y, q.z, q.w};
        ok &= fs_world_add_box(world.get(), &crate, nullptr) == FS_STATUS_OK;
    }
    const fs_sphere boulder{{4, 0, -6}, 2.0f, 0};
    ok &= fs_world_add_sphere(world.get(), &boulder, nullptr) == FS_STATUS_OK;
    if (!ok) world.reset();
    return world;
}

void BM_ProjectileCpp(benchmark::State& state) {
    const StaticWorld world = makeArena();
    const std::array<Throw, kThrowCount> throws = makeThrows();
    ProjectileSettings settings;
    settings.friction = 0.4f;
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(kFuse, settings, 256));
    for (auto _ : state) {
        for (const Throw& t : throws) {
            ProjectileResult result;
            if (predictProjectile(t.position, t.velocity, kFuse, settings, &world, trajectory, result) != Status::Ok) {
                state.SkipWithError("predictProjectile refused a throw");
                return;
            }
            benchmark::DoNotOptimize(result);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * kThrowCount);
}

void BM_ProjectileC(benchmark::State& state) {
    const CWorld world = makeCArena();
    if (!world) {
        state.SkipWithError("could not build the arena through the C API");
        return;
    }
    const std::array<Throw, kThrowCount> throws = makeThrows();
    fs_projectile_settings settings = fs_projectile_settings_default();
    settings.friction = 0.4f;
    ProjectileSettings same;
    same.friction = 0.4f;
    std::vector<fs_trajectory_point> trajectory(trajectoryCapacity(kFuse, same, 256));
    for (auto _ : state) {
        for (const Throw& t : throws) {
            fs_projectile_result result;
            const fs_dvec3 position{t.position.x, t.position.y, t.position.z};
            const fs_vec3 velocity{t.velocity.x, t.velocity.y, t.velocity.z};
            if (fs_predict_projectile(position, velocity, kFuse, &settings, world.get(), trajectory.data(),
                                      trajectory.size(), &result) != FS_STATUS_OK) {
                state.SkipWithError("fs_predict_projectile refused a throw");
                return;
            }
            benchmark::DoNotOptimize(result);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * kThrowCount);
}

void BM_LinearCpp(benchmark::State& state) {
    const std::array<Throw, kThrowCount> throws = makeThrows();
    for (auto _ : state) {
        for (const Throw& t : throws) {
            PointState out;
            const Status status = predictLinear(PointState{t.position, t.velocity}, 0.5f, out);
            benchmark::DoNotOptimize(status);
            benchmark::DoNotOptimize(out);
        }
    }
    state.SetItemsProcessed(state.iterations() * kThrowCount);
}

void BM_LinearC(benchmark::State& state) {
    const std::array<Throw, kThrowCount> throws = makeThrows();
    for (auto _ : state) {
        for (const Throw& t : throws) {
            const fs_point_state start{
                {t.position.x, t.position.y, t.position.z}, {t.velocity.x, t.velocity.y, t.velocity.z}, 0.0f};
            fs_point_state out;
            const fs_status status = fs_predict_linear(&start, 0.5f, &out);
            benchmark::DoNotOptimize(status);
            benchmark::DoNotOptimize(out);
        }
    }
    state.SetItemsProcessed(state.iterations() * kThrowCount);
}

BENCHMARK(BM_ProjectileCpp)->Name("BM_CallOverhead/Projectile/Cpp");
BENCHMARK(BM_ProjectileC)->Name("BM_CallOverhead/Projectile/C");
BENCHMARK(BM_LinearCpp)->Name("BM_CallOverhead/Linear/Cpp");
BENCHMARK(BM_LinearC)->Name("BM_CallOverhead/Linear/C");

}  // namespace

BENCHMARK_MAIN();
