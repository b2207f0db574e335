// Orientation from a constant angular velocity: hand-computed quaternions (Body q*r and World
// r*q, with a start orientation where the two differ), degenerate angular velocities, refusals.

#include "test_util.h"

#include <foresight/orientation.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using foresight::AngularFrame;
using foresight::Quat;
using foresight::Status;
using foresight::Vec3;
using ftest::DQuat;
using ftest::dquatWXYZ;
using ftest::DVec3;
using ftest::quatWXYZ;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// float trigonometry and a product of two float quaternions: a few ulps of 1.
constexpr double kQuatTol = 1e-6;

TEST(Orientation, RotationFromAngularVelocityArticleExample) {
    // The article: 0.25 rad/s about Y for 2 s turns 0.5 rad: w = cos(0.25), y = sin(0.25).
    const Quat r = foresight::rotationFromAngularVelocity(Vec3(0.0f, 0.25f, 0.0f), 2.0f);
    EXPECT_QUAT_NEAR(r, dquatWXYZ(std::cos(0.25), 0.0, std::sin(0.25), 0.0), kQuatTol);
}

TEST(Orientation, RotationFromAngularVelocityTiltedAxis) {
    // w = (1, 2, 2) rad/s has |w| = 3 and axis (1, 2, 2)/3; for 0.4 s the angle is 1.2 rad:
    // q = (cos 0.6, sin 0.6 * (1, 2, 2)/3).
    const Quat r = foresight::rotationFromAngularVelocity(Vec3(1.0f, 2.0f, 2.0f), 0.4f);
    const double s = std::sin(0.6);
    EXPECT_QUAT_NEAR(r, dquatWXYZ(std::cos(0.6), s / 3.0, 2.0 * s / 3.0, 2.0 * s / 3.0), kQuatTol);
}

TEST(Orientation, RotationRotatesVectorsAsExpected) {
    // pi/2 rad/s about +Z for 1 s turns +X into +Y (right-handed).
    const Quat r = foresight::rotationFromAngularVelocity(Vec3(0.0f, 0.0f, 1.5707963f), 1.0f);
    EXPECT_VEC_NEAR(r * Vec3(1.0f, 0.0f, 0.0f), DVec3(0.0, 1.0, 0.0), 1e-6);  // float rotation of a unit vector
}

TEST(Orientation, LargeAngleWrapsCorrectly) {
    // 3 rad/s about X for 3 s is 9 rad (more than a full turn): q = (cos 4.5, sin 4.5, 0, 0).
    const Quat r = foresight::rotationFromAngularVelocity(Vec3(3.0f, 0.0f, 0.0f), 3.0f);
    // float: the half angle 4.5 has an ulp of 4.8e-7; sin/cos of it are good to a few ulps.
    EXPECT_QUAT_NEAR(r, dquatWXYZ(std::cos(4.5), std::sin(4.5), 0.0, 0.0), 2e-6);
}

TEST(Orientation, SmallAnglesAreAccurateRelatively) {
    // 1e-4 rad/s about X for 1 s: x = sin(5e-5) ~ 5e-5; the sinc series keeps full relative
    // precision (a 1 - cos formulation or a division by a rounded |w| would not matter here, but
    // an absolute 1e-7 error would be a 0.2% error).
    const Quat r = foresight::rotationFromAngularVelocity(Vec3(1e-4f, 0.0f, 0.0f), 1.0f);
    const double expectedX = std::sin(0.5 * static_cast<double>(1e-4f));
    EXPECT_NEAR(static_cast<double>(r.x), expectedX, expectedX * 1e-6);  // float relative precision
    EXPECT_NEAR(static_cast<double>(r.w), 1.0, 1e-7);                    // cos(5e-5) = 1 - 1.25e-9
    EXPECT_EQ(r.y, 0.0f);
    EXPECT_EQ(r.z, 0.0f);
}

