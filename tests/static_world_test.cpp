// StaticWorld casts: enumerated geometric cases (one-line sketch each, as in Jolt's
// RayShapeTests) for planes, spheres, oriented boxes and triangles, as point casts (radius 0)
// and swept spheres (radius > 0). Expected fractions, positions and normals are hand-computed
// (or, for the tilted shapes, computed here in double from the geometry). Validators, and the
// CallbackWorld adapter.

#include "test_util.h"

#include <foresight/static_world.h>
#include <foresight/world.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace {

using foresight::CastHit;
using foresight::OrientedBox;
using foresight::Plane;
using foresight::Real;
using foresight::RVec3;
using foresight::SegmentCast;
using foresight::Sphere;
using foresight::StaticWorld;
using foresight::Status;
using foresight::Triangle;
using foresight::Vec3;
using ftest::DQuat;
using ftest::DVec3;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
const double kSqrt2 = std::sqrt(2.0);
const double kSqrt3 = std::sqrt(3.0);

// Tolerances: float coordinates up to ~6 m (ulp 4.8e-7) through a rotation and a root.
constexpr double kFractionTol = 1e-5;
constexpr double kPositionTol = 2e-5;
constexpr double kNormalTol = 1e-5;

/// An expected hit, in the case's local frame.
struct Expected {
    double fraction;
    DVec3 position;
    DVec3 normal;
};

/// One enumerated case: a sketch, the cast in local coordinates, the expected hit (or none).
struct Case {
    const char* sketch;
    DVec3 origin;
    DVec3 displacement;
    float radius;
    std::optional<Expected> hit;
};

/// Local-to-world placement of a case (a translation and a rotation).
struct Placement {
    DVec3 offset{0.0};
    DQuat rotation = ftest::dquatWXYZ(1.0, 0.0, 0.0, 0.0);
    DVec3 point(const DVec3& p) const { return offset + ftest::dRotate(rotation, p); }
    DVec3 direction(const DVec3& d) const { return ftest::dRotate(rotation, d); }
};

Expected hitAt(double fraction, DVec3 position, DVec3 normal) { return Expected{fraction, position, normal}; }

void runCases(const foresight::CollisionWorld& world, const Case* cases, std::size_t count,
              const Placement& placement = Placement{}) {
    for (std::size_t i = 0; i < count; ++i) {
        const Case& c = cases[i];
        SegmentCast cast;
        cast.origin = ftest::toR(placement.point(c.origin));
        cast.displacement = ftest::toF(placement.direction(c.displacement));
        cast.radius = c.radius;
        CastHit hit;
        const bool didHit = world.castSegment(cast, hit);
        SCOPED_TRACE(std::string(c.sketch) + " (radius " + std::to_string(c.radius) + ")");
        ASSERT_EQ(didHit, c.hit.has_value());
        if (!didHit) continue;
        EXPECT_NEAR(static_cast<double>(hit.fraction), c.hit->fraction, kFractionTol);
        EXPECT_VEC_NEAR(hit.position, placement.point(c.hit->position), kPositionTol);
        EXPECT_VEC_NEAR(hit.normal, placement.direction(c.hit->normal), kNormalTol);
        EXPECT_NEAR(glm::length(ftest::toD(hit.normal)), 1.0, 1e-6);  // unit, float
        // The position is the cast's origin point at the reported fraction.
        EXPECT_VEC_NEAR(hit.position,
                        ftest::toD(cast.origin) + ftest::toD(cast.displacement) * static_cast<double>(hit.fraction),
                        kPositionTol);
    }
}

// ---------------------------------------------------------------------------------------------
// Planes

