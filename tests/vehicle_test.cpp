// Vehicle prediction: the article's iterated loop (predictVehicleIterative) against a faithful
// double-precision port written here, the closed form (predictVehicleExact) against an
// independent numerical integration, first-order convergence of the loop, reversing, custom
// forward axes, refusals.

#include "test_util.h"

#include <foresight/vehicle.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace {

using foresight::AngularFrame;
using foresight::Quat;
using foresight::Real;
using foresight::RVec3;
using foresight::Status;
using foresight::Vec3;
using foresight::VehicleSettings;
using foresight::VehicleState;
using ftest::DQuat;
using ftest::dquatWXYZ;
using ftest::DVec3;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

VehicleState makeVehicle(RVec3 position, Vec3 velocity, Quat orientation, Vec3 angularVelocity) {
    VehicleState s;
    s.position = position;
    s.velocity = velocity;
    s.orientation = orientation;
    s.angularVelocity = angularVelocity;
    return s;
}

VehicleSettings makeSettings(AngularFrame frame, Vec3 forward = Vec3(0.0f, 0.0f, 1.0f)) {
    VehicleSettings s;
    s.frame = frame;
    s.forward = forward;
    return s;
}

struct DVehicle {
    DVec3 position;
    DVec3 velocity;
    DQuat orientation;
};

/// The rotation made by angular velocity `w` during `dt`, in double (identity for w = 0).
DQuat dRotation(const DVec3& w, double dt) {
    const double speed = glm::length(w);
    if (speed == 0.0) return dquatWXYZ(1.0, 0.0, 0.0, 0.0);
    return ftest::dAxisAngle(w / speed, speed * dt);
}

DQuat dNormalize(const DQuat& q) {
    const double len = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return dquatWXYZ(q.w / len, q.x / len, q.y / len, q.z / len);
}

/// The article's signed speed rule: |v|, negated when v points backwards at the start.
double dSignedSpeed(const DVec3& velocity, const DQuat& orientation, const DVec3& forwardLocal) {
    const double speed = glm::length(velocity);
    return glm::dot(velocity, ftest::dRotate(orientation, forwardLocal)) < 0.0 ? -speed : speed;
}

/// A faithful port of the article's VehicleMovementPrediction, in double:
///   DeltaTime = PredictionTime / NumberOfIterations;
///   for i in 1..N: Position = Position + LinearVelocity * DeltaTime;
///                  Orientation = Orientation * RotationFromAngularVelocity(DeltaTime);
///                  LinearVelocity = Orientation * (0, 0, LinearVelocity.magnitude);
/// with the documented extensions: the speed keeps the sign it has at the start (a reversing
/// vehicle keeps reversing), a configurable forward axis and the World frame (r * q).
DVehicle articleVehicle(const VehicleState& start, float time, int iterations, const VehicleSettings& settings) {
    const DVec3 forward = glm::normalize(ftest::toD(settings.forward));
    DVehicle s{ftest::toD(start.position), ftest::toD(start.velocity), dNormalize(ftest::toD(start.orientation))};
    const double speed = dSignedSpeed(s.velocity, s.orientation, forward);
    const double dt = static_cast<double>(time) / iterations;
    const DQuat r = dRotation(ftest::toD(start.angularVelocity), dt);
    for (int i = 1; i <= iterations; ++i) {
        s.position += s.velocity * dt;
        s.orientation =
            settings.frame == AngularFrame::Body ? ftest::dMul(s.orientation, r) : ftest::dMul(r, s.orientation);
        s.velocity = ftest::dRotate(s.orientation, forward * speed);
    }
    return s;
}

