// Firing solutions (aim.h). Every solution is flown, by predictProjectile (Exact, no world) and by
// the closed-form parabola in double, and must meet the target within 1e-3 m at its time.
// References: the range formula R = v^2 sin(2 theta) / g, the straight-line intercept of a
// crossing target, sqrt(2 h / g), and a brute-force time scan of |d(t)| - s t on random problems.
// Built into foresight_aim_tests (float positions) and foresight_aim_double_tests (double
// positions); each binary counts heap allocations (counting_allocator.h).

#include "counting_allocator.h"
#include "test_util.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

using foresight::AimConstraint;
using foresight::AimShot;
using foresight::AimTarget;
using foresight::FiringSolution;
using foresight::Real;
using foresight::RVec3;
using foresight::Status;
using foresight::Vec3;
using ftest::DVec3;

constexpr double kPi = 3.14159265358979323846;

struct Aimed {
    Status status = Status::Ok;
    std::vector<FiringSolution> solutions;
};

Aimed aim(const AimShot& shot, const AimTarget& target) {
    std::array<FiringSolution, foresight::kMaxFiringSolutions> storage{};
    std::size_t count = 99;
    Aimed out;
    out.status = foresight::aimProjectile(shot, target, storage, count);
    if (out.status == Status::Ok)
        out.solutions.assign(storage.begin(), storage.begin() + static_cast<std::ptrdiff_t>(count));
    return out;
}

DVec3 targetAt(const AimTarget& target, double t) {
    return ftest::toD(target.position) + ftest::toD(target.velocity) * t +
           ftest::toD(target.acceleration) * (0.5 * t * t);
}

DVec3 gravityOf(const AimShot& shot) {
    return DVec3(ftest::decimal(shot.gravity.x), ftest::decimal(shot.gravity.y), ftest::decimal(shot.gravity.z));
}

/// Distance between projectile and target at the solution's time, flown by the closed-form
/// parabola in double (the float velocity and time as returned).
double closedFormMiss(const AimShot& shot, const AimTarget& target, const FiringSolution& s) {
    const double t = static_cast<double>(s.time);
    const DVec3 projectile = ftest::toD(shot.from) + ftest::toD(s.velocity) * t + gravityOf(shot) * (0.5 * t * t);
    return glm::length(projectile - targetAt(target, t));
}

/// The same, flown by predictProjectile (Exact, no world), which takes the time at its decimal value.
double predictorMiss(const AimShot& shot, const AimTarget& target, const FiringSolution& s) {
    foresight::ProjectileSettings settings;
    settings.gravity = shot.gravity;
    foresight::ProjectileResult result;
    const Status status = foresight::predictProjectile(shot.from, s.velocity, s.time, settings, nullptr, {}, result);
    EXPECT_EQ(status, Status::Ok);
    return glm::length(ftest::toD(result.position) - targetAt(target, ftest::decimal(s.time)));
}

/// Every solution meets the target (1e-3 m: the contract; float velocity and time round to
/// ~1e-7 relative, i.e. ~1e-4 m over these flights), is within (0, maxTime], sorted, finite,
/// reports the hit where the target is, and has the constrained speed.
void expectHits(const AimShot& shot, const AimTarget& target, const std::vector<FiringSolution>& solutions) {
    float previous = 0.0f;
    for (const auto& s : solutions) {
        EXPECT_GT(s.time, previous);
        EXPECT_LE(s.time, shot.maxTime);
        previous = s.time;
        EXPECT_TRUE(std::isfinite(s.elevation));
        EXPECT_LT(closedFormMiss(shot, target, s), 1e-3) << "t = " << s.time;
        EXPECT_LT(predictorMiss(shot, target, s), 1e-3) << "t = " << s.time;
        EXPECT_LT(glm::length(ftest::toD(s.hit) - targetAt(target, static_cast<double>(s.time))), 1e-3);
        const DVec3 v = ftest::toD(s.velocity);
        if (shot.constraint == AimConstraint::Speed) {
            EXPECT_NEAR(glm::length(v), static_cast<double>(shot.speed), 1e-5 * std::max(1.0, double(shot.speed)));
        }
        if (shot.constraint == AimConstraint::HorizontalSpeed) {
            const DVec3 up = -glm::normalize(gravityOf(shot));
            EXPECT_NEAR(glm::length(v - glm::dot(v, up) * up), static_cast<double>(shot.speed),
                        1e-5 * std::max(1.0, double(shot.speed)));
        }
    }
}

AimShot shotAt(float speed, Vec3 gravity = Vec3(0.0f, -9.81f, 0.0f)) {
    AimShot shot;
    shot.speed = speed;
    shot.gravity = gravity;
    return shot;
}

AimTarget staticAt(double x, double y, double z) {
    AimTarget target;
    target.position = ftest::toR(DVec3(x, y, z));
    return target;
}

// ---------------------------------------------------------------------------------------------
// Static target at a fixed speed: the closed form.