TEST(StaticWorldPlane, FloorCases) {
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0.0f, 1.0f, 0.0f), Real(0)}), Status::Ok);
    const DVec3 up(0.0, 1.0, 0.0);
    // Sketches: "o" start, ">" end, "|" the floor (solid below, y < 0).
    const Case cases[] = {
        {"o above, > below: o--|-->", {1, 2, 3}, {0, -4, 0}, 0.0f, hitAt(0.5, {1, 0, 3}, up)},
        {"slanted through: o-\\-|->", {0, 1, 0}, {2, -2, 0}, 0.0f, hitAt(0.5, {1, 0, 0}, up)},
        {"ends short: o-->  |", {0, 2, 0}, {0, -1, 0}, 0.0f, std::nullopt},
        {"ends inside: o---|->", {0, 1, 0}, {0, -1.5, 0}, 0.0f, hitAt(2.0 / 3.0, {0, 0, 0}, up)},
        {"starts on surface moving in: |o->", {3, 0, -2}, {1, -1, 0}, 0.0f, hitAt(0.0, {3, 0, -2}, up)},
        {"starts 5e-6 behind (within tolerance) moving in",
         {0, -5e-6, 0},
         {0, -1, 0},
         0.0f,
         hitAt(0.0, {0, -5e-6, 0}, up)},
        {"starts on surface moving away: <-o|", {0, 0, 0}, {0, 1, 0}, 0.0f, std::nullopt},
        {"starts deep inside moving deeper: | o->", {0, -1, 0}, {0, -1, 0}, 0.0f, std::nullopt},
        {"starts deep inside moving out: <-|--o", {0, -1, 0}, {0, 3, 0}, 0.0f, std::nullopt},
        {"zero length on surface: |o", {0, 0, 0}, {0, 0, 0}, 0.0f, std::nullopt},
        {"zero length above: o |", {0, 1, 0}, {0, 0, 0}, 0.0f, std::nullopt},
        {"parallel above: o-->  (over |)", {0, 1, 0}, {5, 0, 0}, 0.0f, std::nullopt},
        {"parallel on the surface: |o-->|", {0, 0, 0}, {5, 0, 0}, 0.0f, std::nullopt},
        // Swept sphere r = 0.5: the centre stops at y = 0.5.
        {"sphere from above: O--|-->", {0, 2, 0}, {0, -4, 0}, 0.5f, hitAt(0.375, {0, 0.5, 0}, up)},
        {"sphere slanted", {0, 1.5, 0}, {2, -2, 0}, 0.5f, hitAt(0.5, {1, 0.5, 0}, up)},
        {"sphere ends short of touching", {0, 2, 0}, {0, -1.4, 0}, 0.5f, std::nullopt},
        {"sphere touching, moving in", {0, 0.5, 0}, {0, -1, 0}, 0.5f, hitAt(0.0, {0, 0.5, 0}, up)},
        {"sphere touching, moving away", {0, 0.5, 0}, {0, 1, 0}, 0.5f, std::nullopt},
        {"sphere deep inside", {0, -1, 0}, {0, -1, 0}, 0.5f, std::nullopt},
        {"sphere zero length touching", {0, 0.5, 0}, {0, 0, 0}, 0.5f, std::nullopt},
        {"sphere parallel just clear (0.6 > 0.5)", {0, 0.6, 0}, {5, 0, 0}, 0.5f, std::nullopt},
    };
    runCases(world, cases, std::size(cases));
}

TEST(StaticWorldPlane, TiltedPlane) {
    // Plane (x + y) / sqrt 2 = 1, normal (1, 1, 0) / sqrt 2; cast from (2, 2, 0.5) by (-2, -2, 0):
    // the start is 4 / sqrt 2 - 1 in front, closing at 4 / sqrt 2 per unit fraction.
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{glm::normalize(Vec3(1.0f, 1.0f, 0.0f)), Real(1)}), Status::Ok);
    const DVec3 n(1.0 / kSqrt2, 1.0 / kSqrt2, 0.0);
    const DVec3 o(2.0, 2.0, 0.5);
    const DVec3 d(-2.0, -2.0, 0.0);
    const double front = 4.0 / kSqrt2 - 1.0;
    const double closing = 4.0 / kSqrt2;
    const double f0 = front / closing;
    const double f1 = (front - 0.3) / closing;
    const Case cases[] = {
        {"tilted: o--/-->", o, d, 0.0f, hitAt(f0, o + f0 * d, n)},
        {"tilted, sphere r 0.3", o, d, 0.3f, hitAt(f1, o + f1 * d, n)},
        {"tilted, ends short", o, 0.5 * d, 0.0f, std::nullopt},
        {"tilted, parallel", o, {1, -1, 0}, 0.0f, std::nullopt},
    };
    runCases(world, cases, std::size(cases));
}

TEST(StaticWorldPlane, NormalIsNormalisedWhenAdded) {
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0.0f, 0.0f, -4.0f), Real(0)}), Status::Ok);  // z = 0, facing -Z
    ASSERT_EQ(world.planes().size(), 1u);
    EXPECT_VEC_NEAR(world.planes()[0].normal, DVec3(0, 0, -1), 1e-7);
    const Case cases[] = {
        {"wall z = 0 facing -Z: o--|-->", {0, 0, -1}, {0, 0, 2}, 0.0f, hitAt(0.5, {0, 0, 0}, {0, 0, -1})},
        {"wall from behind (solid side): no hit", {0, 0, 1}, {0, 0, -2}, 0.0f, std::nullopt},
    };
    runCases(world, cases, std::size(cases));
}

TEST(StaticWorldPlane, UnnormalisedNormalKeepsThePlaneDefinition) {
    // Plane: the points x with dot(normal, x) = distance. With normal (0, 2, 0) and distance 4
    // that is y = 2; the stored unit normal comes with the distance scaled to match.
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0.0f, 2.0f, 0.0f), Real(4)}), Status::Ok);
    EXPECT_VEC_NEAR(world.planes()[0].normal, DVec3(0, 1, 0), 1e-7);
    EXPECT_NEAR(static_cast<double>(world.planes()[0].distance), 2.0, 1e-6);
    const Case cases[] = {
        {"floor y = 2: o--|-->", {0, 5, 0}, {0, -6, 0}, 0.0f, hitAt(0.5, {0, 2, 0}, {0, 1, 0})},
    };
    runCases(world, cases, std::size(cases));
}

// ---------------------------------------------------------------------------------------------
// Spheres

