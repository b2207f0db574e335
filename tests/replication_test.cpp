// Network replication (replication.h): the sender's thresholds, the receiver's smoothing,
// extrapolation limit, bad packets and interpolation, and the batch extrapolation. Built twice,
// against the float and the double library (positions as a game uses them, and geocentric).
//
// References, never the code under test:
// - closed forms of the truth (constant acceleration, constant turn rate) and of the error the
//   DIS models make on it (a t^2 / 2 for FPW on a constant-acceleration truth; r t for a fixed
//   orientation on a constant turn);
// - predictDeadReckoning itself where the contract is "the receiver shows exactly the model's
//   extrapolation" (it has its own tests against RK4 in dead_reckoning_test.cpp);
// - the smoothing formulas of docs/ARCHITECTURE.md written out here in double.

#include "test_util.h"

#include <foresight/replication.h>

#include "replication_batch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace {

using foresight::DeadReckoningAlgorithm;
using foresight::DeadReckoningReceiver;
using foresight::DeadReckoningResult;
using foresight::DeadReckoningSender;
using foresight::DeadReckoningState;
using foresight::Quat;
using foresight::Real;
using foresight::ReceivedPose;
using foresight::ReceiverMode;
using foresight::ReceiverSettings;
using foresight::RVec3;
using foresight::SendDecision;
using foresight::SenderSettings;
using foresight::Smoothing;
using foresight::Status;
using foresight::UpdateOutcome;
using foresight::Vec3;
using foresight::detail::BatchSimd;
using ftest::DQuat;
using ftest::DVec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

using ftest::rv;

DeadReckoningState makeState(DeadReckoningAlgorithm algorithm, const DVec3& position, const DVec3& velocity,
                             const Quat& orientation = glm::identity<Quat>()) {
    DeadReckoningState s;
    s.algorithm = algorithm;
    s.position = ftest::toR(position);
    s.velocity = ftest::toF(velocity);
    s.orientation = orientation;
    return s;
}

DeadReckoningState fpw(const DVec3& position, const DVec3& velocity) {
    return makeState(DeadReckoningAlgorithm::Fpw, position, velocity);
}

Quat yaw(double angle) { return ftest::toF(ftest::dAxisAngle(DVec3(0, 1, 0), angle)); }

// The rotation angle between two quaternions (0 to pi), in double, by acos of |dot| (the
// reference; the library uses atan2).
double angleBetween(const Quat& a, const Quat& b) {
    const DQuat da = glm::normalize(ftest::toD(a));
    const DQuat db = glm::normalize(ftest::toD(b));
    const double d = std::fabs(da.w * db.w + da.x * db.x + da.y * db.y + da.z * db.z);
    return 2.0 * std::acos(std::fmin(1.0, d));
}

// Bit equality of each field (ReceivedPose has padding: no memcmp of the whole).
bool samePose(const ReceivedPose& a, const ReceivedPose& b) {
    return ftest::sameBytes(a.position, b.position) && ftest::sameBytes(a.velocity, b.velocity) &&
           ftest::sameBytes(a.orientation, b.orientation) && a.held == b.held;
}

// What a receiver with Snap must show: predictDeadReckoning from the update's timestamp, the
// velocity turned to world axes for body models.
ReceivedPose expectedPose(const DeadReckoningState& state, float age) {
    DeadReckoningResult r;
    EXPECT_EQ(foresight::predictDeadReckoning(state, age, r), Status::Ok);
    ReceivedPose p;
    p.position = r.position;
    p.orientation = r.orientation;
    p.velocity = r.velocity;
    if (foresight::deadReckoningInBodyAxes(state.algorithm))
        p.velocity = ftest::toF(glm::normalize(ftest::toD(r.orientation)) * ftest::toD(r.velocity));
    return p;
}

ReceivedPose sampled(DeadReckoningReceiver& receiver, double time) {
    ReceivedPose p;
    EXPECT_EQ(receiver.sample(time, p), Status::Ok) << "at " << time;
    return p;
}

// =============================================================================================
// Sender

TEST(Sender, FirstUpdateSendsWithoutErrors) {
    DeadReckoningSender sender;
    EXPECT_FALSE(sender.hasSent());
    SendDecision d;
    ASSERT_EQ(sender.update(3.0, fpw(DVec3(1, 2, 3), DVec3(4, 0, 0)), d), Status::Ok);
    EXPECT_EQ(d.reasons, foresight::SendReasonFirst);
    EXPECT_TRUE(d.send());
    EXPECT_EQ(d.positionError, 0.0f);
    EXPECT_EQ(d.orientationError, 0.0f);
    EXPECT_TRUE(sender.hasSent());
    EXPECT_EQ(sender.lastSentTime(), 3.0);
    EXPECT_EQ(sender.lastSent().position, rv(1, 2, 3));
    // Right after, the receivers' extrapolation is the truth: nothing to send.
    ASSERT_EQ(sender.update(3.0 + 1.0 / 64, fpw(DVec3(1.0 + 4.0 / 64, 2, 3), DVec3(4, 0, 0)), d), Status::Ok);
    EXPECT_EQ(d.reasons, foresight::SendReasonNone);
    EXPECT_FALSE(d.send());
    EXPECT_NEAR(d.positionError, 0.0f, 1e-6f);  // 1/16 and 4/64 are exact; rounding of 1 + 1/16 at most
}

// Truth: constant acceleration a from rest, x = a t^2 / 2, sent with FPW (constant velocity).
// After an update at ts (position and velocity exact), receivers show x(ts) + a ts (t - ts), so
// the error is exactly a (t - ts)^2 / 2: it reaches 1 m when t - ts = sqrt(2 / a).
TEST(Sender, PositionThresholdCrossedWhereTheClosedFormSays) {
    constexpr double a = 3.0;  // [m/s^2]
    constexpr double tick = 1.0 / 60.0;
    // The first tick at or past sqrt(2/3) = 0.8165 s: 49 (48 ticks give an error of 0.96 m,
    // 49 give 1.0004 m: margins far above float rounding of positions up to 150 m, 1.5e-5 m).
    const int expectedGap = static_cast<int>(std::ceil(std::sqrt(2.0 / a) / tick));
    ASSERT_EQ(expectedGap, 49);
    DeadReckoningSender sender;
    std::vector<int> sendTicks;
    for (int k = 0; k <= 600; ++k) {
        const double t = k * tick;
        SendDecision d;
        ASSERT_EQ(sender.update(t, fpw(DVec3(0.5 * a * t * t, 0, 0), DVec3(a * t, 0, 0)), d), Status::Ok);
        if (k == 0) continue;
        const double sinceSend = t - sender.lastSentTime();
        if (d.send()) {
            sendTicks.push_back(k);
            EXPECT_EQ(d.reasons, foresight::SendReasonPosition) << k;
            // The error before sending: a gap^2/2 with gap = 49 ticks. Float positions up to
            // 150 m (spacing 1.5e-5) and float velocities (relative 6e-8): 1e-4 m.
            EXPECT_NEAR(d.positionError, 0.5 * a * (expectedGap * tick) * (expectedGap * tick), 1e-4) << k;
        } else {
            EXPECT_NEAR(d.positionError, 0.5 * a * sinceSend * sinceSend, 1e-4) << k;
        }
    }
    ASSERT_EQ(sendTicks.size(), 600u / 49u);  // ticks 49, 98, ..., 588
    for (std::size_t i = 0; i < sendTicks.size(); ++i) EXPECT_EQ(sendTicks[i], static_cast<int>(i + 1) * expectedGap);
}

// Truth: a constant turn at r about +Y, sent with FPW (fixed orientation). The error after an
// update at ts is the rotation angle r (t - ts): it reaches 3 degrees at t - ts = 3 deg / r.
TEST(Sender, OrientationThresholdCrossedAtAConstantTurnRate) {
    constexpr double r = 0.1;  // [rad/s]
    constexpr double tick = 1.0 / 60.0;
    const double threshold = static_cast<double>(SenderSettings{}.orientationThreshold);
    EXPECT_NEAR(threshold, 3.0 * kDegree, 4e-9);  // 3 degrees to float rounding (half an ulp: 1.9e-9)
    // 3 deg / 0.1 rad/s = 0.5236 s = 31.4 ticks: the 32nd tick (31 ticks: 0.0517 rad, 7e-4
    // below; float quaternions resolve 1e-7 rad).
    const int expectedGap = static_cast<int>(std::ceil(threshold / r / tick));
    ASSERT_EQ(expectedGap, 32);
    DeadReckoningSender sender;
    int sends = 0;
    for (int k = 0; k <= 200; ++k) {
        const double t = k * tick;
        DeadReckoningState truth = fpw(DVec3(5, 0, 5), DVec3(0));
        truth.orientation = yaw(r * t);
        SendDecision d;
        ASSERT_EQ(sender.update(t, truth, d), Status::Ok);
        if (k == 0) continue;
        if (d.send()) {
            ++sends;
            EXPECT_EQ(k, sends * expectedGap);
            EXPECT_EQ(d.reasons, foresight::SendReasonOrientation);
            // float quaternions: the angle to ~1e-7 rad; 1e-6 leaves a factor 10.
            EXPECT_NEAR(d.orientationError, r * expectedGap * tick, 1e-6);
        }
    }
    EXPECT_EQ(sends, 200 / 32);
}

TEST(Sender, RotatingModelThatMatchesTheTurnSendsOnlyHeartbeats) {
    // The same turn sent with RPW and the true angular velocity: the model is exact, only the
    // heartbeat sends (at 5 s, 10 s). Ticks of 1/64 s: times exact.
    DeadReckoningSender sender;
    for (int k = 0; k <= 64 * 12; ++k) {
        const double t = k / 64.0;
        DeadReckoningState truth = makeState(DeadReckoningAlgorithm::Rpw, DVec3(0), DVec3(0), yaw(0.7 * t));
        truth.angularVelocity = Vec3(0.0f, 0.7f, 0.0f);
        SendDecision d;
        ASSERT_EQ(sender.update(t, truth, d), Status::Ok);
        // 0.7f differs from 0.7 by 1.2e-8 rad/s: 6e-8 rad after 5 s, plus float quaternion
        // rounding (1e-7): far below 3 degrees.
        EXPECT_LT(d.orientationError, 1e-5f);
        if (k == 0) continue;
        const bool heartbeat = k % (64 * 5) == 0;
        EXPECT_EQ(d.reasons, heartbeat ? foresight::SendReasonHeartbeat : foresight::SendReasonNone) << t;
    }
}

TEST(Sender, HeartbeatEveryFiveSecondsForAStaticEntity) {
    DeadReckoningSender sender;
    std::vector<double> sendTimes;
    for (int k = 0; k <= 64 * 20; ++k) {
        const double t = k / 64.0;  // exact
        SendDecision d;
        ASSERT_EQ(sender.update(t, makeState(DeadReckoningAlgorithm::Static, DVec3(7, 1, -2), DVec3(0)), d),
                  Status::Ok);
        EXPECT_EQ(d.positionError, 0.0f);
        if (d.send()) {
            sendTimes.push_back(t);
            EXPECT_EQ(d.reasons, k == 0 ? foresight::SendReasonFirst : foresight::SendReasonHeartbeat) << t;
        }
    }
    EXPECT_EQ(sendTimes, (std::vector<double>{0.0, 5.0, 10.0, 15.0, 20.0}));
}

