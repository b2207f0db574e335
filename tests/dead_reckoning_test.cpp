// DIS dead reckoning (dead_reckoning.h), built against the double-precision library: DIS
// positions are geocentric (6.4e6 m), where a float resolves only 0.5 m.
//
// References, never the code under test:
// - the Towers & Hines reference cases (DR4 and DR8, published to 2 decimals) and the cases
//   derived from them for the other models, as open-dis-java's DeadReckonerTest uses them;
// - a fourth-order Runge-Kutta integration, in long double with small steps, of the ODE that
//   defines each model: dq/ds = q (0, w) / 2, and dp/ds = v + a s (world models) or
//   dp/ds = R(q(s)) (v + a s) (body models: the body-axis velocity v + a s turns with the body);
// - the closed forms of a coordinated turn (a circle of radius speed / rate).

#include "counting_allocator.h"
#include "test_util.h"

#include <foresight/dead_reckoning.h>

#include <cmath>
#include <limits>
#include <string>

static_assert(foresight::kDoublePrecision, "geocentric dead reckoning is tested in the double build");

namespace {

using foresight::DeadReckoningAlgorithm;
using foresight::DeadReckoningResult;
using foresight::DeadReckoningState;
using foresight::Quat;
using foresight::RVec3;
using foresight::Status;
using foresight::Vec3;
using ftest::DQuat;
using ftest::DVec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

constexpr DeadReckoningAlgorithm kAll[] = {
    DeadReckoningAlgorithm::Static, DeadReckoningAlgorithm::Fpw, DeadReckoningAlgorithm::Rpw,
    DeadReckoningAlgorithm::Rvw,    DeadReckoningAlgorithm::Fvw, DeadReckoningAlgorithm::Fpb,
    DeadReckoningAlgorithm::Rpb,    DeadReckoningAlgorithm::Rvb, DeadReckoningAlgorithm::Fvb};

const char* name(DeadReckoningAlgorithm a) { return foresight::deadReckoningAlgorithmName(a); }

// ---------------------------------------------------------------------------------------------
// DIS Euler angles: body-to-world R = Rz(psi) Ry(theta) Rx(phi).

Quat fromEuler(double psi, double theta, double phi) {
    const DQuat q =
        ftest::dMul(ftest::dMul(ftest::dAxisAngle(DVec3(0, 0, 1), psi), ftest::dAxisAngle(DVec3(0, 1, 0), theta)),
                    ftest::dAxisAngle(DVec3(1, 0, 0), phi));
    return ftest::toF(q);
}

struct Euler {
    double psi, theta, phi;  // [rad]
};

Euler toEuler(const Quat& orientation) {
    const DQuat q = glm::normalize(ftest::toD(orientation));
    // Columns are the images of the body axes.
    const DVec3 x = ftest::dRotate(q, DVec3(1, 0, 0));
    const DVec3 y = ftest::dRotate(q, DVec3(0, 1, 0));
    const DVec3 z = ftest::dRotate(q, DVec3(0, 0, 1));
    return Euler{std::atan2(x.y, x.x), -std::asin(x.z), std::atan2(y.z, z.z)};
}

// ---------------------------------------------------------------------------------------------
// The reference: RK4 in long double on the defining ODE.

struct Reference {
    DVec3 position;
    DVec3 velocity;  // in the input velocity's axes (world for *W, body for *B)
    DQuat orientation;
};

Reference integrate(const DeadReckoningState& s, double time, int steps) {
    using L = long double;
    const bool rotates = foresight::deadReckoningRotates(s.algorithm);
    const bool accelerates = foresight::deadReckoningUsesAcceleration(s.algorithm);
    const bool body = foresight::deadReckoningInBodyAxes(s.algorithm);
    const bool moves = s.algorithm != DeadReckoningAlgorithm::Static;
    const L w[3] = {rotates ? L(s.angularVelocity.x) : 0, rotates ? L(s.angularVelocity.y) : 0,
                    rotates ? L(s.angularVelocity.z) : 0};
    const L v[3] = {moves ? L(s.velocity.x) : 0, moves ? L(s.velocity.y) : 0, moves ? L(s.velocity.z) : 0};
    const L a[3] = {accelerates ? L(s.acceleration.x) : 0, accelerates ? L(s.acceleration.y) : 0,
                    accelerates ? L(s.acceleration.z) : 0};
    // State: q (w, x, y, z) and the displacement d.
    struct State {
        L q[4];
        L d[3];
    };
    const L n0 = std::sqrt(L(s.orientation.w) * s.orientation.w + L(s.orientation.x) * s.orientation.x +
                           L(s.orientation.y) * s.orientation.y + L(s.orientation.z) * s.orientation.z);
    State y{{s.orientation.w / n0, s.orientation.x / n0, s.orientation.y / n0, s.orientation.z / n0}, {0, 0, 0}};
    auto derivative = [&](const State& st, L at) {
        State k{};
        const L* q = st.q;
        // dq/ds = q (0, w) / 2
        k.q[0] = 0.5L * (-q[1] * w[0] - q[2] * w[1] - q[3] * w[2]);
        k.q[1] = 0.5L * (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]);
        k.q[2] = 0.5L * (q[0] * w[1] - q[1] * w[2] + q[3] * w[0]);
        k.q[3] = 0.5L * (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]);
        const L u[3] = {v[0] + a[0] * at, v[1] + a[1] * at, v[2] + a[2] * at};
        if (!body) {
            for (int i = 0; i < 3; ++i) k.d[i] = u[i];
            return k;
        }
        // Rotate u by the normalised q: u + 2 qw (r x u) + 2 r x (r x u).
        const L n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        const L qw = q[0] / n, r[3] = {q[1] / n, q[2] / n, q[3] / n};
        const L c[3] = {2 * (r[1] * u[2] - r[2] * u[1]), 2 * (r[2] * u[0] - r[0] * u[2]),
                        2 * (r[0] * u[1] - r[1] * u[0])};
        k.d[0] = u[0] + qw * c[0] + (r[1] * c[2] - r[2] * c[1]);
        k.d[1] = u[1] + qw * c[1] + (r[2] * c[0] - r[0] * c[2]);
        k.d[2] = u[2] + qw * c[2] + (r[0] * c[1] - r[1] * c[0]);
        return k;
    };
    auto axpy = [](const State& base, const State& k, L h) {
        State r = base;
        for (int i = 0; i < 4; ++i) r.q[i] += h * k.q[i];
        for (int i = 0; i < 3; ++i) r.d[i] += h * k.d[i];
        return r;
    };
    const L h = L(time) / steps;
    for (int i = 0; i < steps; ++i) {
        const L s0 = h * i;
        const State k1 = derivative(y, s0);
        const State k2 = derivative(axpy(y, k1, h / 2), s0 + h / 2);
        const State k3 = derivative(axpy(y, k2, h / 2), s0 + h / 2);
        const State k4 = derivative(axpy(y, k3, h), s0 + h);
        for (int j = 0; j < 4; ++j) y.q[j] += h / 6 * (k1.q[j] + 2 * k2.q[j] + 2 * k3.q[j] + k4.q[j]);
        for (int j = 0; j < 3; ++j) y.d[j] += h / 6 * (k1.d[j] + 2 * k2.d[j] + 2 * k3.d[j] + k4.d[j]);
    }
    const L n = std::sqrt(y.q[0] * y.q[0] + y.q[1] * y.q[1] + y.q[2] * y.q[2] + y.q[3] * y.q[3]);
    Reference r;
    // The displacement is added to the position in long double, then rounded once.
    r.position = DVec3(static_cast<double>(L(s.position.x) + y.d[0]), static_cast<double>(L(s.position.y) + y.d[1]),
                       static_cast<double>(L(s.position.z) + y.d[2]));
    const L t = time;
    r.velocity = moves ? DVec3(static_cast<double>(v[0] + a[0] * t), static_cast<double>(v[1] + a[1] * t),
                               static_cast<double>(v[2] + a[2] * t))
                       : ftest::toD(s.velocity);
    r.orientation = ftest::dquatWXYZ(static_cast<double>(y.q[0] / n), static_cast<double>(y.q[1] / n),
                                     static_cast<double>(y.q[2] / n), static_cast<double>(y.q[3] / n));
    return r;
}

