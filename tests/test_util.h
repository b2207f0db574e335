#pragma once
/// @file test_util.h
/// Small helpers shared by foresight's tests: double-precision conversions, vector and
/// quaternion comparisons (quaternions up to sign), named-component quaternion construction.
/// Reference values in the tests are computed in double from closed forms or independent
/// brute force; these helpers only compare.

#include <foresight/foresight.h>

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <sstream>
#include <string>

namespace ftest {

/// `release` in optimised builds (NDEBUG), `debug` in Debug and sanitizer builds, where the
/// same work runs about 20 to 30 times slower: the number of rounds of a long randomised test.
constexpr int roundsForBuild(int release, int debug) {
#ifdef NDEBUG
    (void)debug;
    return release;
#else
    (void)release;
    return debug;
#endif
}

using DVec3 = glm::dvec3;
using DQuat = glm::dquat;

/// The one random generator of the tests: small, deterministic, the same sequence on every
/// platform, where the standard library's distributions are not (CONTRIBUTING).
///
/// The step (state update and output) is chosen at construction. Every test keeps the step it
/// was written with, so that it draws exactly the cases it always checked:
/// - `SplitMix64` (the default; new tests use it): Steele, Lea and Flood's splitmix64, the state
///   advanced by 0x9e3779b97f4a7c15 and mixed.
/// - `XorShift64`: Marsaglia's xorshift64 (shifts 13, 7, 17), the state itself as output
///   (bullet_test.cpp, bullet_simulation_test.cpp). A seed of 0 stays 0: give a non-zero seed.
/// - `XorShift64Star`: Vigna's xorshift64* (shifts 12, 25, 27), output the state times
///   0x2545f4914f6cdd1d (replication_test.cpp). Non-zero seed, as above.
/// - `Lcg64`: Knuth's MMIX linear congruential step (6364136223846793005, 1442695040888963407),
///   the state itself as output (danger_test.cpp).
/// Draws are the same for every step: uniform(lo, hi) = lo + (hi - lo) u with u the top 53 bits
/// of next() times 2^-53, in [0, 1). (u is formed first; multiplying by 2^-53 is exact, so this
/// equals ((hi - lo) (next() >> 11)) 2^-53 bit for bit, the form some tests were written with.)
class Random {
public:
    enum class Step { SplitMix64, XorShift64, XorShift64Star, Lcg64 };

    explicit Random(std::uint64_t seed, Step step = Step::SplitMix64) : mState(seed), mStep(step) {}