// Flat ground, 20 m/s: the target at R = v^2 sin(2 theta) / g for theta = 30 degrees is hit at
// 30 and 60 degrees (sin(60) = sin(120)); flight times 2 v sin(theta) / g.
TEST(Aim, StaticTargetOnFlatGroundMatchesTheRangeFormula) {
    const double v = 20.0, g = 9.81;
    const double range = v * v * std::sin(2.0 * kPi / 6.0) / g;
    const AimShot shot = shotAt(20.0f);
    const AimTarget target = staticAt(range, 0, 0);
    const Aimed a = aim(shot, target);
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 2u);
    // float inputs (range rounded to ~2e-6 m, g 9.81f): angles to ~1e-6 rad.
    EXPECT_NEAR(a.solutions[0].elevation, kPi / 6.0, 1e-5);
    EXPECT_NEAR(a.solutions[1].elevation, kPi / 3.0, 1e-5);
    EXPECT_NEAR(a.solutions[0].time, 2.0 * v * std::sin(kPi / 6.0) / g, 1e-5);
    EXPECT_NEAR(a.solutions[1].time, 2.0 * v * std::sin(kPi / 3.0) / g, 1e-5);
    expectHits(shot, target, a.solutions);
}

// Exactly at the maximum range v^2 / g (20 m/s, g = 10: 40 m, exact in float): the double root,
// one solution at 45 degrees, no NaN.
TEST(Aim, ExactlyAtMaximumRangeIsTheFortyFiveDegreeDoubleRoot) {
    const AimShot shot = shotAt(20.0f, Vec3(0.0f, -10.0f, 0.0f));
    for (const AimTarget& target : {staticAt(40, 0, 0), staticAt(0, 0, -40), staticAt(24, 0, 32)}) {
        const Aimed a = aim(shot, target);
        ASSERT_EQ(a.status, Status::Ok);
        ASSERT_EQ(a.solutions.size(), 1u);
        EXPECT_NEAR(a.solutions[0].elevation, kPi / 4.0, 1e-6);
        EXPECT_NEAR(a.solutions[0].time, 2.0 * std::sqrt(2.0), 1e-6);  // 2 v sin(45) / g
        expectHits(shot, target, a.solutions);
    }
    // The same through the quartic: a target falling at 2 m/s^2 under a gravity of 12 moves
    // relative to the shot exactly as a static target under 10.
    AimShot quarticShot = shotAt(20.0f, Vec3(0.0f, -12.0f, 0.0f));
    AimTarget falling = staticAt(40, 0, 0);
    falling.acceleration = Vec3(0.0f, -2.0f, 0.0f);
    const Aimed q = aim(quarticShot, falling);
    ASSERT_EQ(q.status, Status::Ok);
    ASSERT_EQ(q.solutions.size(), 1u);
    EXPECT_NEAR(q.solutions[0].time, 2.0 * std::sqrt(2.0), 1e-6);
    expectHits(quarticShot, falling, q.solutions);
}

// Just beyond the range limit: nothing (not an error); just inside: two close arcs.
TEST(Aim, BeyondTheRangeLimitIsEmptyAndJustInsideGivesTwoArcs) {
    const AimShot shot = shotAt(30.0f);
    const double limit = 900.0 / 9.81;
    const Aimed beyond = aim(shot, staticAt(limit * (1 + 1e-5), 0, 0));
    ASSERT_EQ(beyond.status, Status::Ok);
    EXPECT_TRUE(beyond.solutions.empty());
    const AimTarget inside = staticAt(limit * (1 - 1e-5), 0, 0);
    const Aimed a = aim(shot, inside);
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 2u);
    EXPECT_NEAR(a.solutions[0].elevation, kPi / 4, 0.01);
    EXPECT_NEAR(a.solutions[1].elevation, kPi / 4, 0.01);
    expectHits(shot, inside, a.solutions);
    // Far beyond: a target 1 km up with 30 m/s.
    EXPECT_TRUE(aim(shot, staticAt(0, 1000, 0)).solutions.empty());
}