/// Independent reference of the exact model: p(T) = p0 + speed * integral_0^T q(t) forward dt
/// with q(t) = q0 * R(w t) (Body) or R(w t) * q0 (World), integrated with Simpson's rule
/// (RK4 of dp/dt = f(t) with f independent of p) over `intervals` sub-steps, in double.
DVehicle integratedVehicle(const VehicleState& start, float time, const VehicleSettings& settings, int intervals) {
    const DVec3 forward = glm::normalize(ftest::toD(settings.forward));
    const DQuat q0 = dNormalize(ftest::toD(start.orientation));
    const DVec3 w = ftest::toD(start.angularVelocity);
    const double speed = dSignedSpeed(ftest::toD(start.velocity), q0, forward);
    const double T = static_cast<double>(time);
    auto orientationAt = [&](double t) {
        const DQuat r = dRotation(w, t);
        return settings.frame == AngularFrame::Body ? ftest::dMul(q0, r) : ftest::dMul(r, q0);
    };
    auto velocityAt = [&](double t) { return ftest::dRotate(orientationAt(t), forward * speed); };
    const double h = T / intervals;
    DVec3 sum(0.0);
    DVec3 left = velocityAt(0.0);
    for (int i = 0; i < intervals; ++i) {
        const double t = h * i;
        const DVec3 right = velocityAt(t + h);
        sum += left + 4.0 * velocityAt(t + 0.5 * h) + right;
        left = right;
    }
    DVehicle s;
    s.position = ftest::toD(start.position) + sum * (h / 6.0);
    s.orientation = orientationAt(T);
    s.velocity = velocityAt(T);
    return s;
}

// ---------------------------------------------------------------------------------------------
// (1) One iteration by hand.

TEST(VehicleIterative, OneIterationIsOneLinearStepPlusRotation) {
    // Start at (1, 0, 2) moving at (6, 0, 8) (|v| = 10, not on the forward axis), identity
    // orientation, yawing 0.5 rad/s about +Y, for 2 s in one iteration:
    //   position = p + v t = (13, 0, 18)   (the first step uses the given velocity)
    //   orientation = rotation of 1 rad about +Y = (cos 0.5, 0, sin 0.5, 0)
    //   velocity = 10 * (orientation applied to +Z) = 10 * (sin 1, 0, cos 1)
    const VehicleState start = makeVehicle(RVec3(Real(1), Real(0), Real(2)), Vec3(6.0f, 0.0f, 8.0f),
                                           glm::identity<Quat>(), Vec3(0.0f, 0.5f, 0.0f));
    for (const AngularFrame frame : {AngularFrame::Body, AngularFrame::World}) {
        VehicleState out;
        ASSERT_EQ(foresight::predictVehicleIterative(start, 2.0f, 1, makeSettings(frame), out), Status::Ok);
        EXPECT_VEC_NEAR(out.position, DVec3(13.0, 0.0, 18.0), 1e-5);  // float, values ~18
        EXPECT_QUAT_NEAR(out.orientation, dquatWXYZ(std::cos(0.5), 0.0, std::sin(0.5), 0.0), 1e-6);   // float trig
        EXPECT_VEC_NEAR(out.velocity, DVec3(10.0 * std::sin(1.0), 0.0, 10.0 * std::cos(1.0)), 1e-5);  // float, |v| = 10
        EXPECT_VEC_NEAR(out.angularVelocity, DVec3(0.0, 0.5, 0.0), 0.0);  // carried unchanged
    }
}

TEST(VehicleIterative, SignedSpeed) {
    EXPECT_FLOAT_EQ(foresight::signedVehicleSpeed(Vec3(3.0f, 0.0f, 4.0f), Vec3(0.0f, 0.0f, 1.0f)), 5.0f);
    EXPECT_FLOAT_EQ(foresight::signedVehicleSpeed(Vec3(3.0f, 0.0f, -4.0f), Vec3(0.0f, 0.0f, 1.0f)), -5.0f);
    EXPECT_FLOAT_EQ(foresight::signedVehicleSpeed(Vec3(0.0f, 0.0f, -2.0f), Vec3(0.0f, 0.0f, -1.0f)), 2.0f);
    // Perpendicular: dot = 0 is not "backwards".
    EXPECT_FLOAT_EQ(foresight::signedVehicleSpeed(Vec3(7.0f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f)), 7.0f);
}

// ---------------------------------------------------------------------------------------------
// (2) The loop against the article port.

