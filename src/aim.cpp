#include <foresight/aim.h>

#include "internal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

FORESIGHT_NAMESPACE_BEGIN

namespace {

using detail::DVec3;
using LongReal = long double;

// A grazing contact: the polynomial's value within this fraction of the magnitude of its terms
// (sum of |c_i| t^i) counts as zero. Long double evaluation is good to ~1e-18 of that magnitude
// and the rounding of double inputs is ~1e-16, so a target computed in double to be exactly at
// the range limit is recognised. Looser would merge distinct roots: two roots dt apart leave a
// residual ~ p'' dt^2 / 2, so 1e-10 merged roots 3e-4 s apart (found by the brute-force scan).
constexpr LongReal kTouch = 1e-14L;

// Roots of a polynomial closer than this (relative) are the same root.
constexpr LongReal kSameRoot = 1e-12L;

// The double solver's guard band (see realRoots): a value at a critical point within
// kTouch * magnitude + kGuard * bound of zero sends the problem to long double. `bound` sums the
// absolute values of every product that makes up each coefficient, so it bounds the double
// coefficients' rounding (a few ulps of it: ~5e-16) and Horner's (~9e-16 of the magnitude); 1e-13
// leaves a margin of 50 over both, so outside the band double decides every sign and every
// touch as long double would.
constexpr double kGuard = 1e-13;

constexpr int kMaxDegree = 4;

// c[i] is the coefficient of t^i; bound[i] >= |c[i]|, the sum of the absolute values of the
// products c[i] is computed from (the scale of its rounding error; used by the double solver).
template <class T>
struct Polynomial {
    std::array<T, kMaxDegree + 1> c{};
    std::array<T, kMaxDegree + 1> bound{};
    int degree = 0;  // highest index that may be non-zero