// Near-vertical and near-horizontal shots (no cancellation in the closed form):
// straight up, straight down, 0.1 mm off vertical, and 1000 m/s at 100 m (elevation 4.9e-4 rad).
TEST(Aim, NearVerticalAndNearHorizontalShotsAreAccurate) {
    const AimShot shot = shotAt(40.0f);
    for (const AimTarget& target :
         {staticAt(0, 50, 0), staticAt(0, -20, 0), staticAt(1e-4, 50, 0), staticAt(0, 81.5, 1e-4)}) {
        const Aimed a = aim(shot, target);
        ASSERT_EQ(a.status, Status::Ok);
        ASSERT_FALSE(a.solutions.empty());
        expectHits(shot, target, a.solutions);
    }
    // Straight up to 50 m at 40 m/s: t = (v - sqrt(v^2 - 2 g h)) / g, the elevation pi / 2.
    const Aimed up = aim(shot, staticAt(0, 50, 0));
    ASSERT_EQ(up.solutions.size(), 2u);
    EXPECT_NEAR(up.solutions[0].time, (40.0 - std::sqrt(1600.0 - 2 * 9.81 * 50)) / 9.81, 1e-5);
    EXPECT_NEAR(up.solutions[0].elevation, kPi / 2, 1e-6);

    AimShot fast = shotAt(1000.0f);
    fast.maxTime = 300.0f;  // the high arc flies 204 s
    const AimTarget far = staticAt(100, 0, 0);
    const Aimed a = aim(fast, far);
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 2u);
    // sin(2 theta) = g R / v^2: theta = 4.905e-4 rad, to float rounding of the velocity.
    EXPECT_NEAR(a.solutions[0].elevation, 0.5 * std::asin(9.81 * 100 / 1e6), 1e-7);
    EXPECT_NEAR(a.solutions[0].time, 0.1, 1e-6);
    EXPECT_LT(closedFormMiss(fast, far, a.solutions[0]), 1e-3);
    // The high arc (204 s, 200 km up) is ~1e-7 relative off in float: check the closed form
    // in double for the exact arc instead, with the double time the float rounds from.
    EXPECT_NEAR(a.solutions[1].elevation, kPi / 2 - 0.5 * std::asin(9.81 * 100 / 1e6), 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Straight line (no gravity)

// A target 30 m ahead crossing at 10 m/s, a 20 m/s shot: (100 - 400) t^2 + 900 = 0, t = sqrt(3).
TEST(Aim, StraightLineInterceptOfACrossingTarget) {
    const AimShot shot = shotAt(20.0f, Vec3(0.0f));
    AimTarget target = staticAt(0, 0, 30);
    target.velocity = Vec3(10.0f, 0.0f, 0.0f);
    const Aimed a = aim(shot, target);
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 1u);
    EXPECT_NEAR(a.solutions[0].time, std::sqrt(3.0), 1e-6);
    EXPECT_NEAR(a.solutions[0].hit.x, 10 * std::sqrt(3.0), 1e-5);
    EXPECT_NEAR(a.solutions[0].elevation, 0.0, 1e-7);
    expectHits(shot, target, a.solutions);

    // Running away faster than the shot: none. Coming closer faster: two (earliest first).
    target.velocity = Vec3(0.0f, 0.0f, 25.0f);
    EXPECT_TRUE(aim(shot, target).solutions.empty());
    target.velocity = Vec3(1.0f, 0.0f, -25.0f);
    const Aimed b = aim(shot, target);
    ASSERT_EQ(b.solutions.size(), 2u);
    expectHits(shot, target, b.solutions);

    // Zero gravity falls back to the straight line at a static target: t = R / s, aimed at it.
    const Aimed line = aim(shot, staticAt(30, 40, 0));
    ASSERT_EQ(line.solutions.size(), 1u);
    EXPECT_NEAR(line.solutions[0].time, 2.5, 1e-6);
    EXPECT_NEAR(line.solutions[0].velocity.x, 12.0f, 1e-5f);
    EXPECT_NEAR(line.solutions[0].velocity.y, 16.0f, 1e-5f);
}

// ---------------------------------------------------------------------------------------------
// Moving targets under gravity (the quartic)

TEST(Aim, MovingAndAcceleratingTargetsUnderGravityAreHit) {
    // The contract's example: a grenade at 18 m/s from 1.6 m at a target moving and accelerating.
    AimShot grenade = shotAt(18.0f);
    grenade.from = ftest::toR(DVec3(0, 1.6, 0));
    AimTarget runner = staticAt(10, 0, 12);
    runner.velocity = Vec3(2.0f, 0.0f, 0.0f);
    runner.acceleration = Vec3(0.0f, 0.0f, 0.5f);
    const Aimed a = aim(grenade, runner);
    ASSERT_EQ(a.status, Status::Ok);
    EXPECT_EQ(a.solutions.size(), 2u);  // low and high arc
    expectHits(grenade, runner, a.solutions);

    // A target falling faster than the shot (a = -20 against g = -9.81), passing through
    // the shooter's reach twice more: up to four solutions, all hits.
    AimShot shot = shotAt(15.0f);
    AimTarget diver = staticAt(5, 30, 0);
    diver.velocity = Vec3(-3.0f, 10.0f, 0.0f);
    diver.acceleration = Vec3(0.0f, -20.0f, 0.0f);
    const Aimed b = aim(shot, diver);
    ASSERT_EQ(b.status, Status::Ok);
    EXPECT_GE(b.solutions.size(), 2u);
    expectHits(shot, diver, b.solutions);
}

// maxTime drops later solutions; a smaller span keeps the earliest ones.
TEST(Aim, MaxTimeAndSmallSpans) {
    AimShot shot = shotAt(20.0f);
    const AimTarget target = staticAt(20, 0, 0);
    const Aimed both = aim(shot, target);
    ASSERT_EQ(both.solutions.size(), 2u);
    shot.maxTime = 0.5f * (both.solutions[0].time + both.solutions[1].time);
    const Aimed low = aim(shot, target);
    ASSERT_EQ(low.solutions.size(), 1u);
    EXPECT_EQ(low.solutions[0].time, both.solutions[0].time);
    expectHits(shot, target, low.solutions);
    shot.maxTime = 0.0f;  // nothing flies
    const Aimed none = aim(shot, target);
    EXPECT_EQ(none.status, Status::Ok);
    EXPECT_TRUE(none.solutions.empty());

    shot.maxTime = 60.0f;
    std::array<FiringSolution, 1> one{};
    std::size_t count = 0;
    ASSERT_EQ(foresight::aimProjectile(shot, target, one, count), Status::Ok);
    EXPECT_EQ(count, 1u);
    EXPECT_EQ(one[0].time, both.solutions[0].time);
    expectHits(shot, target, std::vector<FiringSolution>(one.begin(), one.end()));
    ASSERT_EQ(foresight::aimProjectile(shot, target, std::span<FiringSolution>(), count), Status::Ok);
    EXPECT_EQ(count, 0u);
}

