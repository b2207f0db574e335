/// article_scenarios.cpp: the reference article's three scenarios, printed to the last digit.
///
/// Every language binding has a twin of this program (bindings/*/): the C one
/// (article_scenarios.c), the C# one, the Python one and the node one. Each must print exactly
/// the same text as this one: the bindings add no arithmetic of their own, so any difference is
/// a binding bug (a field in the wrong place, a float passed as a double, a default lost). CTest
/// compares their outputs with this program's.
///
///   1. a character: constant velocity and constant acceleration, 0.5 s ahead;
///   2. a grenade thrown at a wall with a 3 s fuse, in a world of a floor plane and a wall box:
///      the article's stepped loop, the exact method, and the flight as Jolt will simulate it;
///   3. a turning car, 2 s ahead: the article's 4-iteration loop and the exact arc.
///
/// Numbers are printed with 6 decimals (printf "%.6f"; -0 is printed as 0).
/// Conventions: metres, seconds, radians; +Y up, +Z forward.

#include <foresight/foresight.h>

#include <cstdio>
#include <vector>

using namespace foresight;

namespace {

/// A number with 6 decimals; adding 0.0 turns -0 into 0.
void number(double value) { std::printf("%.6f", value + 0.0); }

void vec(const char* label, double x, double y, double z) {
    std::printf("%s (", label);
    number(x);
    std::printf(", ");
    number(y);
    std::printf(", ");
    number(z);
    std::printf(")");
}

template <typename V>
void vec(const char* label, V v) {
    vec(label, static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

bool ok(Status status, const char* what) {
    if (status == Status::Ok) return true;
    std::fprintf(stderr, "%s: %s\n", what, statusMessage(status));
    return false;
}

bool character() {
    PointState now;
    now.position = RVec3(1, 0, 2);
    now.velocity = Vec3(3, 0, 4);
    const Vec3 acceleration(0, 0, -2);
    PointState linear, accelerated;
    if (!ok(predictLinear(now, 0.5f, linear), "predictLinear")) return false;
    if (!ok(predictAccelerated(now, acceleration, 0.5f, accelerated), "predictAccelerated")) return false;
    std::printf("character\n");
    vec("  linear      position", linear.position);
    vec(" velocity", linear.velocity);
    std::printf("\n");
    vec("  accelerated position", accelerated.position);
    vec(" velocity", accelerated.velocity);
    std::printf("\n");
    return true;
}

bool grenade(const char* name, const ProjectileSettings& settings, const StaticWorld& world) {
    const float fuse = 3.0f;
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(fuse, settings));
    ProjectileResult result;
    if (!ok(predictProjectile(RVec3(0, 1.6f, 0), Vec3(0, 4, 12), fuse, settings, &world, trajectory, result), name))
        return false;
    std::printf("grenade %s: %u bounces, %llu points\n", name, result.bounces,
                static_cast<unsigned long long>(result.trajectorySize));
    int shown = 0;
    for (std::size_t i = 0; i < result.trajectorySize; ++i) {
        const TrajectoryPoint& point = trajectory[i];
        if (point.event != TrajectoryEvent::Bounce || shown == 3) continue;
        ++shown;
        std::printf("  bounce t ");
        number(point.time);
        vec(" position", point.position);
        vec(" normal", point.normal);
        std::printf("\n");
    }
    std::printf("  end    t ");
    number(result.time);
    vec(" position", result.position);
    vec(" velocity", result.velocity);
    std::printf("%s\n", result.atRest ? " at rest" : "");
    return true;
}

bool grenades() {
    StaticWorld world;
    Plane floor;
    floor.normal = Vec3(0, 1, 0);
    floor.distance = 0;
    OrientedBox wall;
    wall.center = RVec3(0, 1.5f, 10);
    wall.halfExtents = Vec3(5, 1.5f, 0.25f);
    if (!ok(world.add(floor), "add floor") || !ok(world.add(wall), "add wall")) return false;

    ProjectileSettings settings;
    settings.restitution = 0.5f;
    settings.friction = 0.4f;
    settings.radius = 0.05f;
    settings.method = ProjectileMethod::Stepped;
    if (!grenade("stepped", settings, world)) return false;
    settings.method = ProjectileMethod::Exact;
    if (!grenade("exact", settings, world)) return false;
    settings.method = ProjectileMethod::Engine;
    settings.engine = engineProfile(PhysicsEngine::Jolt);
    return grenade("jolt", settings, world);
}

bool car() {
    VehicleState start;
    start.position = RVec3(0, 0, 0);
    start.velocity = Vec3(0, 0, 10);
    start.orientation = Quat(1, 0, 0, 0);
    start.angularVelocity = Vec3(0, 0.5f, 0);
    const VehicleSettings settings;
    VehicleState iterated, exact;
    if (!ok(predictVehicleIterative(start, 2.0f, 4, settings, iterated), "predictVehicleIterative")) return false;
    if (!ok(predictVehicleExact(start, 2.0f, settings, exact), "predictVehicleExact")) return false;
    std::printf("car\n");
    for (const auto& [label, state] : {std::pair{"  iterative", &iterated}, std::pair{"  exact    ", &exact}}) {
        vec(label, state->position);
        vec(" velocity", state->velocity);
        std::printf(" orientation (");
        number(state->orientation.w);
        std::printf(", ");
        number(state->orientation.x);
        std::printf(", ");
        number(state->orientation.y);
        std::printf(", ");
        number(state->orientation.z);
        std::printf(")\n");
    }
    return true;
}

}  // namespace

int main() { return character() && grenades() && car() ? 0 : 1; }