TEST(VehicleIterative, MatchesArticlePort) {
    struct Case {
        const char* what;
        VehicleState start;
        AngularFrame frame;
        Vec3 forward;
        float time;
    };
    const Quat tilted = glm::angleAxis(0.7f, glm::normalize(Vec3(1.0f, 2.0f, 3.0f)));
    const Case cases[] = {
        {"article car",
         makeVehicle(RVec3(Real(0)), Vec3(0.0f, 0.0f, 10.0f), glm::identity<Quat>(), Vec3(0.0f, 0.5f, 0.0f)),
         AngularFrame::Body, Vec3(0.0f, 0.0f, 1.0f), 2.0f},
        {"off-axis velocity, tilted, body",
         makeVehicle(RVec3(Real(5), Real(1), Real(-3)), Vec3(2.0f, 1.0f, 9.0f), tilted, Vec3(0.3f, 0.8f, -0.2f)),
         AngularFrame::Body, Vec3(0.0f, 0.0f, 1.0f), 2.5f},
        {"off-axis velocity, tilted, world",
         makeVehicle(RVec3(Real(5), Real(1), Real(-3)), Vec3(2.0f, 1.0f, 9.0f), tilted, Vec3(0.3f, 0.8f, -0.2f)),
         AngularFrame::World, Vec3(0.0f, 0.0f, 1.0f), 2.5f},
        {"reversing",
         makeVehicle(RVec3(Real(0)), Vec3(0.0f, 0.0f, -6.0f), glm::identity<Quat>(), Vec3(0.0f, -0.7f, 0.0f)),
         AngularFrame::Body, Vec3(0.0f, 0.0f, 1.0f), 1.5f},
        {"forward +X", makeVehicle(RVec3(Real(0)), Vec3(8.0f, 0.0f, 1.0f), tilted, Vec3(0.0f, 0.4f, 0.1f)),
         AngularFrame::Body, Vec3(1.0f, 0.0f, 0.0f), 2.0f},
    };
    for (const Case& c : cases) {
        for (const int n : {1, 4, 16}) {
            VehicleState out;
            ASSERT_EQ(foresight::predictVehicleIterative(c.start, c.time, n, makeSettings(c.frame, c.forward), out),
                      Status::Ok);
            const DVehicle ref = articleVehicle(c.start, c.time, n, makeSettings(c.frame, c.forward));
            // float positions ~25 m over up to 16 steps (ulp 1.9e-6 each) plus the heading's
            // float rounding (~1e-6 rad per composition) times the distance: < 1e-4 m.
            EXPECT_VEC_NEAR(out.position, ref.position, 1e-4) << c.what << " N=" << n;
            EXPECT_VEC_NEAR(out.velocity, ref.velocity, 2e-5) << c.what << " N=" << n;         // |v| <= 10, float
            EXPECT_QUAT_NEAR(out.orientation, ref.orientation, 4e-6) << c.what << " N=" << n;  // 16 float products
        }
    }
}

// ---------------------------------------------------------------------------------------------
// (3) First-order convergence of the loop to the exact arc.

TEST(VehicleIterative, ConvergesFirstOrderToExact) {
    // 10 m/s, 0.5 rad/s about +Y, 2 s (the article's car): a 20 m radius arc of 1 rad.
    const VehicleState start =
        makeVehicle(RVec3(Real(0)), Vec3(0.0f, 0.0f, 10.0f), glm::identity<Quat>(), Vec3(0.0f, 0.5f, 0.0f));
    const VehicleSettings settings = makeSettings(AngularFrame::Body);
    VehicleState exact;
    ASSERT_EQ(foresight::predictVehicleExact(start, 2.0f, settings, exact), Status::Ok);
    // Closed form of the arc (independent): x = R (1 - cos 1), z = R sin 1 with R = 20 m.
    EXPECT_VEC_NEAR(exact.position, DVec3(20.0 * (1.0 - std::cos(1.0)), 0.0, 20.0 * std::sin(1.0)),
                    2e-5);  // float, 17 m

    auto error = [&](int n) {
        VehicleState out;
        EXPECT_EQ(foresight::predictVehicleIterative(start, 2.0f, n, settings, out), Status::Ok);
        return glm::length(ftest::toD(out.position) - ftest::toD(exact.position));
    };
    for (const int n : {16, 32, 64}) {
        const double ratio = error(n) / error(2 * n);
        EXPECT_GE(ratio, 1.6) << "N=" << n;
        EXPECT_LE(ratio, 2.4) << "N=" << n;
    }
    // The same in the double port against the integration (the method's own behaviour).
    const DVehicle reference = integratedVehicle(start, 2.0f, settings, 1000);
    for (const int n : {1, 4, 16, 64}) {
        const double libraryError = error(n);
        const double portError = glm::length(articleVehicle(start, 2.0f, n, settings).position - reference.position);
        std::printf("[ vehicle ] article loop, 10 m/s, 0.5 rad/s, 2 s: N=%2d error %.6f m (double port %.6f m)\n", n,
                    libraryError, portError);
        ::testing::Test::RecordProperty("vehicle_error_N" + std::to_string(n), std::to_string(libraryError));
        // float result vs double port: the same first-order error.
        EXPECT_NEAR(libraryError, portError, 1e-4) << "N=" << n;  // float positions ~17 m
    }
    // The article's 4 iterations are about 2 m off: the heading lags by half a step on average.
    const double e4 = error(4);
    EXPECT_GT(e4, 1.5);
    EXPECT_LT(e4, 3.0);
}