TEST(StaticWorldSphere, Cases) {
    StaticWorld world;
    ASSERT_EQ(world.add(Sphere{RVec3(Real(2), Real(1), Real(-3)), 1.0f}), Status::Ok);
    Placement placement;
    placement.offset = DVec3(2, 1, -3);  // cases are relative to the centre
    const Case cases[] = {
        {"through the centre: o--(  )-->", {-3, 0, 0}, {4, 0, 0}, 0.0f, hitAt(0.5, {-1, 0, 0}, {-1, 0, 0})},
        {"off-axis chord at y 0.6: enters at x -0.8",
         {-3, 0.6, 0},
         {6, 0, 0},
         0.0f,
         hitAt(2.2 / 6.0, {-0.8, 0.6, 0}, {-0.8, 0.6, 0})},
        {"ends short: o-->  ( )", {-3, 0, 0}, {1.5, 0, 0}, 0.0f, std::nullopt},
        {"ends inside: o--(->)", {-3, 0, 0}, {2.5, 0, 0}, 0.0f, hitAt(0.8, {-1, 0, 0}, {-1, 0, 0})},
        {"starts on surface moving in: (o->)", {-1, 0, 0}, {1, 0, 0}, 0.0f, hitAt(0.0, {-1, 0, 0}, {-1, 0, 0})},
        {"starts on surface moving away: <-o( )", {-1, 0, 0}, {-1, 0, 0}, 0.0f, std::nullopt},
        {"starts on surface moving tangentially", {-1, 0, 0}, {0, 1, 0}, 0.0f, std::nullopt},
        {"starts at the centre moving out: ( o-)->", {0, 0, 0}, {3, 0, 0}, 0.0f, std::nullopt},
        {"zero length on the surface", {-1, 0, 0}, {0, 0, 0}, 0.0f, std::nullopt},
        {"passes above: o------> over ( )", {-3, 1.5, 0}, {6, 0, 0}, 0.0f, std::nullopt},
        // Swept sphere r = 0.5: hits when the centres are 1.5 apart.
        {"sphere through the centre", {-3, 0, 0}, {4, 0, 0}, 0.5f, hitAt(0.375, {-1.5, 0, 0}, {-1, 0, 0})},
        {"sphere off-axis at y 1.2: touches at x -0.9",
         {-3, 1.2, 0},
         {6, 0, 0},
         0.5f,
         hitAt(2.1 / 6.0, {-0.9, 1.2, 0}, {-0.6, 0.8, 0})},
        {"sphere passes at y 1.6 > 1.5", {-3, 1.6, 0}, {6, 0, 0}, 0.5f, std::nullopt},
        {"sphere touching, moving in", {-1.5, 0, 0}, {1, 0, 0}, 0.5f, hitAt(0.0, {-1.5, 0, 0}, {-1, 0, 0})},
        {"sphere touching, moving away", {-1.5, 0, 0}, {-1, 0, 0}, 0.5f, std::nullopt},
        {"sphere from deep inside", {0, 0, 0}, {3, 0, 0}, 0.5f, std::nullopt},
    };
    runCases(world, cases, std::size(cases), placement);
}

// ---------------------------------------------------------------------------------------------
// Oriented boxes

TEST(StaticWorldBox, RotatedBoxCases) {
    // Box at (1, 2, 3), half extents (1, 0.5, 2), rotated 0.6 rad about (1, 2, -1). Cases are
    // written in the box's local frame and placed with the same rotation (in double).
    const Vec3 axis = glm::normalize(Vec3(1.0f, 2.0f, -1.0f));
    const foresight::Quat q = glm::angleAxis(0.6f, axis);
    StaticWorld world;
    ASSERT_EQ(world.add(OrientedBox{RVec3(Real(1), Real(2), Real(3)), Vec3(1.0f, 0.5f, 2.0f), q}), Status::Ok);
    Placement placement;
    placement.offset = DVec3(1, 2, 3);
    placement.rotation = ftest::toD(q);
    const double r = 0.25;
    const double e = r / kSqrt2;  // edge contact offset along each of the two face normals
    const double k = r / kSqrt3;  // corner contact offset along each of the three
    const Case cases[] = {
        {"+X face: o--[ ]", {3, 0.1, 0.2}, {-4, 0, 0}, 0.0f, hitAt(0.5, {1, 0.1, 0.2}, {1, 0, 0})},
        {"-Z face", {0.3, -0.2, -5}, {0, 0, 4}, 0.0f, hitAt(0.75, {0.3, -0.2, -2}, {0, 0, -1})},
        {"oblique past the +Y slab onto the +X face", {2, 1, 0}, {-2, -2, 0}, 0.0f, hitAt(0.5, {1, 0, 0}, {1, 0, 0})},
        {"ends short: o-> [ ]", {3, 0, 0}, {-1.5, 0, 0}, 0.0f, std::nullopt},
        {"ends inside: o--[<]", {3, 0, 0}, {-2.5, 0, 0}, 0.0f, hitAt(0.8, {1, 0, 0}, {1, 0, 0})},
        {"starts on the face moving in: [<o", {1, 0.1, 0.2}, {-1, 0, 0}, 0.0f, hitAt(0.0, {1, 0.1, 0.2}, {1, 0, 0})},
        {"starts on the face moving away: [ o>", {1, 0.1, 0.2}, {1, 0, 0}, 0.0f, std::nullopt},
        {"starts deep inside moving out: [o-]->", {0, 0, 0}, {3, 0, 0}, 0.0f, std::nullopt},
        {"zero length on the face", {1, 0.1, 0.2}, {0, 0, 0}, 0.0f, std::nullopt},
        {"parallel to the +X face, outside", {1.5, 0, -3}, {0, 0, 6}, 0.0f, std::nullopt},
        {"passes over the top (y 0.7 > 0.5)", {3, 0.7, 0}, {-6, 0, 0}, 0.0f, std::nullopt},
        // Swept sphere r = 0.25 against the rounded box.
        {"sphere onto the +X face", {3, 0.1, 0.2}, {-4, 0, 0}, 0.25f, hitAt(0.4375, {1.25, 0.1, 0.2}, {1, 0, 0})},
        {"sphere onto the (+X, +Y) edge along the diagonal",
         {2, 1.5, 0},
         {-2, -2, 0},
         0.25f,
         hitAt((1.0 - e) / 2.0, {1 + e, 0.5 + e, 0}, {1 / kSqrt2, 1 / kSqrt2, 0})},
        {"sphere onto the (+X, +Y, +Z) corner along the diagonal",
         {2, 1.5, 3},
         {-2, -2, -2},
         0.25f,
         hitAt((1.0 - k) / 2.0, {1 + k, 0.5 + k, 2 + k}, {1 / kSqrt3, 1 / kSqrt3, 1 / kSqrt3})},
        // At y 0.7 the centre line is 0.2 above the edge: contact at x = 1 + sqrt(r^2 - 0.2^2) = 1.15.
        {"sphere grazing the rounded edge (y 0.7)",
         {3, 0.7, 0},
         {-6, 0, 0},
         0.25f,
         hitAt(1.85 / 6.0, {1.15, 0.7, 0}, {0.6, 0.8, 0})},
        // 0.2 above and 0.2 beyond the corner: 0.283 > r from it, inside a square inflation.
        {"sphere missing the rounded corner (y 0.7, z 2.2)", {3, 0.7, 2.2}, {-6, 0, 0}, 0.25f, std::nullopt},
        {"sphere passing over the top (y 0.76 > 0.75)", {3, 0.76, 0}, {-6, 0, 0}, 0.25f, std::nullopt},
        {"sphere touching the face, moving in", {1.25, 0, 0}, {-1, 0, 0}, 0.25f, hitAt(0.0, {1.25, 0, 0}, {1, 0, 0})},
        {"sphere from deep inside", {0, 0, 0}, {3, 0, 0}, 0.25f, std::nullopt},
    };
    runCases(world, cases, std::size(cases), placement);
}

