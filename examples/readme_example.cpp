#include <foresight/foresight.h>

#include <array>
#include <cstdio>
using namespace foresight;

int main() {
    // A character, 0.4 s ahead (constant velocity; predictAccelerated adds a t^2/2).
    PointState runner{RVec3(0, 0, 0), Vec3(3, 0, 4)}, ahead;
    predictLinear(runner, 0.4f, ahead);

    // A grenade bouncing in a world of planes, boxes, spheres and triangles (or your engine's
    // ray cast: derive from CollisionWorld or wrap a lambda with CallbackWorld::wrap).
    StaticWorld world;
    world.add(Plane{Vec3(0, 1, 0), 0});                         // the floor y = 0
    world.add(OrientedBox{RVec3(0, 2, 8), Vec3(4, 2, 0.25f)});  // a wall
    ProjectileSettings settings;                                // Exact by default; Stepped = article
    std::array<TrajectoryPoint, 256> points;                    // caller-owned: no allocation
    ProjectileResult grenade;
    if (Status s = predictProjectile(RVec3(0, 1.5f, 0), Vec3(0, 4, 12), 3.0f, settings, &world, points, grenade);
        s != Status::Ok)
        std::printf("refused: %s\n", statusMessage(s));  // nothing throws
    // grenade.position, .bounces, .atRest; points[0 .. grenade.trajectorySize) to draw.

    // A car turning at 0.5 rad/s: the exact arc, or the article's loop with N iterations.
    VehicleState car;
    car.velocity = Vec3(0, 0, 10);
    car.angularVelocity = Vec3(0, 0.5f, 0);  // body frame by default
    VehicleState exact, loop;
    predictVehicleExact(car, 2.0f, {}, exact);
    predictVehicleIterative(car, 2.0f, 4, {}, loop);

    // A turret at 20 m/s against the runner: up to kMaxFiringSolutions launch velocities.
    std::array<FiringSolution, kMaxFiringSolutions> solutions;
    std::size_t count = 0;
    aimProjectile(AimShot{.from = RVec3(0, 1.6f, -10), .speed = 20.0f},
                  AimTarget{.position = runner.position, .velocity = runner.velocity}, solutions, count);

    std::printf("runner z %.2f, grenade %u bounces, car x %.2f (loop %.2f), %zu firing solutions\n",
                double(ahead.position.z), unsigned(grenade.bounces), double(exact.position.x), double(loop.position.x),
                count);
}
