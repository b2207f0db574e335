// The per-frame calls never allocate: global operator new/delete are replaced (in this binary
// only) by counting versions; after the StaticWorld is built and the trajectory storage is
// reserved, every prediction and cast must leave the count unchanged.

#include "counting_allocator.h"
#include "test_util.h"

#include <atomic>
#include <cstdlib>
#include <functional>
#include <new>
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

// The sanity check's pointers escape through these volatile sinks, so the compiler may not
// elide its allocations (new/delete pairs may be optimised away since C++14).
int* volatile intSink = nullptr;
double* volatile vectorSink = nullptr;

/// Allocations made while running `f` (f must not use gtest assertions that allocate).
template <class F>
long allocationsDuring(F&& f) {
    const long before = ftest::gAllocations.load();
    f();
    return ftest::gAllocations.load() - before;
}

class Allocation : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_EQ(world.add(foresight::Plane{Vec3(0.0f, 1.0f, 0.0f), Real(0)}), Status::Ok);
        ASSERT_EQ(world.add(foresight::Plane{Vec3(0.0f, 0.0f, -1.0f), Real(-10)}), Status::Ok);
        ASSERT_EQ(world.add(foresight::Sphere{rv(0.0, 0.5, 5.0), 1.0f}), Status::Ok);
        ASSERT_EQ(world.add(foresight::OrientedBox{rv(2.0, 1.0, 7.0), Vec3(1.0f, 1.0f, 0.5f),
                                                   glm::angleAxis(0.4f, Vec3(0.0f, 1.0f, 0.0f))}),
                  Status::Ok);
        ASSERT_EQ(world.add(foresight::Triangle{rv(-3, 0, 2), rv(3, 2, 3), rv(0, 0, 4)}), Status::Ok);
        points.resize(4096);
    }

    StaticWorld world;
    std::vector<TrajectoryPoint> points;
};

TEST_F(Allocation, CounterCountsAllocations) {
    // The replacement is in effect (otherwise every check below would pass vacuously).
    const long n = allocationsDuring([] {
        intSink = new int(3);
        delete intSink;
        std::vector<double> v(100);
        vectorSink = v.data();
    });
    EXPECT_EQ(n, 2);
}

TEST_F(Allocation, CharacterOrientationVehicleDoNotAllocate) {
    foresight::PointState character;
    character.velocity = Vec3(1.0f, 2.0f, 3.0f);
    foresight::PointState outCharacter;
    foresight::VehicleState vehicle;
    vehicle.velocity = Vec3(0.0f, 0.0f, 10.0f);
    vehicle.angularVelocity = Vec3(0.0f, 0.5f, 0.0f);
    foresight::VehicleState outVehicle;
    foresight::VehicleSettings settings;
    foresight::Quat q;
    Status s[8] = {};
    const long n = allocationsDuring([&] {
        s[0] = foresight::predictLinear(character, 0.5f, outCharacter);
        s[1] = foresight::predictAccelerated(character, Vec3(0.0f, -9.81f, 0.0f), 0.5f, outCharacter);
        s[2] = foresight::predictOrientation(glm::identity<foresight::Quat>(), Vec3(0.0f, 0.25f, 0.0f),
                                             AngularFrame::Body, 2.0f, q);
        s[3] = foresight::predictVehicleExact(vehicle, 2.0f, settings, outVehicle);
        s[4] = foresight::predictVehicleIterative(vehicle, 2.0f, 4, settings, outVehicle);
        s[5] = foresight::predictVehicleIterative(vehicle, 2.0f, 1000, settings, outVehicle);
        s[6] = foresight::predictLinear(character, -1.0f, outCharacter);  // a refusal
        s[7] = foresight::Status::Ok;
        (void)foresight::statusMessage(s[6]);
    });
    EXPECT_EQ(n, 0);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(s[i], Status::Ok) << i;
    EXPECT_EQ(s[6], Status::NegativeTime);
}

TEST_F(Allocation, ProjectilesDoNotAllocate) {
    for (const ProjectileMethod method : {ProjectileMethod::Exact, ProjectileMethod::Stepped}) {
        for (const float radius : {0.0f, 0.2f}) {
            ProjectileSettings settings;
            settings.method = method;
            settings.radius = radius;
            settings.friction = 0.3f;
            ProjectileResult result;
            ProjectileResult truncated;
            ProjectileResult free;
            Status s[3] = {};
            const long n = allocationsDuring([&] {
                s[0] = foresight::predictProjectile(rv(0, 1.5, 0), Vec3(0.5f, 4.0f, 12.0f), 3.0f, settings, &world,
                                                    points, result);
                s[1] = foresight::predictProjectile(rv(0, 1.5, 0), Vec3(0.5f, 4.0f, 12.0f), 3.0f, settings, &world,
                                                    std::span<TrajectoryPoint>(points.data(), 3), truncated);
                s[2] = foresight::predictProjectile(rv(0, 1.5, 0), Vec3(0.5f, 4.0f, 12.0f), 3.0f, settings, nullptr, {},
                                                    free);
            });
            EXPECT_EQ(n, 0) << "method " << static_cast<int>(method) << " radius " << radius;
            for (const Status st : s) EXPECT_EQ(st, Status::Ok);
            EXPECT_GT(result.bounces, 0u);  // the call did real work
        }
    }
}