TEST(Sender, ReasonsAreBits) {
    DeadReckoningSender sender;
    SendDecision d;
    ASSERT_EQ(sender.update(0.0, fpw(DVec3(0), DVec3(0)), d), Status::Ok);
    // Jumped 2 m and turned 10 degrees: both bits.
    DeadReckoningState moved = fpw(DVec3(2, 0, 0), DVec3(0));
    moved.orientation = yaw(10 * kDegree);
    ASSERT_EQ(sender.update(0.5, moved, d), Status::Ok);
    EXPECT_EQ(d.reasons, foresight::SendReasonPosition | foresight::SendReasonOrientation);
    EXPECT_NEAR(d.positionError, 2.0f, 1e-6f);            // exact inputs
    EXPECT_NEAR(d.orientationError, 10 * kDegree, 1e-6);  // float quaternion
    // The same pose with another algorithm: only the algorithm bit.
    DeadReckoningState rvw = moved;
    rvw.algorithm = DeadReckoningAlgorithm::Rvw;
    ASSERT_EQ(sender.update(1.0, rvw, d), Status::Ok);
    EXPECT_EQ(d.reasons, foresight::SendReasonAlgorithm);
    // 5 s later, 3 m off: heartbeat and position.
    DeadReckoningState far = rvw;
    far.position = rv(5, 0, 0);
    ASSERT_EQ(sender.update(6.0, far, d), Status::Ok);
    EXPECT_EQ(d.reasons, foresight::SendReasonPosition | foresight::SendReasonHeartbeat);
}

TEST(Sender, OrientationErrorIsTheTrueRotationAngleUpToPi) {
    DeadReckoningSender sender;
    SendDecision d;
    ASSERT_EQ(sender.update(0.0, fpw(DVec3(0), DVec3(0)), d), Status::Ok);
    // Half a turn: pi exactly (acos would be at its worst here), never NaN.
    DeadReckoningState turned = fpw(DVec3(0), DVec3(0));
    turned.orientation = ftest::quatWXYZ(0.0f, 0.0f, 1.0f, 0.0f);
    ASSERT_EQ(sender.update(0.1, turned, d), Status::Ok);
    EXPECT_FLOAT_EQ(d.orientationError, static_cast<float>(kPi));
    // The same rotation with the opposite sign, not normalised (q and -2q): no error.
    DeadReckoningSender second;
    DeadReckoningState s = fpw(DVec3(0), DVec3(0));
    s.orientation = yaw(1.0);
    ASSERT_EQ(second.update(0.0, s, d), Status::Ok);
    s.orientation = -2.0f * s.orientation;
    ASSERT_EQ(second.update(0.1, s, d), Status::Ok);
    EXPECT_LT(d.orientationError, 1e-6f);  // float normalisation of the two: a few 1e-8
    EXPECT_EQ(d.reasons, foresight::SendReasonNone);
}

TEST(Sender, TimeWentBackwardsIsRefusedAndChangesNothing) {
    DeadReckoningSender sender;
    SendDecision d;
    ASSERT_EQ(sender.update(1.0, fpw(DVec3(0), DVec3(1, 0, 0)), d), Status::Ok);
    ASSERT_EQ(sender.update(1.5, fpw(DVec3(0.5, 0, 0), DVec3(1, 0, 0)), d), Status::Ok);
    SendDecision untouched;
    untouched.reasons = 0xAA;
    EXPECT_EQ(sender.update(1.25, fpw(DVec3(9, 0, 0), DVec3(0)), untouched), Status::TimeWentBackwards);
    EXPECT_EQ(untouched.reasons, 0xAA);
    EXPECT_EQ(sender.lastSentTime(), 1.0);
    // The same time again is fine (a second look in the same tick).
    EXPECT_EQ(sender.update(1.5, fpw(DVec3(0.5, 0, 0), DVec3(1, 0, 0)), d), Status::Ok);
    EXPECT_EQ(d.reasons, foresight::SendReasonNone);
}