// A rounded box (OrientedBox::rounding, Jolt's convex radius): the box shrunk by the rounding,
// grown back by it. Faces stay; edges and corners are arcs of that radius.
TEST(StaticWorldBox, RoundedBoxCases) {
    StaticWorld world;
    const auto q = ftest::quatWXYZ(0.9238795f, 0.0f, 0.3826834f, 0.0f);  // 45 degrees about y
    OrientedBox box{RVec3(Real(1), Real(2), Real(3)), Vec3(1.0f, 0.5f, 2.0f), q};
    box.rounding = 0.1f;
    ASSERT_EQ(world.add(box), Status::Ok);
    Placement placement;
    placement.offset = DVec3(1, 2, 3);
    placement.rotation = ftest::toD(q);
    // Seen from outside, the (+X, +Y) edge is an arc of radius 0.1 + r about (0.9, 0.4).
    const double R = 0.35, e = R / kSqrt2;
    const Case cases[] = {
        {"sphere onto the +X face: as the sharp box",
         {3, 0.1, 0.2},
         {-4, 0, 0},
         0.25f,
         hitAt(0.4375, {1.25, 0.1, 0.2}, {1, 0, 0})},
        {"ray onto the +Y face", {0.2, 3, 0.3}, {0, -5, 0}, 0.0f, hitAt(0.5, {0.2, 0.5, 0.3}, {0, 1, 0})},
        {"sphere onto the (+X, +Y) edge along the diagonal: later than the sharp edge",
         {2, 1.5, 0},
         {-2, -2, 0},
         0.25f,
         hitAt((1.1 - e) / 2.0, {0.9 + e, 0.4 + e, 0}, {1 / kSqrt2, 1 / kSqrt2, 0})},
        // At y 0.7 the centre line is 0.3 above the arc's axis: contact at x = 0.9 + sqrt(R^2 - 0.3^2).
        {"sphere grazing the rounded edge (y 0.7)",
         {3, 0.7, 0},
         {-6, 0, 0},
         0.25f,
         hitAt((3 - 0.9 - std::sqrt(R * R - 0.09)) / 6.0, {0.9 + std::sqrt(R * R - 0.09), 0.7, 0},
               {std::sqrt(R * R - 0.09) / R, 0.3 / R, 0})},
        // 0.234 from the sharp box's corner (1, 0.5, 2), but 0.375 > R from the arc's centre.
        {"sphere missing the rounded corner (y 0.68, z 2.15)", {3, 0.68, 2.15}, {-6, 0, 0}, 0.25f, std::nullopt},
    };
    runCases(world, cases, std::size(cases), placement);
}

// ---------------------------------------------------------------------------------------------
// Triangles