// ---------------------------------------------------------------------------------------------
// Variants: horizontal speed, apex height

// 50 m away horizontally (30, 40), 2 m up, lateral 10 m/s: t = 5 s, vertical speed
// (2 + g t^2 / 2) / t.
TEST(Aim, HorizontalSpeedFixesTheTimeAndTheVerticalSpeedFollows) {
    AimShot shot = shotAt(10.0f);
    shot.constraint = AimConstraint::HorizontalSpeed;
    const AimTarget target = staticAt(30, 2, 40);
    const Aimed a = aim(shot, target);
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 1u);
    EXPECT_NEAR(a.solutions[0].time, 5.0, 1e-6);
    EXPECT_NEAR(a.solutions[0].velocity.y, (2 + 9.81 * 12.5) / 5, 1e-5);
    expectHits(shot, target, a.solutions);

    // A moving, accelerating target, and a tilted gravity ("horizontal" is across it).
    AimTarget runner = staticAt(10, 0, 12);
    runner.velocity = Vec3(2.0f, 1.0f, 0.0f);
    runner.acceleration = Vec3(0.5f, 0.0f, -1.0f);
    shot.gravity = Vec3(1.0f, -9.0f, 0.5f);
    const Aimed b = aim(shot, runner);
    ASSERT_EQ(b.status, Status::Ok);
    ASSERT_FALSE(b.solutions.empty());
    expectHits(shot, runner, b.solutions);
}

// Apex above the start: vertical speed sqrt(2 g h); above the target: the apex h above the hit.
TEST(Aim, ApexHeightAboveTheStartOrTheTarget) {
    const double g = 9.81;
    AimShot shot = shotAt(0.0f);
    shot.constraint = AimConstraint::ApexAboveStart;
    shot.apexHeight = 10.0f;
    const AimTarget target = staticAt(20, 0, 0);
    const Aimed a = aim(shot, target);
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 1u);  // the descending hit only
    const double w = std::sqrt(2 * g * 10);
    EXPECT_NEAR(a.solutions[0].velocity.y, w, 1e-5);
    EXPECT_NEAR(a.solutions[0].time, 2 * w / g, 1e-6);
    expectHits(shot, target, a.solutions);

    // A target 5 m up, apex 3 m above it (8 m above the start): w = sqrt(2 g 8), and it
    // falls 3 m from the apex: t = (w + sqrt(2 g 3)) / g.
    shot.constraint = AimConstraint::ApexAboveTarget;
    shot.apexHeight = 3.0f;
    const AimTarget high = staticAt(20, 5, 0);
    const Aimed b = aim(shot, high);
    ASSERT_EQ(b.solutions.size(), 1u);
    EXPECT_NEAR(b.solutions[0].velocity.y, std::sqrt(2 * g * 8), 1e-5);
    EXPECT_NEAR(b.solutions[0].time, (std::sqrt(2 * g * 8) + std::sqrt(2 * g * 3)) / g, 1e-6);
    expectHits(shot, high, b.solutions);

    // A target moving up and sideways: the apex is still 3 m above where it is hit.
    AimTarget lift = high;
    lift.velocity = Vec3(1.0f, 2.0f, -1.0f);
    const Aimed c = aim(shot, lift);
    ASSERT_EQ(c.solutions.size(), 1u);
    expectHits(shot, lift, c.solutions);
    const double vy = static_cast<double>(c.solutions[0].velocity.y);
    EXPECT_NEAR(vy * vy / (2 * g) - (c.solutions[0].hit.y - 0.0), 3.0, 1e-4);

    // Apex above the start lower than the target: unreachable. Negative heights: nothing.
    shot.constraint = AimConstraint::ApexAboveStart;
    shot.apexHeight = 4.0f;
    EXPECT_TRUE(aim(shot, high).solutions.empty());
    shot.apexHeight = -1.0f;
    EXPECT_TRUE(aim(shot, target).solutions.empty());
}

// ---------------------------------------------------------------------------------------------
// Degenerate input

TEST(Aim, TargetAtTheShooter) {
    // Under gravity: straight up and back, t = 2 v / g. Time 0 is never a solution.
    AimShot shot = shotAt(10.0f);
    const Aimed a = aim(shot, staticAt(0, 0, 0));
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 1u);
    EXPECT_NEAR(a.solutions[0].time, 2 * 10 / 9.81, 1e-6);
    EXPECT_NEAR(a.solutions[0].elevation, kPi / 2, 1e-6);
    expectHits(shot, staticAt(0, 0, 0), a.solutions);
    // The same through the quartic (a target with a negligible... exactly zero-offset but
    // moving): it walks away at 1 m/s; the shot still comes back to where it is.
    AimTarget walker = staticAt(0, 0, 0);
    walker.velocity = Vec3(1.0f, 0.0f, 0.0f);
    const Aimed w = aim(shot, walker);
    ASSERT_EQ(w.solutions.size(), 1u);
    expectHits(shot, walker, w.solutions);
    // Without gravity a shot never comes back: none.
    EXPECT_TRUE(aim(shotAt(10.0f, Vec3(0.0f)), staticAt(0, 0, 0)).solutions.empty());
    // Nothing moves at all (no speed, no gravity, target at the shooter): every time meets it;
    // one solution at maxTime with a zero velocity.
    const Aimed still = aim(shotAt(0.0f, Vec3(0.0f)), staticAt(0, 0, 0));
    ASSERT_EQ(still.solutions.size(), 1u);
    EXPECT_EQ(still.solutions[0].time, 60.0f);
    EXPECT_EQ(still.solutions[0].velocity, Vec3(0.0f));
    expectHits(shotAt(0.0f, Vec3(0.0f)), staticAt(0, 0, 0), still.solutions);
}

