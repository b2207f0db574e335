/// bench_predict.cpp: what the exact methods cost next to the reference article's loops.
///
/// Benchmarks come in pairs that run the same inputs, so their times compare directly:
///   BM_Projectile/Stepped  vs  BM_Projectile/Exact       (64 grenade throws, 3 s fuse)
///   BM_Vehicle/Iterative4  vs  BM_Vehicle/Exact          (64 vehicles, 2 s)
/// Targets: the exact projectile within 1.1x of the stepped loop; the exact vehicle no slower
/// than 4 iterations. scripts/bench.sh runs repetitions and prints these ratios.
///
/// Inputs are deterministic (a fixed-seed generator written here, not <random>'s
/// distributions, whose output differs between standard libraries).

#include <foresight/foresight.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using namespace foresight;

constexpr int kThrowCount = 64;
constexpr float kFuse = 3.0f;      // [s]
constexpr float kStep = 0.02f;     // [s], the article's
constexpr float kDriveTime = 2.0f; // [s]
constexpr float kPi = 3.14159265358979f;

/// xorshift64*: small, fast and the same on every platform.
class Random {
public:
    explicit Random(std::uint64_t seed) : mState(seed) {}

    /// Uniform in [lo, hi).
    float uniform(float lo, float hi) {
        mState ^= mState >> 12;
        mState ^= mState << 25;
        mState ^= mState >> 27;
        const std::uint64_t bits = (mState * 0x2545F4914F6CDD1DULL) >> 40; // 24 bits
        return lo + (hi - lo) * (static_cast<float>(bits) * (1.0f / 16777216.0f));
    }

private:
    std::uint64_t mState;
};

/// A walled arena: floor, four walls 20 m out, a few crates (some rotated) and a boulder.
StaticWorld makeArena() {
    StaticWorld world;
    bool ok = true;
    ok &= world.add(Plane{Vec3(0, 1, 0), 0}) == Status::Ok;   // floor, y = 0
    ok &= world.add(Plane{Vec3(1, 0, 0), -20}) == Status::Ok;  // wall at x = -20
    ok &= world.add(Plane{Vec3(-1, 0, 0), -20}) == Status::Ok; // wall at x = +20
    ok &= world.add(Plane{Vec3(0, 0, 1), -20}) == Status::Ok;  // wall at z = -20
    ok &= world.add(Plane{Vec3(0, 0, -1), -20}) == Status::Ok; // wall at z = +20

    Random random(7);
    for (int i = 0; i < 6; ++i) {
        OrientedBox crate;
        crate.center = RVec3(random.uniform(-12, 12), 0.75f, random.uniform(-12, 12));
        crate.halfExtents = Vec3(random.uniform(0.5f, 2), 0.75f, random.uniform(0.5f, 2));
        crate.orientation = glm::angleAxis(random.uniform(0, kPi), Vec3(0, 1, 0));
        ok &= world.add(crate) == Status::Ok;
    }
    ok &= world.add(Sphere{RVec3(4, 0, -6), 2.0f}) == Status::Ok;
    if (!ok) world.clear(); // the benchmarks then report the empty world as an error
    return world;
}

struct Throw {
    RVec3 position{0};
    Vec3 velocity{0};
};

/// Grenades thrown from around the centre in every direction, 8 to 20 m/s, 10 to 60 deg up.
std::array<Throw, kThrowCount> makeThrows() {
    Random random(42);
    std::array<Throw, kThrowCount> throws{};
    for (Throw& t : throws) {
        t.position = RVec3(random.uniform(-5, 5), random.uniform(1.2f, 2), random.uniform(-5, 5));
        const float speed = random.uniform(8, 20);
        const float yaw = random.uniform(0, 2 * kPi);
        const float pitch = random.uniform(10, 60) * (kPi / 180);
        t.velocity = speed * Vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                  std::cos(pitch) * std::cos(yaw));
    }
    return throws;
}

/// Vehicles with random headings, speeds (some reversing) and turn rates (mostly yaw, some
/// pitch and roll, as on uneven ground).
std::array<VehicleState, kThrowCount> makeVehicles() {
    Random random(1234);
    std::array<VehicleState, kThrowCount> vehicles{};
    for (VehicleState& v : vehicles) {
        v.position = RVec3(random.uniform(-100, 100), random.uniform(0, 5), random.uniform(-100, 100));
        v.orientation = glm::angleAxis(random.uniform(0, 2 * kPi), Vec3(0, 1, 0)) *
                        glm::angleAxis(random.uniform(-0.2f, 0.2f), Vec3(1, 0, 0));
        const Vec3 forward = v.orientation * Vec3(0, 0, 1);
        v.velocity = forward * random.uniform(-5, 30);
        v.angularVelocity = Vec3(random.uniform(-0.1f, 0.1f), random.uniform(-1, 1),
                                 random.uniform(-0.1f, 0.1f));
    }
    return vehicles;
}

/// Both methods, same throws, same world; the trajectory goes into a buffer allocated once.
void BM_Projectile(benchmark::State& state, ProjectileMethod method) {
    const StaticWorld world = makeArena();
    if (world.shapeCount() == 0) {
        state.SkipWithError("could not build the arena");
        return;
    }
    const std::array<Throw, kThrowCount> throws = makeThrows();

    ProjectileSettings settings; // the article's: restitution 0.5, no friction
    settings.method = method;
    settings.step = kStep;
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(kFuse, settings, 256));

    std::uint64_t bounces = 0;
    for (auto _ : state) {
        for (const Throw& t : throws) {
            ProjectileResult result;
            const Status status =
                predictProjectile(t.position, t.velocity, kFuse, settings, &world, trajectory, result);
            if (status != Status::Ok) {
                state.SkipWithError(statusMessage(status));
                return;
            }
            bounces += result.bounces;
            benchmark::DoNotOptimize(result);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * kThrowCount);
    state.counters["bounces/throw"] = static_cast<double>(bounces) /
                                      static_cast<double>(state.iterations() * kThrowCount);
}
BENCHMARK_CAPTURE(BM_Projectile, Stepped, ProjectileMethod::Stepped);
BENCHMARK_CAPTURE(BM_Projectile, Exact, ProjectileMethod::Exact);

enum class VehicleMethod { Iterative4, Exact };

void BM_Vehicle(benchmark::State& state, VehicleMethod method) {
    const std::array<VehicleState, kThrowCount> vehicles = makeVehicles();
    const VehicleSettings settings; // body frame, forward +Z (the article's)

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

} // namespace

BENCHMARK_MAIN();