TEST(StaticWorldTriangle, Cases) {
    // Triangle (0,0,0), (2,0,0), (0,0,2) in the y = 0 plane, placed at offset (-1, 0.5, 2).
    // Two-sided: hit from above with normal +Y, from below with -Y.
    const DVec3 offset(-1.0, 0.5, 2.0);
    StaticWorld world;
    ASSERT_EQ(world.add(Triangle{ftest::toR(offset), ftest::toR(offset + DVec3(2, 0, 0)),
                                 ftest::toR(offset + DVec3(0, 0, 2))}),
              Status::Ok);
    Placement placement;
    placement.offset = offset;
    const double e = 0.25 / kSqrt2;
    const Case cases[] = {
        {"face from above: o--/\\-->", {0.5, 1, 0.5}, {0, -2, 0}, 0.0f, hitAt(0.5, {0.5, 0, 0.5}, {0, 1, 0})},
        {"face from below (two-sided)", {0.5, -1, 0.5}, {0, 2, 0}, 0.0f, hitAt(0.5, {0.5, 0, 0.5}, {0, -1, 0})},
        {"slanted onto the face", {0, 1, 0.25}, {1, -2, 0.5}, 0.0f, hitAt(0.5, {0.5, 0, 0.5}, {0, 1, 0})},
        {"outside, beyond the long edge", {1.5, 1, 1.5}, {0, -2, 0}, 0.0f, std::nullopt},
        {"outside, beside the x edge", {1, 1, -0.1}, {0, -2, 0}, 0.0f, std::nullopt},
        {"ends short", {0.5, 1, 0.5}, {0, -0.9, 0}, 0.0f, std::nullopt},
        {"starts on its plane (ignored)", {0.5, 0, 0.5}, {0, -1, 0}, 0.0f, std::nullopt},
        {"in its plane (parallel)", {-1, 0, 0.5}, {3, 0, 0}, 0.0f, std::nullopt},
        {"zero length on it", {0.5, 0, 0.5}, {0, 0, 0}, 0.0f, std::nullopt},
        // Swept sphere r = 0.25.
        {"sphere onto the face from above",
         {0.5, 1, 0.5},
         {0, -2, 0},
         0.25f,
         hitAt(0.375, {0.5, 0.25, 0.5}, {0, 1, 0})},
        {"sphere onto the face from below",
         {0.5, -1, 0.5},
         {0, 2, 0},
         0.25f,
         hitAt(0.375, {0.5, -0.25, 0.5}, {0, -1, 0})},
        {"sphere onto the x edge diagonally from above-outside",
         {1, 1, -1},
         {0, -2, 2},
         0.25f,
         hitAt((1.0 - e) / 2.0, {1, e, -e}, {0, 1 / kSqrt2, -1 / kSqrt2})},
        {"sphere passing above (0.3 > 0.25)", {0.5, 0.3, 0.5}, {1, 0, 0}, 0.25f, std::nullopt},
        {"sphere ends short", {0.5, 1, 0.5}, {0, -0.7, 0}, 0.25f, std::nullopt},
    };
    runCases(world, cases, std::size(cases), placement);
}

TEST(StaticWorldTriangle, TiltedTriangleAgainstDoubleGeometry) {
    // A tilted triangle; the expected hit is the ray-plane intersection in double, checked to be
    // inside the triangle by barycentric coordinates.
    const DVec3 a(0.0, 0.0, 0.0), b(2.0, 1.0, 0.0), c(0.0, 1.0, 2.0);
    StaticWorld world;
    ASSERT_EQ(world.add(Triangle{ftest::toR(a), ftest::toR(b), ftest::toR(c)}), Status::Ok);
    const DVec3 n = glm::normalize(glm::cross(b - a, c - a));
    const DVec3 origin(0.6, 3.0, 0.5);
    const DVec3 d(0.1, -4.0, 0.3);
    const double f = glm::dot(n, a - origin) / glm::dot(n, d);
    const DVec3 p = origin + f * d;
    // Barycentric check that p is inside (so the case really is a face hit).
    const DVec3 v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = glm::dot(v0, v0), d01 = glm::dot(v0, v1), d11 = glm::dot(v1, v1);
    const double d20 = glm::dot(v2, v0), d21 = glm::dot(v2, v1);
    const double den = d00 * d11 - d01 * d01;
    const double bv = (d11 * d20 - d01 * d21) / den, bw = (d00 * d21 - d01 * d20) / den;
    ASSERT_GT(bv, 0.05);
    ASSERT_GT(bw, 0.05);
    ASSERT_LT(bv + bw, 0.95);
    const DVec3 facing = glm::dot(n, d) < 0.0 ? n : -n;
    const Case cases[] = {
        {"tilted face", origin, d, 0.0f, hitAt(f, p, facing)},
    };
    runCases(world, cases, std::size(cases));
}

// ---------------------------------------------------------------------------------------------
// Several shapes: the closest hit wins.