TEST(Aim, ZeroAndNegativeSpeed) {
    // Zero speed drops the projectile: a target 20 m below is hit after sqrt(2 h / g).
    const AimShot drop = shotAt(0.0f);
    const Aimed a = aim(drop, staticAt(0, -20, 0));
    ASSERT_EQ(a.status, Status::Ok);
    ASSERT_EQ(a.solutions.size(), 1u);
    EXPECT_NEAR(a.solutions[0].time, std::sqrt(2 * 20 / 9.81), 1e-6);
    EXPECT_EQ(a.solutions[0].velocity, Vec3(0.0f));
    EXPECT_EQ(a.solutions[0].elevation, 0.0f);
    expectHits(drop, staticAt(0, -20, 0), a.solutions);
    // ... and a target beside it never.
    EXPECT_TRUE(aim(drop, staticAt(1, -20, 0)).solutions.empty());
    // A negative speed reaches nothing.
    const Aimed negative = aim(shotAt(-5.0f), staticAt(5, 0, 0));
    EXPECT_EQ(negative.status, Status::Ok);
    EXPECT_TRUE(negative.solutions.empty());
}

// A time that rounds to 0 as a float is not reported (the contract: time in (0, maxTime]).
// Straight line, no gravity: t = distance / speed.
TEST(Aim, TimesThatRoundToZeroAsAFloatAreDropped) {
    // 1e-44 m at 1e6 m/s (the envelope's speed): t = 1e-50 s, 0 as a float (the smallest
    // float is 1.4e-45).
    const Aimed tiny = aim(shotAt(1e6f, Vec3(0.0f)), staticAt(1e-44, 0, 0));
    ASSERT_EQ(tiny.status, Status::Ok);
    EXPECT_TRUE(tiny.solutions.empty());
    // 1e-24 m at 1e6 m/s: t = 1e-30 s, a normal float (> 1.2e-38): kept, and flown.
    const AimShot fast = shotAt(1e6f, Vec3(0.0f));
    const AimTarget near = staticAt(1e-24, 0, 0);
    const Aimed kept = aim(fast, near);
    ASSERT_EQ(kept.status, Status::Ok);
    ASSERT_EQ(kept.solutions.size(), 1u);
    EXPECT_GT(kept.solutions[0].time, 0.0f);
    EXPECT_NEAR(kept.solutions[0].time, 1e-30, 1e-36);  // float rounding: 6e-8 relative
    expectHits(fast, near, kept.solutions);
}

TEST(Aim, RefusalsLeaveTheOutputUntouched) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const AimShot good = shotAt(20.0f);
    const AimTarget target = staticAt(20, 0, 0);
    auto refused = [&](const AimShot& shot, const AimTarget& t) {
        std::array<FiringSolution, 4> storage{};
        storage[0].time = 123.0f;
        std::size_t count = 77;
        const Status status = foresight::aimProjectile(shot, t, storage, count);
        EXPECT_EQ(count, 77u);
        EXPECT_EQ(storage[0].time, 123.0f);
        EXPECT_EQ(foresight::validateAim(shot, t), status);
        return status;
    };
    for (const float bad : {nan, inf}) {
        AimShot s = good;
        s.speed = bad;
        EXPECT_EQ(refused(s, target), Status::NonFiniteInput);
        s = good;
        s.from.y = static_cast<foresight::Real>(bad);
        EXPECT_EQ(refused(s, target), Status::NonFiniteInput);
        s = good;
        s.gravity.x = bad;
        EXPECT_EQ(refused(s, target), Status::NonFiniteInput);
        s = good;
        s.maxTime = bad;
        EXPECT_EQ(refused(s, target), Status::NonFiniteInput);
        s = good;
        s.apexHeight = bad;
        EXPECT_EQ(refused(s, target), Status::NonFiniteInput);
        AimTarget t = target;
        t.position.z = static_cast<foresight::Real>(bad);
        EXPECT_EQ(refused(good, t), Status::NonFiniteInput);
        t = target;
        t.velocity.x = bad;
        EXPECT_EQ(refused(good, t), Status::NonFiniteInput);
        t = target;
        t.acceleration.y = bad;
        EXPECT_EQ(refused(good, t), Status::NonFiniteInput);
    }
    AimShot s = good;
    s.maxTime = -1.0f;
    EXPECT_EQ(refused(s, target), Status::NegativeTime);
    s = shotAt(0.0f, Vec3(0.0f));
    s.constraint = AimConstraint::ApexAboveStart;
    EXPECT_EQ(refused(s, target), Status::ZeroVector);
    s.constraint = AimConstraint::ApexAboveTarget;
    EXPECT_EQ(refused(s, target), Status::ZeroVector);
    EXPECT_EQ(foresight::validateAim(good, target), Status::Ok);
}