TEST(Sender, RefusalsLeaveTheDecisionUntouched) {
    SendDecision untouched;
    untouched.reasons = 0x55;
    // Settings: each field zero, negative, NaN, infinite.
    for (const float bad :
         {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        for (int field = 0; field < 3; ++field) {
            SenderSettings settings;
            (field == 0   ? settings.positionThreshold
             : field == 1 ? settings.orientationThreshold
                          : settings.heartbeat) = bad;
            EXPECT_EQ(foresight::validateSenderSettings(settings), Status::InvalidSetting) << field << " " << bad;
            DeadReckoningSender sender(settings);
            EXPECT_EQ(sender.update(0.0, fpw(DVec3(0), DVec3(0)), untouched), Status::InvalidSetting);
        }
    }
    EXPECT_EQ(foresight::validateSenderSettings(SenderSettings{}), Status::Ok);
    DeadReckoningSender sender;
    EXPECT_EQ(sender.update(kNaN, fpw(DVec3(0), DVec3(0)), untouched), Status::NonFiniteInput);
    EXPECT_EQ(sender.update(kInfinity, fpw(DVec3(0), DVec3(0)), untouched), Status::NonFiniteInput);
    DeadReckoningState zero = fpw(DVec3(0), DVec3(0));
    zero.orientation = ftest::quatWXYZ(0, 0, 0, 0);
    EXPECT_EQ(sender.update(0.0, zero, untouched), Status::ZeroQuaternion);
    DeadReckoningState nan = fpw(DVec3(0), DVec3(0));
    nan.velocity.y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(sender.update(0.0, nan, untouched), Status::NonFiniteInput);
    DeadReckoningState unknown = fpw(DVec3(0), DVec3(0));
    unknown.algorithm = static_cast<DeadReckoningAlgorithm>(10);
    EXPECT_EQ(sender.update(0.0, unknown, untouched), Status::InvalidAlgorithm);
    EXPECT_EQ(untouched.reasons, 0x55);
    EXPECT_FALSE(sender.hasSent());
}

TEST(Sender, ResetSendsFirstAgainAndHugeGapsSaturate) {
    DeadReckoningSender sender;
    SendDecision d;
    ASSERT_EQ(sender.update(0.0, fpw(DVec3(0), DVec3(1e30, 0, 0)), d), Status::Ok);
    // 1e300 s later the extrapolation overflows: sent, the error saturates (no infinity).
    ASSERT_EQ(sender.update(1e300, fpw(DVec3(0), DVec3(0)), d), Status::Ok);
    EXPECT_EQ(d.reasons, foresight::SendReasonPosition | foresight::SendReasonHeartbeat);
    EXPECT_EQ(d.positionError, std::numeric_limits<float>::max());
    EXPECT_EQ(d.orientationError, 0.0f);
    sender.reset();
    EXPECT_FALSE(sender.hasSent());
    ASSERT_EQ(sender.update(0.0, fpw(DVec3(0), DVec3(0)), d), Status::Ok);  // time may restart
    EXPECT_EQ(d.reasons, foresight::SendReasonFirst);
}

// =============================================================================================
// Receiver, Extrapolate mode

// Updates of a constant-acceleration truth (exact for RVW/FVW), stamped every 0.1 s, arriving
// 0.08 s late. With Snap the shown pose is the model extrapolated from the timestamp, bit for
// bit, so it matches the truth whatever the latency.
TEST(Receiver, SnapShowsTheExtrapolationFromTheTimestampNotTheReceipt) {
    ReceiverSettings settings;
    settings.smoothing = Smoothing::Snap;
    DeadReckoningReceiver receiver(settings);
    const DVec3 v0(3, 2, -1), a(0, -2, 0.5);
    auto truthAt = [&](double t) { return v0 * t + 0.5 * a * t * t; };
    auto stateAt = [&](double t) {
        DeadReckoningState s = makeState(DeadReckoningAlgorithm::Fvw, truthAt(t), v0 + a * t, yaw(0.3));
        s.acceleration = ftest::toF(a);
        return s;
    };
    constexpr double latency = 0.08;
    for (int k = 0; k < 20; ++k) {
        const double stamp = k * 0.1;
        const UpdateOutcome outcome = receiver.receive(stamp, stateAt(stamp), stamp + latency);
        EXPECT_EQ(outcome, UpdateOutcome::Snapped);
        for (const double dt : {0.0, 0.03, 0.0999}) {
            const double t = stamp + latency + dt;
            const ReceivedPose shown = sampled(receiver, t);
            EXPECT_TRUE(samePose(shown, expectedPose(stateAt(stamp), static_cast<float>(t - stamp)))) << t;
            // Against the truth: float positions below 10 m (1e-6) and float velocities: 1e-5.
            // Extrapolating from the receipt time would be 0.08 s * 3.7 m/s = 0.3 m off.
            EXPECT_VEC_NEAR(shown.position, truthAt(t), 1e-5) << t;
            EXPECT_VEC_NEAR(shown.velocity, v0 + a * t, 1e-5) << t;
            EXPECT_FALSE(shown.held);
        }
    }
    EXPECT_EQ(receiver.counters().snaps, 20u);
    EXPECT_EQ(receiver.counters().accepted, 20u);
}

TEST(Receiver, BodyModelVelocityIsReportedInWorldAxes) {
    ReceiverSettings settings;
    settings.smoothing = Smoothing::Snap;
    DeadReckoningReceiver receiver(settings);
    // Facing +X (yaw 90 degrees maps body +Z to world +X), moving forward at 4 m/s in body axes.
    DeadReckoningState s = makeState(DeadReckoningAlgorithm::Fpb, DVec3(1, 0, 0), DVec3(0, 0, 4), yaw(kPi / 2));
    ASSERT_EQ(receiver.receive(0.0, s, 0.0), UpdateOutcome::Snapped);
    const ReceivedPose p = sampled(receiver, 0.125);
    EXPECT_VEC_NEAR(p.velocity, DVec3(4, 0, 0), 1e-6);  // float rotation of 4 m/s
    EXPECT_VEC_NEAR(p.position, DVec3(1.5, 0, 0), 1e-6);
}

// One correction for every smoothing: an entity at 5 m/s along +X (FPW, update every 0.2 s);
// the update at t = 1 disagrees (0.6 m further, 0.4 m aside, now 5 m/s with 1 m/s sideways, and
// turned 0.2 rad). Receipt at the timestamp.
struct Correction {
    DeadReckoningState before = fpw(DVec3(4, 0, 0), DVec3(5, 0, 0));  // stamped 0.8
    DeadReckoningState after = [] {
        DeadReckoningState s = fpw(DVec3(5.6, 0.4, 0), DVec3(5, 1, 0));
        s.orientation = yaw(0.2);
        return s;
    }();
    double distance = std::sqrt(0.6 * 0.6 + 0.4 * 0.4);  // the jump at t = 1
};

class Smoothings : public ::testing::TestWithParam<Smoothing> {};

TEST_P(Smoothings, ContinuousAtTheCorrectionAndConvergedAfterIt) {
    const Correction c;
    ReceiverSettings settings;
    settings.smoothing = GetParam();
    settings.extrapolationLimit = 10.0f;  // the comparisons below extrapolate up to 1.2 s
    DeadReckoningReceiver receiver(settings);
    ASSERT_EQ(receiver.receive(0.8, c.before, 0.8), UpdateOutcome::Snapped);
    const ReceivedPose justBefore = sampled(receiver, 1.0);
    EXPECT_VEC_NEAR(justBefore.position, DVec3(5, 0, 0), 1e-6);
    const UpdateOutcome outcome = receiver.receive(1.0, c.after, 1.0);
    const ReceivedPose justAfter = sampled(receiver, 1.0);
    const double jump = glm::length(ftest::toD(justAfter.position) - ftest::toD(justBefore.position));
    if (GetParam() == Smoothing::Snap) {
        EXPECT_EQ(outcome, UpdateOutcome::Snapped);
        EXPECT_NEAR(jump, c.distance, 1e-6);  // the visible jump the other smoothings hide
        return;
    }
    EXPECT_EQ(outcome, UpdateOutcome::Accepted);
    // Continuous: the same instant shows the same pose (float rounding of positions near 5 m,
    // 5e-7, through a double blend).
    EXPECT_LT(jump, 1e-6);
    EXPECT_LT(angleBetween(justAfter.orientation, justBefore.orientation), 1e-6);  // float quaternion
    // Frame to frame during the correction the pose moves at most (speed + correction speed)
    // dt: |v| <= 5.1 m/s, and the correction of 0.72 m goes at most at 2 d / blendTime (the
    // derivative of the PVB/linear blend terms) or ln 2 d / halfLife (decay).
    const double dt = 1.0 / 240.0;
    const double correctionSpeed = std::fmax(2.0 * c.distance / static_cast<double>(settings.blendTime),
                                             std::log(2.0) * c.distance / static_cast<double>(settings.decayHalfLife));
    const double bound = (std::sqrt(26.0) + correctionSpeed) * dt;
    ReceivedPose previous = justAfter;
    for (int k = 1; k <= 240; ++k) {
        const ReceivedPose p = sampled(receiver, 1.0 + k * dt);
        EXPECT_LE(glm::length(ftest::toD(p.position) - ftest::toD(previous.position)), bound) << k;
        // The orientation turns by at most 0.2 rad over the blend: per frame 2 * 0.2 * dt / 0.1.
        EXPECT_LE(angleBetween(p.orientation, previous.orientation), 4.0 * 0.2 * dt / 0.1 + 1e-6) << k;
        previous = p;
    }
    // Converged: LinearBlend and PVB show the new extrapolation exactly once blendTime is over.
    const float blendTime = settings.blendTime;
    if (GetParam() != Smoothing::ExponentialDecay) {
        for (const double t : {1.0 + static_cast<double>(blendTime) + 1e-9, 1.5, 2.0}) {
            ReceivedPose expected = expectedPose(c.after, static_cast<float>(t - 1.0));
            EXPECT_TRUE(samePose(sampled(receiver, t), expected)) << t;
        }
    } else {
        // Decay: the offset at the correction halves every halfLife, exactly 2^-k of it after
        // k half-lives (to float rounding of the positions, 1e-6 at 10 m).
        const double halfLife = static_cast<double>(settings.decayHalfLife);
        for (int k = 1; k <= 12; ++k) {
            const double t = 1.0 + k * halfLife;
            const ReceivedPose p = sampled(receiver, t);
            const ReceivedPose target = expectedPose(c.after, static_cast<float>(t - 1.0));
            const double offset = glm::length(ftest::toD(p.position) - ftest::toD(target.position));
            EXPECT_NEAR(offset, c.distance * std::exp2(-k), 2e-6) << k;
            EXPECT_NEAR(angleBetween(p.orientation, target.orientation), 0.2 * std::exp2(-k), 2e-6) << k;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Receiver, Smoothings,
                         ::testing::Values(Smoothing::Snap, Smoothing::LinearBlend,
                                           Smoothing::ProjectiveVelocityBlending, Smoothing::ExponentialDecay),
                         [](const ::testing::TestParamInfo<Smoothing>& param) {
                             switch (param.param) {
                                 case Smoothing::Snap:
                                     return std::string("Snap");
                                 case Smoothing::LinearBlend:
                                     return std::string("LinearBlend");
                                 case Smoothing::ProjectiveVelocityBlending:
                                     return std::string("ProjectiveVelocityBlending");
                                 case Smoothing::ExponentialDecay:
                                     return std::string("ExponentialDecay");
                             }
                             return std::string("unknown");
                         });

// Mid-blend values from the formulas (docs/ARCHITECTURE.md), written out here.
TEST(Receiver, ProjectiveVelocityBlendingFollowsMurphy) {
    const Correction c;
    ReceiverSettings settings;  // PVB is the default, blendTime 0.2 s
    DeadReckoningReceiver receiver(settings);
    ASSERT_EQ(receiver.receive(0.8, c.before, 0.8), UpdateOutcome::Snapped);
    ASSERT_EQ(receiver.receive(1.0, c.after, 1.0), UpdateOutcome::Accepted);
    const DVec3 p0(5, 0, 0), v0(5, 0, 0);  // shown at the correction
    const DVec3 vNew(5, 1, 0);             // V' (A' = 0: FPW)
    for (const double T : {0.05, 0.1, 0.15}) {
        const double alpha = T / static_cast<double>(settings.blendTime);
        const DVec3 vb = v0 + (vNew - v0) * alpha;
        const DVec3 projected = p0 + vb * T;
        const DVec3 target = DVec3(5.6, 0.4, 0) + vNew * T;
        const DVec3 expected = projected + (target - projected) * alpha;
        // float positions near 6 m (5e-7) and float inputs 5.6f, 0.4f (2e-7).
        EXPECT_VEC_NEAR(sampled(receiver, 1.0 + T).position, expected, 2e-6) << T;
    }
}

TEST(Receiver, LinearBlendLerpsTheTwoExtrapolations) {
    const Correction c;
    ReceiverSettings settings;
    settings.smoothing = Smoothing::LinearBlend;
    settings.extrapolationLimit = 1.0f;  // the old update is extrapolated 0.35 s
    DeadReckoningReceiver receiver(settings);
    ASSERT_EQ(receiver.receive(0.8, c.before, 0.8), UpdateOutcome::Snapped);
    ASSERT_EQ(receiver.receive(1.0, c.after, 1.0), UpdateOutcome::Accepted);
    for (const double T : {0.05, 0.1, 0.15}) {
        const double alpha = T / static_cast<double>(settings.blendTime);
        const DVec3 oldExtrapolation = DVec3(4, 0, 0) + DVec3(5, 0, 0) * (0.2 + T);
        const DVec3 newExtrapolation = DVec3(5.6, 0.4, 0) + DVec3(5, 1, 0) * T;
        const ReceivedPose p = sampled(receiver, 1.0 + T);
        EXPECT_VEC_NEAR(p.position, oldExtrapolation + (newExtrapolation - oldExtrapolation) * alpha, 2e-6) << T;
        // slerp from yaw 0 to yaw 0.2 at alpha: yaw 0.2 alpha (float quaternions).
        EXPECT_NEAR(angleBetween(p.orientation, yaw(0.2 * alpha)), 0.0, 1e-6) << T;
    }
}

TEST(Receiver, AnUpdateDuringABlendStaysContinuous) {
    for (const Smoothing smoothing :
         {Smoothing::LinearBlend, Smoothing::ProjectiveVelocityBlending, Smoothing::ExponentialDecay}) {
        const Correction c;
        ReceiverSettings settings;
        settings.smoothing = smoothing;
        DeadReckoningReceiver receiver(settings);
        ASSERT_EQ(receiver.receive(0.8, c.before, 0.8), UpdateOutcome::Snapped);
        ASSERT_EQ(receiver.receive(1.0, c.after, 1.0), UpdateOutcome::Accepted);
        const ReceivedPose before = sampled(receiver, 1.1);  // half-way through the first blend
        DeadReckoningState third = fpw(DVec3(6.0, 0.9, 0.3), DVec3(4, 2, 0));
        third.orientation = yaw(-0.1);
        ASSERT_EQ(receiver.receive(1.1, third, 1.1), UpdateOutcome::Accepted);
        const ReceivedPose after = sampled(receiver, 1.1);
        EXPECT_VEC_NEAR(after.position, before.position, 1e-6) << static_cast<int>(smoothing);
        EXPECT_LT(angleBetween(after.orientation, before.orientation), 1e-6) << static_cast<int>(smoothing);
    }
}

TEST(Receiver, TeleportSnaps) {
    const Correction c;
    ReceiverSettings settings;  // teleportDistance 10 m
    DeadReckoningReceiver receiver(settings);
    ASSERT_EQ(receiver.receive(0.8, c.before, 0.8), UpdateOutcome::Snapped);
    const DeadReckoningState respawn = fpw(DVec3(-40, 3, 12), DVec3(0));
    ASSERT_EQ(receiver.receive(1.0, respawn, 1.0), UpdateOutcome::Snapped);
    EXPECT_EQ(receiver.counters().teleports, 1u);
    EXPECT_EQ(receiver.counters().snaps, 2u);  // the first update and the teleport
    EXPECT_TRUE(samePose(sampled(receiver, 1.05), expectedPose(respawn, 0.05f)));
    // A 9.9 m correction still blends; infinity disables the teleport rule.
    DeadReckoningReceiver near(settings);
    ASSERT_EQ(near.receive(0.0, fpw(DVec3(0), DVec3(0)), 0.0), UpdateOutcome::Snapped);
    EXPECT_EQ(near.receive(0.1, fpw(DVec3(9.9, 0, 0), DVec3(0)), 0.1), UpdateOutcome::Accepted);
    settings.teleportDistance = std::numeric_limits<float>::infinity();
    DeadReckoningReceiver never(settings);
    ASSERT_EQ(never.receive(0.0, fpw(DVec3(0), DVec3(0)), 0.0), UpdateOutcome::Snapped);
    EXPECT_EQ(never.receive(0.1, respawn, 0.1), UpdateOutcome::Accepted);
    EXPECT_EQ(never.counters().teleports, 0u);
}

TEST(Receiver, ExtrapolationHoldsAtExactlyTheLimit) {
    ReceiverSettings settings;  // extrapolationLimit 0.25 s
    DeadReckoningReceiver receiver(settings);
    const DeadReckoningState s = fpw(DVec3(1, 0, 0), DVec3(2, 0, 0));
    ASSERT_EQ(receiver.receive(10.0, s, 10.0), UpdateOutcome::Snapped);
    const ReceivedPose early = sampled(receiver, 10.125);
    EXPECT_FALSE(early.held);
    EXPECT_EQ(early.position, rv(1.25, 0, 0));  // 1 + 2 * 0.125: exact
    const ReceivedPose atLimit = sampled(receiver, 10.25);
    EXPECT_FALSE(atLimit.held);  // age == limit: not clamped yet
    EXPECT_EQ(atLimit.position, rv(1.5, 0, 0));
    for (const double t : {10.25 + 1e-9, 10.3, 11.0, 1e6, 1e300}) {
        const ReceivedPose p = sampled(receiver, t);
        EXPECT_TRUE(p.held) << t;
        EXPECT_EQ(p.position, rv(1.5, 0, 0)) << t;           // held at 1 + 2 * 0.25, never infinity
        EXPECT_EQ(p.velocity, Vec3(2.0f, 0.0f, 0.0f)) << t;  // the model's velocity at the hold
    }
    EXPECT_EQ(receiver.counters().held, 5u);
    // Limit 0: the update as stamped, always held after it.
    settings.extrapolationLimit = 0.0f;
    DeadReckoningReceiver zero(settings);
    ASSERT_EQ(zero.receive(0.0, s, 0.0), UpdateOutcome::Snapped);
    EXPECT_EQ(sampled(zero, 3.0).position, rv(1, 0, 0));
    // No limit and a gap the float age cannot hold: refused, never infinity.
    settings.extrapolationLimit = std::numeric_limits<float>::infinity();
    DeadReckoningReceiver unlimited(settings);
    ASSERT_EQ(unlimited.receive(0.0, s, 0.0), UpdateOutcome::Snapped);
    EXPECT_EQ(sampled(unlimited, 100.0).position, rv(201, 0, 0));
    ReceivedPose untouched;
    untouched.position = rv(-7, -7, -7);
    EXPECT_EQ(unlimited.sample(1e300, untouched), Status::NonFiniteResult);
    EXPECT_EQ(untouched.position, rv(-7, -7, -7));
}

TEST(Receiver, FutureStampedUpdateIsShownAsStampedUntilItsTime) {
    DeadReckoningReceiver receiver;
    const DeadReckoningState s = fpw(DVec3(0, 1, 0), DVec3(0, 0, 4));
    ASSERT_EQ(receiver.receive(2.0, s, 1.0), UpdateOutcome::Snapped);  // clocks disagree by > 1 s
    EXPECT_EQ(receiver.counters().futureUpdates, 1u);
    EXPECT_EQ(sampled(receiver, 1.5).position, rv(0, 1, 0));      // age 0, not -0.5
    EXPECT_EQ(sampled(receiver, 2.125).position, rv(0, 1, 0.5));  // 4 * 0.125
}

TEST(Receiver, BadPacketsAreDroppedCountedAndChangeNothing) {
    DeadReckoningReceiver receiver;
    const DeadReckoningState s = fpw(DVec3(0), DVec3(1, 0, 0));
    ASSERT_EQ(receiver.receive(1.0, s, 1.0), UpdateOutcome::Snapped);
    ASSERT_EQ(receiver.receive(1.1, fpw(DVec3(0.2, 0, 0), DVec3(1, 0, 0)), 1.1), UpdateOutcome::Accepted);
    const ReceivedPose shown = sampled(receiver, 1.15);

    const DeadReckoningState far = fpw(DVec3(3, 0, 0), DVec3(0));
    EXPECT_EQ(receiver.receive(1.05, far, 1.12), UpdateOutcome::OutOfOrder);  // older than the newest
    EXPECT_EQ(receiver.receive(1.1, far, 1.12), UpdateOutcome::Duplicate);    // same stamp as the newest
    DeadReckoningState nanPosition = far;
    nanPosition.position.x = std::numeric_limits<Real>::quiet_NaN();
    EXPECT_EQ(receiver.receive(1.2, nanPosition, 1.12), UpdateOutcome::Invalid);
    DeadReckoningState infiniteVelocity = far;
    infiniteVelocity.velocity.z = std::numeric_limits<float>::infinity();
    EXPECT_EQ(receiver.receive(1.2, infiniteVelocity, 1.12), UpdateOutcome::Invalid);
    DeadReckoningState zeroQuaternion = far;
    zeroQuaternion.orientation = ftest::quatWXYZ(0, 0, 0, 0);
    EXPECT_EQ(receiver.receive(1.2, zeroQuaternion, 1.12), UpdateOutcome::Invalid);
    DeadReckoningState unknown = far;
    unknown.algorithm = static_cast<DeadReckoningAlgorithm>(0);
    EXPECT_EQ(receiver.receive(1.2, unknown, 1.12), UpdateOutcome::Invalid);
    EXPECT_EQ(receiver.receive(kNaN, far, 1.12), UpdateOutcome::Invalid);
    EXPECT_EQ(receiver.receive(kInfinity, far, 1.12), UpdateOutcome::Invalid);
    EXPECT_EQ(receiver.receive(1.2, far, kNaN), UpdateOutcome::Invalid);

    EXPECT_TRUE(samePose(sampled(receiver, 1.15), shown));
    const foresight::ReceiverCounters& n = receiver.counters();
    EXPECT_EQ(n.accepted, 2u);
    EXPECT_EQ(n.outOfOrder, 1u);
    EXPECT_EQ(n.duplicates, 1u);
    EXPECT_EQ(n.invalid, 7u);
    receiver.reset();
    EXPECT_EQ(receiver.counters().invalid, 0u);
    ReceivedPose p;
    EXPECT_EQ(receiver.sample(1.15, p), Status::NoUpdate);
}

// A corrupt timestamp far ahead is dropped: accepted, it would make every real update after it
// out of order (the receiver would never move again).
TEST(Receiver, UpdateStampedTooFarAheadIsDroppedAndLaterUpdatesStillApply) {
    DeadReckoningReceiver receiver;  // maxFutureSkew 1 s
    ASSERT_EQ(receiver.receive(1.0, fpw(DVec3(0), DVec3(10, 0, 0)), 1.0), UpdateOutcome::Snapped);
    EXPECT_EQ(receiver.receive(1.0e6, fpw(DVec3(5000, 0, 0), DVec3(0)), 1.5), UpdateOutcome::TooFarAhead);
    EXPECT_EQ(receiver.counters().tooFarAhead, 1u);
    // Exactly 1 s ahead is still accepted (a clock slightly off), counted as a future update.
    // (Shown at 2.0: 0 + 10 * 0.25, held at the 0.25 s limit; the update says 5: a correction.)
    ASSERT_EQ(receiver.receive(3.0, fpw(DVec3(5, 0, 0), DVec3(10, 0, 0)), 2.0), UpdateOutcome::Accepted);
    EXPECT_EQ(receiver.counters().futureUpdates, 1u);
    // The real stream goes on; once the default 0.2 s blend is over, the newest update's
    // extrapolation: 10 + 10 * 0.25 at 3.75.
    ASSERT_EQ(receiver.receive(3.5, fpw(DVec3(10, 0, 0), DVec3(10, 0, 0)), 3.5), UpdateOutcome::Accepted);
    EXPECT_EQ(sampled(receiver, 3.75).position, rv(12.5, 0, 0));
}

// A sender whose clock starts again (a restart) sends older timestamps: after restartAfter of
// silence they are taken as the new stream (snap), before it they are late packets (dropped).
TEST(Receiver, SenderClockRestartIsFollowedAfterRestartAfter) {
    ReceiverSettings settings;
    settings.restartAfter = 2.0f;
    DeadReckoningReceiver receiver(settings);
    ASSERT_EQ(receiver.receive(100.0, fpw(DVec3(0), DVec3(1, 0, 0)), 100.0), UpdateOutcome::Snapped);
    // 1.5 s later (receive time), an update stamped 0.5: a late packet still, dropped.
    EXPECT_EQ(receiver.receive(0.5, fpw(DVec3(40, 0, 0), DVec3(0, 0, 1)), 101.5), UpdateOutcome::OutOfOrder);
    // 2.5 s of silence: the restarted clock is followed, and its successors apply normally.
    EXPECT_EQ(receiver.receive(1.0, fpw(DVec3(40, 0, 0), DVec3(0, 0, 1)), 102.5), UpdateOutcome::Snapped);
    EXPECT_EQ(receiver.counters().clockRestarts, 1u);
    EXPECT_EQ(receiver.counters().snaps, 2u);
    // Receive times and timestamps are now on the new clock: shown at the update, age 0.
    EXPECT_EQ(sampled(receiver, 1.0).position, rv(40, 0, 0));
    EXPECT_EQ(receiver.receive(1.5, fpw(DVec3(40, 0, 0.5), DVec3(0, 0, 1)), 1.5), UpdateOutcome::Accepted);
    EXPECT_EQ(receiver.counters().outOfOrder, 1u);
}

TEST(Receiver, SampleRefusals) {
    DeadReckoningReceiver receiver;
    ReceivedPose untouched;
    untouched.position = rv(4, 4, 4);
    EXPECT_EQ(receiver.sample(0.0, untouched), Status::NoUpdate);
    ASSERT_EQ(receiver.receive(0.0, fpw(DVec3(0), DVec3(0)), 0.0), UpdateOutcome::Snapped);
    EXPECT_EQ(receiver.sample(kNaN, untouched), Status::NonFiniteInput);
    EXPECT_EQ(receiver.sample(-kInfinity, untouched), Status::NonFiniteInput);
    EXPECT_EQ(untouched.position, rv(4, 4, 4));
}

TEST(Receiver, InvalidSettingsAreRefused) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(foresight::validateReceiverSettings(ReceiverSettings{}), Status::Ok);
    std::vector<ReceiverSettings> bad;
    for (const float v : {0.0f, -1.0f, nan, inf}) {
        ReceiverSettings s;
        s.blendTime = v;
        bad.push_back(s);
        s = {};
        s.decayHalfLife = v;
        bad.push_back(s);
        s = {};
        s.interpolationDelay = v;
        bad.push_back(s);
    }
    for (const float v : {0.0f, -1.0f, nan}) {
        ReceiverSettings s;
        s.teleportDistance = v;
        bad.push_back(s);
    }
    for (const float v : {-0.01f, nan}) {
        ReceiverSettings s;
        s.extrapolationLimit = v;
        bad.push_back(s);
        s = {};
        s.maxFutureSkew = v;
        bad.push_back(s);
        s = {};
        s.restartAfter = v;
        bad.push_back(s);
    }
    ReceiverSettings noRestartWindow;
    noRestartWindow.restartAfter = 0.0f;
    bad.push_back(noRestartWindow);
    ReceiverSettings mode;
    mode.mode = static_cast<ReceiverMode>(7);
    bad.push_back(mode);
    ReceiverSettings smoothing;
    smoothing.smoothing = static_cast<Smoothing>(9);
    bad.push_back(smoothing);
    for (std::size_t i = 0; i < bad.size(); ++i) {
        EXPECT_EQ(foresight::validateReceiverSettings(bad[i]), Status::InvalidSetting) << i;
        DeadReckoningReceiver receiver(bad[i]);
        EXPECT_EQ(receiver.receive(0.0, fpw(DVec3(0), DVec3(0)), 0.0), UpdateOutcome::Invalid) << i;
        ReceivedPose p;
        EXPECT_EQ(receiver.sample(0.0, p), Status::InvalidSetting) << i;
    }
    // The documented "infinity disables" values are valid.
    ReceiverSettings disabled;
    disabled.teleportDistance = inf;
    disabled.extrapolationLimit = inf;
    disabled.maxFutureSkew = inf;
    disabled.restartAfter = inf;
    EXPECT_EQ(foresight::validateReceiverSettings(disabled), Status::Ok);
}

TEST(Receiver, ReplayBeforeTheCorrectionShowsItsStart) {
    const Correction c;
    DeadReckoningReceiver receiver;  // PVB
    ASSERT_EQ(receiver.receive(0.8, c.before, 0.8), UpdateOutcome::Snapped);
    const ReceivedPose atStart = [&] {
        DeadReckoningReceiver copy = receiver;
        return sampled(copy, 1.0);
    }();
    ASSERT_EQ(receiver.receive(1.0, c.after, 1.0), UpdateOutcome::Accepted);
    // Earlier than the correction: alpha clamps to 0; the shown start projected back with V0.
    const ReceivedPose earlier = sampled(receiver, 0.9);
    EXPECT_TRUE(ftest::finite(earlier.position));
    EXPECT_VEC_NEAR(sampled(receiver, 1.0).position, atStart.position, 1e-6);
}

// =============================================================================================
// Receiver, Interpolate mode

ReceiverSettings interpolating(float delay) {
    ReceiverSettings s;
    s.mode = ReceiverMode::Interpolate;
    s.interpolationDelay = delay;
    return s;
}

// A straight line at constant velocity, with a constant turn: p(t) = (2t, 1, -t), yaw 0.5 t.
DeadReckoningState lineAt(double t) {
    DeadReckoningState s = makeState(DeadReckoningAlgorithm::Rpw, DVec3(2 * t, 1, -t), DVec3(2, 0, -1), yaw(0.5 * t));
    s.angularVelocity = Vec3(0.0f, 0.5f, 0.0f);
    return s;
}

TEST(Interpolation, ReproducesALinearTrajectoryExactlyAndLagsByTheDelay) {
    // Updates every 1/16 s, delay 1/8 s, samples every 1/256 s: every value is a short dyadic
    // fraction, so the lerp is exact in float and double.
    DeadReckoningReceiver receiver(interpolating(0.125f));
    for (int k = 0; k < 32; ++k)
        ASSERT_EQ(receiver.receive(k / 16.0, lineAt(k / 16.0), k / 16.0), UpdateOutcome::Buffered);
    for (int j = 32; j <= 256 + 32; ++j) {
        const double t = j / 256.0;
        const double render = t - 0.125;
        const ReceivedPose p = sampled(receiver, t);
        EXPECT_EQ(p.position, rv(2 * render, 1, -render)) << t;
        EXPECT_EQ(p.velocity, Vec3(2.0f, 0.0f, -1.0f)) << t;
        EXPECT_FALSE(p.held);
        // slerp between yaws 1/32 rad apart: float quaternion rounding, 1e-6.
        EXPECT_LT(angleBetween(p.orientation, yaw(0.5 * render)), 1e-6) << t;
    }
    EXPECT_EQ(receiver.counters().accepted, 32u);
}

TEST(Interpolation, DefaultDelayRendersATenthOfASecondBehind) {
    DeadReckoningReceiver receiver(interpolating(ReceiverSettings{}.interpolationDelay));
    for (int k = 0; k <= 20; ++k)
        ASSERT_EQ(receiver.receive(k * 0.05, lineAt(k * 0.05), k * 0.05 + 0.03), UpdateOutcome::Buffered);
    for (const double t : {0.3, 0.512, 0.77, 1.0}) {
        const double render = t - 0.1;
        // The delay is 0.1f (1.5e-9 s from 0.1: 3e-9 m) and the stamps k * 0.05 round in
        // double: float rounding of the buffered and shown positions (spacing 2.4e-7 near
        // 2 m, three components) dominates.
        EXPECT_VEC_NEAR(sampled(receiver, t).position, DVec3(2 * render, 1, -render), 1e-6) << t;
    }
}

TEST(Interpolation, BeforeTheOldestHoldsItAfterTheNewestExtrapolatesUpToTheLimit) {
    DeadReckoningReceiver receiver(interpolating(0.125f));
    ASSERT_EQ(receiver.receive(1.0, lineAt(1.0), 1.0), UpdateOutcome::Buffered);
    ASSERT_EQ(receiver.receive(1.0625, lineAt(1.0625), 1.0625), UpdateOutcome::Buffered);
    // Render time 0.875, before the oldest (1.0): the oldest as stamped.
    EXPECT_EQ(sampled(receiver, 1.0).position, rv(2, 1, -1));
    // Render time 1.125, 1/16 past the newest: extrapolated from it (RPW: p + v t).
    const ReceivedPose ahead = sampled(receiver, 1.25);
    EXPECT_EQ(ahead.position, rv(2.25, 1, -1.125));
    EXPECT_FALSE(ahead.held);
    // Render time 1.5625, 0.5 s past the newest: held at its 0.25 s extrapolation.
    const ReceivedPose held = sampled(receiver, 1.6875);
    EXPECT_TRUE(held.held);
    EXPECT_EQ(held.position, rv(2 * 1.3125, 1, -1.3125));
    EXPECT_EQ(receiver.counters().held, 1u);
    ReceivedPose p;
    DeadReckoningReceiver empty(interpolating(0.1f));
    EXPECT_EQ(empty.sample(1.0, p), Status::NoUpdate);
}

TEST(Interpolation, LateUpdatesAreInsertedInOrderOrDroppedWhenAlreadyRendered) {
    DeadReckoningReceiver receiver(interpolating(0.125f));
    ASSERT_EQ(receiver.receive(0.0, lineAt(0.0), 0.0), UpdateOutcome::Buffered);
    ASSERT_EQ(receiver.receive(0.25, lineAt(0.25), 0.25), UpdateOutcome::Buffered);
    ASSERT_EQ(receiver.receive(0.5, lineAt(0.5), 0.5), UpdateOutcome::Buffered);
    // Render time 0.125 (sample at 0.25).
    EXPECT_EQ(sampled(receiver, 0.25).position, rv(0.25, 1, -0.125));
    // A late update stamped 0.375 (after the render time): inserted between 0.25 and 0.5, and
    // it bends the path (it says the entity was 1 m up then).
    DeadReckoningState late = lineAt(0.375);
    late.position.y = 2;
    EXPECT_EQ(receiver.receive(0.375, late, 0.3), UpdateOutcome::Buffered);
    EXPECT_EQ(sampled(receiver, 0.4375).position, rv(0.625, 1.5, -0.3125));  // half-way 0.25 -> 0.375
    // Stamped before the last render time (0.3125): too late to show, dropped.
    EXPECT_EQ(receiver.receive(0.3, lineAt(0.3), 0.45), UpdateOutcome::OutOfOrder);
    EXPECT_EQ(receiver.receive(0.25, lineAt(0.25), 0.45), UpdateOutcome::OutOfOrder);  // also rendered
    EXPECT_EQ(receiver.receive(0.5, lineAt(0.5), 0.45), UpdateOutcome::Duplicate);
    DeadReckoningState bad = lineAt(0.6);
    bad.orientation.x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(receiver.receive(0.6, bad, 0.45), UpdateOutcome::Invalid);
    const foresight::ReceiverCounters& n = receiver.counters();
    EXPECT_EQ(n.accepted, 4u);
    EXPECT_EQ(n.outOfOrder, 2u);
    EXPECT_EQ(n.duplicates, 1u);
    EXPECT_EQ(n.invalid, 1u);
}

TEST(Interpolation, TheRingKeepsTheNewestUpdates) {
    DeadReckoningReceiver receiver(interpolating(0.125f));
    const std::size_t n = DeadReckoningReceiver::kBufferCapacity + 8;
    // Arriving newest first within each pair, to exercise the ordered insertion.
    for (int k = 0; k < static_cast<int>(n); k += 2) {
        ASSERT_EQ(receiver.receive((k + 1) / 16.0, lineAt((k + 1) / 16.0), (k + 1) / 16.0), UpdateOutcome::Buffered);
        ASSERT_EQ(receiver.receive(k / 16.0, lineAt(k / 16.0), (k + 1) / 16.0), UpdateOutcome::Buffered);
    }
    // The 8 oldest are forgotten: a render time before stamp 8/16 holds the update stamped 8/16.
    EXPECT_EQ(sampled(receiver, 0.125 + 3 / 16.0).position, rv(1.0, 1, -0.5));
    // A stamp older than every buffered one of a full buffer is dropped (it would be forgotten).
    EXPECT_EQ(receiver.receive(7 / 16.0 + 1 / 64.0, lineAt(0.45), 0.0), UpdateOutcome::OutOfOrder);
    // Between the buffered ones, exact interpolation still.
    const double render = 20 / 16.0 + 1 / 32.0;
    EXPECT_EQ(sampled(receiver, render + 0.125).position, rv(2 * render, 1, -render));
}

// Sparse updates of a fast entity (a threshold sender: seconds apart, far apart) are not
// teleports when each lands on the previous one's prediction: they are interpolated.
TEST(Interpolation, SparseUpdatesOnThePredictedPathAreNotTeleports) {
    DeadReckoningReceiver receiver(interpolating(0.125f));
    for (int k = 0; k < 4; ++k)
        ASSERT_EQ(receiver.receive(5.0 * k, fpw(DVec3(50.0 * k, 0, 0), DVec3(10, 0, 0)), 5.0 * k),
                  UpdateOutcome::Buffered);
    EXPECT_EQ(receiver.counters().teleports, 0u);
    EXPECT_EQ(receiver.counters().snaps, 0u);
    // Render time 7.5: half-way between the updates at 5 and 10 (50 m and 100 m).
    EXPECT_EQ(sampled(receiver, 7.625).position, rv(75, 0, 0));
}

// A car at 20 m/s turning at 0.5 rad/s (a 40 m circle), RPB updates every 2 s (1 rad apart)
// exactly on the circle: between two updates the shown car stays on the arc (the older update's
// own prediction, which the newer one confirms), where the chord would cut 40 (1 - cos 0.5) =
// 4.9 m inside at mid-span.
TEST(Interpolation, SparseUpdatesOfATurningCarFollowTheArcNotTheChord) {
    auto onCircle = [](double t) {
        const double heading = 0.5 * t;
        DeadReckoningState s =
            makeState(DeadReckoningAlgorithm::Rpb, DVec3(40 * (1 - std::cos(heading)), 0, 40 * std::sin(heading)),
                      DVec3(0, 0, 20), yaw(heading));
        s.angularVelocity = Vec3(0.0f, 0.5f, 0.0f);
        return s;
    };
    DeadReckoningReceiver receiver(interpolating(0.125f));
    for (int k = 0; k < 4; ++k)
        ASSERT_EQ(receiver.receive(2.0 * k, onCircle(2.0 * k), 2.0 * k), UpdateOutcome::Buffered);
    EXPECT_EQ(receiver.counters().teleports, 0u);
    double worst = 0;
    for (double render = 0.0; render <= 6.0; render += 1.0 / 16) {
        const ReceivedPose p = sampled(receiver, render + 0.125);
        const double heading = 0.5 * render;
        const DVec3 expected(40 * (1 - std::cos(heading)), 0, 40 * std::sin(heading));
        worst = std::max(worst, glm::length(ftest::toD(p.position) - expected));
        EXPECT_LT(angleBetween(p.orientation, yaw(heading)), 1e-5) << render;
    }
    // Float positions (up to 80 m: 8e-6 m spacing) and float trigonometry of the updates and
    // the model: far below the 4.9 m of the chord.
    EXPECT_LT(worst, 1e-4);
}

// The buffer runs dry (the render time passes the newest update, which is then extrapolated);
// when a newer update arrives, interpolating towards it would move the shown entity at once.
// That difference fades out over blendTime instead. STATIC updates at x = 0, 1, 2 (stamped 0,
// 1, 2), delay 1/8 s, blend 1/4 s: every value is dyadic.
TEST(Interpolation, SwitchFromExtrapolatingToInterpolatingDoesNotPop) {
    ReceiverSettings settings = interpolating(0.125f);
    settings.blendTime = 0.25f;
    DeadReckoningReceiver receiver(settings);
    auto at = [](double x) { return makeState(DeadReckoningAlgorithm::Static, DVec3(x, 0, 0), DVec3(0)); };
    ASSERT_EQ(receiver.receive(0.0, at(0), 0.0), UpdateOutcome::Buffered);
    ASSERT_EQ(receiver.receive(1.0, at(1), 1.0), UpdateOutcome::Buffered);
    // Render 1.125, past the newest: STATIC extrapolated, x = 1.
    EXPECT_EQ(sampled(receiver, 1.25).position, rv(1, 0, 0));
    ASSERT_EQ(receiver.receive(2.0, at(2), 1.25), UpdateOutcome::Buffered);
    // Same render time: still x = 1 (plain interpolation would say 1.125).
    EXPECT_EQ(sampled(receiver, 1.25).position, rv(1, 0, 0));
    // Half-way through the fade (render 1.25): 1.25 - 0.125 / 2.
    EXPECT_EQ(sampled(receiver, 1.375).position, rv(1.1875, 0, 0));
    // Faded (render 1.375 and later): plain interpolation.
    EXPECT_EQ(sampled(receiver, 1.5).position, rv(1.375, 0, 0));
    EXPECT_EQ(sampled(receiver, 2.0).position, rv(1.875, 0, 0));
    EXPECT_EQ(receiver.counters().snaps, 0u);
}

// A late update landing in the pair being shown bends the path there: the shown entity moves
// onto the bent path over blendTime, not at once.
TEST(Interpolation, LateUpdateInTheShownPairFadesIn) {
    ReceiverSettings settings = interpolating(0.125f);
    settings.blendTime = 0.25f;
    DeadReckoningReceiver receiver(settings);
    ASSERT_EQ(receiver.receive(0.0, lineAt(0.0), 0.0), UpdateOutcome::Buffered);
    ASSERT_EQ(receiver.receive(0.25, lineAt(0.25), 0.25), UpdateOutcome::Buffered);
    ASSERT_EQ(receiver.receive(0.5, lineAt(0.5), 0.5), UpdateOutcome::Buffered);
    EXPECT_EQ(sampled(receiver, 0.4375).position.y, 1.0f);  // render 0.3125, on the line
    DeadReckoningState late = lineAt(0.375);
    late.position.y = 2;
    ASSERT_EQ(receiver.receive(0.375, late, 0.45), UpdateOutcome::Buffered);
    // Same render time: y still 1 (the bent path says 1.5 there); half-way through the fade
    // (render 0.4375, where the bent path says 1.5 again): 1.5 - 0.5 / 2; then the bent path.
    EXPECT_EQ(sampled(receiver, 0.4375).position.y, 1.0f);
    EXPECT_EQ(sampled(receiver, 0.5625).position.y, 1.25f);
    EXPECT_EQ(sampled(receiver, 0.6875).position.y, 1.0f);  // render 0.5625: faded, past the bend
}

TEST(Interpolation, NoSweepAcrossATeleport) {
    DeadReckoningReceiver receiver(interpolating(0.125f));
    ASSERT_EQ(receiver.receive(0.0, fpw(DVec3(0), DVec3(1, 0, 0)), 0.0), UpdateOutcome::Buffered);
    ASSERT_EQ(receiver.receive(0.25, fpw(DVec3(50, 0, 0), DVec3(1, 0, 0)), 0.25), UpdateOutcome::Buffered);
    EXPECT_EQ(receiver.counters().teleports, 1u);
    // Render time 0.125: the first update moving on its own (0.125 m), not 25 m into the level.
    EXPECT_EQ(sampled(receiver, 0.25).position, rv(0.125, 0, 0));
    EXPECT_EQ(sampled(receiver, 0.375).position, rv(50, 0, 0));
}

// =============================================================================================
// Batch

// The cases were drawn with xorshift64* (ftest::Random, test_util.h); keep the step.
constexpr ftest::Random::Step kRandomStep = ftest::Random::Step::XorShift64Star;

// Bad input never leads to a crash or a non-finite pose: every mode and smoothing, 20 000
// random packets each (out of order, duplicates, far in the future, NaN fields, zero
// quaternions, clock restarts, huge gaps, teleports), sampled at times that mostly go forward
// and sometimes back. Every Ok sample must be finite, unit in orientation, and within reach of
// the updates: positions are within 1.5e3 m of the origin, speeds 1.1e2 m/s, accelerations
// 35 m/s^2, and the default limit stops extrapolation after 0.25 s (blends add at most a
// correction), so 1e6 m is a loose bound that only a runaway would break.
TEST(Receiver, RandomBadPacketsNeverGiveANonFinitePose) {
    for (const ReceiverMode mode : {ReceiverMode::Extrapolate, ReceiverMode::Interpolate}) {
        for (const Smoothing smoothing : {Smoothing::Snap, Smoothing::LinearBlend,
                                          Smoothing::ProjectiveVelocityBlending, Smoothing::ExponentialDecay}) {
            if (mode == ReceiverMode::Interpolate && smoothing != Smoothing::Snap) continue;
            ReceiverSettings settings;
            settings.mode = mode;
            settings.smoothing = smoothing;
            DeadReckoningReceiver receiver(settings);
            ftest::Random random(1000 + static_cast<std::uint64_t>(smoothing) * 10 + static_cast<std::uint64_t>(mode),
                                 kRandomStep);
            double now = 0.0;
            std::size_t okSamples = 0;
            std::uint64_t acceptedAtHalf = 0;
            for (int i = 0; i < 20000; ++i) {
                if (i == 10000) acceptedAtHalf = receiver.counters().accepted;
                now += random.uniform(0.0, 0.05);
                if (random.uniform(0, 1) < 0.001) now += random.uniform(10, 1e5);  // a huge gap
                DeadReckoningState s = makeState(
                    static_cast<DeadReckoningAlgorithm>(1 + i % 9),
                    DVec3(random.uniform(-1e3, 1e3), random.uniform(-10, 10), random.uniform(-1e3, 1e3)),
                    DVec3(random.uniform(-100, 100), random.uniform(-10, 10), random.uniform(-100, 100)),
                    ftest::quatWXYZ(
                        static_cast<float>(random.uniform(-1, 1)), static_cast<float>(random.uniform(-1, 1)),
                        static_cast<float>(random.uniform(-1, 1)), static_cast<float>(random.uniform(-1, 1))));
                s.acceleration =
                    ftest::toF(DVec3(random.uniform(-20, 20), random.uniform(-20, 20), random.uniform(-20, 20)));
                s.angularVelocity =
                    ftest::toF(DVec3(random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-5, 5)));
                double stamp = now - random.uniform(0.0, 0.3);
                const double u = random.uniform(0, 1);
                if (u < 0.05)
                    stamp -= random.uniform(0.5, 20);  // late, or a restarted clock
                else if (u < 0.08)
                    stamp += random.uniform(0.5, 1e6);  // in the future, some far
                else if (u < 0.10)
                    s.position.x = std::numeric_limits<Real>::quiet_NaN();
                else if (u < 0.12)
                    s.orientation = ftest::quatWXYZ(0, 0, 0, 0);
                else if (u < 0.13)
                    stamp = kNaN;
                (void)receiver.receive(stamp, s, now);
                if (random.uniform(0, 1) < 0.3) (void)receiver.receive(stamp, s, now);  // a duplicate
                const double sampleTime = random.uniform(0, 1) < 0.05 ? now - random.uniform(0, 2) : now;
                ReceivedPose pose;
                if (receiver.sample(sampleTime, pose) != Status::Ok) continue;
                ++okSamples;
                const DVec3 p = ftest::toD(pose.position);
                ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << i;
                ASSERT_LT(glm::length(p), 1e6) << i;
                const DVec3 v = ftest::toD(pose.velocity);
                ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) << i;
                const double length = glm::length(ftest::toD(pose.orientation));
                ASSERT_NEAR(length, 1.0, 1e-5) << i;  // unit within float rounding of a few operations
            }
            // Most frames show something, and updates still apply in the second half: bad packets
            // (a timestamp 1e6 s ahead, say) did not lock the receiver on a stale update.
            EXPECT_GT(okSamples, 19000u) << static_cast<int>(mode) << " " << static_cast<int>(smoothing);
            EXPECT_GT(receiver.counters().accepted - acceptedAtHalf, 2000u);  // 3400 to 3900 measured; a lock: 0
            EXPECT_GT(receiver.counters().tooFarAhead, 0u);
            EXPECT_GT(receiver.counters().invalid, 0u);
            EXPECT_GT(receiver.counters().duplicates, 0u);
        }
    }
}

