/// bench_predict.cpp: what the exact methods cost next to the reference article's loops.
///
/// Benchmarks come in pairs that run the same inputs, so their times compare directly:
///   BM_Projectile/Stepped  vs  BM_Projectile/Exact       (64 grenade throws, 3 s fuse)
///   BM_Projectile/SteppedFriction vs .../ExactFriction    (the same throws, friction 0.4)
///   BM_Vehicle/Iterative4  vs  BM_Vehicle/Exact          (64 vehicles, 2 s)
/// Targets: the exact projectile within 1.1x of the stepped loop; the exact vehicle no slower
/// than 4 iterations. scripts/bench.sh runs repetitions and prints these ratios.
/// The inputs are in bench_scenes.h (shared with count_instructions.cpp).

#include "bench_throws.h"

#include <foresight/foresight.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using namespace foresight;
using namespace foresight_bench;

/// Both methods, same throws, same world; the trajectory goes into a buffer allocated once.
void BM_Projectile(benchmark::State& state, ProjectileMethod method, float friction) {
    const StaticWorld world = makeArena();
    if (world.shapeCount() == 0) {
        state.SkipWithError("could not build the arena");
        return;
    }
    const std::array<Throw, kThrowCount> throws = makeThrows();

    ProjectileSettings settings;  // the article's: restitution 0.5 (and no friction)
    settings.method = method;
    settings.friction = friction;
    settings.step = kStep;
    timeThrows(state, throws, kFuse, settings, world, true);
}
// The article's settings (no friction: landed grenades slide on for the rest of the fuse).
BENCHMARK_CAPTURE(BM_Projectile, Stepped, ProjectileMethod::Stepped, 0.0f);
BENCHMARK_CAPTURE(BM_Projectile, Exact, ProjectileMethod::Exact, 0.0f);
// With friction 0.4, as most games set it: landed grenades come to rest.
BENCHMARK_CAPTURE(BM_Projectile, SteppedFriction, ProjectileMethod::Stepped, 0.4f);
BENCHMARK_CAPTURE(BM_Projectile, ExactFriction, ProjectileMethod::Exact, 0.4f);

enum class VehicleMethod { Iterative4, Exact };

void BM_Vehicle(benchmark::State& state, VehicleMethod method) {
    const std::array<VehicleState, kThrowCount> vehicles = makeVehicles();
    const VehicleSettings settings;  // body frame, forward +Z (the article's)

    for (auto _ : state) {
        for (const VehicleState& vehicle : vehicles) {
            VehicleState out;
            const Status status = method == VehicleMethod::Exact
                                      ? predictVehicleExact(vehicle, kDriveTime, settings, out)
                                      : predictVehicleIterative(vehicle, kDriveTime, 4, settings, out);
            if (status != Status::Ok) {
                state.SkipWithError(statusMessage(status));
                return;
            }
            benchmark::DoNotOptimize(out);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * kThrowCount);
}
BENCHMARK_CAPTURE(BM_Vehicle, Iterative4, VehicleMethod::Iterative4);
BENCHMARK_CAPTURE(BM_Vehicle, Exact, VehicleMethod::Exact);

}  // namespace

BENCHMARK_MAIN();