// Finite but absurd input: a velocity beyond the float range is NonFiniteResult, not inf.
// aimProjectile is a per-frame call: every constraint, moving and static targets, no heap use.
TEST(Aim, DoesNotAllocate) {
    std::array<FiringSolution, foresight::kMaxFiringSolutions> storage{};
    std::size_t total = 0;
    std::size_t calls = 0;
    long allocations = 0;
    for (const AimConstraint constraint : {AimConstraint::Speed, AimConstraint::HorizontalSpeed,
                                           AimConstraint::ApexAboveStart, AimConstraint::ApexAboveTarget}) {
        for (const float gravity : {0.0f, -9.81f}) {
            if (gravity == 0.0f &&
                (constraint == AimConstraint::ApexAboveStart || constraint == AimConstraint::ApexAboveTarget))
                continue;  // an apex needs gravity (refused: ZeroVector)
            AimShot shot;
            shot.from = ftest::toR(DVec3(0, 1.5, 0));
            shot.constraint = constraint;
            shot.speed = 30.0f;
            shot.apexHeight = 4.0f;
            shot.gravity = Vec3(0.0f, gravity, 0.0f);
            shot.maxTime = 10.0f;
            AimTarget target;
            target.position = ftest::toR(DVec3(20, 0, 15));
            target.velocity = Vec3(-3.0f, 0.0f, 2.0f);
            target.acceleration = Vec3(0.5f, 0.0f, -1.0f);
            std::size_t count = 0;
            const long before = ftest::gAllocations.load();
            const Status status = foresight::aimProjectile(shot, target, storage, count);
            allocations += ftest::gAllocations.load() - before;
            ASSERT_EQ(status, Status::Ok);
            total += count;
            ++calls;
        }
    }
    EXPECT_EQ(calls, 6u);
    EXPECT_GE(total, calls);  // every shot has a solution: the solvers ran to the end
    EXPECT_EQ(allocations, 0);
}

TEST(Aim, OverflowIsNonFiniteResult) {
    AimShot shot = shotAt(1.0f);
    shot.constraint = AimConstraint::HorizontalSpeed;
    // 1e-35 m away horizontally, 1e4 m up (inside the envelope): t = 1e-35 s, vertical speed
    // 1e39 m/s, beyond float.
    std::array<FiringSolution, 4> storage{};
    std::size_t count = 0;
    const Status status = foresight::aimProjectile(shot, staticAt(1e-35, 1e4, 0), storage, count);
    EXPECT_TRUE(status == Status::NonFiniteResult || (status == Status::Ok && count == 0)) << int(status);
}

// ---------------------------------------------------------------------------------------------
// Brute force: a time scan of g(t) = |d(t)| - s t on random problems against the solver.

struct ScanReport {
    std::uint64_t problems = 0;
    std::uint64_t scanRoots = 0;    ///< roots the scan finds (crossings and clear touches)
    std::uint64_t solverRoots = 0;  ///< solutions the solver reports
    std::uint64_t missed = 0;       ///< scan roots without a solver solution near them
    std::uint64_t spurious = 0;     ///< solver solutions that miss the target by > 1e-3 m, flown
                                    ///< by the closed-form parabola or by predictProjectile
    std::uint64_t flown = 0;        ///< solver solutions flown by predictProjectile
    std::uint64_t unmatched = 0;    ///< solver solutions the scan did not see (but that hit)
    std::uint64_t grazing = 0;      ///< problems built to graze (double roots)
    std::uint64_t closePairs = 0;   ///< scan roots within 1e-2 s of the next (near-double roots)
};

// One random problem: target in a 100 m box, up to 12 m/s and 4 m/s^2, speed 1..40 m/s, gravity
// 9.81 (1 in 8 without), a 10 s window. One in four is built to graze: the speed is set to the
// minimum over t of |d(t)| / t, so |d(t)| - s t touches zero (a double root).
void randomProblem(ftest::Random& random, AimShot& shot, AimTarget& target, bool& grazing) {
    shot = AimShot();
    shot.from = ftest::toR(DVec3(random.uniform(-5, 5), random.uniform(0, 3), random.uniform(-5, 5)));
    shot.gravity = random.uniform() < 0.125 ? Vec3(0.0f) : Vec3(0.0f, -9.81f, 0.0f);
    shot.maxTime = 10.0f;
    target.position = ftest::toR(DVec3(random.uniform(-50, 50), random.uniform(-10, 30), random.uniform(-50, 50)));
    target.velocity = Vec3(static_cast<float>(random.uniform(-12, 12)), static_cast<float>(random.uniform(-6, 6)),
                           static_cast<float>(random.uniform(-12, 12)));
    target.acceleration = random.uniform() < 0.25 ? Vec3(0.0f)
                                                  : Vec3(static_cast<float>(random.uniform(-4, 4)),
                                                         static_cast<float>(random.uniform(-4, 4)),
                                                         static_cast<float>(random.uniform(-4, 4)));
    shot.speed = static_cast<float>(random.uniform(1, 40));
    grazing = random.uniform() < 0.25;
    if (grazing) {
        const DVec3 from = ftest::toD(shot.from);
        const DVec3 g = gravityOf(shot);
        auto ratio = [&](double t) { return glm::length(targetAt(target, t) - from - 0.5 * g * t * t) / t; };
        double best = 0.5, bestValue = ratio(0.5);
        for (int i = 1; i <= 400; ++i) {
            const double t = 10.0 * i / 400;
            if (ratio(t) < bestValue) best = t, bestValue = ratio(t);
        }
        double lo = std::max(best - 0.025, 1e-3), hi = std::min(best + 0.025, 10.0);
        for (int i = 0; i < 200; ++i) {  // golden section on the bracket
            const double a = lo + 0.381966 * (hi - lo), b = hi - 0.381966 * (hi - lo);
            (ratio(a) < ratio(b) ? hi : lo) = ratio(a) < ratio(b) ? b : a;
        }
        shot.speed = static_cast<float>(ratio(0.5 * (lo + hi)));
    }
}