// Start orientation: 0.6 rad about X, c = cos 0.3, s = sin 0.3. Angular velocity 0.25 rad/s
// about Y for 2 s: r = (cb, 0, sb, 0) with cb = cos 0.25, sb = sin 0.25. By hand (Hamilton
// product (w1, v1)(w2, v2) = (w1 w2 - v1.v2, w1 v2 + w2 v1 + v1 x v2), X x Y = Z):
//   Body  q * r = (c cb, s cb, c sb,  s sb)
//   World r * q = (c cb, s cb, c sb, -s sb)
// They differ in the sign of z, so a swapped product fails.
struct FrameCase {
    Quat start;
    DQuat body;
    DQuat world;
};

FrameCase frameCase() {
    const double c = std::cos(0.3), s = std::sin(0.3);
    const double cb = std::cos(0.25), sb = std::sin(0.25);
    FrameCase fc;
    fc.start = quatWXYZ(static_cast<float>(c), static_cast<float>(s), 0.0f, 0.0f);
    fc.body = dquatWXYZ(c * cb, s * cb, c * sb, s * sb);
    fc.world = dquatWXYZ(c * cb, s * cb, c * sb, -s * sb);
    return fc;
}

TEST(Orientation, BodyFrameComposesOnTheRight) {
    const FrameCase fc = frameCase();
    Quat out;
    ASSERT_EQ(foresight::predictOrientation(fc.start, Vec3(0.0f, 0.25f, 0.0f), AngularFrame::Body, 2.0f, out),
              Status::Ok);
    EXPECT_QUAT_NEAR(out, fc.body, kQuatTol);
}

TEST(Orientation, WorldFrameComposesOnTheLeft) {
    const FrameCase fc = frameCase();
    Quat out;
    ASSERT_EQ(foresight::predictOrientation(fc.start, Vec3(0.0f, 0.25f, 0.0f), AngularFrame::World, 2.0f, out),
              Status::Ok);
    EXPECT_QUAT_NEAR(out, fc.world, kQuatTol);
}

TEST(Orientation, ComposeRotationFrames) {
    const FrameCase fc = frameCase();
    const Quat r = quatWXYZ(static_cast<float>(std::cos(0.25)), 0.0f, static_cast<float>(std::sin(0.25)), 0.0f);
    EXPECT_QUAT_NEAR(foresight::composeRotation(fc.start, r, AngularFrame::Body), fc.body, kQuatTol);
    EXPECT_QUAT_NEAR(foresight::composeRotation(fc.start, r, AngularFrame::World), fc.world, kQuatTol);
    // Renormalised: a start scaled by 3 gives the same unit result.
    const Quat scaled = quatWXYZ(3.0f * fc.start.w, 3.0f * fc.start.x, 0.0f, 0.0f);
    EXPECT_QUAT_NEAR(foresight::composeRotation(scaled, r, AngularFrame::Body), fc.body, kQuatTol);
}

TEST(Orientation, BodyFrameTurnsAboutTheBodyAxis) {
    // Geometric meaning: a body rotated 90 degrees about X has its local Y along world Z, so a
    // body-frame yaw about local Y turns local forward (+Z, which points to world -Y) about
    // world Z. The world-frame yaw turns it about world Y, which leaves world -Y unchanged.
    const Quat start = quatWXYZ(static_cast<float>(std::sqrt(0.5)), static_cast<float>(std::sqrt(0.5)), 0.0f, 0.0f);
    const Vec3 w(0.0f, 1.0f, 0.0f);  // 1 rad/s, 0.5 s: 0.5 rad
    Quat body;
    Quat world;
    ASSERT_EQ(foresight::predictOrientation(start, w, AngularFrame::Body, 0.5f, body), Status::Ok);
    ASSERT_EQ(foresight::predictOrientation(start, w, AngularFrame::World, 0.5f, world), Status::Ok);
    const Vec3 forward(0.0f, 0.0f, 1.0f);
    // Local +Z after the start orientation is world -Y; turning -Y by 0.5 rad about +Z gives
    // (sin 0.5, -cos 0.5, 0).
    EXPECT_VEC_NEAR(body * forward, DVec3(std::sin(0.5), -std::cos(0.5), 0.0), 1e-6);  // float unit vectors
    EXPECT_VEC_NEAR(world * forward, DVec3(0.0, -1.0, 0.0), 1e-6);
}