bool sameResult(const DeadReckoningResult& a, const DeadReckoningResult& b) {
    return ftest::sameBytes(a.position, b.position) && ftest::sameBytes(a.velocity, b.velocity) &&
           ftest::sameBytes(a.orientation, b.orientation);
}

TEST(Batch, EqualsPredictDeadReckoningPerEntityBitForBit) {
    ftest::Random random(2024, kRandomStep);
    const std::size_t n = 4000;
    std::vector<DeadReckoningState> states(n);
    std::vector<double> stamps(n);
    const double now = 1000.0;
    for (std::size_t i = 0; i < n; ++i) {
        DeadReckoningState& s = states[i];
        s.algorithm = static_cast<DeadReckoningAlgorithm>(1 + i % 9);
        s.position = rv(random.uniform(-500, 500), random.uniform(-10, 50), random.uniform(-500, 500));
        s.velocity = ftest::toF(DVec3(random.uniform(-30, 30), random.uniform(-5, 5), random.uniform(-30, 30)));
        s.acceleration = ftest::toF(DVec3(random.uniform(-10, 10), random.uniform(-10, 10), random.uniform(-10, 10)));
        s.angularVelocity = ftest::toF(DVec3(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3)));
        // Not normalised on purpose, some with negative w and signed zeros.
        s.orientation = ftest::quatWXYZ(
            static_cast<float>(random.uniform(-2, 2)), static_cast<float>(random.uniform(-2, 2)),
            i % 7 == 0 ? -0.0f : static_cast<float>(random.uniform(-2, 2)), static_cast<float>(random.uniform(-2, 2)));
        if (i % 11 == 0) s.angularVelocity = Vec3(0.0f);
        stamps[i] = now - random.uniform(-0.05, 0.5);  // some stamped in the future
    }
    // Refusals: NaN, zero quaternion, unknown algorithm, NaN stamp, overflow.
    states[5].position.x = std::numeric_limits<Real>::quiet_NaN();
    states[17].orientation = ftest::quatWXYZ(0, 0, 0, 0);
    states[29].algorithm = static_cast<DeadReckoningAlgorithm>(12);
    stamps[41] = kNaN;
    states[53].velocity = Vec3(3e38f, 0.0f, 0.0f);
    states[53].algorithm = DeadReckoningAlgorithm::Fpw;
    stamps[53] = now - 100.0;  // 3e40 m: beyond float and NonFiniteResult in the float build
    states[54].position.y = -0.0f;
    states[54].velocity = Vec3(0.0f, -0.0f, 0.0f);  // signed zeros

    std::vector<DeadReckoningResult> out(n);
    const std::size_t refused = foresight::predictDeadReckoningBatch(states, stamps, now, out);
    std::size_t expectedRefused = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double age = now - stamps[i];
        const float ageF = age <= 0.0 ? 0.0f : static_cast<float>(age);
        DeadReckoningResult expected;
        if (foresight::predictDeadReckoning(states[i], ageF, expected) != Status::Ok) {
            ++expectedRefused;
            expected.position = states[i].position;
            expected.velocity = states[i].velocity;
            expected.orientation = states[i].orientation;
        }
        EXPECT_TRUE(sameResult(out[i], expected))
            << i << " " << foresight::deadReckoningAlgorithmName(states[i].algorithm);
    }
    EXPECT_EQ(refused, expectedRefused);
    EXPECT_GE(refused, foresight::kDoublePrecision ? 4u : 5u);
    // Spans of different lengths: the shortest is processed, the states beyond it are refused.
    std::vector<DeadReckoningResult> shortOut(10);
    EXPECT_EQ(
        foresight::predictDeadReckoningBatch(std::span(states.data(), 12), std::span(stamps.data(), 12), now, shortOut),
        2u + 1u);  // states 10, 11, and 5 (NaN)
}