TEST(StaticWorld, ClosestHitWins) {
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0.0f, 1.0f, 0.0f), Real(0)}), Status::Ok);
    ASSERT_EQ(world.add(Sphere{RVec3(Real(0), Real(2), Real(0)), 1.0f}), Status::Ok);
    ASSERT_EQ(world.add(OrientedBox{RVec3(Real(0), Real(5), Real(0)), Vec3(1.0f), glm::identity<foresight::Quat>()}),
              Status::Ok);
    ASSERT_EQ(world.add(Triangle{RVec3(Real(-1), Real(8), Real(-1)), RVec3(Real(3), Real(8), Real(-1)),
                                 RVec3(Real(-1), Real(8), Real(3))}),
              Status::Ok);
    EXPECT_EQ(world.shapeCount(), 4u);
    const Case cases[] = {
        // Down from y 10: triangle at 8, box top at 6, sphere top at 3, floor at 0.
        {"down through all: triangle first", {0, 10, 0}, {0, -10, 0}, 0.0f, hitAt(0.2, {0, 8, 0}, {0, 1, 0})},
        {"from between triangle and box: box top", {0, 7, 0}, {0, -7, 0}, 0.0f, hitAt(1.0 / 7.0, {0, 6, 0}, {0, 1, 0})},
        {"from between box and sphere: sphere top",
         {0, 3.5, 0},
         {0, -3.5, 0},
         0.0f,
         hitAt(1.0 / 7.0, {0, 3, 0}, {0, 1, 0})},
        {"beside everything: the floor", {5, 10, 0}, {0, -20, 0}, 0.0f, hitAt(0.5, {5, 0, 0}, {0, 1, 0})},
        {"up from the floor: the sphere's bottom", {0, 0, 0}, {0, 10, 0}, 0.0f, hitAt(0.1, {0, 1, 0}, {0, -1, 0})},
    };
    runCases(world, cases, std::size(cases));
}

// ---------------------------------------------------------------------------------------------
// Validators: refused shapes leave the world unchanged.

TEST(StaticWorld, ValidatorsRefuseBadShapes) {
    const Real rnan = std::numeric_limits<Real>::quiet_NaN();
    const Real rinf = std::numeric_limits<Real>::infinity();

    EXPECT_EQ(foresight::validatePlane(Plane{Vec3(0.0f, 1.0f, 0.0f), Real(2)}), Status::Ok);
    EXPECT_EQ(foresight::validatePlane(Plane{Vec3(0.0f), Real(0)}), Status::ZeroVector);
    EXPECT_EQ(foresight::validatePlane(Plane{Vec3(0.0f, kNaN, 1.0f), Real(0)}), Status::NonFiniteInput);
    EXPECT_EQ(foresight::validatePlane(Plane{Vec3(0.0f, 1.0f, 0.0f), rinf}), Status::NonFiniteInput);

    EXPECT_EQ(foresight::validateSphere(Sphere{RVec3(Real(0)), 0.5f}), Status::Ok);
    EXPECT_EQ(foresight::validateSphere(Sphere{RVec3(Real(0)), 0.0f}), Status::InvalidRadius);
    EXPECT_EQ(foresight::validateSphere(Sphere{RVec3(Real(0)), -1.0f}), Status::InvalidRadius);
    EXPECT_EQ(foresight::validateSphere(Sphere{RVec3(rnan, Real(0), Real(0)), 1.0f}), Status::NonFiniteInput);
    {
        // A NaN radius is both non-finite and not positive: either refusal is documented.
        const Status s = foresight::validateSphere(Sphere{RVec3(Real(0)), kNaN});
        EXPECT_TRUE(s == Status::NonFiniteInput || s == Status::InvalidRadius) << static_cast<int>(s);
    }

    const foresight::Quat id = glm::identity<foresight::Quat>();
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f), id}), Status::Ok);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f, 0.0f, 1.0f), id}), Status::DegenerateShape);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f, 1.0f, -2.0f), id}),
              Status::DegenerateShape);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f), ftest::quatWXYZ(0.0f, 0.0f, 0.0f, 0.0f)}),
              Status::ZeroQuaternion);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0), rinf, Real(0)), Vec3(1.0f), id}),
              Status::NonFiniteInput);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f, 0.5f, 1.0f), id, 0.5f}), Status::Ok);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f, 0.5f, 1.0f), id, 0.6f}),
              Status::InvalidRadius);  // more than the smallest half extent
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f), id, -0.1f}), Status::InvalidRadius);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f), id, kNaN}), Status::NonFiniteInput);
    EXPECT_EQ(foresight::validateBox(OrientedBox{RVec3(Real(0)), Vec3(1.0f), ftest::quatWXYZ(kNaN, 0.0f, 0.0f, 0.0f)}),
              Status::NonFiniteInput);

    const RVec3 o(Real(0));
    const RVec3 x(Real(1), Real(0), Real(0));
    const RVec3 z(Real(0), Real(0), Real(1));
    EXPECT_EQ(foresight::validateTriangle(Triangle{o, x, z}), Status::Ok);
    // A 1 mm triangle (area 5e-7 m^2) is small but fine.
    EXPECT_EQ(foresight::validateTriangle(Triangle{o, x * Real(1e-3), z * Real(1e-3)}), Status::Ok);
    EXPECT_EQ(foresight::validateTriangle(Triangle{o, x, x * Real(2)}), Status::DegenerateShape);  // collinear
    EXPECT_EQ(foresight::validateTriangle(Triangle{o, o, z}), Status::DegenerateShape);            // repeated vertex
    EXPECT_EQ(foresight::validateTriangle(Triangle{o, o, o}), Status::DegenerateShape);            // a point
    // Area 5e-13 m^2 < 1e-12 m^2 (also a sliver: height 1e-12 m under a 1 m base).
    EXPECT_EQ(foresight::validateTriangle(Triangle{o, x, RVec3(Real(0.5), Real(1e-12), Real(0))}),
              Status::DegenerateShape);
    EXPECT_EQ(foresight::validateTriangle(Triangle{o, x, RVec3(rnan, Real(0), Real(0))}), Status::NonFiniteInput);
}

