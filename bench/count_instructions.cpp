/// count_instructions.cpp: runs one method on the benchmark's throws a fixed number of times,
/// to be run under `valgrind --tool=callgrind`: instruction counts are repeatable on a shared,
/// noisy machine where times are not. scripts/bench.sh --instructions runs the pairs and prints
/// the ratios.
///
///   foresight_count_instructions projectile-stepped|projectile-exact|vehicle-iterative4|vehicle-exact [friction]

#include "bench_scenes.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using namespace foresight_bench;
    if (argc < 2) {
        std::fprintf(stderr,
                     "usage: %s projectile-stepped|projectile-exact|vehicle-iterative4|vehicle-exact [friction]\n",
                     argv[0]);
        return 2;
    }
    const std::string what = argv[1];
    const float friction = argc > 2 ? std::strtof(argv[2], nullptr) : 0.0f;
    constexpr int kRounds = 20;
    double checksum = 0.0;
    if (what == "projectile-stepped" || what == "projectile-exact") {
        const StaticWorld world = makeArena();
        const auto throws = makeThrows();
        ProjectileSettings settings;
        settings.method = what == "projectile-exact" ? ProjectileMethod::Exact : ProjectileMethod::Stepped;
        settings.step = kStep;
        settings.friction = friction;
        std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(kFuse, settings, 256));
        for (int round = 0; round < kRounds; ++round)
            for (const Throw& t : throws) {
                ProjectileResult result;
                if (predictProjectile(t.position, t.velocity, kFuse, settings, &world, trajectory, result) !=
                    Status::Ok)
                    return 1;
                checksum += static_cast<double>(result.position.x);
            }
    } else if (what == "vehicle-iterative4" || what == "vehicle-exact") {
        const auto vehicles = makeVehicles();
        for (int round = 0; round < kRounds * 100; ++round)
            for (const VehicleState& vehicle : vehicles) {
                VehicleState out;
                const Status status = what == "vehicle-exact"
                                          ? predictVehicleExact(vehicle, kDriveTime, {}, out)
                                          : predictVehicleIterative(vehicle, kDriveTime, 4, {}, out);
                if (status != Status::Ok) return 1;
                checksum += static_cast<double>(out.position.x);
            }
    } else {
        std::fprintf(stderr, "unknown case '%s'\n", what.c_str());
        return 2;
    }
    std::printf("%.6f\n", checksum);  // keeps the work observable
    return 0;
}