/// The scan: g at `samples` times over (0, maxTime]; each sign change is a root; between
/// samples, the extremum of g nearest zero is refined (golden section) and is a root when g
/// touches zero within 1e-14 of the distances (a double root), or two roots when it crosses.
int scanRoots(const AimShot& shot, const AimTarget& target, int samples, std::vector<double>& roots) {
    roots.clear();
    const DVec3 from = ftest::toD(shot.from);
    const DVec3 grav = gravityOf(shot);
    const double s = static_cast<double>(shot.speed);
    auto miss = [&](double t) { return glm::length(targetAt(target, t) - from - 0.5 * grav * t * t) - s * t; };
    auto scale = [&](double t) { return glm::length(targetAt(target, t) - from - 0.5 * grav * t * t) + s * t; };
    const double tMax = static_cast<double>(shot.maxTime);
    auto bisect = [&](double a, double b) {
        double fa = miss(a);
        for (int i = 0; i < 100; ++i) {
            const double m = 0.5 * (a + b);
            const double fm = miss(m);
            if ((fm < 0) == (fa < 0))
                a = m, fa = fm;
            else
                b = m;
        }
        return 0.5 * (a + b);
    };
    std::vector<double> t(static_cast<std::size_t>(samples) + 1), f(t.size());
    for (int i = 0; i <= samples; ++i) {
        t[static_cast<std::size_t>(i)] = tMax * i / samples;
        f[static_cast<std::size_t>(i)] = miss(std::max(t[static_cast<std::size_t>(i)], 1e-12));
    }
    for (std::size_t i = 1; i < t.size(); ++i) {
        if ((f[i - 1] < 0) != (f[i] < 0)) roots.push_back(bisect(t[i - 1], t[i]));
        // An interior extremum of g that approaches zero: refine over the two neighbouring intervals.
        if (i + 1 < t.size()) {
            const bool minimum = f[i] > 0 && f[i] <= f[i - 1] && f[i] <= f[i + 1];
            const bool maximum = f[i] < 0 && f[i] >= f[i - 1] && f[i] >= f[i + 1];
            if (!minimum && !maximum) continue;
            double lo = t[i - 1], hi = t[i + 1];
            const double sign = minimum ? 1.0 : -1.0;
            for (int k = 0; k < 100; ++k) {
                const double a = lo + 0.381966 * (hi - lo), b = hi - 0.381966 * (hi - lo);
                if (sign * miss(a) < sign * miss(b))
                    hi = b;
                else
                    lo = a;
            }
            const double extremum = 0.5 * (lo + hi);
            const double value = miss(extremum);
            if (std::fabs(value) <= 1e-14 * scale(extremum)) {
                roots.push_back(extremum);
            } else if ((value < 0) != (f[i] < 0)) {
                // Two crossings inside one sample pair, missed by the sign test.
                roots.push_back(bisect(t[i - 1], extremum));
                roots.push_back(bisect(extremum, t[i + 1]));
            }
        }
    }
    std::sort(roots.begin(), roots.end());
    return static_cast<int>(roots.size());
}

ScanReport compareWithScan(std::uint64_t problems, int samples, std::uint64_t seed) {
    ScanReport report;
    ftest::Random random(seed);
    std::vector<double> scanned;
    for (std::uint64_t n = 0; n < problems; ++n) {
        AimShot shot;
        AimTarget target;
        bool grazing = false;
        randomProblem(random, shot, target, grazing);
        report.grazing += grazing ? 1 : 0;
        ++report.problems;
        const Aimed solved = aim(shot, target);
        if (solved.status != Status::Ok) {
            ++report.missed;
            continue;
        }
        scanRoots(shot, target, samples, scanned);
        report.scanRoots += scanned.size();
        for (std::size_t i = 1; i < scanned.size(); ++i)
            report.closePairs += scanned[i] - scanned[i - 1] < 1e-2 ? 1 : 0;
        report.solverRoots += solved.solutions.size();
        // Float times: the solver's root rounded to a float (6e-8 relative); the scan's root is
        // bisected to double. Two roots are the same within 1e-5 s (relative, at least 1e-5).
        auto near = [](double a, double b) { return std::fabs(a - b) <= 1e-5 * std::max(1.0, std::fabs(b)); };
        for (const double root : scanned) {
            const bool found =
                std::any_of(solved.solutions.begin(), solved.solutions.end(),
                            [&](const FiringSolution& s) { return near(static_cast<double>(s.time), root); });
            if (!found) {
                // A root at the window's end may fall on either side of maxTime.
                if (root > static_cast<double>(shot.maxTime) * (1 - 1e-6)) continue;
                ++report.missed;
                if (report.missed <= 5) {
                    std::printf("[aim scan] missed root %.9g; solver:", root);
                    for (const auto& s : solved.solutions) std::printf(" %.9g", static_cast<double>(s.time));
                    std::printf("\n");
                }
            }
        }
        for (const auto& s : solved.solutions) {
            // Every solution is flown twice: by the parabola in double and by predictProjectile
            // (Exact, no world), as expectHits does; 1e-3 m is the contract.
            ++report.flown;
            if (closedFormMiss(shot, target, s) > 1e-3 || predictorMiss(shot, target, s) > 1e-3) ++report.spurious;
            const bool seen = std::any_of(scanned.begin(), scanned.end(),
                                          [&](double root) { return near(static_cast<double>(s.time), root); });
            if (!seen) ++report.unmatched;
        }
    }
    return report;
}