// =============================================================================================
// Prepared extrapolation (extrapolateDeadReckoning, DeadReckoningBatch): the accuracy contract
// against predictDeadReckoning on 100 000 random states (every model, |w| from 0 through
// 1e-30 to 10 rad/s, ages up to 1e6 s, limits 0 to infinity, updates stamped in the future).

struct ContractErrors {
    double position = 0.0;     // worst |error| / (1e-6 scale + 2 ulps), must stay <= 1
    double orientation = 0.0;  // [rad]
    double length = 0.0;       // worst ||q| - 1|
    std::size_t velocityMismatches = 0;
};

void checkAgainstReference(const DeadReckoningState& state, double stamp, double now, float limit,
                           const DeadReckoningResult& got, ContractErrors& worst) {
    double age = now - stamp;
    age = age > 0.0 ? age : 0.0;
    age = age < static_cast<double>(limit) ? age : static_cast<double>(limit);
    const float ageF = static_cast<float>(age);
    DeadReckoningResult expected;
    ASSERT_EQ(foresight::predictDeadReckoning(state, ageF, expected), Status::Ok);
    const double t = ageF;
    const double uses = foresight::deadReckoningUsesAcceleration(state.algorithm) ? 1.0 : 0.0;
    const double scale = state.algorithm == DeadReckoningAlgorithm::Static
                             ? 0.0
                             : glm::length(ftest::toD(state.velocity)) * t +
                                   uses * glm::length(ftest::toD(state.acceleration)) * 0.5 * t * t;
    const DVec3 e = ftest::toD(expected.position);
    const double magnitude = std::max({1.0, std::abs(e.x), std::abs(e.y), std::abs(e.z)});
    const double ulp = magnitude * static_cast<double>(std::numeric_limits<Real>::epsilon());
    const double allowed = 1e-6 * scale + 2.0 * ulp;
    const double error = glm::length(ftest::toD(got.position) - e);
    worst.position = std::max(worst.position, error / allowed);
    worst.orientation = std::max(worst.orientation, angleBetween(got.orientation, expected.orientation));
    const double length = glm::length(ftest::toD(got.orientation));
    worst.length = std::max(worst.length, std::abs(length - 1.0));
    // Velocity: v + a t in float for every model; reference in double, rounded once.
    const DVec3 dv = ftest::toD(got.velocity) - ftest::toD(expected.velocity);
    const double vScale = glm::length(ftest::toD(expected.velocity)) + 1e-30;
    if (glm::length(dv) >
        4.0 * static_cast<double>(std::numeric_limits<float>::epsilon()) * vScale +
            1e-6 * (glm::length(ftest::toD(state.velocity)) + uses * glm::length(ftest::toD(state.acceleration)) * t))
        ++worst.velocityMismatches;
}