DeadReckoningResult predict(const DeadReckoningState& state, float time) {
    DeadReckoningResult out;
    EXPECT_EQ(foresight::predictDeadReckoning(state, time, out), Status::Ok) << name(state.algorithm);
    return out;
}

// ---------------------------------------------------------------------------------------------
// Towers & Hines. Two entity state updates (open-dis-java's espdu4 and espdu8), extrapolated
// 0.5 s. The float casts are those of the PDU fields.

DeadReckoningState towersHines4(DeadReckoningAlgorithm algorithm) {
    DeadReckoningState s;
    s.algorithm = algorithm;
    s.position = RVec3(-6378137.0, -5.0, -10.0);
    s.velocity = Vec3(30.0f, 35.0f, 40.0f);
    s.acceleration = Vec3(-80.0f, -85.0f, -90.0f);
    s.orientation = fromEuler(static_cast<float>(15.0 * kDegree), static_cast<float>(20.0 * kDegree),
                              static_cast<float>(25.0 * kDegree));
    s.angularVelocity = Vec3(static_cast<float>(60.0 * kDegree), static_cast<float>(65.0 * kDegree),
                             static_cast<float>(70.0 * kDegree));
    return s;
}

DeadReckoningState towersHines8(DeadReckoningAlgorithm algorithm) {
    DeadReckoningState s = towersHines4(algorithm);
    s.position = RVec3(6378137.0, 5.0, 10.0);
    s.angularVelocity = -s.angularVelocity;
    return s;
}