    void trim() {
        while (degree > 0 && c[static_cast<std::size_t>(degree)] == 0) --degree;
    }
    bool identicallyZero() const { return degree == 0 && c[0] == 0; }
};

template <class T>
T evaluate(const Polynomial<T>& p, T t) {
    T value = 0;
    for (int i = p.degree; i >= 0; --i) value = value * t + p.c[static_cast<std::size_t>(i)];
    return value;
}

// The scale of p's rounding errors at t >= 0.
template <class T>
T magnitude(const Polynomial<T>& p, T t) {
    T value = 0;
    for (int i = p.degree; i >= 0; --i) value = value * t + std::fabs(p.c[static_cast<std::size_t>(i)]);
    return value;
}

// The bound of the coefficients' rounding at t >= 0 (sum of bound[i] t^i).
template <class T>
T coefficientBound(const Polynomial<T>& p, T t) {
    T value = 0;
    for (int i = p.degree; i >= 0; --i) value = value * t + p.bound[static_cast<std::size_t>(i)];
    return value;
}

template <class T>
Polynomial<T> derivative(const Polynomial<T>& p) {
    Polynomial<T> d;
    d.degree = std::max(p.degree - 1, 0);
    for (int i = 1; i <= p.degree; ++i) {
        d.c[static_cast<std::size_t>(i - 1)] = static_cast<T>(i) * p.c[static_cast<std::size_t>(i)];
        d.bound[static_cast<std::size_t>(i - 1)] = static_cast<T>(i) * p.bound[static_cast<std::size_t>(i)];
    }
    d.trim();
    return d;
}

// The root of p in [a, b], where p(a) and p(b) have opposite signs: Newton steps kept inside the
// bracket, bisection when a step leaves it or does not halve the bracket (Numerical Recipes'
// rtsafe). To the precision of T: ~1e-19 relative in long double; in double, until p(x) is
// within the rounding of its evaluation.
template <class T>
T solveBracket(const Polynomial<T>& p, const Polynomial<T>& slope, T a, T b, T fa) {
    const bool risingAtA = fa < 0;  // p(a) < 0 < p(b), or the reverse
    T x = T(0.5) * (a + b);
    T stepBefore = b - a;
    T step = stepBefore;
    for (int iteration = 0; iteration < 200; ++iteration) {
        const T fx = evaluate(p, x);
        if (fx == 0) return x;
        if constexpr (std::is_same_v<T, double>) {
            // x is a root to the precision of double evaluation (Horner's rounding is below
            // 2 n eps of the magnitude): further steps only move x within that noise, bisecting
            // as Newton stops halving (8 more evaluations a root, measured).
            if (std::fabs(fx) <= 8 * std::numeric_limits<T>::epsilon() * magnitude(p, std::fabs(x))) return x;
        }
        if ((fx < 0) == risingAtA) {
            a = x;
        } else {
            b = x;
        }
        const T dfx = evaluate(slope, x);
        const T newton = dfx != 0 ? x - fx / dfx : a - 1;
        if (newton <= a || newton >= b || std::fabs(2 * fx) > std::fabs(stepBefore * dfx)) {
            stepBefore = step;
            step = T(0.5) * (b - a);
            x = a + step;
        } else {
            stepBefore = step;
            step = x - newton;
            x = newton;
        }
        if (b - a <= std::numeric_limits<T>::epsilon() * std::max(std::fabs(a), std::fabs(b)) ||
            std::fabs(step) <= std::numeric_limits<T>::epsilon() * std::fabs(x)) {
            break;
        }
    }
    return x;
}

// The root of p in [a, b] (a sign change, the only root there). A quadratic in double takes the
// cancellation-free formula (q / c2 or c0 / q with q = -(c1 + sign(c1) sqrt(disc)) / 2): the
// guard band has kept its discriminant away from 0, so its roots are good to a few ulps; the
// one in [a, b] is the root, else (rounding at an end) solveBracket decides.
template <class T>
T solveSignChange(const Polynomial<T>& p, const Polynomial<T>& slope, T a, T b, T fa) {
    if constexpr (std::is_same_v<T, double>) {
        if (p.degree == 2) {
            const double disc = p.c[1] * p.c[1] - 4 * p.c[2] * p.c[0];
            if (disc > 0) {
                const double q = -0.5 * (p.c[1] + std::copysign(std::sqrt(disc), p.c[1]));
                const double first = q / p.c[2];
                const double second = q != 0 ? p.c[0] / q : first;
                if (first >= a && first <= b) return first;
                if (second >= a && second <= b) return second;
            }
        }
    }
    return solveBracket(p, slope, a, b, fa);
}

// Every real root of p in [lo, hi], sorted, each once: sign changes between consecutive
// critical points (the roots of p', found the same way) are solved by solveBracket; a critical
// point where p touches zero (|p| <= kTouch * magnitude) is a double root. Returns the count.
//
// In double, a critical point whose value is within the guard band (kTouch * magnitude +
// kGuard * coefficientBound) at any level of the recursion sets `doubtful` and returns 0: there,
// double rounding could decide a sign or a touch differently from long double, and the caller
// solves the problem again in long double (grazing shots, near-double roots). Outside the band
// every decision is long double's, and a root found in double differs from long double's by
// its rounding over |p'|: p' at a root is at least ~p'' * sqrt(1e-13) * t there, so below
// ~1e-8 t, and ~1e-15 t for a simple root.
template <class T>
int realRoots(const Polynomial<T>& p, T lo, T hi, std::array<T, kMaxDegree>& roots, bool& doubtful) {
    if (p.degree == 0) return 0;
    if (p.degree == 1) {
        const T root = -p.c[0] / p.c[1];
        if constexpr (std::is_same_v<T, double>) {
            // The window's ends decide whether a root near them is in: as for the critical points.
            for (const T x : {lo, hi}) {
                const T ax = std::fabs(x);
                if (std::fabs(evaluate(p, x)) <=
                    static_cast<T>(kTouch) * magnitude(p, ax) + kGuard * coefficientBound(p, ax)) {
                    doubtful = true;
                    return 0;
                }
            }
        }
        if (root >= lo && root <= hi) {
            roots[0] = root;
            return 1;
        }
        return 0;
    }
    const Polynomial<T> slope = derivative(p);
    std::array<T, kMaxDegree> critical{};
    const int criticalCount = realRoots(slope, lo, hi, critical, doubtful);
    if (doubtful) return 0;

    std::array<T, kMaxDegree + 2> points{};
    int pointCount = 0;
    points[static_cast<std::size_t>(pointCount++)] = lo;
    for (int i = 0; i < criticalCount; ++i) {
        const T x = critical[static_cast<std::size_t>(i)];
        if (x > points[static_cast<std::size_t>(pointCount - 1)] && x < hi)
            points[static_cast<std::size_t>(pointCount++)] = x;
    }
    if (hi > points[static_cast<std::size_t>(pointCount - 1)]) points[static_cast<std::size_t>(pointCount++)] = hi;

    std::array<T, kMaxDegree + 2> values{};
    std::array<bool, kMaxDegree + 2> zero{};
    for (int i = 0; i < pointCount; ++i) {
        const auto k = static_cast<std::size_t>(i);
        values[k] = evaluate(p, points[k]);
        const T x = std::fabs(points[k]);
        const T touch = static_cast<T>(kTouch) * magnitude(p, x);
        zero[k] = std::fabs(values[k]) <= touch;
        if constexpr (std::is_same_v<T, double>) {
            if (std::fabs(values[k]) <= touch + kGuard * coefficientBound(p, x)) {
                doubtful = true;
                return 0;
            }
        }
    }

    int count = 0;
    auto add = [&](T root) {
        if (count > 0) {
            const T previous = roots[static_cast<std::size_t>(count - 1)];
            const T same = static_cast<T>(kSameRoot);
            if (root - previous <= same * std::max({std::fabs(root), std::fabs(previous), hi * same})) return;
        }
        if (count < kMaxDegree) roots[static_cast<std::size_t>(count++)] = root;
    };
    for (int i = 0; i < pointCount; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (i > 0 && !zero[k - 1] && !zero[k] && (values[k - 1] < 0) != (values[k] < 0)) {
            add(solveSignChange(p, slope, points[k - 1], points[k], values[k - 1]));
        }
        if (zero[k]) add(points[k]);
    }
    return count;
}

DVec3 toDouble(const RVec3& v) {
    return DVec3(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

LongReal dotL(const DVec3& a, const DVec3& b) {
    return static_cast<LongReal>(a.x) * static_cast<LongReal>(b.x) +
           static_cast<LongReal>(a.y) * static_cast<LongReal>(b.y) +
           static_cast<LongReal>(a.z) * static_cast<LongReal>(b.z);
}

// The problem in double: d(t) = c0 + c1 t + c2 t^2 is what the launch velocity must cover in t.
struct Relative {
    DVec3 c0{0.0};  // target - from at t = 0
    DVec3 c1{0.0};  // target velocity
    DVec3 c2{0.0};  // (target acceleration - gravity) / 2
    DVec3 gravity{0.0};
    double gravityLength = 0;
    DVec3 up{0.0, 1.0, 0.0};  // -gravity / |gravity|, +Y without gravity
    DVec3 targetPosition{0.0};
    DVec3 targetVelocity{0.0};
    DVec3 targetAcceleration{0.0};
};

DVec3 across(const DVec3& v, const DVec3& up) { return v - glm::dot(v, up) * up; }

double dotAbs(const DVec3& a, const DVec3& b) {
    return std::fabs(a.x * b.x) + std::fabs(a.y * b.y) + std::fabs(a.z * b.z);
}

// |P d(t)|^2 - (speed t)^2, with P the identity (Speed) or the projection across gravity: in
// long double (the products of doubles nearly exact), or in double with each coefficient's
// bound (the sum of its products' absolute values).
template <class T>
Polynomial<T> speedPolynomial(const DVec3& c0, const DVec3& c1, const DVec3& c2, double speed) {
    Polynomial<T> p;
    p.degree = 4;
    if constexpr (std::is_same_v<T, LongReal>) {
        p.c[4] = dotL(c2, c2);
        p.c[3] = 2 * dotL(c1, c2);
        p.c[2] = dotL(c1, c1) + 2 * dotL(c0, c2) - static_cast<LongReal>(speed) * static_cast<LongReal>(speed);
        p.c[1] = 2 * dotL(c0, c1);
        p.c[0] = dotL(c0, c0);
    } else {
        const double c11 = glm::dot(c1, c1);
        p.c[4] = glm::dot(c2, c2);
        p.c[3] = 2 * glm::dot(c1, c2);
        p.c[2] = c11 + 2 * glm::dot(c0, c2) - speed * speed;
        p.c[1] = 2 * glm::dot(c0, c1);
        p.c[0] = glm::dot(c0, c0);
        p.bound[4] = p.c[4];
        p.bound[3] = 2 * dotAbs(c1, c2);
        p.bound[2] = c11 + 2 * dotAbs(c0, c2) + speed * speed;
        p.bound[1] = 2 * dotAbs(c0, c1);
        p.bound[0] = p.c[0];
    }
    p.trim();
    return p;
}

// The closed form for a static target at a fixed speed: |c0 - g t^2 / 2| = s t is a quadratic
// in T = t^2, (|g|^2 / 4) T^2 - (s^2 + g.c0) T + |c0|^2 = 0. Both roots are taken from the
// cancellation-free pair q / a and c / q, and the discriminant as the product
// (s^2 + g.c0 - |g||c0|)(s^2 + g.c0 + |g||c0|), whose first factor is zero at the range limit.
int staticTargetTimes(const Relative& r, double speed, std::array<double, 2>& times) {
    const double distanceSquared = glm::dot(r.c0, r.c0);
    const double distance = std::sqrt(distanceSquared);
    const double g = r.gravityLength;
    const double s2 = speed * speed;
    const double gDotR = glm::dot(r.gravity, r.c0);
    if (distanceSquared == 0) {
        // At the shooter: straight up and back down, t = 2 s / |g|.
        if (g > 0 && speed > 0) {
            times[0] = 2.0 * speed / g;
            return 1;
        }
        return 0;
    }
    if (g == 0) {
        if (speed <= 0) return 0;
        times[0] = distance / speed;
        return 1;
    }
    const double reach = s2 + gDotR - g * distance;  // < 0: beyond the range limit
    const double sum = s2 + gDotR + g * distance;
    bool doubleRoot = false;
    if (std::fabs(reach) <= static_cast<double>(kTouch) * (s2 + std::fabs(gDotR) + g * distance)) {
        doubleRoot = true;
    } else if (reach < 0) {
        return 0;
    }
    const double root = doubleRoot ? 0.0 : std::sqrt(reach * sum);
    const double q = 0.5 * (s2 + gDotR + root);
    if (!(q > 0)) return 0;
    const double low = distanceSquared / q;  // c / q
    const double high = 4.0 * q / (g * g);   // q / a
    times[0] = std::sqrt(low);
    if (doubleRoot) return 1;
    times[1] = std::sqrt(high);
    return times[1] > times[0] ? 2 : 1;
}

}  // namespace

Status validateAim(const AimShot& shot, const AimTarget& target) {
    using detail::isFinite;
    if (!isFinite(shot.from) || !std::isfinite(shot.speed) || !std::isfinite(shot.apexHeight) ||
        !isFinite(shot.gravity) || !std::isfinite(shot.maxTime) || !isFinite(target.position) ||
        !isFinite(target.velocity) || !isFinite(target.acceleration)) {
        return Status::NonFiniteInput;
    }
    if (shot.maxTime < 0.0f) return Status::NegativeTime;
    const auto far = [](const RVec3& p) {
        const DVec3 d = toDouble(p);
        return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) > kMaxCoordinate;
    };
    if (far(shot.from) || far(target.position) || std::abs(static_cast<double>(shot.speed)) > kMaxSpeed ||
        glm::length(DVec3(target.velocity)) > kMaxSpeed)
        return Status::OutOfRange;
    const bool apex =
        shot.constraint == AimConstraint::ApexAboveStart || shot.constraint == AimConstraint::ApexAboveTarget;
    if (apex && shot.gravity == Vec3(0.0f)) return Status::ZeroVector;
    return Status::Ok;
}

Status aimProjectile(const AimShot& shot, const AimTarget& target, std::span<FiringSolution> solutions,
                     std::size_t& count) {
    const Status valid = validateAim(shot, target);
    if (valid != Status::Ok) return valid;

    Relative r;
    r.gravity = DVec3(detail::decimalValue(shot.gravity.x), detail::decimalValue(shot.gravity.y),
                      detail::decimalValue(shot.gravity.z));
    r.gravityLength = glm::length(r.gravity);
    if (r.gravityLength > 0) r.up = -r.gravity / r.gravityLength;
    r.targetPosition = toDouble(target.position);
    r.targetVelocity = DVec3(target.velocity);
    r.targetAcceleration = DVec3(target.acceleration);
    const DVec3 from = toDouble(shot.from);
    r.c0 = r.targetPosition - from;
    r.c1 = r.targetVelocity;
    r.c2 = 0.5 * (r.targetAcceleration - r.gravity);
    const double speed = static_cast<double>(shot.speed);
    // Hits beyond the precision envelope are not meaningful: the search ends when the target may
    // leave it (|p| + |v| t + |a| t^2 / 2 <= kMaxCoordinate on every axis). Without this, a
    // maxTime of 1e28 s scales the polynomials' brackets past what double can resolve.
    double maxTime = static_cast<double>(shot.maxTime);
    {
        const double p =
            std::max({std::abs(r.targetPosition.x), std::abs(r.targetPosition.y), std::abs(r.targetPosition.z)});
        const double v = glm::length(r.targetVelocity), a = glm::length(r.targetAcceleration);
        const double room = kMaxCoordinate - p;
        double limit = std::numeric_limits<double>::infinity();
        if (a > 0.0)
            limit = 2.0 * room / (v + std::sqrt(v * v + 2.0 * a * room));  // a t^2 / 2 + v t = room
        else if (v > 0.0)
            limit = room / v;
        maxTime = std::min(maxTime, limit);
    }

    std::array<double, kMaxFiringSolutions> times{};
    int timeCount = 0;
    bool everyTime = false;  // every t works: no earliest time (see below)

    // `build(T())` makes the polynomial in T. Solved in double; when the double solver doubts
    // (a grazing or near-double root, see realRoots), again in long double.
    auto polynomialTimes = [&](auto&& build, auto&& accept) {
        const Polynomial<double> p = build(0.0);
        // The degree is long double's unless a leading coefficient cancels to its rounding.
        bool doubtful = p.identicallyZero();
        for (int i = p.degree; i <= kMaxDegree; ++i) {
            const auto k = static_cast<std::size_t>(i);
            if (p.bound[k] > 0 && std::fabs(p.c[k]) <= kGuard * p.bound[k]) doubtful = true;
        }
        std::array<double, kMaxDegree> roots{};
        int n = doubtful ? 0 : realRoots(p, 0.0, maxTime, roots, doubtful);
        if (doubtful) {
            const Polynomial<LongReal> exact = build(0.0L);
            if (exact.identicallyZero()) {
                everyTime = true;
                return;
            }
            doubtful = false;
            std::array<LongReal, kMaxDegree> exactRoots{};
            n = realRoots(exact, 0.0L, static_cast<LongReal>(maxTime), exactRoots, doubtful);
            for (int i = 0; i < n; ++i)
                roots[static_cast<std::size_t>(i)] = static_cast<double>(exactRoots[static_cast<std::size_t>(i)]);
        }
        for (int i = 0; i < n; ++i) {
            const double t = roots[static_cast<std::size_t>(i)];
            if (t > 0 && t <= maxTime && accept(t) && timeCount < static_cast<int>(kMaxFiringSolutions)) {
                times[static_cast<std::size_t>(timeCount++)] = t;
            }
        }
    };
    auto always = [](double) { return true; };

    if (maxTime > 0) {
        switch (shot.constraint) {
            case AimConstraint::Speed: {
                if (speed < 0) break;
                if (r.c1 == DVec3(0.0) && r.targetAcceleration == DVec3(0.0)) {
                    if (glm::dot(r.c0, r.c0) == 0 && speed == 0 && r.gravityLength == 0) {
                        everyTime = true;
                        break;
                    }
                    std::array<double, 2> closed{};
                    const int n = staticTargetTimes(r, speed, closed);
                    for (int i = 0; i < n; ++i) {
                        if (closed[static_cast<std::size_t>(i)] > 0 && closed[static_cast<std::size_t>(i)] <= maxTime) {
                            times[static_cast<std::size_t>(timeCount++)] = closed[static_cast<std::size_t>(i)];
                        }
                    }
                    break;
                }
                polynomialTimes([&](auto zero) { return speedPolynomial<decltype(zero)>(r.c0, r.c1, r.c2, speed); },
                                always);
                break;
            }
            case AimConstraint::HorizontalSpeed: {
                if (speed < 0) break;
                const DVec3 c0 = across(r.c0, r.up), c1 = across(r.c1, r.up), c2 = across(r.c2, r.up);
                polynomialTimes([&](auto zero) { return speedPolynomial<decltype(zero)>(c0, c1, c2, speed); }, always);
                break;
            }
            case AimConstraint::ApexAboveStart:
            case AimConstraint::ApexAboveTarget: {
                const double height = static_cast<double>(shot.apexHeight);
                if (height < 0) break;
                const double g = r.gravityLength;
                const double apexSpeed = std::sqrt(2.0 * g * height);  // vertical speed gained falling `height`
                // The launch's vertical speed w covers the vertical displacement: d(t).up = w t.
                // Above the start: w = sqrt(2 g h), hit descending (t >= w / g). Above the hit
                // point: the apex is (w - g t)^2 / (2 g) above it, so w = g t - sqrt(2 g h) on the
                // descending branch, and w >= 0 (the apex is reached in flight): t >= sqrt(2 g h) / g.
                const double apexTime = apexSpeed / g;
                const bool aboveStart = shot.constraint == AimConstraint::ApexAboveStart;
                auto apexPolynomial = [&](auto zero) {
                    using T = decltype(zero);
                    Polynomial<T> p;
                    p.degree = 2;
                    p.c[0] = static_cast<T>(glm::dot(r.c0, r.up));
                    p.c[1] = static_cast<T>(glm::dot(r.c1, r.up));
                    p.c[2] = static_cast<T>(glm::dot(r.c2, r.up));
                    p.bound[0] = static_cast<T>(dotAbs(r.c0, r.up));
                    p.bound[1] = static_cast<T>(dotAbs(r.c1, r.up) + apexSpeed);
                    p.bound[2] = static_cast<T>(dotAbs(r.c2, r.up) + (aboveStart ? 0.0 : g));
                    if (aboveStart) {
                        p.c[1] -= static_cast<T>(apexSpeed);
                    } else {
                        p.c[1] += static_cast<T>(apexSpeed);
                        p.c[2] -= static_cast<T>(g);
                    }
                    p.trim();
                    return p;
                };
                // A hit at the apex itself is a double root, found to ~1e-10: accept it.
                polynomialTimes(apexPolynomial, [&](double t) { return t >= apexTime * (1.0 - 1e-9); });
                break;
            }
        }
    }
    if (everyTime) {
        // The target leaves the shooter exactly as a shot would (e.g. both at rest, no speed, no
        // gravity): every time meets it and none is the earliest. One solution, at maxTime.
        timeCount = 0;
        if (maxTime > 0) times[static_cast<std::size_t>(timeCount++)] = maxTime;
    }
    // A time that rounds to 0 as a float (a tiny positive double, e.g. a target 1e-30 m away
    // at 3e38 m/s) would be reported as `time: 0`, outside (0, maxTime]: drop it.
    {
        int kept = 0;
        for (int i = 0; i < timeCount; ++i) {
            const double t = times[static_cast<std::size_t>(i)];
            if (static_cast<float>(t) > 0.0f) times[static_cast<std::size_t>(kept++)] = t;
        }
        timeCount = kept;
    }
    // Insertion sort of at most 4 (std::sort trips GCC 12's -Warray-bounds here).
    for (int i = 1; i < timeCount; ++i) {
        for (int j = i; j > 0 && times[static_cast<std::size_t>(j)] < times[static_cast<std::size_t>(j - 1)]; --j) {
            std::swap(times[static_cast<std::size_t>(j)], times[static_cast<std::size_t>(j - 1)]);
        }
    }

    std::array<FiringSolution, kMaxFiringSolutions> found{};
    for (int i = 0; i < timeCount; ++i) {
        const double t = times[static_cast<std::size_t>(i)];
        const DVec3 displacement = r.c0 + r.c1 * t + r.c2 * (t * t);
        DVec3 velocity = displacement / t;
        if (shot.constraint == AimConstraint::Speed) {
            // |d(t)| = s t to the root's precision; the contract is a velocity of length s.
            const double length = glm::length(velocity);
            velocity = length > 0 ? velocity * (speed / length) : DVec3(0.0);
        }
        const double vertical = glm::dot(velocity, r.up);
        const double horizontal = glm::length(across(velocity, r.up));
        FiringSolution& solution = found[static_cast<std::size_t>(i)];
        solution.velocity = detail::toF(velocity);
        solution.time = static_cast<float>(t);
        solution.hit = detail::toR(r.targetPosition + r.targetVelocity * t + r.targetAcceleration * (0.5 * t * t));
        solution.elevation =
            static_cast<float>(vertical == 0 && horizontal == 0 ? 0.0 : std::atan2(vertical, horizontal));
        if (!detail::isFinite(solution.velocity) || !detail::isFinite(solution.hit) || !std::isfinite(solution.time)) {
            return Status::NonFiniteResult;
        }
    }
    const std::size_t written = std::min(static_cast<std::size_t>(timeCount), solutions.size());
    std::copy(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(written), solutions.begin());
    count = written;
    return Status::Ok;
}

FORESIGHT_NAMESPACE_END
