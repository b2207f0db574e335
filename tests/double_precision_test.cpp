// Double-precision positions (built against foresight_double, FORESIGHT_DOUBLE_PRECISION):
// geocentric-scale coordinates (6.4e6 m, where a float's spacing is 0.5 m) keep sub-micrometre
// resolution, and predictions far from the origin match the same predictions at the origin.

#include "test_util.h"

#include <vector>

static_assert(sizeof(foresight::Real) == 8, "this test is built against the double-precision library");
static_assert(foresight::kDoublePrecision, "kDoublePrecision must be true in the double build");
static_assert(sizeof(foresight::RVec3) == 24, "RVec3 holds three doubles");
static_assert(sizeof(foresight::Vec3) == 12, "everything but positions stays float");

namespace {

using foresight::ProjectileMethod;
using foresight::ProjectileResult;
using foresight::ProjectileSettings;
using foresight::RVec3;
using foresight::StaticWorld;
using foresight::Status;
using foresight::TrajectoryPoint;
using foresight::Vec3;
using ftest::DVec3;

constexpr double kEarth = 6.4e6;  // [m], about the Earth's radius

TEST(DoublePrecision, CharacterAtGeocentricScaleResolvesMicrometres) {
    foresight::PointState start;
    start.position = RVec3(kEarth, -kEarth * 0.5, 1234.5);
    start.velocity = Vec3(0.01f, 0.0f, 0.0f);  // 0.01 m in 1 s: 1/50 of a float's spacing at 6.4e6
    foresight::PointState out;
    ASSERT_EQ(foresight::predictLinear(start, 1.0f, out), Status::Ok);
    // double positions at 6.4e6 m have a spacing of 9.3e-10 m; the float velocity 0.01f is
    // 0.01 to 2.2e-10 m/s. 1e-6 m, the bar here, is 1000 spacings.
    EXPECT_NEAR(out.position.x - kEarth, static_cast<double>(0.01f), 1e-6);
    EXPECT_NE(out.position.x, start.position.x);  // it moved at all (a float position would not)
    EXPECT_EQ(out.position.y, start.position.y);
    ASSERT_EQ(foresight::predictAccelerated(start, Vec3(0.0f, 0.02f, 0.0f), 1.0f, out), Status::Ok);
    EXPECT_NEAR(out.position.x - kEarth, static_cast<double>(0.01f), 1e-6);
    EXPECT_NEAR(out.position.y - (-kEarth * 0.5), 0.5 * static_cast<double>(0.02f), 1e-6);
}

TEST(DoublePrecision, VehicleFarFromTheOriginMatchesTheOrigin) {
    foresight::VehicleState near;
    near.velocity = Vec3(0.0f, 0.0f, 10.0f);
    near.angularVelocity = Vec3(0.0f, 0.5f, 0.0f);
    foresight::VehicleState far = near;
    far.position = RVec3(kEarth, 0.0, kEarth);
    foresight::VehicleSettings settings;
    for (const bool exact : {true, false}) {
        foresight::VehicleState a;
        foresight::VehicleState b;
        if (exact) {
            ASSERT_EQ(foresight::predictVehicleExact(near, 2.0f, settings, a), Status::Ok);
            ASSERT_EQ(foresight::predictVehicleExact(far, 2.0f, settings, b), Status::Ok);
        } else {
            ASSERT_EQ(foresight::predictVehicleIterative(near, 2.0f, 16, settings, a), Status::Ok);
            ASSERT_EQ(foresight::predictVehicleIterative(far, 2.0f, 16, settings, b), Status::Ok);
        }
        // Relative displacement identical up to double rounding at 6.4e6 (9.3e-10 m per step).
        EXPECT_VEC_NEAR(b.position - far.position, a.position - near.position, 1e-6) << exact;
    }
}

struct Points {
    Status status;
    ProjectileResult result;
    std::vector<TrajectoryPoint> points;
};

Points throwOnPlane(double planeDistance, const RVec3& start, const Vec3& velocity, ProjectileMethod method,
                    float radius) {
    StaticWorld world;
    EXPECT_EQ(world.add(foresight::Plane{Vec3(0.0f, 1.0f, 0.0f), planeDistance}), Status::Ok);
    EXPECT_EQ(world.add(foresight::Plane{Vec3(0.0f, 0.0f, -1.0f), -(start.z + 9.0)}), Status::Ok);  // a wall 9 m ahead
    ProjectileSettings settings;
    settings.method = method;
    settings.restitution = 0.6f;
    settings.friction = 0.2f;
    settings.radius = radius;
    Points p;
    p.points.resize(foresight::trajectoryCapacity(4.0f, settings, 256));
    p.status = foresight::predictProjectile(start, velocity, 4.0f, settings, &world, p.points, p.result);
    p.points.resize(p.result.trajectorySize);
    return p;
}

TEST(DoublePrecision, ProjectileOnAFarPlaneMatchesTheOrigin) {
    // A plane with normal +Y at distance 6.4e6 (a floor on the Earth's surface, in geocentric
    // coordinates along Y) against the same plane through the origin.
    const Vec3 velocity(1.0f, 4.0f, 6.0f);
    for (const ProjectileMethod method : {ProjectileMethod::Exact, ProjectileMethod::Stepped}) {
        for (const float radius : {0.0f, 0.1f}) {
            const RVec3 nearStart(0.0, 2.0, 0.0);
            const RVec3 farStart(0.0, kEarth + 2.0, 0.0);
            const Points near = throwOnPlane(0.0, nearStart, velocity, method, radius);
            const Points far = throwOnPlane(kEarth, farStart, velocity, method, radius);
            ASSERT_EQ(near.status, Status::Ok);
            ASSERT_EQ(far.status, Status::Ok);
            ASSERT_GT(near.result.bounces, 2u);  // floor and wall bounces happen
            EXPECT_EQ(far.result.bounces, near.result.bounces);
            EXPECT_EQ(far.result.atRest, near.result.atRest);
            ASSERT_EQ(far.points.size(), near.points.size());
            const DVec3 offset(0.0, kEarth, 0.0);
            for (std::size_t k = 0; k < near.points.size(); ++k) {
                // Same relative trajectory: double positions at 6.4e6 m (spacing 9.3e-10 m)
                // over a few hundred steps stay far below 1e-6 m.
                EXPECT_VEC_NEAR(ftest::toD(far.points[k].position) - offset, near.points[k].position, 1e-6)
                    << "method " << static_cast<int>(method) << " r " << radius << " point " << k;
                EXPECT_EQ(far.points[k].event, near.points[k].event) << k;
            }
            EXPECT_VEC_NEAR(ftest::toD(far.result.position) - offset, near.result.position, 1e-6);
            // Still on the far floor, not under it (float positions would be 0.5 m off).
            for (const TrajectoryPoint& p : far.points) {
                EXPECT_GE(p.position.y - kEarth, static_cast<double>(radius) - 1e-6);
            }
        }
    }
}

// Two-sided triangles at double resolution: the body is put on surfaces to ulps of double,
// where the float normal a world reports, and a cast's float displacement, are much coarser.

/// Adds the quad a b c d (in order) as two triangles.
void addQuad(StaticWorld& world, const DVec3& a, const DVec3& b, const DVec3& c, const DVec3& d) {
    ASSERT_EQ(world.add(foresight::Triangle{a, b, c}), Status::Ok);
    ASSERT_EQ(world.add(foresight::Triangle{a, c, d}), Status::Ok);
}

TEST(DoublePrecision, BounceOnAnObliqueSlopeIsNotFollowedByAHitFromBehind) {
    // The demo level's ramp slope (17.35 degrees, two triangles). The bounce put the body on
    // the plane of the hit's float normal, 1e-11 m behind the triangles' own plane; the next
    // cast met the triangle from behind at once and the body went on inside the ramp.
    StaticWorld world;
    addQuad(world, DVec3(-1, 0, 11), DVec3(-1, 0, 14), DVec3(-7, 1.875, 14), DVec3(-7, 1.875, 11));
    if (HasFatalFailure()) return;
    ProjectileSettings settings;
    settings.restitution = 0.69054931402206421f;
    std::vector<TrajectoryPoint> points(foresight::trajectoryCapacity(0.2f, settings));
    ProjectileResult result;
    ASSERT_EQ(foresight::predictProjectile(RVec3(-4.1496719085437608, 1.1732715847369795, 13.272881517199785),
                                           Vec3(-1.0579562187194824f, -2.213991641998291f, -3.7539980411529541f), 0.2f,
                                           settings, &world, points, result),
              Status::Ok);
    EXPECT_EQ(result.bounces, 1u);
    for (std::size_t k = 0; k < result.trajectorySize; ++k) {
        const DVec3 p = points[k].position;
        // Above the slope y = (-1 - x) 1.875 / 6; 1e-9 m: double rounding and the skin are ulps.
        EXPECT_GE(p.y, (-1.0 - p.x) * 1.875 / 6.0 - 1e-9) << "t=" << points[k].time;
    }
}

TEST(DoublePrecision, StepEndingExactlyOnAWallOfTrianglesBouncesOffIt) {
    // x = 0 - 6 t reaches the wall x = -15 at t = 2.5 s, a step boundary; at double resolution
    // x = -15.000000000000043 there. The cast's float displacement (0.12 m to 7e-9 m) stopped
    // short of the wall, and the next cast started behind it: the body went through.
    StaticWorld world;
    addQuad(world, DVec3(-15, -60, -60), DVec3(-15, -60, 60), DVec3(-15, 60, 60), DVec3(-15, 60, -60));
    if (HasFatalFailure()) return;
    ProjectileSettings settings;
    std::vector<TrajectoryPoint> points(foresight::trajectoryCapacity(3.0f, settings));
    ProjectileResult result;
    ASSERT_EQ(foresight::predictProjectile(RVec3(0, 1.5, -13), Vec3(-6, 6, 11), 3.0f, settings, &world, points, result),
              Status::Ok);
    EXPECT_EQ(result.bounces, 1u);
    for (std::size_t k = 0; k < result.trajectorySize; ++k) {
        EXPECT_GE(points[k].position.x, -15.0 - 1e-9) << "t=" << points[k].time;  // ulps of double
    }
    EXPECT_NEAR(result.position.x, -13.5, 1e-9);  // back at e * 6 = 3 m/s for 0.5 s
}

TEST(DoublePrecision, ImpactExactlyOnTheEdgeOfTwoWallsOfTrianglesBouncesOffBoth) {
    // Walls x = -5 and z = -5 of triangles; the diagonal throw reaches their edge at t = 0.625 s
    // exactly. The bounce off one wall left the body exactly on the other's plane, where a
    // two-sided triangle ignores a start: it went through that wall.
    StaticWorld world;
    addQuad(world, DVec3(-5, -20, -5), DVec3(-5, -20, 20), DVec3(-5, 20, 20), DVec3(-5, 20, -5));
    addQuad(world, DVec3(-5, -20, -5), DVec3(20, -20, -5), DVec3(20, 20, -5), DVec3(-5, 20, -5));
    if (HasFatalFailure()) return;
    ProjectileSettings settings;
    settings.restitution = 0.38f;
    std::vector<TrajectoryPoint> points(foresight::trajectoryCapacity(1.5f, settings));
    ProjectileResult result;
    ASSERT_EQ(foresight::predictProjectile(RVec3(-3.75, 1.5, -3.75), Vec3(-2.0f, -1.25f, -2.0f), 1.5f, settings, &world,
                                           points, result),
              Status::Ok);
    EXPECT_EQ(result.bounces, 2u);
    for (std::size_t k = 0; k < result.trajectorySize; ++k) {
        EXPECT_GE(points[k].position.x, -5.0 - 1e-9) << "t=" << points[k].time;
        EXPECT_GE(points[k].position.z, -5.0 - 1e-9) << "t=" << points[k].time;
    }
}

}  // namespace