struct Published {
    const char* label;
    DeadReckoningState state;
    DVec3 position;      // [m]
    DVec3 eulerDegrees;  // psi, theta, phi
    DVec3 velocity;      // [m/s]
};

std::vector<Published> publishedCases() {
    using A = DeadReckoningAlgorithm;
    const DVec3 unturned(15.0, 20.0, 25.0);
    const DVec3 v0(30.0, 35.0, 40.0);
    const DVec3 v1(-10.0, -7.5, -5.0);  // v + a t
    return {
        // DR4 (published) and its special cases: F drops the rotation, P the acceleration.
        {"DR1 (espdu4)", towersHines4(A::Static), DVec3(-6378137.0, -5.0, -10.0), unturned, v0},
        {"DR2", towersHines4(A::Fpw), DVec3(-6378122.0, 12.5, 10.0), unturned, v0},
        {"DR3", towersHines4(A::Rpw), DVec3(-6378122.0, 12.5, 10.0), DVec3(64.32, 14.84, 72.5), v0},
        {"DR4", towersHines4(A::Rvw), DVec3(-6378132.0, 1.88, -1.25), DVec3(64.32, 14.84, 72.5), v1},
        {"DR5", towersHines4(A::Fvw), DVec3(-6378132.0, 1.88, -1.25), unturned, v1},
        // DR8 (published) and its special cases.
        {"DR1 (espdu8)", towersHines8(A::Static), DVec3(6378137.0, 5.0, 10.0), unturned, v0},
        {"DR6", towersHines8(A::Fpb), DVec3(6378157.13, 18.06, 28.85), unturned, v0},
        {"DR7", towersHines8(A::Rpb), DVec3(6378156.77, 18.75, 28.73), DVec3(-23.07, -8.68, -10.86), v0},
        {"DR8", towersHines8(A::Rvb), DVec3(6378144.03, 10.46, 18.32), DVec3(-23.07, -8.68, -10.86), v1},
        {"DR9", towersHines8(A::Fvb), DVec3(6378144.46, 9.62, 18.47), unturned, v1},
    };
}

TEST(DeadReckoning, TowersAndHinesReferenceCases) {
    for (const Published& c : publishedCases()) {
        SCOPED_TRACE(c.label);
        const DeadReckoningResult out = predict(c.state, 0.5f);
        // The published values have 2 decimals (e.g. 1.88 for 1.875): 0.01 is their rounding,
        // as in open-dis-java's tests.
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(out.position[i], c.position[i], 0.01) << "position " << i;
            EXPECT_NEAR(out.velocity[i], c.velocity[i], 0.01) << "velocity " << i;
        }
        const Euler e = toEuler(out.orientation);
        EXPECT_NEAR(e.psi / kDegree, c.eulerDegrees.x, 0.01);
        EXPECT_NEAR(e.theta / kDegree, c.eulerDegrees.y, 0.01);
        EXPECT_NEAR(e.phi / kDegree, c.eulerDegrees.z, 0.01);
    }
}

// The same ten cases against the integrated ODE, far tighter than the published decimals.
TEST(DeadReckoning, TowersAndHinesCasesMatchTheIntegratedMotion) {
    for (const Published& c : publishedCases()) {
        SCOPED_TRACE(c.label);
        const DeadReckoningResult out = predict(c.state, 0.5f);
        const Reference ref = integrate(c.state, 0.5, 4000);
        // RK4 error (h |w| = 1.6e-4)^4 on a 30 m displacement plus one rounding of 6.4e6 m
        // (9.3e-10 m): 1e-8 m. Velocity and orientation are float outputs: 1e-5 and 1e-6.
        EXPECT_TRUE(ftest::vecNear(out.position, ref.position, 1e-8));
        EXPECT_TRUE(ftest::vecNear(out.velocity, ref.velocity, 1e-5));
        EXPECT_TRUE(ftest::quatNear(out.orientation, ref.orientation, 1e-6));
    }
}

