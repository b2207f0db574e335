#pragma once
/// @file bench_scenes.h
/// The benchmark's inputs, shared by the timing benchmark (bench_predict.cpp) and the
/// instruction-count harness (count_instructions.cpp): the same arena, throws and vehicles.
///
/// Inputs are deterministic (a fixed-seed generator written here, not <random>'s
/// distributions, whose output differs between standard libraries).

#include <foresight/foresight.h>

#include <array>
#include <cmath>
#include <cstdint>

namespace foresight_bench {

using namespace foresight;

constexpr int kThrowCount = 64;
constexpr float kFuse = 3.0f;       // [s]
constexpr float kStep = 0.02f;      // [s], the article's
constexpr float kDriveTime = 2.0f;  // [s]
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
        const std::uint64_t bits = (mState * 0x2545F4914F6CDD1DULL) >> 40;  // 24 bits
        return lo + (hi - lo) * (static_cast<float>(bits) * (1.0f / 16777216.0f));
    }

private:
    std::uint64_t mState;
};

/// A walled arena: floor, four walls 20 m out, a few crates (some rotated) and a boulder.
inline StaticWorld makeArena() {
    StaticWorld world;
    bool ok = true;
    ok &= world.add(Plane{Vec3(0, 1, 0), 0}) == Status::Ok;     // floor, y = 0
    ok &= world.add(Plane{Vec3(1, 0, 0), -20}) == Status::Ok;   // wall at x = -20
    ok &= world.add(Plane{Vec3(-1, 0, 0), -20}) == Status::Ok;  // wall at x = +20
    ok &= world.add(Plane{Vec3(0, 0, 1), -20}) == Status::Ok;   // wall at z = -20
    ok &= world.add(Plane{Vec3(0, 0, -1), -20}) == Status::Ok;  // wall at z = +20

    Random random(7);
    for (int i = 0; i < 6; ++i) {
        OrientedBox crate;
        crate.center = RVec3(random.uniform(-12, 12), 0.75f, random.uniform(-12, 12));
        crate.halfExtents = Vec3(random.uniform(0.5f, 2), 0.75f, random.uniform(0.5f, 2));
        crate.orientation = glm::angleAxis(random.uniform(0, kPi), Vec3(0, 1, 0));
        ok &= world.add(crate) == Status::Ok;
    }
    ok &= world.add(Sphere{RVec3(4, 0, -6), 2.0f}) == Status::Ok;
    if (!ok) world.clear();  // the benchmarks then report the empty world as an error
    return world;
}

struct Throw {
    RVec3 position{0};
    Vec3 velocity{0};
};

/// Grenades thrown from around the centre in every direction, 8 to 20 m/s, 10 to 60 deg up.
inline std::array<Throw, kThrowCount> makeThrows() {
    Random random(42);
    std::array<Throw, kThrowCount> throws{};
    for (Throw& t : throws) {
        t.position = RVec3(random.uniform(-5, 5), random.uniform(1.2f, 2), random.uniform(-5, 5));
        const float speed = random.uniform(8, 20);
        const float yaw = random.uniform(0, 2 * kPi);
        const float pitch = random.uniform(10, 60) * (kPi / 180);
        t.velocity = speed * Vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    }
    return throws;
}

/// Vehicles with random headings, speeds (some reversing) and turn rates (mostly yaw, some
/// pitch and roll, as on uneven ground).
inline std::array<VehicleState, kThrowCount> makeVehicles() {
    Random random(1234);
    std::array<VehicleState, kThrowCount> vehicles{};
    for (VehicleState& v : vehicles) {
        v.position = RVec3(random.uniform(-100, 100), random.uniform(0, 5), random.uniform(-100, 100));
        v.orientation = glm::angleAxis(random.uniform(0, 2 * kPi), Vec3(0, 1, 0)) *
                        glm::angleAxis(random.uniform(-0.2f, 0.2f), Vec3(1, 0, 0));
        const Vec3 forward = v.orientation * Vec3(0, 0, 1);
        v.velocity = forward * random.uniform(-5, 30);
        v.angularVelocity = Vec3(random.uniform(-0.1f, 0.1f), random.uniform(-1, 1), random.uniform(-0.1f, 0.1f));
    }
    return vehicles;
}

}  // namespace foresight_bench
