// Character prediction: constant velocity and constant acceleration against their closed forms,
// and the refusals documented in character.h (the output is left untouched on refusal).

#include "test_util.h"

#include <foresight/character.h>

#include <limits>

namespace {

using foresight::PointState;
using foresight::Real;
using foresight::RVec3;
using foresight::Status;
using foresight::Vec3;
using ftest::DVec3;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

PointState makeState(RVec3 position, Vec3 velocity) {
    PointState s;
    s.position = position;
    s.velocity = velocity;
    return s;
}

/// A recognisable output, to check that refused calls do not write it.
PointState sentinel() { return makeState(RVec3(Real(-123.25)), Vec3(77.5f)); }

TEST(Character, LinearMatchesClosedForm) {
    const PointState start = makeState(RVec3(Real(1), Real(2), Real(3)), Vec3(3.0f, -1.0f, 4.0f));
    PointState out;
    ASSERT_EQ(foresight::predictLinear(start, 0.5f, out), Status::Ok);
    // p + v t = (1 + 1.5, 2 - 0.5, 3 + 2); float, one multiply-add per component of values ~5.
    EXPECT_VEC_NEAR(out.position, DVec3(2.5, 1.5, 5.0), 1e-6);
    EXPECT_EQ(out.velocity, start.velocity);
}

TEST(Character, LinearManyCasesMatchClosedForm) {
    // A spread of inputs, reference p + v t evaluated in double.
    const float times[] = {0.0f, 0.016f, 0.1f, 0.75f, 2.0f};
    const Vec3 velocities[] = {Vec3(0.0f), Vec3(1.5f, 0.0f, -2.25f), Vec3(-7.0f, 3.5f, 12.0f)};
    const RVec3 positions[] = {RVec3(Real(0)), RVec3(Real(-10), Real(0.5), Real(42))};
    for (const float t : times) {
        for (const Vec3& v : velocities) {
            for (const RVec3& p : positions) {
                PointState out;
                ASSERT_EQ(foresight::predictLinear(makeState(p, v), t, out), Status::Ok);
                const DVec3 expected = ftest::toD(p) + ftest::toD(v) * static_cast<double>(t);
                // float positions of magnitude <= 66: a few ulps (ulp at 64 is 7.6e-6).
                EXPECT_VEC_NEAR(out.position, expected, 3e-5) << "t=" << t;
                EXPECT_EQ(out.velocity, v);
            }
        }
    }
}

TEST(Character, AcceleratedMatchesClosedForm) {
    const PointState start = makeState(RVec3(Real(0), Real(1), Real(0)), Vec3(3.0f, 0.0f, 4.0f));
    const Vec3 a(0.0f, -9.81f, 2.0f);
    PointState out;
    ASSERT_EQ(foresight::predictAccelerated(start, a, 0.5f, out), Status::Ok);
    // p + v t + a t^2 / 2 = (1.5, 1 - 9.81/8, 2 + 0.25); v + a t = (3, -4.905, 5).
    const double ay = static_cast<double>(a.y);
    EXPECT_VEC_NEAR(out.position, DVec3(1.5, 1.0 + ay * 0.125, 2.25), 2e-6);  // float, values ~2
    EXPECT_VEC_NEAR(out.velocity, DVec3(3.0, ay * 0.5, 5.0), 2e-6);           // float, values ~5
}

TEST(Character, AcceleratedWithZeroAccelerationEqualsLinear) {
    const PointState start = makeState(RVec3(Real(5), Real(-2), Real(7)), Vec3(-1.0f, 2.0f, 0.5f));
    PointState linear;
    PointState accelerated;
    ASSERT_EQ(foresight::predictLinear(start, 1.25f, linear), Status::Ok);
    ASSERT_EQ(foresight::predictAccelerated(start, Vec3(0.0f), 1.25f, accelerated), Status::Ok);
    // Same closed form with a = 0: (5 - 1.25, -2 + 2.5, 7 + 0.625); float values ~7.
    EXPECT_VEC_NEAR(accelerated.position, DVec3(3.75, 0.5, 7.625), 2e-6);
    EXPECT_VEC_NEAR(linear.position, DVec3(3.75, 0.5, 7.625), 2e-6);
    EXPECT_EQ(accelerated.velocity, start.velocity);
}

TEST(Character, TimeZeroReturnsStartExactly) {
    const PointState start = makeState(RVec3(Real(1.25), Real(-3.5), Real(1e3)), Vec3(9.0f, -8.0f, 7.0f));
    PointState out = sentinel();
    ASSERT_EQ(foresight::predictLinear(start, 0.0f, out), Status::Ok);
    EXPECT_EQ(out.position, start.position);  // p + v * 0 is exactly p
    EXPECT_EQ(out.velocity, start.velocity);
    out = sentinel();
    ASSERT_EQ(foresight::predictAccelerated(start, Vec3(1.0f, 2.0f, 3.0f), 0.0f, out), Status::Ok);
    EXPECT_EQ(out.position, start.position);
    EXPECT_EQ(out.velocity, start.velocity);
}

TEST(Character, NegativeTimeIsRefusedAndOutUntouched) {
    const PointState start = makeState(RVec3(Real(0)), Vec3(1.0f, 0.0f, 0.0f));
    const PointState before = sentinel();
    for (const float t : {-1.0f, -1e-30f, -kInf}) {
        PointState out = before;
        const Status linear = foresight::predictLinear(start, t, out);
        // -inf is both negative and non-finite; either refusal is documented.
        if (std::isinf(t)) {
            EXPECT_TRUE(linear == Status::NegativeTime || linear == Status::NonFiniteInput);
        } else {
            EXPECT_EQ(linear, Status::NegativeTime) << "t=" << t;
        }
        EXPECT_TRUE(ftest::sameBytes(out, before));
        const Status accelerated = foresight::predictAccelerated(start, Vec3(0.0f), t, out);
        if (std::isinf(t)) {
            EXPECT_TRUE(accelerated == Status::NegativeTime || accelerated == Status::NonFiniteInput);
        } else {
            EXPECT_EQ(accelerated, Status::NegativeTime) << "t=" << t;
        }
        EXPECT_TRUE(ftest::sameBytes(out, before));
    }
}

TEST(Character, NonFiniteInputsAreRefusedAndOutUntouched) {
    const PointState good = makeState(RVec3(Real(1)), Vec3(1.0f));
    const PointState before = sentinel();
    const Real rnan = std::numeric_limits<Real>::quiet_NaN();
    const Real rinf = std::numeric_limits<Real>::infinity();

    struct Case {
        const char* what;
        PointState state;
        Vec3 acceleration;
        float time;
    };
    const Case cases[] = {
        {"NaN position", makeState(RVec3(Real(0), rnan, Real(0)), Vec3(1.0f)), Vec3(0.0f), 1.0f},
        {"inf position", makeState(RVec3(rinf, Real(0), Real(0)), Vec3(1.0f)), Vec3(0.0f), 1.0f},
        {"NaN velocity", makeState(RVec3(Real(0)), Vec3(0.0f, 0.0f, kNaN)), Vec3(0.0f), 1.0f},
        {"inf velocity", makeState(RVec3(Real(0)), Vec3(-kInf, 0.0f, 0.0f)), Vec3(0.0f), 1.0f},
        {"NaN time", good, Vec3(0.0f), kNaN},
        {"inf time", good, Vec3(0.0f), kInf},
    };
    for (const Case& c : cases) {
        PointState out = before;
        EXPECT_EQ(foresight::predictLinear(c.state, c.time, out), Status::NonFiniteInput) << c.what;
        EXPECT_TRUE(ftest::sameBytes(out, before)) << c.what;
        EXPECT_EQ(foresight::predictAccelerated(c.state, c.acceleration, c.time, out), Status::NonFiniteInput)
            << c.what;
        EXPECT_TRUE(ftest::sameBytes(out, before)) << c.what;
    }
    // A non-finite acceleration (only predictAccelerated takes one).
    for (const Vec3 a : {Vec3(kNaN, 0.0f, 0.0f), Vec3(0.0f, kInf, 0.0f)}) {
        PointState out = before;
        EXPECT_EQ(foresight::predictAccelerated(good, a, 1.0f, out), Status::NonFiniteInput);
        EXPECT_TRUE(ftest::sameBytes(out, before));
    }
}

TEST(Character, OverflowingResultIsRefused) {
    if constexpr (foresight::kDoublePrecision) {
        GTEST_SKIP() << "double positions do not overflow for float inputs";
    } else {
        // 3e38 + 3e38 * 10 overflows a float position: finite inputs, non-finite result.
        const PointState start = makeState(RVec3(Real(3e38f)), Vec3(3e38f));
        const PointState before = sentinel();
        PointState out = before;
        EXPECT_EQ(foresight::predictLinear(start, 10.0f, out), Status::NonFiniteResult);
        EXPECT_TRUE(ftest::sameBytes(out, before));
        EXPECT_EQ(foresight::predictAccelerated(start, Vec3(3e38f), 10.0f, out), Status::NonFiniteResult);
        EXPECT_TRUE(ftest::sameBytes(out, before));
    }
}

TEST(Character, StatusMessagesAreNeverNull) {
    for (int s = 0; s <= static_cast<int>(Status::NonFiniteResult); ++s) {
        const char* message = foresight::statusMessage(static_cast<Status>(s));
        ASSERT_NE(message, nullptr);
        EXPECT_GT(std::strlen(message), 0u) << s;
    }
}

}  // namespace
