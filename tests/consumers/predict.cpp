// The program both consumer projects build (add_subdirectory/ and fetch_content/): one grenade
// throw against a floor, printed. It exits with status 1 if foresight refuses the input or the
// grenade ends anywhere but on the floor, so the test fails on a wrong link as well as on a
// wrong build.

#include <foresight/foresight.h>

#include <array>
#include <cstdio>

int main() {
    using namespace foresight;

    StaticWorld world;
    if (world.add(Plane{Vec3(0, 1, 0), 0}) != Status::Ok) return 1;  // the floor y = 0

    // Thrown from 1.5 m up at 4 m/s up and 8 m/s forward; 3 s lets it bounce and settle.
    ProjectileSettings settings;  // Exact, gravity 9.81 m/s^2 down, restitution 0.5
    std::array<TrajectoryPoint, 256> points{};
    ProjectileResult grenade;
    const Status status = predictProjectile(RVec3(0, 1.5f, 0), Vec3(0, 4, 8), 3.0f, settings, &world, points, grenade);
    if (status != Status::Ok) {
        std::fprintf(stderr, "predictProjectile refused the throw: %s\n", statusMessage(status));
        return 1;
    }
    std::printf("foresight %s: the grenade ends at (%.3f, %.3f, %.3f) m after %u bounces\n", versionString(),
                static_cast<double>(grenade.position.x), static_cast<double>(grenade.position.y),
                static_cast<double>(grenade.position.z), static_cast<unsigned>(grenade.bounces));
    const bool onFloor = grenade.position.y > -1e-3f && grenade.position.y < 1e-3f;
    return onFloor && grenade.bounces > 0 ? 0 : 1;
}