// The body-axis R2 is the integral of s exp([w]x s), not the double integral of exp([w]x s):
// the latter moves DR8 to (6378144.06, 10.38, 18.35), 0.08 m off the published 10.46.
TEST(DeadReckoning, BodyAccelerationIsTheBodyRateOfTheBodyVelocity) {
    const DeadReckoningResult out = predict(towersHines8(DeadReckoningAlgorithm::Rvb), 0.5f);
    EXPECT_NEAR(out.position.y, 10.4596, 1e-3);  // the python quadrature of the standard's R2
    EXPECT_GT(std::abs(out.position.y - 10.382), 0.05);
}

// ---------------------------------------------------------------------------------------------
// The integrated motion for a range of times and rates, per model.

DeadReckoningState generic(DeadReckoningAlgorithm algorithm, double rate) {
    DeadReckoningState s;
    s.algorithm = algorithm;
    s.position = RVec3(-2742000.25, 4651000.5, 3343000.75);  // a geocentric point
    s.velocity = Vec3(12.0f, -3.0f, 5.0f);
    s.acceleration = Vec3(-1.5f, 2.0f, 0.5f);
    s.orientation = ftest::toF(glm::normalize(ftest::dquatWXYZ(0.8, 0.3, -0.4, 0.33)));
    const DVec3 axis = glm::normalize(DVec3(0.3, -0.5, 0.8));
    s.angularVelocity = ftest::toF(axis * rate);
    return s;
}

TEST(DeadReckoning, EveryModelMatchesTheIntegratedMotion) {
    for (const DeadReckoningAlgorithm algorithm : kAll) {
        for (const double rate : {0.0, 0.2, 1.3, 4.0}) {
            for (const float time : {0.0f, 0.25f, 1.0f, 3.0f}) {
                SCOPED_TRACE(std::string(name(algorithm)) + " rate " + std::to_string(rate) + " t " +
                             std::to_string(time));
                const DeadReckoningState s = generic(algorithm, rate);
                const DeadReckoningResult out = predict(s, time);
                const Reference ref = integrate(s, time, 1000 + static_cast<int>(2000.0f * time));
                // RK4 (h |w| <= 1.8e-3)^4 relative on displacements under 60 m, plus the rounding
                // of 5e6 m (9.3e-10): 1e-8 m. Float outputs: velocity 1e-5 m/s, quaternion 1e-6.
                EXPECT_TRUE(ftest::vecNear(out.position, ref.position, 1e-8));
                EXPECT_TRUE(ftest::vecNear(out.velocity, ref.velocity, 1e-5));
                EXPECT_TRUE(ftest::quatNear(out.orientation, ref.orientation, 1e-6));
            }
        }
    }
}

// Many turns (x = |w| t = 60 rad): the closed forms hold far from the series.
TEST(DeadReckoning, ManyTurnsMatchTheIntegratedMotion) {
    for (const DeadReckoningAlgorithm algorithm : {DeadReckoningAlgorithm::Rpb, DeadReckoningAlgorithm::Rvb}) {
        SCOPED_TRACE(name(algorithm));
        const DeadReckoningState s = generic(algorithm, 6.0);
        const DeadReckoningResult out = predict(s, 10.0f);
        const Reference ref = integrate(s, 10.0, 50000);
        // RK4 (h |w| = 1.2e-3)^4 on a ~200 m path; float orientation over 60 rad: 1e-5 rad.
        EXPECT_TRUE(ftest::vecNear(out.position, ref.position, 1e-7));
        EXPECT_TRUE(ftest::quatNear(out.orientation, ref.orientation, 1e-5));
    }
}

// ---------------------------------------------------------------------------------------------
// Near zero angular velocity: the series take over without a step and without losing digits.