// ---------------------------------------------------------------------------------------------
// (4) The closed form against an independent integration.

TEST(VehicleExact, MatchesNumericalIntegration) {
    const Quat tilted = glm::angleAxis(0.7f, glm::normalize(Vec3(1.0f, 2.0f, 3.0f)));
    struct Case {
        const char* what;
        Vec3 angularVelocity;
        float time;
    };
    const Case cases[] = {
        {"tilted w", Vec3(0.3f, 0.8f, -0.2f), 3.0f},
        {"more than a turn", Vec3(-0.5f, 2.0f, 0.9f), 4.0f},
        {"roll only", Vec3(0.0f, 0.0f, 1.3f), 2.0f},
    };
    for (const Case& c : cases) {
        for (const AngularFrame frame : {AngularFrame::Body, AngularFrame::World}) {
            // Velocity on the (tilted) forward axis at 12 m/s, from a non-origin start.
            const Vec3 velocity = tilted * Vec3(0.0f, 0.0f, 12.0f);
            const VehicleState start =
                makeVehicle(RVec3(Real(3), Real(-1), Real(4)), velocity, tilted, c.angularVelocity);
            const VehicleSettings settings = makeSettings(frame);
            VehicleState out;
            ASSERT_EQ(foresight::predictVehicleExact(start, c.time, settings, out), Status::Ok);
            const DVehicle ref = integratedVehicle(start, c.time, settings, 100000);
            EXPECT_VEC_NEAR(out.position, ref.position, 1e-3)
                << c.what << (frame == AngularFrame::Body ? " body" : " world");
            // Velocity stays on the forward axis with the same speed; orientation is q0 * R(w t).
            EXPECT_VEC_NEAR(out.velocity, ref.velocity, 1e-4) << c.what;         // |v| = 12, float trig
            EXPECT_QUAT_NEAR(out.orientation, ref.orientation, 2e-6) << c.what;  // float, angle <= 9 rad
        }
    }
}

