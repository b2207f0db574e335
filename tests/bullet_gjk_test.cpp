// src/bullet_gjk.h against the linked Bullet: the box-sphere contact of btGjkPairDetector, as
// btConvexConvexAlgorithm asks it (the box as shape A), reproduced to the bit.

#include "bullet_gjk.h"

#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <btBulletCollisionCommon.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

namespace {

using foresight::detail::BulletBox;
using foresight::detail::BulletVec;

std::uint32_t bits(float x) { return std::bit_cast<std::uint32_t>(x); }

bool same(const BulletVec& a, const btVector3& b) {
    return bits(a.x) == bits(b.x()) && bits(a.y) == bits(b.y()) && bits(a.z) == bits(b.z());
}

struct Placement {
    btVector3 half;
    btQuaternion rotation;
    btVector3 origin;
    btVector3 center;
    float radius = 0.1f;
};

// A box (from thin boards to a 30 m floor, turned or not) and a sphere near its surface: inside
// it by up to its radius plus the margin, or outside by up to 5 cm.
Placement randomSetup(std::mt19937& random) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const auto between = [&](float lo, float hi) { return lo + (hi - lo) * unit(random); };
    Placement s;
    const int kind = static_cast<int>(random() % 4);
    if (kind == 0) {
        s.half = btVector3(30.0f, 0.5f, 30.0f);  // the engine oracle's floor
    } else {
        s.half = btVector3(between(0.05f, 3.0f), between(0.05f, 3.0f), between(0.05f, 3.0f));
    }
    if (kind == 0 || kind == 1) {
        s.rotation = btQuaternion(0, 0, 0, 1);
    } else if (kind == 2) {
        const float yaw = between(-3.14f, 3.14f);
        s.rotation = btQuaternion(0.0f, std::sin(0.5f * yaw), 0.0f, std::cos(0.5f * yaw));
    } else {
        btVector3 axis(between(-1, 1), between(-1, 1), between(-1, 1));
        if (axis.length2() < 1e-4f) axis = btVector3(0, 1, 0);
        s.rotation = btQuaternion(axis.normalized(), between(-3.14f, 3.14f));
    }
    s.origin = kind == 0 ? btVector3(0.0f, -0.5f, 0.0f) : btVector3(between(-20, 20), between(-2, 5), between(-20, 20));
    s.radius = between(0.02f, 0.5f);
    // A point of the box's surface (a face, an edge or a corner), pushed along the outward
    // direction there.
    btVector3 local(between(-1, 1) * s.half.x(), between(-1, 1) * s.half.y(), between(-1, 1) * s.half.z());
    const int snapped = 1 + static_cast<int>(random() % 3);
    for (int i = 0; i < snapped; ++i) {
        const int axis = static_cast<int>(random() % 3);
        local[axis] = (unit(random) < 0.5f ? -1.0f : 1.0f) * s.half[axis];
    }
    btVector3 outward(0, 0, 0);
    for (int axis = 0; axis < 3; ++axis)
        if (std::abs(local[axis]) >= s.half[axis]) outward[axis] = local[axis] > 0 ? 1.0f : -1.0f;
    if (outward.length2() == 0) outward = btVector3(0, 1, 0);
    outward.normalize();
    const float depth = between(-s.radius - 0.04f, 0.05f);
    const btTransform t(s.rotation, s.origin);
    s.center = t(local + outward * (s.radius + depth));
    return s;
}

TEST(BulletGjk, BoxShapeAndBasisAsBullet) {
    std::mt19937 random(7);
    for (int i = 0; i < 2000; ++i) {
        const Placement s = randomSetup(random);
        btBoxShape shape(s.half);
        BulletBox box;
        foresight::detail::bulletBoxShape(BulletVec{s.half.x(), s.half.y(), s.half.z()}, -1.0f, box);
        ASSERT_TRUE(same(box.halfExtents, shape.getImplicitShapeDimensions())) << i;
        ASSERT_EQ(bits(box.margin), bits(shape.getMargin())) << i;
        shape.setMargin(0.013f);  // a margin set after construction
        foresight::detail::bulletBoxShape(BulletVec{s.half.x(), s.half.y(), s.half.z()}, 0.013f, box);
        ASSERT_TRUE(same(box.halfExtents, shape.getImplicitShapeDimensions())) << i;
        const btMatrix3x3 m(s.rotation);
        const auto rows =
            foresight::detail::bulletBasis(s.rotation.x(), s.rotation.y(), s.rotation.z(), s.rotation.w());
        for (int r = 0; r < 3; ++r) ASSERT_TRUE(same(rows[static_cast<std::size_t>(r)], m[r])) << i;
    }
}