TEST(StaticWorld, RefusedShapesLeaveTheWorldUnchanged) {
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0.0f, 1.0f, 0.0f), Real(0)}), Status::Ok);
    ASSERT_EQ(world.shapeCount(), 1u);
    EXPECT_EQ(world.add(Plane{Vec3(0.0f), Real(3)}), Status::ZeroVector);
    EXPECT_EQ(world.add(Sphere{RVec3(Real(0), Real(5), Real(0)), 0.0f}), Status::InvalidRadius);
    EXPECT_EQ(world.add(Sphere{RVec3(Real(0), Real(5), Real(0)), -1.0f}), Status::InvalidRadius);
    EXPECT_EQ(world.add(OrientedBox{RVec3(Real(0), Real(5), Real(0)), Vec3(1.0f, 1.0f, 0.0f),
                                    glm::identity<foresight::Quat>()}),
              Status::DegenerateShape);
    EXPECT_EQ(
        world.add(OrientedBox{RVec3(Real(0), Real(5), Real(0)), Vec3(1.0f), ftest::quatWXYZ(0.0f, 0.0f, 0.0f, 0.0f)}),
        Status::ZeroQuaternion);
    EXPECT_EQ(world.add(Triangle{RVec3(Real(0)), RVec3(Real(1), Real(0), Real(0)), RVec3(Real(2), Real(0), Real(0))}),
              Status::DegenerateShape);
    EXPECT_EQ(world.add(Sphere{RVec3(Real(0), std::numeric_limits<Real>::quiet_NaN(), Real(0)), 1.0f}),
              Status::NonFiniteInput);
    EXPECT_EQ(world.shapeCount(), 1u);
    EXPECT_EQ(world.planes().size(), 1u);
    EXPECT_TRUE(world.spheres().empty());
    EXPECT_TRUE(world.boxes().empty());
    EXPECT_TRUE(world.triangles().empty());
    // The casts still see only the floor (a refused sphere at y 5 would stop this at y 6).
    SegmentCast cast;
    cast.origin = RVec3(Real(0), Real(10), Real(0));
    cast.displacement = Vec3(0.0f, -20.0f, 0.0f);
    CastHit hit;
    ASSERT_TRUE(world.castSegment(cast, hit));
    EXPECT_NEAR(static_cast<double>(hit.fraction), 0.5, kFractionTol);

    world.clear();
    EXPECT_EQ(world.shapeCount(), 0u);
    EXPECT_FALSE(world.castSegment(cast, hit));
}

TEST(StaticWorld, ShapesAreStoredNormalised) {
    StaticWorld world;
    const foresight::Quat q2 = ftest::quatWXYZ(0.0f, 2.0f, 0.0f, 0.0f);  // 180 degrees about X, length 2
    ASSERT_EQ(world.add(OrientedBox{RVec3(Real(0)), Vec3(1.0f, 2.0f, 3.0f), q2}), Status::Ok);
    ASSERT_EQ(world.boxes().size(), 1u);
    EXPECT_QUAT_NEAR(world.boxes()[0].orientation, ftest::dquatWXYZ(0.0, 1.0, 0.0, 0.0), 1e-7);
    // Cast down onto the box: its top is at y = 2 whatever the 180-degree flip.
    SegmentCast cast;
    cast.origin = RVec3(Real(0.5), Real(5), Real(0.5));
    cast.displacement = Vec3(0.0f, -6.0f, 0.0f);
    CastHit hit;
    ASSERT_TRUE(world.castSegment(cast, hit));
    EXPECT_NEAR(static_cast<double>(hit.fraction), 0.5, kFractionTol);
    EXPECT_VEC_NEAR(hit.normal, DVec3(0, 1, 0), kNormalTol);
}

// ---------------------------------------------------------------------------------------------
// CallbackWorld and EmptyWorld

TEST(CallbackWorld, WrapForwardsTheQueryToALambda) {
    int calls = 0;
    SegmentCast seen;
    auto lambda = [&](const SegmentCast& cast, CastHit& hit) -> bool {
        ++calls;
        seen = cast;
        if (cast.displacement.y >= 0.0f) return false;
        hit.fraction = 0.25f;
        hit.position = cast.origin + RVec3(cast.displacement) * Real(0.25);
        hit.normal = Vec3(0.0f, 1.0f, 0.0f);
        return true;
    };
    const foresight::CallbackWorld world = foresight::CallbackWorld::wrap(lambda);
    const foresight::CollisionWorld& base = world;
    SegmentCast cast;
    cast.origin = RVec3(Real(1), Real(4), Real(2));
    cast.displacement = Vec3(0.0f, -8.0f, 0.0f);
    cast.radius = 0.125f;
    CastHit hit;
    ASSERT_TRUE(base.castSegment(cast, hit));
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(seen.origin, cast.origin);
    EXPECT_EQ(seen.displacement, cast.displacement);
    EXPECT_EQ(seen.radius, 0.125f);
    EXPECT_EQ(hit.fraction, 0.25f);
    EXPECT_VEC_NEAR(hit.position, DVec3(1, 2, 2), 0.0);
    cast.displacement = Vec3(0.0f, 1.0f, 0.0f);
    EXPECT_FALSE(base.castSegment(cast, hit));
    EXPECT_EQ(calls, 2);
}