// The instruction sets of DeadReckoningBatch's passes that this build has and this machine runs.
std::vector<BatchSimd> availableSimd() {
    std::vector<BatchSimd> sets;
    for (const BatchSimd simd : {BatchSimd::Baseline, BatchSimd::Avx2})
        if (foresight::detail::BatchAccess::available(simd)) sets.push_back(simd);
    return sets;
}

const char* simdName(BatchSimd simd) { return simd == BatchSimd::Avx2 ? "AVX2" : "baseline"; }

// The first entity whose results differ in a byte (field by field: the double build's struct has
// padding), or a.size() when none does.
std::size_t firstDifference(const std::vector<DeadReckoningResult>& a, const std::vector<DeadReckoningResult>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!ftest::sameBytes(a[i].position, b[i].position) || !ftest::sameBytes(a[i].velocity, b[i].velocity) ||
            !ftest::sameBytes(a[i].orientation, b[i].orientation))
            return i;
    return a.size();
}

void randomPrepared(std::size_t n, std::vector<DeadReckoningState>& states, std::vector<double>& stamps, double now) {
    ftest::Random random(77, kRandomStep);
    states.resize(n);
    stamps.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        DeadReckoningState& s = states[i];
        s.algorithm = static_cast<DeadReckoningAlgorithm>(1 + i % 9);
        s.position = rv(random.uniform(-2000, 2000), random.uniform(-50, 500), random.uniform(-2000, 2000));
        s.velocity = ftest::toF(DVec3(random.uniform(-300, 300), random.uniform(-30, 30), random.uniform(-300, 300)));
        s.acceleration = ftest::toF(DVec3(random.uniform(-20, 20), random.uniform(-20, 20), random.uniform(-20, 20)));
        s.orientation =
            ftest::quatWXYZ(static_cast<float>(random.uniform(-2, 2)), static_cast<float>(random.uniform(-2, 2)),
                            static_cast<float>(random.uniform(-2, 2)), static_cast<float>(random.uniform(-2, 2)));
        const DVec3 axis =
            glm::normalize(DVec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)) + DVec3(1e-3));
        // |w|: zero, tiny (series territory), small, typical, fast.
        const double rates[] = {0.0, 1e-30, 1e-7, 1e-3, random.uniform(0, 3), random.uniform(3, 10)};
        s.angularVelocity = ftest::toF(axis * rates[(i / 9) % 6]);
        // Ages: typical, a few seconds, huge (hours to 11 days); some stamped in the future.
        const double ages[] = {random.uniform(-0.05, 0.3), random.uniform(0, 5), random.uniform(0, 1e6)};
        stamps[i] = now - ages[(i / 54) % 3];
    }
}