TEST(Orientation, ZeroAngularVelocityLeavesOrientationUnchanged) {
    const Quat start = glm::angleAxis(0.8f, glm::normalize(Vec3(1.0f, -2.0f, 0.5f)));
    for (const AngularFrame frame : {AngularFrame::Body, AngularFrame::World}) {
        for (const float t : {0.0f, 1.0f, 1e6f}) {
            Quat out;
            ASSERT_EQ(foresight::predictOrientation(start, Vec3(0.0f), frame, t, out), Status::Ok);
            ASSERT_TRUE(ftest::finite(out));
            EXPECT_QUAT_NEAR(out, start, 1e-7);  // identity composition of a unit quaternion
        }
    }
    const Quat r = foresight::rotationFromAngularVelocity(Vec3(0.0f), 5.0f);
    EXPECT_EQ(r.w, 1.0f);
    EXPECT_EQ(r.x, 0.0f);
    EXPECT_EQ(r.y, 0.0f);
    EXPECT_EQ(r.z, 0.0f);
}

TEST(Orientation, TinyAngularVelocityGivesNoNaN) {
    // 1e-30 rad/s: |w|^2 underflows float; the documented result is (close to) the identity.
    for (const Vec3 w : {Vec3(1e-30f, 0.0f, 0.0f), Vec3(1e-30f, -1e-30f, 1e-30f), Vec3(0.0f, 1e-38f, 0.0f),
                         Vec3(0.0f, 0.0f, std::numeric_limits<float>::denorm_min())}) {
        for (const float t : {1.0f, 1e-30f, 1e6f}) {
            const Quat r = foresight::rotationFromAngularVelocity(w, t);
            ASSERT_TRUE(ftest::finite(r)) << w.x << " " << t;
            // The true angle |w| t is below 2e-24 rad: the identity to float precision.
            const double angle = glm::length(ftest::toD(w)) * static_cast<double>(t);
            const DVec3 axis = glm::normalize(ftest::toD(w));
            EXPECT_QUAT_NEAR(r, ftest::dAxisAngle(axis, angle), 1e-6) << "t=" << t;  // float trig
            Quat out;
            ASSERT_EQ(foresight::predictOrientation(glm::identity<Quat>(), w, AngularFrame::Body, t, out), Status::Ok);
            ASSERT_TRUE(ftest::finite(out));
            EXPECT_NEAR(ftest::quatLength(out), 1.0, 1e-6);  // unit within float rounding
        }
    }
}

TEST(Orientation, ZeroQuaternionIsRefused) {
    const Quat before = quatWXYZ(0.5f, 0.5f, 0.5f, 0.5f);
    Quat out = before;
    EXPECT_EQ(foresight::predictOrientation(quatWXYZ(0.0f, 0.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f),
                                            AngularFrame::Body, 1.0f, out),
              Status::ZeroQuaternion);
    EXPECT_TRUE(ftest::sameBytes(out, before));
    EXPECT_EQ(foresight::normalizeQuaternion(quatWXYZ(0.0f, 0.0f, 0.0f, 0.0f), out), Status::ZeroQuaternion);
    EXPECT_TRUE(ftest::sameBytes(out, before));
}