bool plainFunction(void* context, const SegmentCast& cast, CastHit& hit) {
    *static_cast<int*>(context) += 1;
    hit.fraction = 0.5f;
    hit.position = cast.origin;
    return true;
}

TEST(CallbackWorld, FunctionPointerAndContext) {
    int calls = 0;
    const foresight::CallbackWorld world(&plainFunction, &calls);
    CastHit hit;
    EXPECT_TRUE(world.castSegment(SegmentCast{}, hit));
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(hit.fraction, 0.5f);
}

TEST(EmptyWorld, HitsNothing) {
    const foresight::EmptyWorld world;
    SegmentCast cast;
    cast.displacement = Vec3(0.0f, -100.0f, 0.0f);
    CastHit hit;
    EXPECT_FALSE(world.castSegment(cast, hit));
}

// StaticWorld::addMesh: the usable triangles, as if added one by one (the same answers to the
// same casts); a refused mesh adds nothing and says why.
TEST(StaticWorld, AddMeshAddsTheUsableTrianglesOrNothing) {
    // A 2 x 2 floor of four quads (eight triangles) and one degenerate triangle (a repeated vertex).
    std::vector<RVec3> vertices;
    for (int z = 0; z <= 2; ++z)
        for (int x = 0; x <= 2; ++x) vertices.emplace_back(static_cast<Real>(x), 0, static_cast<Real>(z));
    std::vector<std::uint32_t> indices;
    for (std::uint32_t z = 0; z < 2; ++z)
        for (std::uint32_t x = 0; x < 2; ++x) {
            const std::uint32_t a = 3 * z + x, b = a + 1, c = a + 4, d = a + 3;
            for (const std::uint32_t k : {a, d, c, a, c, b}) indices.push_back(k);
        }
    for (const std::uint32_t k : {0u, 0u, 4u}) indices.push_back(k);
    StaticWorld mesh, oneByOne;
    foresight::MeshReport report;
    ASSERT_EQ(mesh.addMesh(vertices, indices, &report), Status::Ok) << report.error;
    EXPECT_EQ(report.triangles, 8u);
    EXPECT_EQ(report.degenerateTriangles, 1u);
    EXPECT_EQ(report.firstDegenerateTriangle, 8u);
    EXPECT_TRUE(report.error.empty());
    EXPECT_EQ(mesh.triangles().size(), 8u);
    for (std::size_t t = 0; t < 8; ++t)
        ASSERT_EQ(oneByOne.add(
                      Triangle{vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]}),
                  Status::Ok);
    for (int i = 0; i < 200; ++i) {
        const double u = (i % 20) / 10.0 + 0.013, w = (i / 20) / 5.0 + 0.007;
        const SegmentCast cast{RVec3(static_cast<Real>(u), 1, static_cast<Real>(w)), Vec3(0.3f, -2, -0.2f),
                               i % 2 ? 0.1f : 0.0f};
        CastHit a, b;
        const bool hitA = mesh.castSegment(cast, a), hitB = oneByOne.castSegment(cast, b);
        ASSERT_EQ(hitA, hitB) << i;
        if (!hitA) continue;
        EXPECT_EQ(a.fraction, b.fraction);
        EXPECT_EQ(a.normal, b.normal);
    }
    // Degenerate triangles first and between usable ones: only the usable ones, in order.
    StaticWorld mixed;
    ASSERT_EQ(mixed.addMesh(vertices, std::vector<std::uint32_t>{0, 0, 4, 0, 3, 4, 1, 1, 1, 1, 4, 2}, &report),
              Status::Ok);
    EXPECT_EQ(report.triangles, 2u);
    EXPECT_EQ(report.degenerateTriangles, 2u);
    EXPECT_EQ(report.firstDegenerateTriangle, 0u);
    ASSERT_EQ(mixed.triangles().size(), 2u);
    EXPECT_EQ(mixed.triangles()[0].b, vertices[3]);
    EXPECT_EQ(mixed.triangles()[1].c, vertices[2]);
    // Refused, nothing added: non-finite vertex, index count, index range, nothing usable.
    const std::size_t before = mesh.triangles().size();
    std::vector<RVec3> bad = vertices;
    bad[4].y = std::numeric_limits<Real>::quiet_NaN();
    EXPECT_EQ(mesh.addMesh(bad, indices, &report), Status::NonFiniteInput);
    EXPECT_EQ(report.error, "vertex 4 is not finite");
    EXPECT_EQ(mesh.addMesh(vertices, std::vector<std::uint32_t>{0, 1}, &report), Status::DegenerateShape);
    EXPECT_NE(report.error.find("not a multiple of 3"), std::string::npos);
    EXPECT_EQ(mesh.addMesh(vertices, std::vector<std::uint32_t>{0, 1, 9}, &report), Status::DegenerateShape);
    EXPECT_NE(report.error.find("out of range"), std::string::npos);
    EXPECT_EQ(mesh.addMesh(vertices, std::vector<std::uint32_t>{0, 1, 2}, &report), Status::DegenerateShape);
    EXPECT_NE(report.error.find("no usable triangles"), std::string::npos);
    EXPECT_EQ(mesh.addMesh(vertices, std::vector<std::uint32_t>{}, nullptr), Status::DegenerateShape);
    EXPECT_EQ(mesh.triangles().size(), before);
}

}  // namespace
