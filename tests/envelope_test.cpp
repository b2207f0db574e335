// The precision envelope (config.h: kMaxCoordinate, kMaxSpeed). Inside it, a throw far from the
// origin ends where the same throw ends at the origin, moved (within what the envelope
// documents for this build's position type); beyond it, predictions are refused. Built in both
// precisions (foresight_envelope_tests, foresight_envelope_double_tests).
#include "test_util.h"

#include <foresight/engine_profile.h>
#include <foresight/projectile.h>
#include <foresight/static_world.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using foresight::ProjectileMethod;
using foresight::ProjectileSettings;
using foresight::Real;
using foresight::RVec3;
using foresight::StaticWorld;
using foresight::Status;
using foresight::TrajectoryPoint;
using foresight::Vec3;
using ftest::DVec3;

using ftest::rv;

// The largest power of two at most half the envelope: exactly representable, so the shifted
// start is exactly the start moved.
double farOffset() { return std::exp2(std::floor(std::log2(0.5 * foresight::kMaxCoordinate))); }

struct Flight {
    Status status = Status::Ok;
    DVec3 end{0.0};
};

Flight throwAt(double x, ProjectileMethod method, bool scene, float time = 3.0f, Vec3 velocity = Vec3(0, 5, 12)) {
    StaticWorld world;
    if (scene) {
        EXPECT_EQ(world.add(foresight::Plane{Vec3(0, 1, 0), Real(0)}), Status::Ok);
        foresight::OrientedBox box;
        box.center = rv(x, 1, 20);
        box.halfExtents = Vec3(3, 3, 1);
        EXPECT_EQ(world.add(box), Status::Ok);
    }
    ProjectileSettings settings;
    settings.method = method;
    settings.restitution = 0.5f;
    settings.friction = 0.2f;
    settings.radius = 0.1f;
    settings.engine = foresight::engineProfile(foresight::PhysicsEngine::Jolt);
    std::vector<TrajectoryPoint> points(foresight::trajectoryCapacity(time, settings, 256));
    foresight::ProjectileResult result;
    Flight run;
    run.status = foresight::predictProjectile(rv(x, 1, 0), velocity, time, settings, &world, points, result);
    run.end = ftest::toD(result.position) - DVec3(x, 0, 0);
    return run;
}

const ProjectileMethod kMethods[] = {ProjectileMethod::Exact, ProjectileMethod::Stepped, ProjectileMethod::Engine};

}  // namespace

TEST(Envelope, FreeFlightFarFromTheOriginIsTheFlightAtTheOriginMoved) {
    const double x = farOffset();
    for (const ProjectileMethod method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        const Flight near = throwAt(0.0, method, false), far = throwAt(x, method, false);
        ASSERT_EQ(near.status, Status::Ok);
        ASSERT_EQ(far.status, Status::Ok);
        // y and z do not mix with x in free flight: the same numbers; x rounds to the position
        // type once (half an ulp of the offset).
        EXPECT_EQ(far.end.y, near.end.y);
        EXPECT_EQ(far.end.z, near.end.z);
        EXPECT_NEAR(far.end.x, near.end.x, 0.5 * x * static_cast<double>(std::numeric_limits<Real>::epsilon()));
    }
}

TEST(Envelope, BouncesFarFromTheOriginInDoubleBuilds) {
    if (!foresight::kDoublePrecision) GTEST_SKIP() << "float positions: the envelope documents their rounding";
    const double x = farOffset();  // 2^26 m
    for (const ProjectileMethod method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        const Flight near = throwAt(0.0, method, true), far = throwAt(x, method, true);
        ASSERT_EQ(near.status, Status::Ok);
        ASSERT_EQ(far.status, Status::Ok);
        // The envelope's promise for double builds: about 2e-14 |x| of rounding (1.3e-6 m at
        // 2^26 m) after bounces off the floor and the box: 1e-5 m.
        EXPECT_NEAR(far.end.x, near.end.x, 1e-5);
        EXPECT_NEAR(far.end.y, near.end.y, 1e-5);
        EXPECT_NEAR(far.end.z, near.end.z, 1e-5);
    }
}

TEST(Envelope, BeyondItIsRefused) {
    const double edge = foresight::kMaxCoordinate;
    for (const ProjectileMethod method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        // At 1e16 m a throw along +z ended at z = -52.8 instead of 36 before the envelope existed.
        EXPECT_EQ(throwAt(1e16, method, true).status, Status::OutOfRange);
        EXPECT_EQ(throwAt(2.0 * edge, method, false).status, Status::OutOfRange);
        EXPECT_EQ(throwAt(0.0, method, false, 3.0f, Vec3(0, 0, 2e6f)).status, Status::OutOfRange);
        // A flight that leaves it (the start is inside): 1e6 m/s for long enough. (Jolt caps
        // speeds at 500 m/s: its flight stays inside.)
        if (method == ProjectileMethod::Engine) continue;
        const float leaving = static_cast<float>(2.0 * edge / 1e6);
        EXPECT_EQ(throwAt(0.0, method, false, leaving, Vec3(1e6f, 0, 0)).status, Status::OutOfRange);
        const float staying = static_cast<float>(0.25 * edge / 1e6);
        EXPECT_EQ(throwAt(0.0, method, false, staying, Vec3(1e6f, 0, 0)).status, Status::Ok);
    }
}