TEST(Orientation, NonFiniteAndNegativeTimeAreRefused) {
    const Quat before = quatWXYZ(0.5f, 0.5f, 0.5f, 0.5f);
    const Quat good = glm::identity<Quat>();
    Quat out = before;
    EXPECT_EQ(
        foresight::predictOrientation(quatWXYZ(kNaN, 0.0f, 0.0f, 0.0f), Vec3(0.0f), AngularFrame::Body, 1.0f, out),
        Status::NonFiniteInput);
    EXPECT_TRUE(ftest::sameBytes(out, before));
    EXPECT_EQ(
        foresight::predictOrientation(quatWXYZ(1.0f, kInf, 0.0f, 0.0f), Vec3(0.0f), AngularFrame::World, 1.0f, out),
        Status::NonFiniteInput);
    EXPECT_TRUE(ftest::sameBytes(out, before));
    EXPECT_EQ(foresight::predictOrientation(good, Vec3(0.0f, kNaN, 0.0f), AngularFrame::Body, 1.0f, out),
              Status::NonFiniteInput);
    EXPECT_TRUE(ftest::sameBytes(out, before));
    EXPECT_EQ(foresight::predictOrientation(good, Vec3(0.0f, 1.0f, 0.0f), AngularFrame::Body, kNaN, out),
              Status::NonFiniteInput);
    EXPECT_TRUE(ftest::sameBytes(out, before));
    EXPECT_EQ(foresight::predictOrientation(good, Vec3(0.0f, 1.0f, 0.0f), AngularFrame::Body, -0.5f, out),
              Status::NegativeTime);
    EXPECT_TRUE(ftest::sameBytes(out, before));
    EXPECT_EQ(foresight::normalizeQuaternion(quatWXYZ(1.0f, 0.0f, kNaN, 0.0f), out), Status::NonFiniteInput);
    EXPECT_TRUE(ftest::sameBytes(out, before));
}

TEST(Orientation, NormalizeQuaternion) {
    Quat out;
    ASSERT_EQ(foresight::normalizeQuaternion(quatWXYZ(0.0f, 3.0f, 0.0f, 4.0f), out), Status::Ok);
    EXPECT_QUAT_NEAR(out, dquatWXYZ(0.0, 0.6, 0.0, 0.8), 1e-7);  // 3-4-5: float division
    // Tiny but non-zero quaternions still normalise (no underflow to zero length).
    ASSERT_EQ(foresight::normalizeQuaternion(quatWXYZ(1e-30f, 0.0f, 0.0f, 0.0f), out), Status::Ok);
    EXPECT_QUAT_NEAR(out, dquatWXYZ(1.0, 0.0, 0.0, 0.0), 1e-7);
}

TEST(Orientation, ResultIsUnitLengthAndMatchesReference) {
    // Random non-normalised starts, angular velocities and times; reference in double.
    std::mt19937 rng(1234u);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_real_distribution<float> time(0.0f, 5.0f);
    for (int i = 0; i < 500; ++i) {
        const Quat start = quatWXYZ(3.0f * unit(rng), 3.0f * unit(rng), 3.0f * unit(rng), 3.0f * unit(rng));
        const Vec3 w(2.0f * unit(rng), 2.0f * unit(rng), 2.0f * unit(rng));
        const float t = time(rng);
        const AngularFrame frame = (i % 2 == 0) ? AngularFrame::Body : AngularFrame::World;
        Quat out;
        const Status status = foresight::predictOrientation(start, w, frame, t, out);
        if (ftest::quatLength(start) == 0.0) continue;
        ASSERT_EQ(status, Status::Ok);
        EXPECT_NEAR(ftest::quatLength(out), 1.0, 1e-6);  // float renormalisation: a few ulps of 1

        DQuat q0 = ftest::toD(start);
        const double len = std::sqrt(q0.w * q0.w + q0.x * q0.x + q0.y * q0.y + q0.z * q0.z);
        q0 = dquatWXYZ(q0.w / len, q0.x / len, q0.y / len, q0.z / len);
        const DVec3 wd = ftest::toD(w);
        const double speed = glm::length(wd);
        const DQuat r = ftest::dAxisAngle(wd / speed, speed * static_cast<double>(t));
        const DQuat expected = frame == AngularFrame::Body ? ftest::dMul(q0, r) : ftest::dMul(r, q0);
        // float: angle up to 17 rad (ulp 2e-6 at 16) and two products.
        EXPECT_QUAT_NEAR(out, expected, 4e-6) << "case " << i;
    }
}

}  // namespace
