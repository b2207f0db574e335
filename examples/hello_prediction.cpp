/// hello_prediction.cpp: foresight in one file. Copy it into your project and start from here.
///
/// It predicts, in this order:
///   1. a character walking at constant velocity (predictLinear),
///   2. a grenade thrown at a wall, bouncing until its fuse ends (predictProjectile, Exact),
///      in the built-in StaticWorld (a floor plane and a wall box),
///   3. a turning car: the exact arc vs the reference article's 4-iteration loop,
///   4. the same grenade, but asking *your engine's* ray cast for the collisions
///      (CallbackWorld::wrap with a lambda).
///
/// Build it against an installed foresight (see CMakeLists.txt beside this file):
///   cmake -S examples -B build-example -DCMAKE_PREFIX_PATH=/where/foresight/is/installed
///   cmake --build build-example && ./build-example/hello_prediction
///
/// Conventions (docs/ARCHITECTURE.md): metres, seconds, radians; +Y up, +Z forward.

#include <foresight/foresight.h>

#include <cmath>
#include <cstdio>
#include <vector>

// Everything lives in namespace foresight (one namespace; see CONTRIBUTING.md).
using namespace foresight;

namespace {

// Every foresight call that can refuse its input returns a Status; nothing throws. A real game
// would log and fall back (e.g. draw no prediction); the example stops at the first error.
bool ok(Status status, const char* what) {
    if (status != Status::Ok) {
        std::fprintf(stderr, "%s failed: %s\n", what, statusMessage(status));
        return false;
    }
    return true;
}

// RVec3 is float by default and double with FORESIGHT_DOUBLE_PRECISION: print it as double
// (adding 0.0 turns -0 into 0, so a point on the floor does not print as -0.000).
void printVec(const char* label, RVec3 v) {
    std::printf("%s(%.3f, %.3f, %.3f)", label, static_cast<double>(v.x) + 0.0, static_cast<double>(v.y) + 0.0,
                static_cast<double>(v.z) + 0.0);
}

/// 1. A character: where will it be in half a second if it keeps walking?
bool predictCharacter() {
    PointState now;
    now.position = RVec3(0, 0, 0);
    now.velocity = Vec3(3, 0, 4);  // 5 m/s, diagonally

    PointState later;
    if (!ok(predictLinear(now, 0.5f, later), "predictLinear")) return false;

    printVec("character in 0.5 s: ", later.position);
    std::printf("\n");
    return true;
}

/// The arena shared by the grenade examples: a floor and a 3 m high wall 10 m ahead.
bool buildArena(StaticWorld& world) {
    Plane floor;
    floor.normal = Vec3(0, 1, 0);  // solid below y = 0
    floor.distance = 0;

    OrientedBox wall;
    wall.center = RVec3(0, 1.5f, 10);
    wall.halfExtents = Vec3(5, 1.5f, 0.25f);  // 10 m wide, 3 m high, 0.5 m thick
    // wall.orientation: identity (axis aligned). Rotations come from glm::angleAxis.

    // Adding validates the shape: a zero normal or a negative size is refused, not stored.
    return ok(world.add(floor), "add floor") && ok(world.add(wall), "add wall");
}

/// Prints what a grenade did: its bounces, where it ended up, whether it came to rest.
void printGrenade(const ProjectileResult& result, std::span<const TrajectoryPoint> trajectory) {
    for (const TrajectoryPoint& point : trajectory) {
        if (point.event == TrajectoryEvent::Bounce) {
            std::printf("  bounce at t = %.3f s ", static_cast<double>(point.time));
            printVec("at ", point.position);
            std::printf(", normal (%.0f, %.0f, %.0f)\n", static_cast<double>(point.normal.x),
                        static_cast<double>(point.normal.y), static_cast<double>(point.normal.z));
        }
    }
    std::printf("  %u bounces; ", result.bounces);
    printVec("explodes at ", result.position);
    std::printf(" at t = %.2f s%s\n", static_cast<double>(result.time), result.atRest ? " (lying still)" : "");
}

/// 2. A grenade with a 3 s fuse thrown towards the wall: where does it explode?
bool predictGrenade(const StaticWorld& world) {
    ProjectileSettings settings;  // defaults: Exact method, 9.81 m/s^2 down, restitution 0.5
    settings.friction = 0.4f;     // rough ground, so it stops rolling
    settings.radius = 0.05f;      // a 10 cm grenade: swept-sphere casts

    const float fuse = 3.0f;
    const RVec3 hand(0, 1.6f, 0);
    const Vec3 throwVelocity(0, 4, 12);  // forward and a little up

    // The caller owns the memory: allocate the trajectory once (e.g. at level load) and reuse
    // it every frame. trajectoryCapacity gives a size that fits the whole path.
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(fuse, settings));

