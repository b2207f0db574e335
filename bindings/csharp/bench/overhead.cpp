/// overhead.cpp: the C++ side of the C# binding's overhead measurement. Times the article's
/// grenade (Exact method, a floor and a wall, 3 s fuse, trajectory into a buffer of CAPACITY
/// points, the first argument; default trajectoryCapacity(3 s) = 281, as article_scenarios.cpp
/// sizes it) through the C++ API and through the C API, and prints the best nanoseconds per
/// call of each: "cpp_ns N" and "c_api_ns N". ArticleScenarios.exe --overhead runs it and
/// compares with the same call through C#.

#include <foresight/foresight.h>
#include <foresight/foresight_c.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <vector>

using namespace foresight;

namespace {

constexpr int kCalls = 20000;  // about 0.1 s per run
constexpr int kRuns = 7;

/// The best of kRuns runs of kCalls calls of `call` [Units: ns per call].
template <class F>
double best(F&& call) {
    for (int i = 0; i < 2000; ++i) call();  // warm caches and branch predictors
    double result = 1e300;
    for (int run = 0; run < kRuns; ++run) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < kCalls; ++i) call();
        const std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
        result = std::min(result, elapsed.count() / kCalls);
    }
    return result;
}

}  // namespace

int main(int argc, char** argv) {
    StaticWorld world;
    Plane floor;
    floor.normal = Vec3(0, 1, 0);
    floor.distance = 0;
    OrientedBox wall;
    wall.center = RVec3(0, 1.5f, 10);
    wall.halfExtents = Vec3(5, 1.5f, 0.25f);
    if (world.add(floor) != Status::Ok || world.add(wall) != Status::Ok) return 1;
    ProjectileSettings settings;
    settings.restitution = 0.5f;
    settings.friction = 0.4f;
    settings.radius = 0.05f;
    settings.method = ProjectileMethod::Exact;
    const std::size_t capacity = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : trajectoryCapacity(3.0f, settings);
    if (capacity == 0) return 1;
    std::vector<TrajectoryPoint> trajectory(capacity);
    ProjectileResult result;
    const double cpp = best([&] {
        if (predictProjectile(RVec3(0, 1.6f, 0), Vec3(0, 4, 12), 3.0f, settings, &world, trajectory, result) !=
            Status::Ok)
            std::abort();
    });

    fs_world* cWorld = fs_world_create();
    const fs_plane cFloor = {{0.0f, 1.0f, 0.0f}, 0.0f, 0.0};
    const fs_box cWall = {{0.0, 1.5f, 10.0}, {5.0f, 1.5f, 0.25f}, {0.0f, 0.0f, 0.0f, 1.0f}, 0.0f};
    if (cWorld == nullptr || fs_world_add_plane(cWorld, &cFloor, nullptr) != FS_STATUS_OK ||
        fs_world_add_box(cWorld, &cWall, nullptr) != FS_STATUS_OK)
        return 1;
    fs_projectile_settings cSettings = fs_projectile_settings_default();
    cSettings.restitution = 0.5f;
    cSettings.friction = 0.4f;
    cSettings.radius = 0.05f;
    cSettings.method = FS_METHOD_EXACT;
    std::vector<fs_trajectory_point> points(capacity);
    fs_projectile_result cResult;
    const double c = best([&] {
        if (fs_predict_projectile(fs_dvec3{0.0, 1.6f, 0.0}, fs_vec3{0.0f, 4.0f, 12.0f}, 3.0f, &cSettings, cWorld,
                                  points.data(), points.size(), &cResult) != FS_STATUS_OK)
            std::abort();
    });
    fs_world_destroy(cWorld);
    std::printf("cpp_ns %.1f\nc_api_ns %.1f\n", cpp, c);
    return 0;
}