TEST(Prepared, RefusesWhatPredictDeadReckoningRefuses) {
    foresight::PreparedDeadReckoning p;
    DeadReckoningState s = makeState(DeadReckoningAlgorithm::Rvw, DVec3(1, 2, 3), DVec3(4, 5, 6));
    EXPECT_EQ(foresight::prepareDeadReckoning(s, kNaN, p), Status::NonFiniteInput);
    EXPECT_EQ(foresight::prepareDeadReckoning(s, kInfinity, p), Status::NonFiniteInput);
    DeadReckoningState bad = s;
    bad.velocity.y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(foresight::prepareDeadReckoning(bad, 0.0, p), Status::NonFiniteInput);
    bad = s;
    bad.orientation = ftest::quatWXYZ(0, 0, 0, 0);
    EXPECT_EQ(foresight::prepareDeadReckoning(bad, 0.0, p), Status::ZeroQuaternion);
    bad = s;
    bad.algorithm = static_cast<DeadReckoningAlgorithm>(0);
    EXPECT_EQ(foresight::prepareDeadReckoning(bad, 0.0, p), Status::InvalidAlgorithm);
    // Untouched on refusal: still the default STATIC update.
    EXPECT_EQ(p.algorithm(), DeadReckoningAlgorithm::Static);
    EXPECT_EQ(p.timestamp(), 0.0);
    ASSERT_EQ(foresight::prepareDeadReckoning(s, 12.5, p), Status::Ok);
    EXPECT_EQ(p.algorithm(), DeadReckoningAlgorithm::Rvw);
    EXPECT_EQ(p.timestamp(), 12.5);

    // Bad per-frame arguments: nothing written, every entity counted.
    std::vector<foresight::PreparedDeadReckoning> entities(3, p);
    std::vector<DeadReckoningResult> out(3);
    out[0].position = rv(7, 7, 7);
    EXPECT_EQ(foresight::extrapolateDeadReckoning(entities, kNaN, 1.0f, out), 3u);
    EXPECT_EQ(foresight::extrapolateDeadReckoning(entities, 13.0, -1.0f, out), 3u);
    EXPECT_EQ(foresight::extrapolateDeadReckoning(entities, 13.0, std::numeric_limits<float>::quiet_NaN(), out), 3u);
    EXPECT_EQ(out[0].position, rv(7, 7, 7));
    // A short `out`: the first out.size() are processed, the rest counted.
    EXPECT_EQ(foresight::extrapolateDeadReckoning(entities, 13.0, 1.0f, std::span(out.data(), 2)), 1u);

    foresight::DeadReckoningBatch batch(3);
    EXPECT_EQ(batch.capacity(), 3u);
    EXPECT_EQ(batch.set(3, p), Status::InvalidSetting);
    EXPECT_EQ(batch.extrapolate(kInfinity, 1.0f, out), 3u);
    EXPECT_EQ(batch.extrapolate(13.0, -0.5f, out), 3u);
    EXPECT_EQ(batch.extrapolate(13.0, 1.0f, std::span(out.data(), 2)), 3u);
    // Entities never set are the default STATIC update at the origin.
    EXPECT_EQ(batch.extrapolate(13.0, 1.0f, out), 0u);
    EXPECT_EQ(out[2].position, rv(0, 0, 0));
    EXPECT_TRUE(ftest::sameBytes(out[2].orientation, glm::identity<Quat>()));
}

TEST(Prepared, OverflowIsRefusedWithTheUpdateAsGiven) {
    DeadReckoningState s = makeState(DeadReckoningAlgorithm::Fpw, DVec3(1, 2, 3), DVec3(3e38, 0, 0));
    for (DeadReckoningAlgorithm algorithm : {DeadReckoningAlgorithm::Fpw, DeadReckoningAlgorithm::Rpb}) {
        s.algorithm = algorithm;
        s.angularVelocity = Vec3(1.0f, 0.0f, 0.0f);  // along v: RPB moves straight, v t
        foresight::PreparedDeadReckoning p;
        ASSERT_EQ(foresight::prepareDeadReckoning(s, 0.0, p), Status::Ok);
        // 3e40 m overflows a float position; in double 3e40 is finite, so a faster one.
        if (foresight::kDoublePrecision) continue;
        std::vector<foresight::PreparedDeadReckoning> entities(1, p);
        std::vector<DeadReckoningResult> out(1);
        EXPECT_EQ(foresight::extrapolateDeadReckoning(entities, 100.0, kInfinity, out), 1u);
        EXPECT_EQ(out[0].position, s.position);
        foresight::DeadReckoningBatch batch(1);
        ASSERT_EQ(batch.set(0, p), Status::Ok);
        out[0] = DeadReckoningResult{};
        EXPECT_EQ(batch.extrapolate(100.0, std::numeric_limits<float>::infinity(), out), 1u);
        EXPECT_EQ(out[0].position, s.position);
        EXPECT_EQ(out[0].velocity, s.velocity);
    }
}