// Every contact the port answers is btGjkPairDetector's, bit for bit (normal, point, distance),
// and so is every "no contact"; the cases it leaves to Bullet's EPA (the sphere's centre within
// 2 mm of the box shrunk by its margin, or inside it) are the only ones it declines.
TEST(BulletGjk, ContactsAreBulletsToTheBit) {
    std::mt19937 random(20261128);
    btVoronoiSimplexSolver simplexSolver;
    btGjkEpaPenetrationDepthSolver epa;
    int handled = 0, found = 0, tilted = 0;
    constexpr int kCases = 20000;
    for (int i = 0; i < kCases; ++i) {
        const Placement s = randomSetup(random);
        btBoxShape boxShape(s.half);
        btSphereShape sphereShape(s.radius);
        // btConvexConvexAlgorithm's distance of interest, with the manifold's contact breaking
        // threshold (btCollisionDispatcher's relative one: the smaller of the two shapes').
        const float threshold = std::min(boxShape.getContactBreakingThreshold(gContactBreakingThreshold),
                                         sphereShape.getContactBreakingThreshold(gContactBreakingThreshold));
        float maximum = boxShape.getMargin() + sphereShape.getMargin() + threshold;
        maximum *= maximum;

        btGjkPairDetector gjk(&boxShape, &sphereShape, &simplexSolver, &epa);
        btGjkPairDetector::ClosestPointInput input;
        input.m_transformA = btTransform(s.rotation, s.origin);
        input.m_transformB = btTransform(btQuaternion::getIdentity(), s.center);
        input.m_maximumDistanceSquared = maximum;
        btPointCollector bullet;
        gjk.getClosestPoints(input, bullet, nullptr);

        BulletBox box;
        foresight::detail::bulletBoxShape(BulletVec{s.half.x(), s.half.y(), s.half.z()}, -1.0f, box);
        box.basis = foresight::detail::bulletBasis(s.rotation.x(), s.rotation.y(), s.rotation.z(), s.rotation.w());
        box.origin = BulletVec{s.origin.x(), s.origin.y(), s.origin.z()};
        ASSERT_EQ(bits(foresight::detail::bulletContactDistanceSquared(box, s.radius)), bits(maximum)) << "case " << i;
        const auto ours = foresight::detail::bulletBoxSphereGjk(
            box, BulletVec{s.center.x(), s.center.y(), s.center.z()}, s.radius, maximum);
        if (!ours.handled) continue;
        ++handled;
        ASSERT_EQ(ours.found, bullet.m_hasResult) << "case " << i;
        if (!ours.found) continue;
        ++found;
        ASSERT_TRUE(same(ours.normalOnB, bullet.m_normalOnBInWorld))
            << "case " << i << ": normal " << ours.normalOnB.x << " " << ours.normalOnB.y << " " << ours.normalOnB.z
            << " against " << bullet.m_normalOnBInWorld.x() << " " << bullet.m_normalOnBInWorld.y() << " "
            << bullet.m_normalOnBInWorld.z();
        ASSERT_TRUE(same(ours.pointOnB, bullet.m_pointInWorld)) << "case " << i;
        ASSERT_EQ(bits(ours.distance), bits(bullet.m_distance)) << "case " << i;
        const btVector3 n = bullet.m_normalOnBInWorld;
        const float largest = std::max({std::abs(n.x()), std::abs(n.y()), std::abs(n.z())});
        if (largest < 1.0f && largest > 0.9999f) ++tilted;
    }
    // The port answers nearly every case; the float rounding it reproduces tilts many normals.
    EXPECT_GT(handled, kCases * 9 / 10);
    EXPECT_GT(found, kCases / 2);
    EXPECT_GT(tilted, 100);
    std::printf("BulletGjk: %d cases, %d answered (%d contacts, %d with a normal tilted by rounding)\n", kCases,
                handled, found, tilted);
}

// The contact that parted the prediction from Bullet 3.24 in the engine oracle (seed 26, scene
// 26): a 0.143 m ball 1.6 cm below the top of the 30 m floor box after a 30 Hz step. Bullet's
// normal is tilted by 1.4e-4 rad; a micrometre elsewhere, the tilt is another.
TEST(BulletGjk, TheFloorBoxTiltsTheNormal) {
    BulletBox box;
    foresight::detail::bulletBoxShape(BulletVec{30.0f, 0.5f, 30.0f}, -1.0f, box);
    box.basis = foresight::detail::bulletBasis(0, 0, 0, 1);
    box.origin = BulletVec{0.0f, -0.5f, 0.0f};
    const float radius = 0.1432974149934232f;
    const auto at = [&](float x, float y, float z) {
        return foresight::detail::bulletBoxSphereGjk(box, BulletVec{x, y, z}, radius, 1.0f);
    };
    const auto a = at(-10.4416914f, -0.016469568f, -9.09558773f);
    ASSERT_TRUE(a.handled && a.found);
    EXPECT_EQ(a.normalOnB.x, 0.000101323538f);
    EXPECT_EQ(a.normalOnB.y, -1.0f);
    EXPECT_EQ(a.normalOnB.z, 0.000101323538f);
    const auto b = at(-10.44169f, -0.01647f, -9.09559f);
    ASSERT_TRUE(b.handled && b.found);
    EXPECT_LT(b.normalOnB.x, -1e-4f);
    EXPECT_LT(b.normalOnB.z, -1e-4f);
}

}  // namespace
