// Determinism: a fixed scenario (projectiles with bounces in a world of every shape kind, both
// methods; vehicles, both methods; orientations; characters) run twice, and on another thread,
// gives bit-identical output. The hash is printed for information (it may differ between
// compilers and platforms; within one build it must not change between runs).

#include "test_util.h"

#include <cinttypes>
#include <cmath>
#include <string>
#include <cstdio>
#include <thread>
#include <vector>

namespace {

using foresight::AngularFrame;
using foresight::ProjectileMethod;
using foresight::ProjectileResult;
using foresight::ProjectileSettings;
using foresight::Real;
using foresight::RVec3;
using foresight::StaticWorld;
using foresight::Status;
using foresight::TrajectoryPoint;
using foresight::Vec3;

using ftest::rv;

void buildWorld(StaticWorld& world) {
    EXPECT_EQ(world.add(foresight::Plane{Vec3(0.0f, 1.0f, 0.0f), Real(0)}), Status::Ok);
    EXPECT_EQ(world.add(foresight::Plane{Vec3(0.0f, 0.0f, -1.0f), Real(-12)}), Status::Ok);
    EXPECT_EQ(world.add(foresight::Plane{glm::normalize(Vec3(1.0f, 0.2f, 0.0f)), Real(-6)}), Status::Ok);
    EXPECT_EQ(world.add(foresight::Sphere{rv(1.0, 0.5, 6.0), 1.2f}), Status::Ok);
    EXPECT_EQ(world.add(foresight::OrientedBox{rv(-2.0, 1.0, 8.0), Vec3(1.0f, 1.0f, 0.5f),
                                               glm::angleAxis(0.7f, glm::normalize(Vec3(0.3f, 1.0f, 0.2f)))}),
              Status::Ok);
    EXPECT_EQ(world.add(foresight::Triangle{rv(-3.0, 0.0, 3.0), rv(3.0, 3.0, 4.0), rv(0.0, 0.0, 5.0)}), Status::Ok);
}

void hashPoints(ftest::Hasher& h, const std::vector<TrajectoryPoint>& points, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
        h.add(points[k].time);
        h.add(static_cast<std::uint64_t>(points[k].event));
        h.add(points[k].position);
        h.add(points[k].velocity);
        h.add(points[k].normal);
    }
}

/// Runs the whole scenario; returns the hash and fills `floats` with every output float.
std::uint64_t runScenario(std::vector<double>& outputs) {
    ftest::Hasher h;
    StaticWorld world;
    buildWorld(world);
    std::vector<TrajectoryPoint> points(4096);
    std::uint32_t bounces = 0;
    for (int i = 0; i < 24; ++i) {
        ProjectileSettings settings;
        settings.method = (i % 2 == 0) ? ProjectileMethod::Exact : ProjectileMethod::Stepped;
        settings.restitution = 0.2f + 0.1f * static_cast<float>(i % 7);
        settings.friction = 0.1f * static_cast<float>(i % 4);
        settings.radius = (i % 3 == 0) ? 0.0f : 0.05f * static_cast<float>(i % 5 + 1);
        // Inputs from exact arithmetic only (no libm calls, which a compiler may constant-fold
        // with a different rounding than the runtime library).
        const float f = static_cast<float>(i % 9) - 4.0f;
        const Vec3 velocity(0.75f * f, 4.0f + 0.25f * static_cast<float>(i), 9.0f - 0.5f * f);
        ProjectileResult result;
        EXPECT_EQ(foresight::predictProjectile(rv(0.1 * i, 1.5, 0.0), velocity, 4.0f, settings, &world, points, result),
                  Status::Ok);
        bounces += result.bounces;
        h.add(result);
        hashPoints(h, points, result.trajectorySize);
        for (std::size_t k = 0; k < result.trajectorySize; ++k) {
            outputs.push_back(static_cast<double>(points[k].position.x));
            outputs.push_back(static_cast<double>(points[k].position.y));
            outputs.push_back(static_cast<double>(points[k].position.z));
        }
    }
    EXPECT_GT(bounces, 40u);  // the scenario exercises bounces
    for (int i = 0; i < 8; ++i) {
        foresight::VehicleState start;
        start.position = rv(i, 0.0, -i);
        start.orientation = glm::angleAxis(0.3f * static_cast<float>(i), glm::normalize(Vec3(0.1f, 1.0f, 0.2f)));
        start.velocity = start.orientation * Vec3(0.0f, 0.0f, 5.0f + static_cast<float>(i));
        start.angularVelocity = Vec3(0.05f * static_cast<float>(i), 0.4f, -0.1f);
        foresight::VehicleSettings settings;
        settings.frame = (i % 2 == 0) ? AngularFrame::Body : AngularFrame::World;
        foresight::VehicleState exact;
        foresight::VehicleState iterative;
        EXPECT_EQ(foresight::predictVehicleExact(start, 2.5f, settings, exact), Status::Ok);
        EXPECT_EQ(foresight::predictVehicleIterative(start, 2.5f, 4 + i, settings, iterative), Status::Ok);
        for (const foresight::VehicleState* s : {&exact, &iterative}) {
            h.add(s->position);
            h.add(s->velocity);
            h.add(s->orientation);
            outputs.push_back(static_cast<double>(s->position.x));
            outputs.push_back(static_cast<double>(s->position.z));
        }
        foresight::Quat q;
        EXPECT_EQ(foresight::predictOrientation(start.orientation, start.angularVelocity, settings.frame, 1.7f, q),
                  Status::Ok);
        h.add(q);
        foresight::PointState character;
        character.position = start.position;
        character.velocity = start.velocity;
        foresight::PointState predicted;
        EXPECT_EQ(foresight::predictAccelerated(character, Vec3(0.5f, -1.0f, 0.25f), 0.8f, predicted), Status::Ok);
        h.add(predicted.position);
        h.add(predicted.velocity);
    }
    return h.value();
}

TEST(Determinism, SameScenarioGivesBitIdenticalResults) {
    std::vector<double> first;
    std::vector<double> second;
    const std::uint64_t a = runScenario(first);
    const std::uint64_t b = runScenario(second);
    std::printf("[ determinism ] scenario hash %016" PRIx64 " (%zu output positions)\n", a, first.size());
    ::testing::Test::RecordProperty("scenario_hash", std::to_string(a));
    EXPECT_EQ(a, b);
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)), 0);
}

TEST(Determinism, ConcurrentThreadsGiveTheSameHash) {
    std::vector<double> reference;
    const std::uint64_t expected = runScenario(reference);
    std::uint64_t hashes[2] = {0, 0};
    std::vector<double> outputs[2];
    std::thread worker([&] { hashes[1] = runScenario(outputs[1]); });
    hashes[0] = runScenario(outputs[0]);
    worker.join();
    EXPECT_EQ(hashes[0], expected);
    EXPECT_EQ(hashes[1], expected);
}

TEST(Determinism, HashCoversTheOutput) {
    // The hash must react to a single bit of any output (else the tests above cannot fail).
    ftest::Hasher h1;
    ftest::Hasher h2;
    h1.add(1.0f);
    h2.add(std::nextafter(1.0f, 2.0f));
    EXPECT_NE(h1.value(), h2.value());
}

}  // namespace