TEST(VehicleExact, AcrossAngularSpeedMagnitudes) {
    // Covers the switch between the series and the closed form: |w| t from 2e-9 to 20 rad.
    const Vec3 axis = glm::normalize(Vec3(0.2f, 1.0f, -0.3f));
    const Quat start = glm::angleAxis(-0.4f, glm::normalize(Vec3(0.0f, 1.0f, 1.0f)));
    for (const float magnitude : {1e-9f, 1e-6f, 1e-4f, 1e-3f, 1e-2f, 0.1f, 1.0f, 10.0f}) {
        for (const AngularFrame frame : {AngularFrame::Body, AngularFrame::World}) {
            const VehicleState s =
                makeVehicle(RVec3(Real(0)), start * Vec3(0.0f, 0.0f, 10.0f), start, axis * magnitude);
            VehicleState out;
            ASSERT_EQ(foresight::predictVehicleExact(s, 2.0f, makeSettings(frame), out), Status::Ok);
            const DVehicle ref = integratedVehicle(s, 2.0f, makeSettings(frame), 5000);
            // Simpson with 5000 intervals: error ~ T h^4 |w|^4 v / 180 < 1e-9 m for |w| <= 10.
            // float positions of magnitude <= 20 m: ulp 1.9e-6; the series/closed-form switch
            // must not lose more than a few of them (cancellation in 1 - cos, t - sin/w).
            EXPECT_VEC_NEAR(out.position, ref.position, 2e-5) << "|w|=" << magnitude;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// (5) Small angular velocity: a straight line.

TEST(Vehicle, SmallAngularVelocityIsAStraightLine) {
    for (const float w : {1e-7f, 0.0f}) {
        const VehicleState start = makeVehicle(RVec3(Real(1), Real(2), Real(3)), Vec3(0.0f, 0.0f, 10.0f),
                                               glm::identity<Quat>(), Vec3(0.0f, w, 0.0f));
        // p + v t = (1, 2, 23); the arc deviates by v w t^2 / 2 = 2e-6 m for w = 1e-7.
        VehicleState exact;
        VehicleState iterative;
        ASSERT_EQ(foresight::predictVehicleExact(start, 2.0f, makeSettings(AngularFrame::Body), exact), Status::Ok);
        ASSERT_EQ(foresight::predictVehicleIterative(start, 2.0f, 4, makeSettings(AngularFrame::Body), iterative),
                  Status::Ok);
        // float positions ~23 m (ulp 1.9e-6) plus the 2e-6 m true deviation.
        EXPECT_VEC_NEAR(exact.position, DVec3(1.0, 2.0, 23.0), 1e-5) << "w=" << w;
        EXPECT_VEC_NEAR(iterative.position, DVec3(1.0, 2.0, 23.0), 1e-5) << "w=" << w;
        ASSERT_TRUE(ftest::finite(exact.orientation));
        EXPECT_VEC_NEAR(exact.velocity, DVec3(0.0, 0.0, 10.0), 1e-5);
        EXPECT_VEC_NEAR(iterative.velocity, DVec3(0.0, 0.0, 10.0), 1e-5);
    }
}

TEST(Vehicle, TimeZeroKeepsThePosition) {
    const Quat q = glm::angleAxis(0.3f, Vec3(0.0f, 1.0f, 0.0f));
    const VehicleState start =
        makeVehicle(RVec3(Real(4), Real(5), Real(6)), q * Vec3(0.0f, 0.0f, 3.0f), q, Vec3(0.1f, 0.2f, 0.3f));
    VehicleState out;
    ASSERT_EQ(foresight::predictVehicleExact(start, 0.0f, makeSettings(AngularFrame::Body), out), Status::Ok);
    EXPECT_VEC_NEAR(out.position, start.position, 0.0);
    EXPECT_QUAT_NEAR(out.orientation, q, 1e-7);  // renormalised unit quaternion
    ASSERT_EQ(foresight::predictVehicleIterative(start, 0.0f, 4, makeSettings(AngularFrame::Body), out), Status::Ok);
    EXPECT_VEC_NEAR(out.position, start.position, 0.0);
    EXPECT_QUAT_NEAR(out.orientation, q, 1e-7);
}

// ---------------------------------------------------------------------------------------------
// (6) Reversing.

TEST(Vehicle, ReversingVehicleKeepsReversing) {
    // Velocity (0, 0, -10) against forward +Z: speed -10. Yawing 0.5 rad/s for 1 s.
    const VehicleState start =
        makeVehicle(RVec3(Real(0)), Vec3(0.0f, 0.0f, -10.0f), glm::identity<Quat>(), Vec3(0.0f, 0.5f, 0.0f));
    const VehicleSettings settings = makeSettings(AngularFrame::Body);
    // Closed form: forward(t) = (sin wt, 0, cos wt), displacement = speed * integral:
    //   -10 * ((1 - cos 0.5) / 0.5, 0, sin 0.5 / 0.5).
    const DVec3 expected = -10.0 * DVec3((1.0 - std::cos(0.5)) / 0.5, 0.0, std::sin(0.5) / 0.5);
    VehicleState exact;
    ASSERT_EQ(foresight::predictVehicleExact(start, 1.0f, settings, exact), Status::Ok);
    EXPECT_VEC_NEAR(exact.position, expected, 1e-5);  // float, ~10 m
    // The final velocity points backwards along the final forward axis.
    const DVec3 finalForward = ftest::dRotate(ftest::toD(exact.orientation), DVec3(0.0, 0.0, 1.0));
    EXPECT_VEC_NEAR(exact.velocity, -10.0 * finalForward, 1e-5);

    for (const int n : {1, 4, 16}) {
        VehicleState iterative;
        ASSERT_EQ(foresight::predictVehicleIterative(start, 1.0f, n, settings, iterative), Status::Ok);
        EXPECT_LT(iterative.position.z, Real(-8)) << "N=" << n;  // backwards, not forwards
        const DVec3 forward = ftest::dRotate(ftest::toD(iterative.orientation), DVec3(0.0, 0.0, 1.0));
        EXPECT_LT(glm::dot(ftest::toD(iterative.velocity), forward), -9.99) << "N=" << n;  // still reversing
        // And it tends to the same arc, first order: the heading lags by about w dt / 2 over
        // the 10 m travelled, 10 * 0.5 / (2 N) = 2.5 / N m; allow 4 / N.
        EXPECT_VEC_NEAR(iterative.position, expected, 4.0 / n) << "N=" << n;
    }
}

// ---------------------------------------------------------------------------------------------
// (7) Custom forward axis.

TEST(Vehicle, ForwardXIsTheRotatedEquivalentOfForwardZ) {
    // Simple case: identity start, yaw about +Y. A +X-forward vehicle moving along +X is the
    // +Z-forward one rotated by +90 degrees about Y (which maps +Z to +X).
    const DQuat ry90 = ftest::dAxisAngle(DVec3(0.0, 1.0, 0.0), 0.5 * 3.14159265358979323846);
    const VehicleState z =
        makeVehicle(RVec3(Real(0)), Vec3(0.0f, 0.0f, 10.0f), glm::identity<Quat>(), Vec3(0.0f, 0.5f, 0.0f));
    const VehicleState x =
        makeVehicle(RVec3(Real(0)), Vec3(10.0f, 0.0f, 0.0f), glm::identity<Quat>(), Vec3(0.0f, 0.5f, 0.0f));
    for (const bool exact : {true, false}) {
        VehicleState outZ;
        VehicleState outX;
        const VehicleSettings sz = makeSettings(AngularFrame::Body, Vec3(0.0f, 0.0f, 1.0f));
        const VehicleSettings sx = makeSettings(AngularFrame::Body, Vec3(1.0f, 0.0f, 0.0f));
        if (exact) {
            ASSERT_EQ(foresight::predictVehicleExact(z, 2.0f, sz, outZ), Status::Ok);
            ASSERT_EQ(foresight::predictVehicleExact(x, 2.0f, sx, outX), Status::Ok);
        } else {
            ASSERT_EQ(foresight::predictVehicleIterative(z, 2.0f, 8, sz, outZ), Status::Ok);
            ASSERT_EQ(foresight::predictVehicleIterative(x, 2.0f, 8, sx, outX), Status::Ok);
        }
        // float positions ~20 m.
        EXPECT_VEC_NEAR(outX.position, ftest::dRotate(ry90, ftest::toD(outZ.position)), 2e-5) << exact;
        EXPECT_VEC_NEAR(outX.velocity, ftest::dRotate(ry90, ftest::toD(outZ.velocity)), 2e-5) << exact;
        // Same orientation: both started at identity and turned by the same yaw.
        EXPECT_QUAT_NEAR(outX.orientation, outZ.orientation, 1e-6);
    }
}

TEST(Vehicle, ForwardXWithGeneralOrientationMatchesForwardZ) {
    // General case: C maps local +X to local +Z (-90 degrees about Y). A +Z vehicle with
    // orientation qA is the same physical body as a +X vehicle with qB = qA * C; a body-frame
    // angular velocity wA becomes wB = C^-1 wA (world-frame ones are unchanged). The results
    // then agree in position and velocity, and qB(T) = qA(T) * C.
    const DQuat c = ftest::dAxisAngle(DVec3(0.0, 1.0, 0.0), -0.5 * 3.14159265358979323846);
    const DQuat cInverse = dquatWXYZ(c.w, -c.x, -c.y, -c.z);
    ASSERT_TRUE(ftest::vecNear(ftest::dRotate(c, DVec3(1.0, 0.0, 0.0)), DVec3(0.0, 0.0, 1.0), 1e-12));
    const Quat qA = glm::angleAxis(1.1f, glm::normalize(Vec3(-1.0f, 2.0f, 0.5f)));
    const Quat qB = ftest::toF(ftest::dMul(ftest::toD(qA), c));
    const Vec3 velocity = qA * Vec3(0.5f, -0.5f, 9.0f);  // slightly off the forward axis
    const Vec3 wA(0.2f, -0.6f, 0.3f);
    for (const AngularFrame frame : {AngularFrame::Body, AngularFrame::World}) {
        const Vec3 wB = frame == AngularFrame::Body ? ftest::toF(ftest::dRotate(cInverse, ftest::toD(wA))) : wA;
        const VehicleState a = makeVehicle(RVec3(Real(1), Real(2), Real(3)), velocity, qA, wA);
        const VehicleState b = makeVehicle(RVec3(Real(1), Real(2), Real(3)), velocity, qB, wB);
        const VehicleSettings sa = makeSettings(frame, Vec3(0.0f, 0.0f, 1.0f));
        const VehicleSettings sb = makeSettings(frame, Vec3(1.0f, 0.0f, 0.0f));
        for (const bool exact : {true, false}) {
            VehicleState outA;
            VehicleState outB;
            if (exact) {
                ASSERT_EQ(foresight::predictVehicleExact(a, 2.0f, sa, outA), Status::Ok);
                ASSERT_EQ(foresight::predictVehicleExact(b, 2.0f, sb, outB), Status::Ok);
            } else {
                ASSERT_EQ(foresight::predictVehicleIterative(a, 2.0f, 8, sa, outA), Status::Ok);
                ASSERT_EQ(foresight::predictVehicleIterative(b, 2.0f, 8, sb, outB), Status::Ok);
            }
            // float inputs rounded differently (qB, wB): ~1e-7 rad, times ~20 m.
            EXPECT_VEC_NEAR(outB.position, outA.position, 2e-5) << exact;
            EXPECT_VEC_NEAR(outB.velocity, outA.velocity, 2e-5) << exact;
            EXPECT_QUAT_NEAR(outB.orientation, ftest::dMul(ftest::toD(outA.orientation), c), 2e-6) << exact;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// (8) Refusals.

TEST(Vehicle, RefusalsLeaveOutUntouched) {
    const VehicleState good =
        makeVehicle(RVec3(Real(0)), Vec3(0.0f, 0.0f, 5.0f), glm::identity<Quat>(), Vec3(0.0f, 0.5f, 0.0f));
    VehicleState before =
        makeVehicle(RVec3(Real(-9)), Vec3(-9.0f), ftest::quatWXYZ(0.5f, 0.5f, 0.5f, 0.5f), Vec3(-9.0f));
    const VehicleSettings body = makeSettings(AngularFrame::Body);

    auto expectIterative = [&](const VehicleState& s, float t, int n, const VehicleSettings& settings, Status expected,
                               const char* what) {
        VehicleState out = before;
        EXPECT_EQ(foresight::predictVehicleIterative(s, t, n, settings, out), expected) << what;
        EXPECT_TRUE(ftest::sameBytes(out, before)) << what;
    };
    auto expectExact = [&](const VehicleState& s, float t, const VehicleSettings& settings, Status expected,
                           const char* what) {
        VehicleState out = before;
        EXPECT_EQ(foresight::predictVehicleExact(s, t, settings, out), expected) << what;
        EXPECT_TRUE(ftest::sameBytes(out, before)) << what;
    };

    expectIterative(good, 1.0f, 0, body, Status::InvalidIterations, "0 iterations");
    expectIterative(good, 1.0f, -3, body, Status::InvalidIterations, "negative iterations");
    expectIterative(good, 1.0f, foresight::kMaxVehicleIterations + 1, body, Status::InvalidIterations, "too many");
    expectIterative(good, -1.0f, 4, body, Status::NegativeTime, "negative time");
    expectExact(good, -1.0f, body, Status::NegativeTime, "negative time");

    const VehicleSettings zeroForward = makeSettings(AngularFrame::Body, Vec3(0.0f));
    expectIterative(good, 1.0f, 4, zeroForward, Status::ZeroVector, "zero forward");
    expectExact(good, 1.0f, zeroForward, Status::ZeroVector, "zero forward");

    VehicleState zeroQ = good;
    zeroQ.orientation = ftest::quatWXYZ(0.0f, 0.0f, 0.0f, 0.0f);
    expectIterative(zeroQ, 1.0f, 4, body, Status::ZeroQuaternion, "zero quaternion");
    expectExact(zeroQ, 1.0f, body, Status::ZeroQuaternion, "zero quaternion");

    VehicleState nanPosition = good;
    nanPosition.position.y = std::numeric_limits<Real>::quiet_NaN();
    expectIterative(nanPosition, 1.0f, 4, body, Status::NonFiniteInput, "NaN position");
    expectExact(nanPosition, 1.0f, body, Status::NonFiniteInput, "NaN position");
    VehicleState nanVelocity = good;
    nanVelocity.velocity.x = kNaN;
    expectIterative(nanVelocity, 1.0f, 4, body, Status::NonFiniteInput, "NaN velocity");
    expectExact(nanVelocity, 1.0f, body, Status::NonFiniteInput, "NaN velocity");
    VehicleState nanAngular = good;
    nanAngular.angularVelocity.z = std::numeric_limits<float>::infinity();
    expectIterative(nanAngular, 1.0f, 4, body, Status::NonFiniteInput, "inf angular velocity");
    expectExact(nanAngular, 1.0f, body, Status::NonFiniteInput, "inf angular velocity");
    VehicleState nanQ = good;
    nanQ.orientation.w = kNaN;
    expectIterative(nanQ, 1.0f, 4, body, Status::NonFiniteInput, "NaN quaternion");
    expectExact(nanQ, 1.0f, body, Status::NonFiniteInput, "NaN quaternion");
    expectIterative(good, kNaN, 4, body, Status::NonFiniteInput, "NaN time");
    expectExact(good, kNaN, body, Status::NonFiniteInput, "NaN time");
    expectExact(good, 1.0f, makeSettings(AngularFrame::Body, Vec3(0.0f, kNaN, 1.0f)), Status::NonFiniteInput,
                "NaN forward");
}

TEST(Vehicle, NonNormalisedInputsAreNormalised) {
    // A forward axis of length 3 and an orientation of length 2 mean the same as unit ones.
    const Quat q = glm::angleAxis(0.4f, Vec3(0.0f, 1.0f, 0.0f));
    const Quat q2 = ftest::quatWXYZ(2.0f * q.w, 2.0f * q.x, 2.0f * q.y, 2.0f * q.z);
    const VehicleState unit = makeVehicle(RVec3(Real(0)), q * Vec3(0.0f, 0.0f, 10.0f), q, Vec3(0.0f, 0.5f, 0.0f));
    VehicleState scaled = unit;
    scaled.orientation = q2;
    VehicleState a;
    VehicleState b;
    ASSERT_EQ(foresight::predictVehicleExact(unit, 2.0f, makeSettings(AngularFrame::Body), a), Status::Ok);
    ASSERT_EQ(foresight::predictVehicleExact(scaled, 2.0f, makeSettings(AngularFrame::Body, Vec3(0.0f, 0.0f, 3.0f)), b),
              Status::Ok);
    EXPECT_VEC_NEAR(b.position, a.position, 1e-5);  // float, ~20 m
    EXPECT_NEAR(ftest::quatLength(b.orientation), 1.0, 1e-6);
    EXPECT_NEAR(glm::length(ftest::toD(b.velocity)), 10.0, 1e-5);  // speed kept, not scaled by |forward|
}

TEST(Vehicle, OverflowingResultIsRefused) {
    if constexpr (foresight::kDoublePrecision) {
        GTEST_SKIP() << "double positions do not overflow here";
    } else {
        const VehicleState huge =
            makeVehicle(RVec3(Real(0)), Vec3(0.0f, 0.0f, 3e38f), glm::identity<Quat>(), Vec3(0.0f));
        VehicleState out = huge;
        // 3e38 m/s for 100 s: 3e40 m does not fit a float position.
        EXPECT_EQ(foresight::predictVehicleExact(huge, 100.0f, makeSettings(AngularFrame::Body), out),
                  Status::NonFiniteResult);
        EXPECT_TRUE(ftest::sameBytes(out, huge));
        EXPECT_EQ(foresight::predictVehicleIterative(huge, 100.0f, 4, makeSettings(AngularFrame::Body), out),
                  Status::NonFiniteResult);
        EXPECT_TRUE(ftest::sameBytes(out, huge));
    }
}

}  // namespace