    std::uint64_t next() {
        switch (mStep) {
            case Step::XorShift64:
                mState ^= mState << 13;
                mState ^= mState >> 7;
                mState ^= mState << 17;
                return mState;
            case Step::XorShift64Star:
                mState ^= mState >> 12;
                mState ^= mState << 25;
                mState ^= mState >> 27;
                return mState * 0x2545f4914f6cdd1dull;
            case Step::Lcg64:
                mState = mState * 6364136223846793005ull + 1442695040888963407ull;
                return mState;
            case Step::SplitMix64:
                break;
        }
        std::uint64_t z = (mState += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1): the top 53 bits of next().
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform in [0, n) for n > 0.
    int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
    // inBox and direction draw their three numbers as constructor arguments, whose order of
    // evaluation C++ leaves to the compiler: kept exactly as the tests were written with them,
    // so that the cases drawn do not change.
    /// Uniform in the box [lo, hi).
    DVec3 inBox(const DVec3& lo, const DVec3& hi) {
        return DVec3(uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z));
    }
    /// A unit vector, uniform on the sphere: rejection from the cube [-1, 1)^3 (lengths in
    /// (0.1, 1], so that the normalisation loses nothing).
    DVec3 direction() {
        for (;;) {
            const DVec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    }

private:
    std::uint64_t mState;
    Step mStep;
};

/// Any glm 3-vector (float or double) as double.
template <class T>
DVec3 toD(const glm::vec<3, T, glm::defaultp>& v) {
    return DVec3(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

/// A float quaternion as double.
inline DQuat toD(const foresight::Quat& q) {
    DQuat r;
    r.w = static_cast<double>(q.w);
    r.x = static_cast<double>(q.x);
    r.y = static_cast<double>(q.y);
    r.z = static_cast<double>(q.z);
    return r;
}

/// The decimal value a float was written as: its shortest round-trip decimal representation,
/// read back as a double (0.02f -> 0.02, not 0.0199999995529651641845703125). The projectile
/// predictor documents that it takes `time`, `step` and `gravity` at these values.
inline double decimal(float value) {
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer - 1, value);
    *r.ptr = '\0';
    return std::strtod(buffer, nullptr);
}

/// Identity (lets the comparisons take float or double quaternions).
inline DQuat toD(const DQuat& q) { return q; }

/// A double vector as the library's position type (float or double, as built).
inline foresight::RVec3 toR(const DVec3& v) {
    using R = foresight::Real;
    return foresight::RVec3(static_cast<R>(v.x), static_cast<R>(v.y), static_cast<R>(v.z));
}

/// A position from its coordinates, in the library's position type (float or double, as built).
inline foresight::RVec3 rv(double x, double y, double z) { return toR(DVec3(x, y, z)); }

/// A double vector as float (the library's Vec3).
inline foresight::Vec3 toF(const DVec3& v) {
    return foresight::Vec3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

/// A float quaternion from named components (never the order-ambiguous constructor).
inline foresight::Quat quatWXYZ(float w, float x, float y, float z) {
    foresight::Quat q;
    q.w = w;
    q.x = x;
    q.y = y;
    q.z = z;
    return q;
}

/// A double quaternion from named components.
inline DQuat dquatWXYZ(double w, double x, double y, double z) {
    DQuat q;
    q.w = w;
    q.x = x;
    q.y = y;
    q.z = z;
    return q;
}

/// A double quaternion as float (the library's Quat).
inline foresight::Quat toF(const DQuat& q) {
    return quatWXYZ(static_cast<float>(q.w), static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z));
}

/// The rotation by `angle` [rad] about the unit `axis`, in double (built by hand, not glm).
inline DQuat dAxisAngle(const DVec3& axis, double angle) {
    const double s = std::sin(0.5 * angle);
    return dquatWXYZ(std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s);
}

/// Hamilton product in double, written out (independent of glm's operator*).
inline DQuat dMul(const DQuat& a, const DQuat& b) {
    return dquatWXYZ(a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                     a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w);
}

/// Rotates `v` by the unit quaternion `q` in double: v' = v + 2w (u x v) + 2 u x (u x v).
inline DVec3 dRotate(const DQuat& q, const DVec3& v) {
    const DVec3 u(q.x, q.y, q.z);
    const DVec3 t = 2.0 * glm::cross(u, v);
    return v + q.w * t + glm::cross(u, t);
}

/// Largest component difference, as text for failure messages.
inline std::string describe(const DVec3& v) {
    std::ostringstream s;
    s.precision(10);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

inline std::string describe(const DQuat& q) {
    std::ostringstream s;
    s.precision(10);
    s << "{w " << q.w << ", x " << q.x << ", y " << q.y << ", z " << q.z << "}";
    return s.str();
}

/// |a - b| (Euclidean) <= tol, for any mix of float/double vectors.
template <class A, class B>
::testing::AssertionResult vecNear(const A& a, const B& b, double tol) {
    const DVec3 da = toD(a);
    const DVec3 db = toD(b);
    const double d = glm::length(da - db);
    if (d <= tol) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << describe(da) << " vs " << describe(db) << ": distance " << d << " > "
                                         << tol;
}

/// Quaternions equal up to sign: min(|a - b|, |a + b|) <= tol (4-vector norm).
template <class A, class B>
::testing::AssertionResult quatNear(const A& a, const B& b, double tol) {
    const DQuat da = toD(a);
    const DQuat db = toD(b);
    const double minus = std::sqrt((da.w - db.w) * (da.w - db.w) + (da.x - db.x) * (da.x - db.x) +
                                   (da.y - db.y) * (da.y - db.y) + (da.z - db.z) * (da.z - db.z));
    const double plus = std::sqrt((da.w + db.w) * (da.w + db.w) + (da.x + db.x) * (da.x + db.x) +
                                  (da.y + db.y) * (da.y + db.y) + (da.z + db.z) * (da.z + db.z));
    const double d = std::fmin(minus, plus);
    if (d <= tol) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << describe(da) << " vs " << describe(db) << ": distance (up to sign) " << d
                                         << " > " << tol;
}

/// All components finite.
template <class T>
bool finite(const glm::vec<3, T, glm::defaultp>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool finite(const foresight::Quat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

/// Length of a float quaternion, in double.
inline double quatLength(const foresight::Quat& q) {
    const DQuat d = toD(q);
    return std::sqrt(d.w * d.w + d.x * d.x + d.y * d.y + d.z * d.z);
}

/// True when the bytes of two trivially copyable objects are identical (to check `out` is
/// left untouched by a refused call).
template <class T>
bool sameBytes(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// FNV-1a over raw bytes, for determinism hashes.
class Hasher {
public:
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            mHash ^= p[i];
            mHash *= 1099511628211ull;
        }
    }
    void add(float v) { bytes(&v, sizeof v); }
    void add(double v) { bytes(&v, sizeof v); }
    template <class T>
    void add(const glm::vec<3, T, glm::defaultp>& v) {
        add(v.x);
        add(v.y);
        add(v.z);
    }
    void add(const foresight::Quat& q) {
        add(q.w);
        add(q.x);
        add(q.y);
        add(q.z);
    }
    void add(std::uint64_t v) { bytes(&v, sizeof v); }
    /// Every field of a projectile prediction's result.
    void add(const foresight::ProjectileResult& r) {
        add(r.position);
        add(r.velocity);
        add(r.time);
        add(static_cast<std::uint64_t>(r.bounces));
        add(static_cast<std::uint64_t>(r.atRest));
        add(static_cast<std::uint64_t>(r.stoppedAtHit));
        add(r.hitNormal);
        add(static_cast<std::uint64_t>(r.trajectorySize));
        add(static_cast<std::uint64_t>(r.trajectoryNeeded));
    }
    std::uint64_t value() const { return mHash; }

private:
    std::uint64_t mHash = 14695981039346656037ull;
};

/// Forwards to a world and counts the queries; with `answerTouch` false it leaves mayTouch at
/// CollisionWorld's default (always true), so the predictors cast every free-flight step
/// (and firstTouch says "at once"); with `answerPlane` false it leaves isOnlyPlane at its default
/// (false), so it casts every step in contact.
class CountingWorld final : public foresight::CollisionWorld {
public:
    /// `answerInFront`: firstTouchInFront asks the world's own (else the default: firstTouch).
    CountingWorld(const foresight::CollisionWorld& world, bool answerTouch, bool answerPlane = false,
                  bool answerInFront = false)
        : mWorld(world), mAnswerTouch(answerTouch), mAnswerPlane(answerPlane), mAnswerInFront(answerInFront) {}
    bool castSegment(const foresight::SegmentCast& cast, foresight::CastHit& hit) const override {
        ++casts;
        return mWorld.castSegment(cast, hit);
    }
    bool mayTouch(const foresight::SegmentCast& capsule) const override {
        ++touches;
        return mAnswerTouch ? mWorld.mayTouch(capsule) : true;
    }
    bool firstTouch(const foresight::SegmentCast& capsule, float& fraction) const override {
        ++touches;
        fraction = 0.0f;
        return mAnswerTouch ? mWorld.firstTouch(capsule, fraction) : true;
    }
    bool firstTouchInFront(const foresight::SegmentCast& capsule, const foresight::InFrontOf& front,
                           float& fraction) const override {
        if (!mAnswerInFront) return firstTouch(capsule, fraction);
        ++touches;
        ++inFrontQueries;
        fraction = 0.0f;
        return mAnswerTouch ? mWorld.firstTouchInFront(capsule, front, fraction) : true;
    }
    bool isOnlyPlane(const foresight::PlaneRegion& region) const override {
        if (!mAnswerPlane) return false;
        ++planeQueries;
        const bool only = mWorld.isOnlyPlane(region);
        planePromises += only ? 1 : 0;
        return only;
    }
    float regionQueryCost(float) const override { return queryCost; }
    mutable std::size_t casts = 0, touches = 0, planeQueries = 0, planePromises = 0, inFrontQueries = 0;
    float queryCost = 1.0f;  ///< what regionQueryCost answers (the default world's 1)

private:
    const foresight::CollisionWorld& mWorld;
    bool mAnswerTouch, mAnswerPlane, mAnswerInFront;
};

/// A floor plane (y = 0, normal +Y), three box walls 3 to 9 m around the origin, a sphere and a
/// slanted roof triangle 5.5 to 6.5 m up.
inline foresight::StaticWorld randomScene(Random& random) {
    using namespace foresight;
    StaticWorld world;
    EXPECT_EQ(world.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    for (int i = 0; i < 3; ++i) {
        OrientedBox box;
        const double around = random.uniform(0, 2 * M_PI), distance = random.uniform(3, 9);
        box.center = RVec3(distance * std::cos(around), random.uniform(0.5, 2), distance * std::sin(around));
        box.halfExtents = Vec3(random.uniform(0.2, 0.8), random.uniform(0.5, 2.5), random.uniform(1, 4));
        box.orientation = glm::angleAxis(static_cast<float>(random.uniform(0, M_PI)), Vec3(0, 1, 0));
        EXPECT_EQ(world.add(box), Status::Ok);
    }
    const double x = random.uniform(-6, 6), z = random.uniform(-6, 6);
    EXPECT_EQ(world.add(Sphere{RVec3(x, random.uniform(0, 3), z), static_cast<float>(random.uniform(0.3, 1.0))}),
              Status::Ok);
    // A slanted roof triangle overhead: a parallel ceiling must stop coasting too.
    EXPECT_EQ(world.add(Triangle{RVec3(-8, 5.5, -8), RVec3(8, 6.5, -8), RVec3(0, 6, 8)}), Status::Ok);
    return world;
}

}  // namespace ftest

#define EXPECT_VEC_NEAR(a, b, tol) EXPECT_TRUE(::ftest::vecNear((a), (b), (tol)))
#define ASSERT_VEC_NEAR(a, b, tol) ASSERT_TRUE(::ftest::vecNear((a), (b), (tol)))
#define EXPECT_QUAT_NEAR(a, b, tol) EXPECT_TRUE(::ftest::quatNear((a), (b), (tol)))