    ProjectileResult result;
    if (!ok(predictProjectile(hand, throwVelocity, fuse, settings, &world, trajectory, result), "predictProjectile"))
        return false;

    // With restitution 0.5 each hop is a quarter as high as the one before, so the last bounces
    // come quickly; when a hop would be under a micrometre the grenade slides, then rests.
    std::printf("grenade (exact):\n");
    // Only the first trajectorySize points were written (trajectoryNeeded says how many the
    // whole path has, if the buffer was too small).
    printGrenade(result, std::span<const TrajectoryPoint>(trajectory.data(), result.trajectorySize));
    return true;
}

/// 3. A car driving at 10 m/s and turning left at 0.5 rad/s: where is it in 2 s?
bool predictCar() {
    VehicleState car;
    car.position = RVec3(0, 0, 0);
    car.velocity = Vec3(0, 0, 10);            // along its forward axis (+Z)
    car.orientation = glm::identity<Quat>();  // facing +Z; build rotations with glm::angleAxis
    car.angularVelocity = Vec3(0, 0.5f, 0);   // yaw left, in the car's own axes

    VehicleSettings settings;  // Body-frame angular velocity, forward = +Z (the article's)

    // The closed form is exact and costs about two loop iterations.
    VehicleState exact;
    if (!ok(predictVehicleExact(car, 2.0f, settings, exact), "predictVehicleExact")) return false;

    // The article's loop with 4 steps: cheaper to write, but about 2 m off here.
    VehicleState iterated;
    if (!ok(predictVehicleIterative(car, 2.0f, 4, settings, iterated), "predictVehicleIterative")) return false;

    std::printf("car in 2 s:\n");
    printVec("  exact arc:       ", exact.position);
    std::printf("\n");
    printVec("  4 iterations:    ", iterated.position);
    std::printf("\n  difference: %.2f m\n", static_cast<double>(glm::length(Vec3(exact.position - iterated.position))));
    return true;
}

/// 4. Your engine already has a ray cast: let foresight use it.
///
/// Here the "engine" is a stand-in that knows a single floor at y = 0; in a game this would call
/// PhysX, Jolt, Bullet, Unity's Linecast, etc.
bool predictWithEngineRayCast() {
    // Follow the rules of CollisionWorld (world.h): report the first surface the segment
    // *enters* (moving against the normal), a segment that starts on the surface and moves in
    // hits at fraction 0, and a zero-length segment hits nothing.
    auto engineCast = [](const SegmentCast& cast, CastHit& hit) -> bool {
        const Real startHeight = cast.origin.y - cast.radius;  // the sphere's lowest point
        const float dy = cast.displacement.y;
        if (dy >= 0.0f || startHeight < -1e-4f) return false;  // moving up, or already below
        const float fraction = std::fmax(0.0f, static_cast<float>(-startHeight) / dy);
        if (fraction > 1.0f) return false;  // does not reach the floor in this segment
        hit.fraction = fraction;
        hit.position = cast.origin + RVec3(cast.displacement * fraction);
        hit.normal = Vec3(0, 1, 0);
        return true;
    };
    // The world references the lambda (no copy, no allocation): keep the lambda alive.
    const CallbackWorld engineWorld = CallbackWorld::wrap(engineCast);

    ProjectileSettings settings;
    settings.friction = 0.4f;
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(3.0f, settings));
    ProjectileResult result;
    if (!ok(predictProjectile(RVec3(0, 1.6f, 0), Vec3(0, 4, 6), 3.0f, settings, &engineWorld, trajectory, result),
            "predictProjectile (engine ray cast)"))
        return false;

    std::printf("grenade (engine ray cast):\n");
    printGrenade(result, std::span<const TrajectoryPoint>(trajectory.data(), result.trajectorySize));
    return true;
}

}  // namespace

int main() {
    std::printf("foresight %s\n", foresight::versionString());

    StaticWorld world;  // built once, queried every frame (const, thread-safe casts)
    if (!buildArena(world)) return 1;

    const bool allOk = predictCharacter() && predictGrenade(world) && predictCar() && predictWithEngineRayCast();
    return allOk ? 0 : 1;
}