// The body displacement alone (origin, identity orientation) for x = |w| t around each switch
// of the series: sinc at x = 1e-4 and x / 2 = 1e-4, (x - sin x)/x^3 at 0.5, the R2 axial
// coefficient at 1; and deep in the series (1e-12, 1e-30) and at exactly zero.
TEST(DeadReckoning, SmallAngularVelocityIsContinuousAndExact) {
    const double t = 2.0;
    for (const double x : {0.0, 1e-30, 1e-12, 1e-6, 1e-4, 2e-4, 0.01, 0.5, 1.0, 3.0}) {
        for (const double side : {1.0 - 1e-6, 1.0, 1.0 + 1e-6}) {
            DeadReckoningState s;
            s.algorithm = DeadReckoningAlgorithm::Rvb;
            s.velocity = Vec3(3.0f, -4.0f, 12.0f);
            s.acceleration = Vec3(-2.0f, 1.0f, 6.0f);
            // Not parallel to v or a: every term of R1 and R2 contributes.
            s.angularVelocity = ftest::toF(glm::normalize(DVec3(0.6, 0.64, -0.48)) * (x * side / t));
            SCOPED_TRACE("x " + std::to_string(x * side));
            const DeadReckoningResult out = predict(s, static_cast<float>(t));
            const Reference ref = integrate(s, t, 2000);
            // Origin: no large coordinate. Displacement ~ 40 m; double rounding ~1e-14 relative,
            // RK4 (h |w| <= 3e-3)^4 ~ 1e-10 relative at x = 3. A lost series digit near
            // 0 would be an error of eps / x^2 (1e-8 m at x = 1e-4).
            EXPECT_TRUE(ftest::vecNear(out.position, ref.position, 2e-9));
        }
    }
}

// Velocity and acceleration along the rotation axis do not turn: R1 v = t v, R2 a = t^2/2 a
// for every x. Each is the sum of an I term and a w w^T term (sinc(x) + x^2 (x - sin x)/x^3 = 1,
// (x sin x + cos x - 1)/x^2 + x^2 (x^2/2 - x sin x - cos x + 1)/x^4 = 1/2), so a coefficient
// that lost digits to cancellation near x = 0 (an error of eps / x^2) shows here in full.
TEST(DeadReckoning, MotionAlongTheRotationAxisIsUnturnedToRounding) {
    const double t = 2.0;
    // Components of equal size, so that the float vectors are exactly parallel (w x v = 0).
    const DVec3 axis(1.0, -1.0, 1.0);
    for (const double x : {1e-30, 1e-9, 1e-6, 1e-4, 2e-4, 1e-3, 0.01, 0.1, 0.5, 0.99, 1.0, 1.01, 2.0, 30.0}) {
        DeadReckoningState s;
        s.algorithm = DeadReckoningAlgorithm::Rvb;
        s.velocity = ftest::toF(axis * 5.0);
        s.acceleration = ftest::toF(axis * -3.0);
        s.angularVelocity = ftest::toF(axis * (x / (t * std::sqrt(3.0))));
        const DeadReckoningResult out = predict(s, static_cast<float>(t));
        const DVec3 expected = ftest::toD(s.velocity) * t + ftest::toD(s.acceleration) * (0.5 * t * t);
        // A few double roundings of a 6 m displacement: 1e-14 m (the float inputs are exact).
        // Except just below x = 0.5: vehicle.cpp's series of (x - sin x)/x^3 stops at x^8, and
        // its first omitted term, x^10/13!, is 1.6e-13 there (1e-12 relative): 7e-13 m here.
        EXPECT_TRUE(ftest::vecNear(out.position, expected, x == 0.5 ? 1e-12 : 1e-14)) << "x " << x;
    }
}

TEST(DeadReckoning, ZeroAngularVelocityIsTheStraightLineExactly) {
    // R1 = t I and R2 = t^2/2 I at w = 0: RVB equals FVB and RPB equals FPB bit for bit, and
    // the orientation is untouched.
    for (const float time : {0.0f, 0.5f, 7.0f}) {
        DeadReckoningState s = generic(DeadReckoningAlgorithm::Rvb, 0.0);
        const DeadReckoningResult rvb = predict(s, time);
        s.algorithm = DeadReckoningAlgorithm::Fvb;
        const DeadReckoningResult fvb = predict(s, time);
        EXPECT_TRUE(ftest::sameBytes(rvb, fvb)) << time;
        s.algorithm = DeadReckoningAlgorithm::Rpb;
        const DeadReckoningResult rpb = predict(s, time);
        s.algorithm = DeadReckoningAlgorithm::Fpb;
        const DeadReckoningResult fpb = predict(s, time);
        EXPECT_TRUE(ftest::sameBytes(rpb, fpb)) << time;
        EXPECT_TRUE(ftest::quatNear(rvb.orientation, s.orientation, 1e-7)) << time;
        const double t = time;
        const DVec3 expected = ftest::toD(s.position) +
                               ftest::dRotate(glm::normalize(ftest::toD(s.orientation)),
                                              ftest::toD(s.velocity) * t + ftest::toD(s.acceleration) * (0.5 * t * t));
        // Geocentric: one rounding of 5e6 m (9.3e-10 m) and a few of the 60 m displacement.
        EXPECT_TRUE(ftest::vecNear(rvb.position, expected, 1e-8)) << time;
    }
}