TEST_F(Allocation, RestingAndCallbackWorldDoNotAllocate) {
    // Contact handling (sliding, rest) and a user CallbackWorld.
    const foresight::CollisionWorld& base = world;
    auto forward = [&base](const foresight::SegmentCast& cast, foresight::CastHit& hit) {
        return base.castSegment(cast, hit);
    };
    const foresight::CallbackWorld callbackWorld = foresight::CallbackWorld::wrap(forward);
    ProjectileSettings settings;
    settings.friction = 0.5f;
    ProjectileResult result;
    Status s = Status::NonFiniteInput;
    const long n = allocationsDuring([&] {
        s = foresight::predictProjectile(rv(0, 1, 0), Vec3(2.0f, 0.0f, 0.0f), 3.0f, settings, &callbackWorld, points,
                                         result);
    });
    EXPECT_EQ(n, 0);
    EXPECT_EQ(s, Status::Ok);
    EXPECT_TRUE(result.atRest);
}

TEST_F(Allocation, StaticWorldCastsDoNotAllocate) {
    int hits = 0;
    const long n = allocationsDuring([&] {
        for (int i = 0; i < 200; ++i) {
            foresight::SegmentCast cast;
            cast.origin = rv(-4.0 + 0.04 * i, 6.0, 0.05 * i);
            cast.displacement = Vec3(0.1f, -10.0f, 0.2f);
            cast.radius = (i % 2 == 0) ? 0.0f : 0.3f;
            foresight::CastHit hit;
            hits += world.castSegment(cast, hit) ? 1 : 0;
        }
    });
    EXPECT_EQ(n, 0);
    EXPECT_EQ(hits, 200);  // every cast reaches at least the floor
}

TEST_F(Allocation, ReplicationDoesNotAllocate) {
    // Sender, receivers in every smoothing and in Interpolate mode (past the ring's capacity, so
    // that it wraps), bad packets, and the batch.
    using foresight::DeadReckoningState;
    using foresight::ReceivedPose;
    using foresight::ReceiverSettings;
    DeadReckoningState state;
    state.algorithm = foresight::DeadReckoningAlgorithm::Rvw;
    state.velocity = Vec3(3.0f, 0.0f, 1.0f);
    state.acceleration = Vec3(0.0f, -1.0f, 0.0f);
    state.angularVelocity = Vec3(0.0f, 0.4f, 0.0f);
    DeadReckoningState bad = state;
    bad.orientation = glm::identity<foresight::Quat>() * 0.0f;
    foresight::DeadReckoningSender sender;
    ReceiverSettings settings[5];
    settings[1].smoothing = foresight::Smoothing::LinearBlend;
    settings[2].smoothing = foresight::Smoothing::ExponentialDecay;
    settings[3].smoothing = foresight::Smoothing::Snap;
    settings[4].mode = foresight::ReceiverMode::Interpolate;
    std::vector<foresight::DeadReckoningReceiver> receivers(settings, settings + 5);
    std::vector<DeadReckoningState> states(64, state);
    std::vector<double> stamps(64, 0.5);
    std::vector<foresight::DeadReckoningResult> results(64);
    // The prepared forms: built (and the batch allocated) before counting.
    std::vector<foresight::PreparedDeadReckoning> prepared(64);
    foresight::DeadReckoningBatch batch(64);
    for (std::size_t i = 0; i < prepared.size(); ++i) {
        DeadReckoningState s = state;
        s.algorithm = static_cast<foresight::DeadReckoningAlgorithm>(1 + i % 9);
        ASSERT_EQ(foresight::prepareDeadReckoning(s, 0.5, prepared[i]), Status::Ok);
        ASSERT_EQ(batch.set(i, prepared[i]), Status::Ok);
    }
    std::size_t preparedRefused = 0;
    int sent = 0;
    int shown = 0;
    std::size_t refused = 0;
    const long n = allocationsDuring([&] {
        for (int k = 0; k < 200; ++k) {
            const double t = k / 60.0;
            DeadReckoningState truth = state;
            truth.position = rv(3.0 * t, -0.5 * t * t, 1.0 * t + 0.1 * (k % 7));
            foresight::SendDecision decision;
            if (sender.update(t, truth, decision) == Status::Ok && decision.send()) ++sent;
            if (decision.send() || k % 2 == 0) {  // every other tick: the ring wraps
                for (foresight::DeadReckoningReceiver& r : receivers) {
                    (void)r.receive(t, truth, t + 0.05);
                    (void)r.receive(t, truth, t + 0.05);  // duplicate
                    (void)r.receive(t, bad, t + 0.05);    // invalid
                }
            }
            for (foresight::DeadReckoningReceiver& r : receivers) {
                ReceivedPose pose;
                if (r.sample(t, pose) == Status::Ok) ++shown;
            }
        }
        refused = foresight::predictDeadReckoningBatch(states, stamps, 1.0, results);
        preparedRefused += foresight::extrapolateDeadReckoning(prepared, 1.0, 0.25f, results);
        preparedRefused += batch.extrapolate(1.0, 0.25f, results);
        // set() moves entities in and out of the body-axis list: no allocation either.
        preparedRefused += batch.set(3, prepared[0]) == Status::Ok ? 0u : 1u;
        preparedRefused += batch.set(0, prepared[7]) == Status::Ok ? 0u : 1u;
        preparedRefused += batch.extrapolate(2.0, 0.25f, results);
    });
    EXPECT_EQ(n, 0);
    EXPECT_GT(sent, 10);
    EXPECT_GT(shown, 900);
    EXPECT_EQ(refused, 0u);
    EXPECT_EQ(preparedRefused, 0u);
}

}  // namespace