void printReport(const char* name, const ScanReport& r) {
    const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
    std::printf(
        "[aim scan] %s: %llu problems (%llu built to graze; %llu root pairs under 10 ms apart), scan roots "
        "%llu, solver solutions %llu (each flown by predictProjectile: %llu)\n",
        name, u(r.problems), u(r.grazing), u(r.closePairs), u(r.scanRoots), u(r.solverRoots), u(r.flown));
    std::printf(
        "[aim scan] %s: miss rate %llu / %llu scan roots = %.3g; spurious (miss > 1e-3 m) %llu / %llu "
        "solutions = %.3g; solver-only hits %llu\n",
        name, u(r.missed), u(r.scanRoots),
        r.scanRoots > 0 ? static_cast<double>(r.missed) / static_cast<double>(r.scanRoots) : 0.0, u(r.spurious),
        u(r.solverRoots),
        r.solverRoots > 0 ? static_cast<double>(r.spurious) / static_cast<double>(r.solverRoots) : 0.0, u(r.unmatched));
}

#ifdef NDEBUG
constexpr std::uint64_t kScanProblems = 100000;
#else
constexpr std::uint64_t kScanProblems = 10000;  // Debug and sanitizer builds are ~20x slower
#endif

TEST(AimScan, QuarticSolverAgreesWithABruteForceTimeScan) {
    const ScanReport r = compareWithScan(kScanProblems, 1000, 0x5eed);
    printReport("random problems", r);
    EXPECT_GT(r.scanRoots, kScanProblems / 2);     // the problems have roots to find
    EXPECT_GT(r.closePairs, kScanProblems / 100);  // and near-double roots among them
    EXPECT_EQ(r.flown, r.solverRoots);             // every solution flown
    EXPECT_EQ(r.missed, 0u);
    EXPECT_EQ(r.spurious, 0u);
    EXPECT_EQ(r.unmatched, 0u);
}

// The long run, a million problems: `foresight_aim_tests --gtest_also_run_disabled_tests
// --gtest_filter='AimScan.DISABLED_*'` (about a minute in Release).
TEST(AimScan, DISABLED_MillionRandomProblems) {
    const ScanReport r = compareWithScan(1000000, 1000, 0x1234567);
    printReport("one million random problems", r);
    EXPECT_EQ(r.missed, 0u);
    EXPECT_EQ(r.spurious, 0u);
}

}  // namespace

// The precision envelope: a huge maxTime must not hide a solution (the search ends where the
// target may leave the envelope), and speeds or positions beyond it are refused.
TEST(AimEnvelope, AHugeMaxTimeFindsWhatAShortOneFinds) {
    AimShot shot;
    shot.speed = 20.0f;
    AimTarget target;
    target.position = RVec3(30, 0, 5);
    target.velocity = Vec3(0, 0, 4);
    shot.maxTime = 10.0f;
    const Aimed near = aim(shot, target);
    ASSERT_EQ(near.status, Status::Ok);
    ASSERT_EQ(near.solutions.size(), 2u);  // the low and the high arc
    for (const float huge : {1e12f, 1e28f, 3e38f}) {
        shot.maxTime = huge;
        const Aimed far = aim(shot, target);
        ASSERT_EQ(far.status, Status::Ok) << huge;
        ASSERT_EQ(far.solutions.size(), near.solutions.size()) << huge;
        for (std::size_t i = 0; i < near.solutions.size(); ++i)
            EXPECT_EQ(far.solutions[i].time, near.solutions[i].time) << huge;
    }
}

TEST(AimEnvelope, BeyondItIsRefused) {
    AimTarget target;
    target.position = RVec3(1000, 0, 0);
    AimShot shot;
    shot.speed = 3e38f;  // would meet the target after 3e-36 s
    EXPECT_EQ(aim(shot, target).status, Status::OutOfRange);
    shot.speed = 2e6f;
    EXPECT_EQ(aim(shot, target).status, Status::OutOfRange);
    shot.speed = 20.0f;
    target.position = RVec3(Real(2e8), 0, 0);
    EXPECT_EQ(aim(shot, target).status, Status::OutOfRange);
    target.position = RVec3(10, 0, 0);
    shot.from = RVec3(0, Real(-2e8), 0);
    EXPECT_EQ(aim(shot, target).status, Status::OutOfRange);
    shot.from = RVec3(0);
    target.velocity = Vec3(0, 0, 2e6f);
    EXPECT_EQ(aim(shot, target).status, Status::OutOfRange);
}
