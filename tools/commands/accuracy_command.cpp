#include "accuracy_command.h"

#include <foresight/foresight.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace foresight_cli {
namespace {

using foresight::RVec3;
using foresight::Vec3;

const foresight::StaticWorld& floorWorld() {
    static const foresight::StaticWorld world = [] {
        foresight::StaticWorld w;
        w.add(foresight::Plane{Vec3(0.0f, 1.0f, 0.0f), 0.0f});
        return w;
    }();
    return world;
}

double distance(const RVec3& a, const RVec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

void vehicleTable() {
    std::printf("### Vehicle: the article's loop against the exact arc\n\n");
    std::printf("10 m/s forward (+Z), turning at 0.5 rad/s about +Y, predicted 2 s ahead (1 rad of turn).\n\n");
    foresight::VehicleState start;
    start.velocity = Vec3(0.0f, 0.0f, 10.0f);
    start.angularVelocity = Vec3(0.0f, 0.5f, 0.0f);
    foresight::VehicleState exact;
    foresight::predictVehicleExact(start, 2.0f, {}, exact);
    std::printf("| iterations N | loop position (x, z) m | distance to the exact arc (m) |\n|---:|---|---:|\n");
    for (int n : {1, 2, 4, 8, 16, 64, 256}) {
        foresight::VehicleState loop;
        foresight::predictVehicleIterative(start, 2.0f, n, {}, loop);
        std::printf("| %d | (%.3f, %.3f) | %.3f |\n", n, static_cast<double>(loop.position.x),
                    static_cast<double>(loop.position.z), distance(loop.position, exact.position));
    }
    std::printf("| exact | (%.3f, %.3f) | 0 |\n\n", static_cast<double>(exact.position.x),
                static_cast<double>(exact.position.z));
    // Closed form of the circle: radius v / w = 20 m, turned 1 rad.
    const double radius = 20.0;
    std::printf("Closed form of the circle (radius 20 m, 1 rad): (%.3f, %.3f); the exact method is %.2g m from it.\n\n",
                radius * (1.0 - std::cos(1.0)), radius * std::sin(1.0),
                std::hypot(static_cast<double>(exact.position.x) - radius * (1.0 - std::cos(1.0)),
                           static_cast<double>(exact.position.z) - radius * std::sin(1.0)));
}

// Position at time T of a point thrown at a wall (plane z = distance facing -Z, no floor) from
// the origin at 1.5 m height with velocity (0, 0, speed): closed form, restitution e.
RVec3 wallClosedForm(double distance, double speed, double e, double T) {
    const double t0 = distance / speed;
    const double z = T <= t0 ? speed * T : distance - e * speed * (T - t0);
    return RVec3(0.0f, static_cast<float>(1.5 - 0.5 * 9.81 * T * T), static_cast<float>(z));
}

// Height at time T of a point dropped from `height` onto the floor y = 0: closed form.
double dropClosedForm(double height, double e, double T) {
    const double g = 9.81;
    double t = std::sqrt(2.0 * height / g);
    if (T <= t) return height - 0.5 * g * T * T;
    double v = g * t;
    while (true) {
        const double up = e * v, hop = 2.0 * up / g;
        if (t + hop > T || hop < 1e-12) {
            const double s = T - t;
            return hop < 1e-12 ? 0.0 : up * s - 0.5 * g * s * s;
        }
        t += hop;
        v = up;
    }
}

struct ErrorStats {
    double mean = 0, max = 0;
    int count = 0;
    void add(double x) {
        mean += (x - mean) / ++count;
        max = std::max(max, x);
    }
};

void projectileTable() {
    std::printf("### Projectile: the article's stepped loop against the exact method\n\n");
    std::printf(
        "Restitution 0.5, gravity 9.81 m/s^2, no friction. Errors are distances to the closed-form\n"
        "bounce sequence on planes at the end time, over 201 evenly spaced cases each.\n\n");
    std::printf(
        "| case | step (s) | article: mean error (m) | article: max (m) | exact: max (m) |\n"
        "|---|---:|---:|---:|---:|\n");
    std::vector<foresight::TrajectoryPoint> points(4096);
    for (float step : {0.02f, 0.01f, 0.005f}) {
        ErrorStats stepped, exact;
        for (int i = 0; i <= 200; ++i) {
            const double wallDistance = 4.0 + 0.01 * i;
            foresight::StaticWorld wall;
            wall.add(foresight::Plane{Vec3(0.0f, 0.0f, -1.0f), static_cast<foresight::Real>(-wallDistance)});
            const RVec3 expected = wallClosedForm(wallDistance, 12.0, 0.5, 1.0);
            foresight::ProjectileSettings settings;
            settings.step = step;
            for (auto method : {foresight::ProjectileMethod::Stepped, foresight::ProjectileMethod::Exact}) {
                settings.method = method;
                foresight::ProjectileResult result;
                foresight::predictProjectile(RVec3(0.0f, 1.5f, 0.0f), Vec3(0.0f, 0.0f, 12.0f), 1.0f, settings, &wall,
                                             points, result);
                (method == foresight::ProjectileMethod::Stepped ? stepped : exact)
                    .add(distance(result.position, expected));
            }
        }
        std::printf("| thrown at 12 m/s at a wall 4 to 6 m away, 1 s | %.3f | %.3f | %.3f | %.1e |\n",
                    static_cast<double>(step), stepped.mean, stepped.max, exact.max);
    }
    for (float step : {0.02f, 0.01f, 0.005f}) {
        ErrorStats stepped, exact;
        for (int i = 0; i <= 200; ++i) {
            const double height = 0.5 + 0.005 * i;
            const RVec3 expected(2.0f, static_cast<float>(dropClosedForm(height, 0.5, 1.0)), 0.0f);
            foresight::ProjectileSettings settings;
            settings.step = step;
            for (auto method : {foresight::ProjectileMethod::Stepped, foresight::ProjectileMethod::Exact}) {
                settings.method = method;
                foresight::ProjectileResult result;
                foresight::predictProjectile(RVec3(0.0f, static_cast<float>(height), 0.0f), Vec3(2.0f, 0.0f, 0.0f),
                                             1.0f, settings, &floorWorld(), points, result);
                (method == foresight::ProjectileMethod::Stepped ? stepped : exact)
                    .add(distance(result.position, expected));
            }
        }
        std::printf("| dropped from 0.5 to 1.5 m, 2 m/s sideways, 1 s | %.3f | %.3f | %.3f | %.1e |\n",
                    static_cast<double>(step), stepped.mean, stepped.max, exact.max);
    }
    std::printf("\n");
    const foresight::StaticWorld& floor = floorWorld();

    // Resting and sliding contact: dropped from 1 m with 2 m/s sideways onto the floor, 3 s.
    std::printf(
        "Contact: dropped from 1 m with 2 m/s sideways onto the floor, restitution 0.5, 3 s.\n"
        "Closed form: the bounces end at t = 1.355 s; without friction it then slides on, to x = 6 m.\n\n");
    std::printf(
        "| friction | method | final x (m) | final y (m) | final speed (m/s) | at rest |\n"
        "|---:|---|---:|---:|---:|---|\n");
    for (float friction : {0.0f, 0.5f}) {
        for (auto method : {foresight::ProjectileMethod::Stepped, foresight::ProjectileMethod::Exact}) {
            foresight::ProjectileSettings settings;
            settings.method = method;
            settings.friction = friction;
            foresight::ProjectileResult result;
            foresight::predictProjectile(RVec3(0.0f, 1.0f, 0.0f), Vec3(2.0f, 0.0f, 0.0f), 3.0f, settings, &floor,
                                         points, result);
            std::printf("| %.1f | %s | %.4f | %.1e | %.4f | %s |\n", static_cast<double>(friction),
                        method == foresight::ProjectileMethod::Stepped ? "article (stepped)" : "exact",
                        static_cast<double>(result.position.x), static_cast<double>(result.position.y),
                        static_cast<double>(glm::length(result.velocity)), result.atRest ? "yes" : "no");
        }
    }
    std::printf("\n");
}

}  // namespace

int accuracyCommand() {
    vehicleTable();
    projectileTable();
    return 0;
}

}  // namespace foresight_cli