// ---------------------------------------------------------------------------------------------
// Composition: two steps of t/2 (the first output fed back as the input) equal one step of t.
// It holds for all nine models: each is the flow of an autonomous ODE whose whole state
// (position, velocity in the input's axes, orientation) is the output.

TEST(DeadReckoning, TwoHalfStepsEqualOneStepForAllNineModels) {
    for (const DeadReckoningAlgorithm algorithm : kAll) {
        for (const bool towers : {true, false}) {
            SCOPED_TRACE(std::string(name(algorithm)) + (towers ? " Towers & Hines" : " generic"));
            const DeadReckoningState s = towers ? towersHines8(algorithm) : generic(algorithm, 1.3);
            const float t = towers ? 0.5f : 3.0f;
            const DeadReckoningResult whole = predict(s, t);
            const DeadReckoningResult half = predict(s, 0.5f * t);
            DeadReckoningState next = s;
            next.position = half.position;
            next.velocity = half.velocity;
            next.orientation = half.orientation;
            const DeadReckoningResult twice = predict(next, 0.5f * t);
            // The intermediate velocity and orientation are floats: 6e-8 relative on a 30 m/s
            // velocity and 1e-7 rad on the turn of a 60 m displacement: 2e-5 m.
            EXPECT_TRUE(ftest::vecNear(twice.position, whole.position, 2e-5));
            EXPECT_TRUE(ftest::vecNear(twice.velocity, whole.velocity, 1e-5));
            EXPECT_TRUE(ftest::quatNear(twice.orientation, whole.orientation, 1e-6));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Coordinated turns (open-dis-java's cwCircle): an aircraft at (r, 0, 0) flying north (+Y) at
// 100 m/s, banked, turning about the world Z axis at speed / r. Body axes: x forward, y right,
// z down as in DIS; the body angular velocity is the world yaw rate in body axes.

struct Circle {
    double radius = 5000.0;
    double speed = 100.0;
    double rate() const { return speed / radius; }
    double period() const { return 2.0 * kPi / rate(); }
    DeadReckoningState state(DeadReckoningAlgorithm algorithm, const DVec3& centre) const {
        const double bank = std::atan(speed * rate() / 10.0);  // g rounded to 10 as in the source
        DeadReckoningState s;
        s.algorithm = algorithm;
        s.position = ftest::toR(centre + DVec3(radius, 0.0, 0.0));
        s.velocity = Vec3(static_cast<float>(speed), 0.0f, 0.0f);
        s.orientation = fromEuler(kPi / 2.0, 0.0, bank);
        const DQuat q = ftest::toD(s.orientation);
        s.angularVelocity = ftest::toF(ftest::dRotate(glm::conjugate(q), DVec3(0.0, 0.0, rate())));
        return s;
    }
};

TEST(DeadReckoning, CoordinatedTurnCirclesCloseOnThemselves) {
    const Circle circle;
    for (const DeadReckoningAlgorithm algorithm : {DeadReckoningAlgorithm::Rpb, DeadReckoningAlgorithm::Rvb}) {
        for (const DVec3 centre : {DVec3(0.0), DVec3(6378137.0, 0.0, 0.0)}) {
            SCOPED_TRACE(std::string(name(algorithm)) + " centre x " + std::to_string(centre.x));
            const DeadReckoningState s = circle.state(algorithm, centre);
            // The rate and the times are floats (6e-8 relative): on a 5 km radius the angle is
            // off by about 2 pi 1e-7, 3e-3 m of arc. 0.01 m is the bar this test sets.
            for (int eighth = 1; eighth <= 8; ++eighth) {
                const double angle = eighth * kPi / 4.0;
                const DeadReckoningResult out = predict(s, static_cast<float>(circle.period() * eighth / 8.0));
                const DVec3 expected = centre + circle.radius * DVec3(std::cos(angle), std::sin(angle), 0.0);
                EXPECT_TRUE(ftest::vecNear(out.position, expected, 0.01)) << "eighth " << eighth;
                // Body velocity unchanged; the heading turned by `angle`.
                EXPECT_TRUE(ftest::vecNear(out.velocity, s.velocity, 1e-4));
                const Euler e = toEuler(out.orientation);
                EXPECT_NEAR(std::remainder(e.psi - (kPi / 2.0 + angle), 2.0 * kPi), 0.0, 1e-5) << eighth;
                EXPECT_NEAR(e.theta, 0.0, 1e-5);
            }
            const DeadReckoningResult full = predict(s, static_cast<float>(circle.period()));
            EXPECT_TRUE(ftest::vecNear(full.position, s.position, 0.01));
            EXPECT_TRUE(ftest::quatNear(full.orientation, s.orientation, 1e-5));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// RPB is the library's exact vehicle model (body-frame angular velocity, velocity on the
// forward axis) when the body velocity is along the vehicle's forward axis.

TEST(DeadReckoning, RpbEqualsTheExactVehiclePrediction) {
    foresight::VehicleSettings settings;
    settings.frame = foresight::AngularFrame::Body;
    settings.forward = Vec3(1.0f, 0.0f, 0.0f);  // DIS body x forward
    for (const double rate : {0.0, 1e-7, 0.3, 2.5}) {
        for (const float speed : {10.0f, -4.0f}) {
            SCOPED_TRACE("rate " + std::to_string(rate) + " speed " + std::to_string(speed));
            DeadReckoningState s = generic(DeadReckoningAlgorithm::Rpb, rate);
            s.velocity = Vec3(speed, 0.0f, 0.0f);
            foresight::VehicleState vehicle;
            vehicle.position = s.position;
            vehicle.velocity = ftest::toF(ftest::dRotate(ftest::toD(s.orientation), ftest::toD(s.velocity)));
            vehicle.orientation = s.orientation;
            vehicle.angularVelocity = s.angularVelocity;
            for (const float time : {0.5f, 2.0f, 9.0f}) {
                const DeadReckoningResult out = predict(s, time);
                foresight::VehicleState expected;
                ASSERT_EQ(foresight::predictVehicleExact(vehicle, time, settings, expected), Status::Ok);
                // The vehicle takes its speed from the float world velocity (|v| to 6e-8): on
                // up to 90 m, 1e-5 m.
                EXPECT_TRUE(ftest::vecNear(out.position, expected.position, 1e-5)) << time;
                EXPECT_TRUE(ftest::quatNear(out.orientation, expected.orientation, 1e-6)) << time;
                const DVec3 worldVelocity = ftest::dRotate(ftest::toD(out.orientation), ftest::toD(out.velocity));
                EXPECT_TRUE(ftest::vecNear(worldVelocity, expected.velocity, 1e-5)) << time;
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Geocentric resolution and unused fields.

TEST(DeadReckoning, GeocentricPositionsResolveMillimetres) {
    DeadReckoningState s;
    s.algorithm = DeadReckoningAlgorithm::Fpw;
    s.position = RVec3(6378137.0, -12.0, 3.0);
    s.velocity = Vec3(0.002f, 0.0f, 0.0f);
    const DeadReckoningResult out = predict(s, 0.5f);
    // 1 mm of motion at 6.4e6 m (a float position would not move at all; double: 9.3e-10).
    EXPECT_NEAR(out.position.x - 6378137.0, 0.5 * static_cast<double>(0.002f), 1e-9);
}

TEST(DeadReckoning, ModelsIgnoreTheFieldsTheyDoNotUse) {
    for (const DeadReckoningAlgorithm algorithm : kAll) {
        SCOPED_TRACE(name(algorithm));
        DeadReckoningState s = generic(algorithm, 0.7);
        const DeadReckoningResult a = predict(s, 1.5f);
        if (!foresight::deadReckoningRotates(algorithm)) {
            s.angularVelocity = Vec3(9.0f, -9.0f, 9.0f);
        }
        if (!foresight::deadReckoningUsesAcceleration(algorithm)) s.acceleration = Vec3(100.0f);
        const DeadReckoningResult b = predict(s, 1.5f);
        EXPECT_TRUE(ftest::sameBytes(a, b));
        if (algorithm == DeadReckoningAlgorithm::Static) {
            EXPECT_EQ(a.position, s.position);
            EXPECT_EQ(a.velocity, s.velocity);  // echoed, as DIS receivers leave it
        }
    }
}

TEST(DeadReckoning, NamesRoundTrip) {
    const char* expected[] = {"STATIC", "FPW", "RPW", "RVW", "FVW", "FPB", "RPB", "RVB", "FVB"};
    for (int i = 0; i < foresight::kDeadReckoningAlgorithmCount; ++i) {
        EXPECT_EQ(static_cast<int>(kAll[i]), i + 1);  // the DIS enumeration
        EXPECT_STREQ(name(kAll[i]), expected[i]);
        DeadReckoningAlgorithm found = DeadReckoningAlgorithm::Static;
        EXPECT_TRUE(foresight::findDeadReckoningAlgorithm(expected[i], found));
        EXPECT_EQ(found, kAll[i]);
    }
    DeadReckoningAlgorithm untouched = DeadReckoningAlgorithm::Rvb;
    for (const char* bad : {"", "rvb", "RVB ", "DRM_RVB", "OTHER"}) {
        EXPECT_FALSE(foresight::findDeadReckoningAlgorithm(bad, untouched)) << bad;
    }
    EXPECT_EQ(untouched, DeadReckoningAlgorithm::Rvb);
    EXPECT_STREQ(name(static_cast<DeadReckoningAlgorithm>(0)), "?");
    EXPECT_STREQ(name(static_cast<DeadReckoningAlgorithm>(10)), "?");
}

// ---------------------------------------------------------------------------------------------
// Refusals: each Status, `out` untouched.

TEST(DeadReckoning, RefusesBadInputAndLeavesTheOutputUntouched) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    struct Case {
        const char* what;
        DeadReckoningState state;
        float time;
        Status status;
    };
    const DeadReckoningState good = generic(DeadReckoningAlgorithm::Rvb, 0.5);
    auto with = [&](auto&& change) {
        DeadReckoningState s = good;
        change(s);
        return s;
    };
    const Case cases[] = {
        {"algorithm 0 (DIS Other)", with([](auto& s) { s.algorithm = static_cast<DeadReckoningAlgorithm>(0); }), 1.0f,
         Status::InvalidAlgorithm},
        {"algorithm 10", with([](auto& s) { s.algorithm = static_cast<DeadReckoningAlgorithm>(10); }), 1.0f,
         Status::InvalidAlgorithm},
        {"NaN position", with([&](auto& s) { s.position.y = nan; }), 1.0f, Status::NonFiniteInput},
        {"infinite velocity", with([&](auto& s) { s.velocity.x = inf; }), 1.0f, Status::NonFiniteInput},
        {"NaN acceleration", with([&](auto& s) { s.acceleration.z = nan; }), 1.0f, Status::NonFiniteInput},
        {"NaN angular velocity", with([&](auto& s) { s.angularVelocity.x = nan; }), 1.0f, Status::NonFiniteInput},
        {"NaN quaternion", with([&](auto& s) { s.orientation.w = nan; }), 1.0f, Status::NonFiniteInput},
        {"zero quaternion", with([](auto& s) { s.orientation = ftest::quatWXYZ(0, 0, 0, 0); }), 1.0f,
         Status::ZeroQuaternion},
        {"NaN time", good, nan, Status::NonFiniteInput},
        {"infinite time", good, inf, Status::NonFiniteInput},
        {"negative time", good, -0.001f, Status::NegativeTime},
        // Finite but absurd: v + a t beyond the float range.
        {"overflow", with([](auto& s) { s.acceleration = Vec3(3e38f); }), 1e30f, Status::NonFiniteResult},
        {"overflow of a body model", with([](auto& s) { s.angularVelocity = Vec3(3e38f); }), 3e38f,
         Status::NonFiniteResult},
    };
    for (const Case& c : cases) {
        DeadReckoningResult out;
        out.position = RVec3(1.0, 2.0, 3.0);
        const DeadReckoningResult before = out;
        EXPECT_EQ(foresight::predictDeadReckoning(c.state, c.time, out), c.status) << c.what;
        EXPECT_TRUE(ftest::sameBytes(out, before)) << c.what;
        if (c.status != Status::NonFiniteResult && c.status != Status::NegativeTime && std::isfinite(c.time)) {
            EXPECT_EQ(foresight::validateDeadReckoningState(c.state), c.status) << c.what;
        }
    }
    EXPECT_EQ(foresight::validateDeadReckoningState(good), Status::Ok);
    EXPECT_STRNE(foresight::statusMessage(Status::InvalidAlgorithm), "unknown status");
}

TEST(DeadReckoning, NeverAllocates) {
    DeadReckoningResult out;
    const long before = ftest::gAllocations.load();
    for (const DeadReckoningAlgorithm algorithm : kAll) {
        const DeadReckoningState s = generic(algorithm, 0.9);
        if (foresight::predictDeadReckoning(s, 1.25f, out) != Status::Ok) ADD_FAILURE() << name(algorithm);
    }
    DeadReckoningAlgorithm found;
    (void)foresight::findDeadReckoningAlgorithm("RVB", found);
    EXPECT_EQ(ftest::gAllocations.load() - before, 0);
}

}  // namespace