// A frame whose age does not fit a float (time 1e300 s after the update, no extrapolation
// limit) makes the half angle infinite, or NaN for an entity that does not turn (0 x inf): the
// vectorised pass must not convert such an angle to its quadrant's int (undefined behaviour,
// which the sanitizer build stops at; found by fuzz_predict), and every entity is refused or
// finite, as extrapolateDeadReckoning says.
TEST(Prepared, AnAgeBeyondFloatRangeIsRefusedOrFinite) {
    for (DeadReckoningAlgorithm algorithm :
         {DeadReckoningAlgorithm::Static, DeadReckoningAlgorithm::Fpw, DeadReckoningAlgorithm::Rpw,
          DeadReckoningAlgorithm::Rvw, DeadReckoningAlgorithm::Fvw, DeadReckoningAlgorithm::Fpb,
          DeadReckoningAlgorithm::Rpb, DeadReckoningAlgorithm::Rvb, DeadReckoningAlgorithm::Fvb}) {
        for (const float spin : {0.0f, 0.5f}) {
            DeadReckoningState s = makeState(algorithm, DVec3(1, 2, 3), DVec3(0, 0, 0));
            s.angularVelocity = Vec3(0.0f, spin, 0.0f);
            foresight::PreparedDeadReckoning p;
            ASSERT_EQ(foresight::prepareDeadReckoning(s, 0.0, p), Status::Ok);
            std::vector<foresight::PreparedDeadReckoning> entities(1, p);
            std::vector<DeadReckoningResult> reference(1), out(1);
            const std::size_t refused = foresight::extrapolateDeadReckoning(entities, 1e300, kInfinity, reference);
            foresight::DeadReckoningBatch batch(1);
            ASSERT_EQ(batch.set(0, p), Status::Ok);
            const auto finite = [](const auto& v) {
                return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
            };
            for (const BatchSimd simd : availableSimd()) {
                EXPECT_EQ(foresight::detail::BatchAccess::extrapolate(batch, simd, 1e300,
                                                                      std::numeric_limits<float>::infinity(), out),
                          refused)
                    << static_cast<int>(algorithm) << " " << spin << " " << simdName(simd);
                EXPECT_TRUE(finite(out[0].position) && finite(out[0].velocity))
                    << static_cast<int>(algorithm) << " " << spin << " " << simdName(simd);
            }
        }
    }
}

TEST(Prepared, MeetsTheAccuracyContractOn100000RandomStates) {
    const double now = 1.0e6 + 0.5;
    std::vector<DeadReckoningState> states;
    std::vector<double> stamps;
    const std::size_t n = 100000;
    randomPrepared(n, states, stamps, now);
    std::vector<foresight::PreparedDeadReckoning> prepared(n);
    foresight::DeadReckoningBatch batch(n);
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_EQ(foresight::prepareDeadReckoning(states[i], stamps[i], prepared[i]), Status::Ok);
        ASSERT_EQ(batch.set(i, prepared[i]), Status::Ok);
    }
    const float limits[] = {0.0f, 0.25f, 5.0f, std::numeric_limits<float>::infinity()};
    for (float limit : limits) {
        std::vector<DeadReckoningResult> scalar(n), soa(n);
        EXPECT_EQ(foresight::extrapolateDeadReckoning(prepared, now, limit, scalar), 0u);
        EXPECT_EQ(batch.extrapolate(now, limit, soa), 0u);
        // Every instruction set the passes are compiled for gives the same bytes as the one
        // extrapolate chose (each runs the same source: the same IEEE operations).
        for (const BatchSimd simd : availableSimd()) {
            std::vector<DeadReckoningResult> other(n);
            EXPECT_EQ(foresight::detail::BatchAccess::extrapolate(batch, simd, now, limit, other), 0u);
            ASSERT_EQ(firstDifference(other, soa), n)
                << simdName(simd) << " differs from " << simdName(foresight::detail::BatchAccess::best())
                << " at limit " << limit;
        }
        ContractErrors worstScalar, worstSoa;
        for (std::size_t i = 0; i < n; ++i) {
            checkAgainstReference(states[i], stamps[i], now, limit, scalar[i], worstScalar);
            checkAgainstReference(states[i], stamps[i], now, limit, soa[i], worstSoa);
            // World-axis models and STATIC on the scalar path: the reference's double
            // operations, bit for bit (position and velocity).
            if (!foresight::deadReckoningInBodyAxes(states[i].algorithm)) {
                DeadReckoningResult expected;
                double age = std::max(now - stamps[i], 0.0);
                age = std::min(age, static_cast<double>(limit));
                ASSERT_EQ(foresight::predictDeadReckoning(states[i], static_cast<float>(age), expected), Status::Ok);
                EXPECT_TRUE(ftest::sameBytes(scalar[i].position, expected.position)) << i;
                EXPECT_TRUE(ftest::sameBytes(scalar[i].velocity, expected.velocity)) << i;
            }
        }
        std::printf(
            "limit %g: scalar position %.3g of allowed, orientation %.3g rad, length %.3g; "
            "SoA position %.3g, orientation %.3g rad, length %.3g\n",
            static_cast<double>(limit), worstScalar.position, worstScalar.orientation, worstScalar.length,
            worstSoa.position, worstSoa.orientation, worstSoa.length);
        // The contract of extrapolateDeadReckoning (replication.h).
        for (const ContractErrors* w : {&worstScalar, &worstSoa}) {
            EXPECT_LE(w->position, 1.0);
            EXPECT_LE(w->orientation, 4e-7);
            EXPECT_LE(w->length, 3e-7);
            EXPECT_EQ(w->velocityMismatches, 0u);
        }
    }
    // Moving entities between models keeps the batch consistent (the body-axis list).
    for (std::size_t i = 0; i < n; i += 3) {
        DeadReckoningState s = states[i];
        s.algorithm = static_cast<DeadReckoningAlgorithm>(1 + (i / 3) % 9);
        states[i] = s;
        ASSERT_EQ(foresight::prepareDeadReckoning(s, stamps[i], prepared[i]), Status::Ok);
        ASSERT_EQ(batch.set(i, prepared[i]), Status::Ok);
    }
    std::vector<DeadReckoningResult> soa(n);
    EXPECT_EQ(batch.extrapolate(now, 0.25f, soa), 0u);
    for (const BatchSimd simd : availableSimd()) {
        std::vector<DeadReckoningResult> other(n);
        EXPECT_EQ(foresight::detail::BatchAccess::extrapolate(batch, simd, now, 0.25f, other), 0u);
        ASSERT_EQ(firstDifference(other, soa), n) << simdName(simd);
    }
    ContractErrors worst;
    for (std::size_t i = 0; i < n; ++i) checkAgainstReference(states[i], stamps[i], now, 0.25f, soa[i], worst);
    EXPECT_LE(worst.position, 1.0);
    EXPECT_LE(worst.orientation, 4e-7);
}

// DeadReckoningBatch keeps its columns in one allocation of its own: copies are deep (a change
// to the copy leaves the original as it was), moves take the entities and leave an empty batch.
TEST(Prepared, BatchCopiesAreDeepAndMovesLeaveAnEmptyBatch) {
    const double now = 50.0;
    std::vector<DeadReckoningState> states;
    std::vector<double> stamps;
    const std::size_t n = 3000;
    randomPrepared(n, states, stamps, now);
    foresight::DeadReckoningBatch original(n);
    for (std::size_t i = 0; i < n; ++i) {
        foresight::PreparedDeadReckoning p;
        ASSERT_EQ(foresight::prepareDeadReckoning(states[i], stamps[i], p), Status::Ok);
        ASSERT_EQ(original.set(i, p), Status::Ok);
    }
    const auto frame = [&](const foresight::DeadReckoningBatch& batch) {
        std::vector<DeadReckoningResult> out(batch.capacity());
        EXPECT_EQ(batch.extrapolate(now, 0.25f, out), 0u);
        return out;
    };
    const std::vector<DeadReckoningResult> expected = frame(original);

    foresight::DeadReckoningBatch copy(original);
    EXPECT_EQ(firstDifference(frame(copy), expected), n);
    // Entity 7 becomes a static one in the copy only.
    ASSERT_EQ(copy.set(7, foresight::PreparedDeadReckoning{}), Status::Ok);
    const std::vector<DeadReckoningResult> changed = frame(copy);
    EXPECT_EQ(firstDifference(changed, expected), 7u);
    EXPECT_EQ(changed[7].position, rv(0, 0, 0));
    EXPECT_EQ(firstDifference(frame(original), expected), n);

    foresight::DeadReckoningBatch assigned(5);
    assigned = original;
    EXPECT_EQ(assigned.capacity(), n);
    EXPECT_EQ(firstDifference(frame(assigned), expected), n);

    foresight::DeadReckoningBatch moved(std::move(assigned));
    EXPECT_EQ(firstDifference(frame(moved), expected), n);
    EXPECT_EQ(assigned.capacity(), 0u);  // NOLINT(bugprone-use-after-move): moved-from is empty
    std::vector<DeadReckoningResult> none;
    EXPECT_EQ(assigned.extrapolate(now, 0.25f, none), 0u);

    foresight::DeadReckoningBatch target(2);
    target = std::move(moved);
    EXPECT_EQ(firstDifference(frame(target), expected), n);
    EXPECT_EQ(moved.capacity(), 0u);  // NOLINT(bugprone-use-after-move)
    // A moved-from batch takes a new value.
    moved = copy;
    EXPECT_EQ(firstDifference(frame(moved), changed), n);
}

// DeadReckoningBatch skips the range reduction for chunks whose angles are all in the first
// quadrant: an entity's result must not depend on that, i.e. on its neighbours. Entity 0 (a
// slow turn, h = 0.1 rad) sits once among slow neighbours and once beside one turning fast
// enough (h = 40 rad) that its chunk takes the reducing path: the same bytes both times, for a
// world-axis and a body-axis model.
TEST(Prepared, BatchResultDoesNotDependOnTheNeighbours) {
    for (DeadReckoningAlgorithm algorithm : {DeadReckoningAlgorithm::Rvw, DeadReckoningAlgorithm::Rvb}) {
        DeadReckoningState slow = makeState(algorithm, DVec3(10, 2, -3), DVec3(4, 0.5, 6));
        slow.acceleration = Vec3(0.5f, -9.81f, 1.0f);
        slow.angularVelocity = Vec3(0.2f, 0.8f, 0.0f) * (0.2f / glm::length(Vec3(0.2f, 0.8f, 0.0f)));
        DeadReckoningState fast = slow;
        fast.angularVelocity = Vec3(0.0f, 80.0f, 0.0f);
        const double stamp = 100.0;
        const double now = 101.0;  // age 1 s: h = |w| t / 2 = 0.1 and 40
        const float noLimit = std::numeric_limits<float>::infinity();
        foresight::PreparedDeadReckoning pSlow, pFast;
        ASSERT_EQ(foresight::prepareDeadReckoning(slow, stamp, pSlow), Status::Ok);
        ASSERT_EQ(foresight::prepareDeadReckoning(fast, stamp, pFast), Status::Ok);
        foresight::DeadReckoningBatch calm(4), mixed(4);
        for (std::size_t i = 0; i < 4; ++i) {
            ASSERT_EQ(calm.set(i, pSlow), Status::Ok);
            ASSERT_EQ(mixed.set(i, i == 2 ? pFast : pSlow), Status::Ok);
        }
        std::vector<DeadReckoningResult> a(4), b(4);
        ASSERT_EQ(calm.extrapolate(now, noLimit, a), 0u);
        ASSERT_EQ(mixed.extrapolate(now, noLimit, b), 0u);
        EXPECT_TRUE(ftest::sameBytes(a[0].position, b[0].position));
        EXPECT_TRUE(ftest::sameBytes(a[0].velocity, b[0].velocity));
        EXPECT_TRUE(ftest::sameBytes(a[0].orientation, b[0].orientation));
        // And both within the contract of the reference (the fast one too).
        ContractErrors worst;
        checkAgainstReference(slow, stamp, now, noLimit, a[0], worst);
        checkAgainstReference(fast, stamp, now, noLimit, b[2], worst);
        EXPECT_LE(worst.position, 1.0);
        EXPECT_LE(worst.orientation, 4e-7);
    }
}

}  // namespace
