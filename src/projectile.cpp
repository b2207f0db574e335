#include <foresight/projectile.h>

#include "engine_internal.h"
#include "internal.h"
#include "path_capsule.h"
#include "projectile_internal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace {

using Recorder = TrajectoryRecorder;

// A projectile's state during a prediction.
struct Body {
    DVec3 position;
    DVec3 velocity;
};

// Reflects `velocity` off a surface with normal `n`: the article's restitution response
// `v += -(1 + e) dot(n, v) n`, plus Coulomb friction on the tangential part (never reversing it).
DVec3 bounceVelocity(const DVec3& velocity, const DVec3& n, double restitution, double friction) {
    const double vn = glm::dot(n, velocity);
    DVec3 result = velocity - (1.0 + restitution) * vn * n;
    if (friction > 0.0) {
        const DVec3 tangential = velocity - vn * n;
        const double speed = glm::length(tangential);
        if (speed > 0.0) {
            const double loss = std::min(speed, friction * (1.0 + restitution) * std::abs(vn));
            result -= tangential * (loss / speed);
        }
    }
    return result;
}

// The first time s in [0, limit] at which c + b s + a s^2 (a signed distance to a plane along
// a parabola) reaches zero while decreasing: the body enters the plane. A body that starts on
// the plane moving out (c ~ 0, b > 0) enters it again on its way back, at s = -b / a.
// Returns `fallback` (clamped) if rounding hides the root.
double firstEntry(double c, double b, double a, double limit, double fallback) {
    if (c <= 0.0 && b <= 0.0) return 0.0;  // on or behind the plane and moving in
    double roots[2];
    int count = 0;
    if (std::abs(a) <= 1e-14 * (std::abs(b) + std::abs(c))) {
        if (b != 0.0) roots[count++] = -c / b;
    } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc >= 0.0) {
            // Stable roots: q = -(b + sign(b) sqrt(disc)) / 2, then q / a and c / q.
            const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
            roots[count++] = q / a;
            if (q != 0.0) roots[count++] = c / q;
        }
    }
    double best = std::numeric_limits<double>::infinity();
    const double slack = 1e-9 * limit;
    for (int i = 0; i < count; ++i) {
        const double r = roots[i];
        const bool entering = b + 2.0 * a * r < 0.0;
        if (entering && r >= -slack && r <= limit + slack) best = std::min(best, r);
    }
    if (!std::isfinite(best)) return std::clamp(fallback, 0.0, limit);
    return std::clamp(best, 0.0, limit);
}

DVec3 decimalVector(const Vec3& v) { return DVec3(decimalValue(v.x), decimalValue(v.y), decimalValue(v.z)); }

SegmentCast makeCast(const DVec3& from, const DVec3& to, float radius) {
    SegmentCast cast;
    cast.origin = toR(from);
    cast.displacement = toF(to - toD(cast.origin));
    cast.radius = radius;
    return cast;
}

// The exact method's cast of a chord from -> to. The world sees a body at `to` as toR(to), and
// the next chord is cast from there, so this one must reach it: the float displacement's
// rounding (up to 2^-24 of each component: 7 nm on a 0.12 m chord) could otherwise stop it
// short of a surface that the body ends on, or just beyond (a step ending exactly on a wall's
// plane), and the next chord, starting behind that surface, would not see it. The displacement
// is lengthened by 2^-22 so that every component surely reaches its target; a hit within that
// overshoot (nanometres past the end) is an impact at the end of the chord.
SegmentCast makeChordCast(const DVec3& from, const DVec3& to, float radius) {
    constexpr double kOvershoot = 1.0 + 0x1.0p-22;
    SegmentCast cast;
    cast.origin = toR(from);
    RVec3 end = toR(to);
#if defined(__GNUC__)
    // GCC 12 at -O2 (its SLP vectorizer) was seen to drop the float rounding of a float build's
    // origin and end here (double -> float -> double folded to the double): the displacement
    // then missed the rounded end by up to half an ulp. Read them back from memory.
    asm volatile("" : : "r"(&cast.origin), "r"(&end) : "memory");
#endif
    cast.displacement = toF((toD(end) - toD(cast.origin)) * kOvershoot);
    cast.radius = radius;
    return cast;
}

bool resultIsFinite(const ProjectileResult& r) {
    return detail::isFinite(r.position) && detail::isFinite(r.velocity) && std::isfinite(r.time);
}

// The reference article's loop, faithfully (see projectile.h).
Status runStepped(const DVec3& start, const DVec3& startVelocity, std::uint64_t steps,
                  const ProjectileSettings& settings, const CollisionWorld& world, Recorder& recorder,
                  ProjectileResult& result) {
    const double dt = decimalValue(settings.step);
    const DVec3 g = decimalVector(settings.gravity);
    const double e = settings.restitution;
    DVec3 p = start, v = startVelocity;
    // The surface the loop put the projectile on at the last hit (its normal faces the side the
    // projectile is on), or zero. A chord from that point back into the surface crosses it at
    // once: a hit at fraction 0, as a plane or a box reports it (and as a game engine's line
    // cast from a point on a collider does). Two-sided triangles cannot tell which side such a
    // start is on and ignore their own plane, so without this the loop fell through meshes.
    DVec3 restingNormal(0.0);
    recorder.add(0.0, TrajectoryEvent::Start, p, v);
    for (std::uint64_t i = 1; i <= steps; ++i) {
        const DVec3 previousPosition = p, previousVelocity = v;
        p += v * dt + 0.5 * g * dt * dt;
        v += g * dt;
        const SegmentCast cast = makeCast(previousPosition, p, settings.radius);
        CastHit hit;
        DVec3 normal(0.0);
        bool bounced = false;
        bool found = world.castSegment(cast, hit);
        const double away = glm::dot(p - previousPosition, restingNormal);
        if (away < 0.0 && !(found && hit.fraction <= 0.0f)) {
            hit.fraction = 0.0f;
            hit.position = toR(previousPosition);
            hit.normal = toF(restingNormal);
            found = true;
        } else if (away > 0.0 && found && glm::dot(toD(hit.normal), restingNormal) < -0.999 &&
                   static_cast<double>(hit.fraction) * away <= realUlps(previousPosition, 16.0)) {
            // Leaving the surface, the chord met that same surface from behind within rounding
            // of its start (the hit point was reported just behind it): not a hit. Cast again
            // from a start lifted off the surface, for whatever else lies on the chord.
            const DVec3 lifted = previousPosition + restingNormal * realUlps(previousPosition, 32.0);
            found = world.castSegment(makeCast(lifted, p, settings.radius), hit);
        }
        restingNormal = DVec3(0.0);
        if (found) {
            // The article's HitCoef: the hit distance over the chord length (0 for chords
            // shorter than a micrometre), used as a time fraction for the velocity.
            const double fullDistance = glm::length(p - previousPosition);
            const double hitCoef = fullDistance > 0.000001 ? static_cast<double>(hit.fraction) : 0.0;
            v = previousVelocity + g * dt * hitCoef;
            p = toD(hit.position);
            normal = toD(hit.normal);
            if (result.bounces >= settings.maxBounces) {
                result.stoppedAtHit = true;
                result.hitNormal = toF(normal);
                result.time = static_cast<float>((static_cast<double>(i - 1) + hitCoef) * dt);
                recorder.add(result.time, TrajectoryEvent::Hit, p, v, normal);
                result.position = toR(p);
                result.velocity = toF(v);
                return Status::Ok;
            }
            v = bounceVelocity(v, normal, e, settings.friction);
            ++result.bounces;
            result.hitNormal = toF(normal);
            restingNormal = normal;
            bounced = true;
        }
        const double t = static_cast<double>(i) * dt;
        recorder.add(t, i == steps ? TrajectoryEvent::End : (bounced ? TrajectoryEvent::Bounce : TrajectoryEvent::Step),
                     p, v, normal);
    }
    result.position = toR(p);
    result.velocity = toF(v);
    result.time = static_cast<float>(static_cast<double>(steps) * dt);
    return Status::Ok;
}

// The event-driven exact method (see projectile.h and docs/ARCHITECTURE.md).
class ExactRun {
public:
    ExactRun(const ProjectileSettings& settings, const CollisionWorld& world, Recorder& recorder,
             ProjectileResult& result, const DistanceCutoff* cutoff = nullptr)
        : mSettings(settings), mWorld(world), mRecorder(recorder), mResult(result),
          mGravity(decimalVector(settings.gravity)), mRegionQueries(world.regionQueryCost(settings.radius) <= 2.0f),
          mCutoff(cutoff) {}

    /// True when the run stopped at its cutoff (projectile_internal.h).
    bool abandoned() const { return mAbandoned; }

    Status run(const DVec3& start, const DVec3& startVelocity, double endTime) {
        mBody = {start, startVelocity};
        mRecorder.add(0.0, TrajectoryEvent::Start, mBody.position, mBody.velocity);
        const double step = decimalValue(mSettings.step);
        mStep = step;
        // At least one step, at most 64 (clearAhead's loop over the stretch's points).
        const auto stepsIn = [step](double time) {
            return static_cast<std::uint64_t>(std::clamp(std::round(time / step), 1.0, 64.0));
        };
        mMaxClearSteps = stepsIn(kMaxClearTime);
        mMinClearSteps = std::min(stepsIn(kMinClearTime), mMaxClearSteps);
        mClearSteps = std::clamp(stepsIn(kStartClearTime), mMinClearSteps, mMaxClearSteps);
        mEndTime = endTime;
        std::uint64_t& gridIndex = mGridIndex;  // step points recorded so far
        while (mTime < endTime && !mStopped) {
            const double gridTime = std::min(static_cast<double>(gridIndex + 1) * step, endTime);
            if (mTime >= gridTime) {  // an impact landed exactly on the grid
                ++gridIndex;
                recordStep(gridTime, endTime);
                continue;
            }
            const double h = gridTime - mTime;
            if (!mInContact && mGridIndex < mClearedGrid && !mHasLastSurface && !mHadImpact && !mHadContact) {
                // A step of free flight that clearAhead cleared: advanceBallistic's arithmetic
                // without its questions (no surface is near, no chord is cast).
                const DVec3 p0 = mBody.position, v0 = mBody.velocity;
                mBody = {p0 + v0 * h + 0.5 * mGravity * h * h, v0 + mGravity * h};
                mTime = gridTime;
                ++gridIndex;
                recordStep(gridTime, endTime);
                continue;
            }
            const bool reached = mInContact ? advanceInContact(h) : advanceBallistic(h);
            if (mEvents > mSettings.maxEvents) return Status::TooManyEvents;
            if (mAtRest) {
                mRecorder.add(mTime, TrajectoryEvent::Rest, mBody.position, DVec3(0.0), mContactNormal);
                mBody.velocity = DVec3(0.0);
                mTime = endTime;
                break;
            }
            if (reached) {
                mTime = gridTime;
                ++gridIndex;
                recordStep(gridTime, endTime);
            }
        }
        if (!mStopped) {
            if (!mEndRecorded) mRecorder.add(endTime, TrajectoryEvent::End, mBody.position, mBody.velocity);
            mResult.time = static_cast<float>(endTime);
        }
        mResult.position = toR(mBody.position);
        mResult.velocity = toF(mBody.velocity);
        mResult.atRest = mAtRest;
        return Status::Ok;
    }

private:
    void recordStep(double time, double endTime) {
        mEndRecorded = time >= endTime;
        mRecorder.add(time, mEndRecorded ? TrajectoryEvent::End : TrajectoryEvent::Step, mBody.position,
                      mBody.velocity);
        if (mCutoff && time >= mNextCutoff && !mEndRecorded) checkCutoff(time, endTime);
    }

    // Stops the run where it surely ends beyond the cutoff's distance (projectile_internal.h).
    void checkCutoff(double time, double endTime) {
        mNextCutoff = time + kCutoffInterval;
        const double left = endTime - time;
        const double reach =
            glm::length(mBody.velocity) * left + 0.5 * glm::length(mGravity) * left * left + kCutoffMargin;
        if (glm::length(mBody.position - mCutoff->target) - reach > mCutoff->keepBelow) {
            mAbandoned = true;
            mStopped = true;
        }
    }

    // The normal speed of a one-micrometre hop off a surface with normal n (0 if gravity does
    // not press on it): below it, a bounce turns into sliding contact.
    double restSpeed(const DVec3& n) const { return std::sqrt(2.0 * std::max(0.0, -glm::dot(mGravity, n)) * 1e-6); }

    // How far off a surface a body is placed after an impact: a few units in the last place
    // of the position type, so that rounding to Real never puts it on the surface's far side.
    static double skinDistance(const DVec3& p) { return realUlps(p, 4.0); }

    // How far casts are lifted off the surface the body is on (0.1 mm, more far from the
    // origin, where Real resolves less).
    double liftDistance() const { return 1e-4 + realUlps(mBody.position, 8.0); }

    // Ballistic flight for up to h seconds. Returns true when h was covered without an impact.
    bool advanceBallistic(double h) {
        const DVec3 p0 = mBody.position, v0 = mBody.velocity;
        double duration = h;
        bool returnsToSurface = false;
        // Clear of the surfaces it was on: they can no longer be seen from behind at a start.
        const double clear = 2.0 * liftDistance();
        if (mHadImpact && std::abs(glm::dot(mLastSurfaceNormal, p0 - mLastSurfacePoint)) > clear) mHadImpact = false;
        if (mHadContact && std::abs(glm::dot(mContactNormal, p0 - mContactPoint)) > clear) mHadContact = false;
        if (mHasLastSurface) {
            // After a bounce the body starts on the surface it left. A world need not report a
            // surface the cast starts on (two-sided triangles, most engines' meshes), so the
            // return to that surface's plane is solved here and checked with a probe.
            const DVec3& n = mLastSurfaceNormal;
            const double c = glm::dot(n, p0 - mLastSurfacePoint);
            const double b = glm::dot(n, v0), a = 0.5 * glm::dot(n, mGravity);
            if (c + b * h + a * h * h < 0.0) {
                const double s = firstEntry(c, b, a, h, h);
                if (s < h) {
                    duration = s;
                    returnsToSurface = true;
                }
            } else if (c > 2.0 * liftDistance()) {
                mHasLastSurface = false;  // clear of it: the world's casts see it again
            }
        }
        const DVec3 p1 = p0 + v0 * duration + 0.5 * mGravity * duration * duration;
        // In free flight (no surface near that a cast could start on), the chord may lie in a
        // stretch that one world query cleared (clearAhead): it would hit nothing.
        const bool freeFlight = !mHasLastSurface && !mHadImpact && !mHadContact;
        // Just bounced off a surface and no other surface known near: the hop from it may be
        // cleared in the same way, from its first step on (clearAhead's `hop`).
        const bool hop =
            !freeFlight && mHopPlaneKnown && mHasLastSurface && mHadImpact && !mHadContact && !returnsToSurface;
        if (!freeFlight && !hop) mClearedGrid = 0;
        const bool cleared = (freeFlight || hop) && (mGridIndex < mClearedGrid || clearAhead(p0, v0, hop));
        CastHit hit;
        if (!cleared &&
            (castPath(p0, p1, mHasLastSurface, mLastSurfaceNormal, hit) || crossesRecentSurface(p0, p1, hit))) {
            const Impact found = locateImpact(p0, v0, mGravity, duration, hit, mHasLastSurface, mLastSurfaceNormal);
            arriveAt(p0, v0, found.time, found.normal, found.surfacePoint);
            return false;
        }
        if (returnsToSurface) {
            const DVec3& n = mLastSurfaceNormal;
            const double lift = liftDistance();
            if (world().castSegment(makeCast(p1 + n * lift, p1 - n * lift, mSettings.radius), hit)) {
                arriveAt(p0, v0, duration, toD(hit.normal), toD(hit.position));
                return false;
            }
            mHasLastSurface = false;  // hopped off its edge
            mBody = {p1, v0 + mGravity * duration};
            mTime += duration;
            return false;
        }
        mBody = {p1, v0 + mGravity * duration};
        return true;
    }

    // Clears the free flight from (p0, v0) at mTime over the next grid steps with one world
    // query (path_capsule.h): sets mClearedGrid to the grid point that ends the last step whose
    // chord surely hits nothing, and returns whether that covers the step from mTime. The horizon
    // doubles after a clear capsule and halves after a touched one; after a query that cleared
    // nothing (a surface near, or a world that cannot answer: CollisionWorld::firstTouch's
    // default), the chords are cast one by one for a while, longer each time.
    // After an impact, the stretch ends before the body comes back within liftDistance() of the
    // plane it touched there (the hop over a floor), and the query leaves out the surfaces wholly
    // behind that plane (CollisionWorld::firstTouchInFront): the floor it left and the floor
    // beside, which the chords of the stretch, all that far in front, cannot meet. Without it
    // the floor, within the capsule's radius at the start, would clear nothing.
    // With `justBounced` (the steps after a bounce, on which the body may still lie within
    // liftDistance() of the surface it left: a hop), the plane is the one the world reported at
    // the impact and the tolerance less than the body's height over it, so that every chord of
    // the stretch lies strictly in front of the surfaces left out. A hop's query that clears
    // nothing leaves the stretch's state as it was (the chords go on as they would have); where
    // the world's first two hop queries cleared nothing (a world whose firstTouchInFront is
    // CollisionWorld's default, firstTouch), the hops of that run are not asked again.
    bool clearAhead(const DVec3& p0, const DVec3& v0, bool justBounced = false) {
        if (!mRegionQueries) return false;
        const DVec3& left = mLastSurfaceNormal;  // zero before the first impact: never in front
        const double lift = liftDistance();
        const double radius = static_cast<double>(mSettings.radius);
        bool inFront = glm::dot(left, p0 - mLastSurfacePoint) >= lift;
        const bool hop = justBounced && !inFront;
        if (hop && mHopQueries >= 2 && mHopClears == 0) return false;
        if (!hop && mClearWait > 0) {
            --mClearWait;
            return false;
        }
        // The stretch's points are run()'s grid points after mTime, j = 1 .. last (the end time
        // the last of them), computed when needed rather than stored.
        const auto timeOf = [&](std::uint64_t j) {
            return std::min(static_cast<double>(mGridIndex + j) * mStep, mEndTime) - mTime;
        };
        const auto pointAt = [&](std::uint64_t j) {
            const double s = timeOf(j);
            return p0 + v0 * s + 0.5 * mGravity * s * s;
        };
        InFrontOf front;
        front.point = toR(mLastSurfacePoint - left * radius);
        front.normal = toF(left);
        front.tolerance = kInFrontTolerance;
        if (hop) {
            // The body's height over the reported plane, along the normal BehindTester uses
            // (the float normal, normalised in double); a chord point that high lies beyond the
            // plane's level plus the tolerance, and so beyond every surface left out.
            front.point = toR(mHopPlane - left * radius);
            const DVec3 normal = glm::normalize(DVec3(front.normal));
            const double height = glm::dot(normal, p0) - glm::dot(normal, toD(front.point)) - radius;
            if (!(height > 0.0)) return false;
            front.tolerance = static_cast<float>(std::min(static_cast<double>(kInFrontTolerance), 0.25 * height));
            inFront = true;
        }
        // The last point of the stretch: mClearSteps on, or the first at or past the end time, or
        // (after an impact) the last before the body comes back within `lift` of that plane.
        std::uint64_t last = 0;
        while (last < mClearSteps) {
            const std::uint64_t j = last + 1;
            if (inFront && glm::dot(left, pointAt(j) - mLastSurfacePoint) < lift) break;
            last = j;
            if (static_cast<double>(mGridIndex + j) * mStep >= mEndTime) break;
        }
        if (last < 1) return false;
        const DVec3 end = pointAt(last);
        const std::array<DVec3, 2> ends{p0, end};
        const SegmentCast capsule = pathCapsule(ends, mSettings.radius, parabolaBend(mGravity, timeOf(last)));
        float fraction = 1.0f;
        bool touched = false;
        if (hop) ++mHopQueries;
        if (inFront) {
            touched = mWorld.firstTouchInFront(capsule, front, fraction);
        } else {
            touched = mWorld.firstTouch(capsule, fraction);
        }
        // clearChords (path_capsule.h) over the points, computed one by one up to the touch.
        std::uint64_t clear = last;
        if (touched) {
            const DVec3 chord = end - p0;
            const double length = glm::length(chord);
            const double limit = static_cast<double>(fraction) * length - pathMargin(ends);
            clear = 0;
            if (length > 0.0 && limit > 0.0)
                while (clear < last && glm::dot(pointAt(clear + 1) - p0, chord) / length < limit) ++clear;
        }
        const std::uint64_t points = last + 1;
        if (hop && clear == 0) return false;  // the chords go on; the stretch's state is kept
        if (hop) ++mHopClears;
        if (clear + 1 == points) {
            mClearSteps = std::min<std::uint64_t>(mClearSteps * 2, mMaxClearSteps);
            mClearBackoff = 2;
        } else {
            mClearSteps = std::max<std::uint64_t>(mClearSteps / 2, mMinClearSteps);
        }
        if (clear == 0) {
            mClearWait = mClearBackoff;
            mClearBackoff = std::min<std::uint64_t>(mClearBackoff * 2, mMaxClearSteps);
            return false;
        }
        mClearedGrid = mGridIndex + clear;
        return true;
    }

    // Casts the chord p0 -> p1. A chord that starts on `surface` (the one just left, or slid
    // on) may be reported as hitting it at once; then it is cast again lifted off that surface
    // by liftDistance(), so that the surface cannot mask the obstacles ahead. A chord that starts
    // a hair behind a surface the body is on (seenFromBehind) is cast again from its front.
    bool castPath(const DVec3& p0, const DVec3& p1, bool onSurface, const DVec3& surface, CastHit& hit) const {
        if (!world().castSegment(makeChordCast(p0 + mCastOffset, p1 + mCastOffset, mSettings.radius), hit))
            return false;
        if (!onSurface && !mHadImpact && !mHadContact) return true;  // in free flight
        return recastOffSurfaces(p0, p1, onSurface, surface, hit);
    }

    // castPath's rest, for a hit near surfaces the body is on (kept out of the common path).
    bool recastOffSurfaces(const DVec3& p0, const DVec3& p1, bool onSurface, const DVec3& surface, CastHit& hit) const {
        DVec3 start = p0, end = p1;
        for (int round = 0; round < 2; ++round) {  // at most the two surfaces of seenFromBehind
            const DVec3* n = seenFromBehind(hit, start);
            if (n == nullptr) break;
            const DVec3 nudge = *n * (2.0 * behindTolerance(start));
            start += nudge;
            end += nudge;
            if (!world().castSegment(makeChordCast(start + mCastOffset, end + mCastOffset, mSettings.radius), hit))
                return false;
        }
        if (!onSurface) return true;
        // A hit is that surface when it lies in its plane with its normal.
        const double lift = liftDistance();
        const auto isThatSurface = [&](const CastHit& h) {
            return glm::dot(toD(h.normal), surface) >= 0.999 &&
                   std::abs(glm::dot(surface, toD(h.position) - start)) <= lift;
        };
        if (!isThatSurface(hit)) return true;
        CastHit blocker;
        if (world().castSegment(makeCast(start, start + surface * lift, mSettings.radius), blocker) &&
            !isThatSurface(blocker)) {
            // Wedged: another surface is right above this one. That one is hit at once.
            hit = blocker;
            hit.fraction = 0.0f;
            hit.position = toR(start);
            return true;
        }
        const DVec3 off = surface * lift + mCastOffset;
        return world().castSegment(makeChordCast(start + off, end + off, mSettings.radius), hit);
    }

    // A chord that starts on the plane of a recent impact's surface (within the lift) and ends
    // behind it: a two-sided triangle cannot tell which side a start on its plane is on, and may
    // let it through (a point rattling in a concave edge, put on one face and onto the other's
    // plane by keepInFront). Where the chord crosses that plane, a probe along its normal asks
    // whether the surface is there (not beyond its edge): then `hit` is that impact.
    bool crossesRecentSurface(const DVec3& p0, const DVec3& p1, CastHit& hit) const {
        if (!mHadImpact) return false;
        const double lift = liftDistance();
        for (int i = 0; i < mRecentCount; ++i) {
            const Touched& t = mRecent[static_cast<std::size_t>(i)];
            const double h0 = glm::dot(t.normal, p0 - t.point), h1 = glm::dot(t.normal, p1 - t.point);
            if (std::abs(h0) > lift || h1 >= -behindTolerance(p1) || h0 <= h1) continue;
            const double f = std::clamp(h0 / (h0 - h1), 0.0, 1.0);
            const DVec3 crossing = p0 + (p1 - p0) * f;
            if (world().castSegment(makeCast(crossing + t.normal * lift, crossing - t.normal * lift, mSettings.radius),
                                    hit) &&
                glm::dot(toD(hit.normal), t.normal) >= 0.999) {
                hit.fraction = static_cast<float>(f);
                return true;
            }
        }
        return false;
    }

    // How far behind a surface it is on rounding can leave the body: a few ulps of Real, and
    // the world's own plane (e.g. a triangle's normal from its vertices, in double) against the
    // one the body was put on (the hit's float normal, 1e-7 off, through a point metres away
    // at most): 1 micrometre.
    static double behindTolerance(const DVec3& p) { return 1e-6 + realUlps(p, 4.0); }

    // The normal of the surface the body is on that `hit` is, when the world reports that
    // surface from behind right at the chord's `start`; null otherwise. The body is put on a
    // surface's plane as the world's float normal through the hit point defines it (after an
    // impact), or at a probe's rounded hit point (sliding); the world's plane differs by that
    // rounding, and on an oblique surface the body may lie a hair behind it. A two-sided
    // triangle then reports itself from behind at once, with the reversed normal, as the body
    // moves out: crossing its plane towards the front, which is no impact for a body on the
    // front. The surfaces the body is on: the last one it hit, and the one it slides or slid
    // on (an impact on an obstacle can end a slide: the body then leaves both at once). A
    // surface facing one of them from further than rounding (a wedge) stays a hit.
    const DVec3* seenFromBehind(const CastHit& hit, const DVec3& start) const {
        const double tolerance = behindTolerance(start);
        const DVec3 normal = toD(hit.normal);
        const DVec3 position = toD(hit.position);
        const auto matches = [&](const DVec3& n, const DVec3& point) {
            return glm::dot(normal, n) <= -0.999 && std::abs(glm::dot(n, start - point)) <= tolerance &&
                   std::abs(glm::dot(n, position - start)) <= tolerance;
        };
        if (mHadImpact && matches(mLastSurfaceNormal, mLastSurfacePoint)) return &mLastSurfaceNormal;
        if (mHadContact && matches(mContactNormal, mContactPoint)) return &mContactNormal;
        return nullptr;
    }

    struct Impact {
        double time;  // since the start of the motion
        DVec3 normal;
        DVec3 surfacePoint;  // a point of the surface's tangent plane (body centre at contact)
    };

    // The first impact along p(s) = p0 + v0 s + a s^2 / 2, s in [0, limit], given the chord
    // cast's `hit` (castPath's, lifted or not). The parabola is solved against
    // the plane tangent to the surface at the hit; the chord up to that time is cast again, so
    // that a surface the parabola meets before the chord does (a corner) is not missed.
    Impact locateImpact(const DVec3& p0, const DVec3& v0, const DVec3& a, double limit, CastHit hit, bool onSurface,
                        const DVec3& surface) const {
        Impact found{};
        for (int attempt = 0;; ++attempt) {
            found.normal = toD(hit.normal);
            // The hit's point lies on the surface's plane (for a swept sphere: the plane its
            // centre touches) whether or not the cast was lifted off the path: solve for it.
            found.surfacePoint = toD(hit.position);
            const DVec3& n = found.normal;
            found.time = firstEntry(glm::dot(n, p0 - found.surfacePoint), glm::dot(n, v0), 0.5 * glm::dot(n, a), limit,
                                    static_cast<double>(hit.fraction) * limit);
            if (attempt == 4 || found.time <= 0.0) return found;
            const DVec3 p = p0 + v0 * found.time + 0.5 * a * found.time * found.time;
            CastHit earlier;
            if (!castPath(p0, p, onSurface, surface, earlier) || earlier.fraction >= 1.0f - 1e-6f) return found;
            if (earlier.fraction == 0.0f && glm::dot(toD(earlier.normal), n) >= 0.999) {
                // The surface it starts on, reported at once again (in a crease, the one before
                // the last): the motion up to the impact is cast lifted off it, for another
                // surface met first (the end of the crease).
                const DVec3 off = n * liftDistance() + mCastOffset;
                if (!world().castSegment(makeChordCast(p0 + off, p + off, mSettings.radius), earlier) ||
                    glm::dot(toD(earlier.normal), n) >= 0.999)
                    return found;
            }
            hit = earlier;
            limit = found.time;
        }
    }

    // An impact point p, reached with `velocity`, moved back along that path by a few ulps.
    // Where another surface's plane passes through the impact point too (a corner, an edge,
    // a step ending on a plane), the body is on both at once; the world reports one, and the
    // next chord, starting exactly on (or, by rounding, behind) the other's plane, would not
    // see it (a two-sided triangle cannot tell which side such a start is on) and pass
    // through it. Backed off, the body is surely on the side it came from, and meets the
    // other surface at once. Away from the surface hit, which is then projected on.
    static DVec3 backedOff(const DVec3& p, const DVec3& velocity) {
        const double speed = glm::length(velocity);
        return speed > 0.0 ? p - velocity * (realUlps(p, 8.0) / speed) : p;
    }

    // Moves along the parabola from (p0, v0) for s seconds to an impact with the surface through
    // `surfacePoint` with normal n, and responds to it.
    void arriveAt(const DVec3& p0, const DVec3& v0, double s, const DVec3& n, const DVec3& surfacePoint) {
        DVec3 p = backedOff(p0 + v0 * s + 0.5 * mGravity * s * s, v0 + mGravity * s);
        p -= n * glm::dot(n, p - surfacePoint);  // onto the surface the world reported
        p += n * skinDistance(p);                // and surely on its front side
        keepInFront(p, n, surfacePoint);
        mBody = {p, v0 + mGravity * s};
        mTime += s;
        impact(n, s);
        mHopPlane = surfacePoint;
        mHopPlaneKnown = mHasLastSurface;
    }

    // In a crease or a corner (two or three surfaces meeting in a concave edge) the body
    // rattles from one surface to the next, each impact a millimetre or less from the one
    // before. Put on the front of the surface it hit, it may lie a hair behind the one it hit
    // before (their planes cross there), and a chord that starts behind a two-sided triangle
    // leaves through it. So the new position is put in front of the surfaces of the last
    // impacts and of the slide too, where it lies within 5 cm of where it touched them
    // and behind them by no more than rounding (0.1 mm): a few rounds, as planes meeting in a
    // concave corner push it into their common front. A surface it has really passed (a ledge
    // it fell off) is farther or deeper and left alone.
    void keepInFront(DVec3& p, const DVec3& n, const DVec3& surfacePoint) const {
        for (int round = 0; round < 4; ++round) {
            bool moved = false;
            // `point` on the surface's plane: a skin in front; a body position that was put a
            // skin in front before: not behind it (a skin more each time would ratchet the body
            // off a floor it slides on).
            const auto push = [&](const DVec3& normal, const DVec3& point, double skin) {
                const DVec3 offset = p - point;  // farther than kRecentReach: left alone
                if (glm::dot(offset, offset) > kRecentReach * kRecentReach) return;
                const double height = glm::dot(normal, p - point);
                if (height >= skin || height < -1e-4) return;
                p += normal * (skin - height);
                moved = true;
            };
            push(n, surfacePoint, skinDistance(p));
            for (int i = 0; i < mRecentCount; ++i) push(mRecent[i].normal, mRecent[i].point, 0.0);
            if (mHadContact) push(mContactNormal, mContactPoint, 0.0);
            if (!moved) return;
        }
    }

    // Remembers the surface of an impact for keepInFront (one entry per surface, the oldest
    // forgotten first).
    void rememberSurface(const DVec3& n, const DVec3& point) {
        int slot = mRecentCount;
        for (int i = 0; i < mRecentCount; ++i)
            if (glm::dot(mRecent[i].normal, n) > 1.0 - 1e-9) slot = i;
        if (slot == kRecentSurfaces)
            slot = mRecentOldest++ % kRecentSurfaces;
        else if (slot == mRecentCount)
            ++mRecentCount;
        mRecent[static_cast<std::size_t>(slot)] = {n, point};
    }

    // The world that answers the queries of this step: the contact plane alone within a stretch
    // of sliding that slideAhead cleared, else the world.
    const CollisionWorld& world() const {
        return mInContact && mGridIndex < mSlidGrid ? static_cast<const CollisionWorld&>(mPlaneWorld) : mWorld;
    }

    // Sliding on one plane over many grid steps with one world query: the steps' chord casts and
    // probes (each within the body's radius and 2 lift distances of its path) are answered by
    // the plane the last probe found, held alone in mPlaneWorld, when the world promises
    // (CollisionWorld::isOnlyPlane) that within the capsule around that path it is that plane
    // and nothing else. The path is bounded before it is known: the acceleration in contact
    // (gravity along the plane, friction) is at most A, so over s seconds the body stays within
    // A s^2 / 2 of p0 + v0 s. Sets mSlidGrid (the grid point the stretch ends at), or leaves the
    // steps to the world: after a crease, an impact, or a refusal (then for a while, longer each
    // time).
    void slideAhead() {
        if (mGridIndex < mSlidGrid) return;
        mSlidGrid = 0;
        if (!mRegionQueries) return;
        if (!mHasSupport || mSlideWait > 0) {
            mSlideWait -= mSlideWait > 0 ? 1 : 0;
            return;
        }
        const DVec3 n = toD(mSupport.normal);
        const double lift = liftDistance();
        // A crease (advanceInContact lifts its casts off the obstacle): not a plane alone.
        if (mHadImpact && glm::dot(mLastSurfaceNormal, n) < 0.999 &&
            std::abs(glm::dot(mLastSurfaceNormal, mBody.position - mLastSurfacePoint)) <= 2.0 * lift)
            return;
        if (glm::dot(mContactNormal, n) < 1.0 - 1e-12) return;  // the contact moved to another surface
        const std::uint64_t steps = mSlideSteps;
        const double end = std::min(static_cast<double>(mGridIndex + steps) * mStep, mEndTime);
        const double s = end - mTime;
        if (!(s > 0.0)) return;
        const double gn = glm::dot(mGravity, n);
        const double accel = glm::length(mGravity - gn * n) + mSettings.friction * std::max(0.0, -gn);
        const DVec3 p0 = mBody.position, along = mBody.velocity - glm::dot(mBody.velocity, n) * n;
        const std::array<DVec3, 2> path{p0, p0 + along * s};
        PlaneRegion region;
        region.capsule = pathCapsule(path, mSettings.radius + 0.5 * accel * s * s + 2.0 * lift);
        region.normal = mSupport.normal;
        const DVec3 surface = toD(mSupport.position) - n * static_cast<double>(mSettings.radius);
        region.point = toR(surface);
        region.restitution = mSupport.restitution;
        region.friction = mSupport.friction;
        if (!mWorld.isOnlyPlane(region)) {
            mSlideSteps = std::max<std::uint64_t>(mSlideSteps / 2, 4);
            mSlideWait = mSlideBackoff;
            mSlideBackoff = std::min<std::uint64_t>(mSlideBackoff * 2, kMaxSlideSteps);
            return;
        }
        Plane plane;
        plane.normal = mSupport.normal;
        plane.distance = static_cast<Real>(glm::dot(toD(plane.normal), surface));
        mPlaneWorld = PlaneWorld(plane, SurfaceMaterial{mSupport.restitution, mSupport.friction});
        mSlidGrid = mGridIndex + steps;
        mSlideSteps = std::min<std::uint64_t>(mSlideSteps * 2, kMaxSlideSteps);
        mSlideBackoff = 2;
    }

    // Sliding on the contact surface for up to h seconds. Returns true when h was covered.
    bool advanceInContact(double h) {
        slideAhead();
        const DVec3 n = mContactNormal;
        const double gn = glm::dot(mGravity, n);
        const DVec3 gt = mGravity - gn * n;
        mBody.velocity -= glm::dot(mBody.velocity, n) * n;
        const DVec3 v0 = mBody.velocity;
        const double speed = glm::length(v0);
        const double frictionDeceleration = mSettings.friction * std::max(0.0, -gn);
        const double slope = glm::length(gt);
        DVec3 a = gt;
        double duration = h;
        bool stops = false;
        if (speed <= 1e-9) {
            if (slope <= frictionDeceleration || slope <= 1e-12) {
                mAtRest = true;  // static friction holds it (or nothing pulls it along)
                return false;
            }
            a -= gt * (frictionDeceleration / slope);
        } else {
            // Kinetic friction against the motion, its direction held over the step.
            a -= v0 * (frictionDeceleration / speed);
            const double along = glm::dot(a, v0);
            if (frictionDeceleration > 0.0 && along < 0.0) {
                const double stopTime = speed * speed / -along;  // v(s) . v0 = 0
                if (stopTime < duration) {
                    duration = stopTime;
                    stops = true;
                }
            }
        }
        const DVec3 p0 = mBody.position;
        const double lift = liftDistance();
        // In a crease: the body slides on n and still touches the obstacle it hit last (a wall
        // beside the floor), which gravity or the slide may press it into again. That obstacle
        // would be reported at once by every cast from here, hiding whatever lies ahead (the
        // end of the crease): the casts are lifted off it, and the return to its plane is
        // solved here, as advanceBallistic does for the surface a bounce left.
        bool returnsToObstacle = false;
        mCastOffset = DVec3(0.0);
        if (mSettings.radius > 0.0f && mHadImpact && glm::dot(mLastSurfaceNormal, n) < 0.999 &&
            std::abs(glm::dot(mLastSurfaceNormal, p0 - mLastSurfacePoint)) <= 2.0 * lift) {
            const DVec3& m = mLastSurfaceNormal;
            const double c = glm::dot(m, p0 - mLastSurfacePoint);
            const double b = glm::dot(m, v0), am = 0.5 * glm::dot(m, a);
            if (c + b * duration + am * duration * duration < 0.0) {
                const double s = firstEntry(c, b, am, duration, duration);
                if (s < duration) {
                    duration = s;
                    stops = false;
                    returnsToObstacle = true;
                }
            }
            mCastOffset = m * lift;
        }
        const DVec3 p1 = p0 + v0 * duration + 0.5 * a * duration * duration;
        CastHit hit;
        // On the plane alone (a stretch slideAhead cleared), a chord that comes no nearer to the
        // plane than half a lift distance is not blocked: castPath's first cast reports the plane
        // at once or not at all, and its cast lifted off the plane misses it.
        const bool planeAlone = mGridIndex < mSlidGrid && mCastOffset == DVec3(0.0) &&
                                glm::dot(toD(mPlaneWorld.plane().normal), p1 - p0) > -0.5 * lift;
        const bool blocked = !planeAlone && castPath(p0, p1, true, n, hit);
        Impact found{};
        if (blocked) found = locateImpact(p0, v0, a, duration, hit, true, n);
        mCastOffset = DVec3(0.0);
        if (!blocked && returnsToObstacle) {
            // Back on the obstacle's plane: an impact if the obstacle is there (a probe), else
            // the crease has ended and the slide goes on past it.
            const DVec3& m = mLastSurfaceNormal;
            if (world().castSegment(makeCast(p1 + m * lift, p1 - m * lift, mSettings.radius), hit)) {
                DVec3 p = backedOff(p1, v0 + a * duration);
                p -= m * glm::dot(m, p - mLastSurfacePoint);
                p += m * skinDistance(p);
                keepInFront(p, m, mLastSurfacePoint);
                mBody = {p, v0 + a * duration};
                mTime += duration;
                impact(m, duration);
                return false;
            }
            mHadImpact = false;
        }
        if (blocked) {
            const double s = found.time;
            // Out of the obstacle if rounding left the body behind its plane, and a skin off
            // it; not onto its plane, which would lift the body off the surface it slides on
            // when the obstacle leans over it.
            DVec3 p = backedOff(p0 + v0 * s + 0.5 * a * s * s, v0 + a * s);
            p -= found.normal * std::min(0.0, glm::dot(found.normal, p - found.surfacePoint));
            p += found.normal * skinDistance(p);
            keepInFront(p, found.normal, found.surfacePoint);
            mBody = {p, v0 + a * s};
            mTime += s;
            impact(found.normal, s);
            return false;
        }
        DVec3 v1 = v0 + a * duration;
        if (stops) v1 -= glm::dot(v1, v0) / (speed * speed) * v0;  // exactly no speed along v0
        if (glm::length(v1) <= 1e-9) v1 = DVec3(0.0);
        mTime += duration;
        // Is the surface still under the new position? (An edge: fly off.)
        DVec3 probed = p1;  // where the probe ran
        bool supported = world().castSegment(makeCast(p1 + n * lift, p1 - n * lift, mSettings.radius), hit);
        if (supported && glm::dot(toD(hit.normal), n) < 0.05) {
            // The probe grazed a wall beside the surface (sliding along a concave edge, the probe
            // runs in the wall's plane): probe again that far off the wall, for the surface
            // under the body. The body stays there, clear of the wall.
            probed = p1 + toD(hit.normal) * lift;
            supported = world().castSegment(makeCast(probed + n * lift, probed - n * lift, mSettings.radius), hit) &&
                        glm::dot(toD(hit.normal), n) >= 0.05;
        }
        if (supported) {
            mSupport = hit;
            mHasSupport = true;
            const DVec3 support = toD(hit.normal);
            // Onto the surface the probe found, along its normal only: the probe's hit point is
            // rounded to Real across the surface too, which could carry the body a hair behind a
            // wall it slides along a few micrometres off. The hit point's rounding along the
            // normal may leave it a hair behind the surface: put the body a skin in front, as
            // after an impact (arriveAt). From behind, the next chord would slip through the
            // crack where this surface meets the next one in a concave edge (a triangle met from
            // behind beyond its edge is not hit).
            mBody.position = probed - support * glm::dot(support, probed - toD(hit.position));
            mBody.position += support * skinDistance(mBody.position);
            keepInFront(mBody.position, support, toD(hit.position));
            mContactPoint = mBody.position;
            if (glm::dot(support, n) < 1.0 - 1e-12) {
                mContactNormal = support;
                v1 -= glm::dot(v1, support) * support;
            }
        } else {
            mBody.position = p1;
            mInContact = false;
            mHasSupport = false;
            ++mEvents;
        }
        mBody.velocity = v1;
        return !stops;
    }

    // An impact at the current state with surface normal n, `elapsed` after the last event.
    void impact(const DVec3& n, double elapsed) {
        ++mEvents;
        mSlidGrid = 0;
        mClearedGrid = 0;
        mHopPlaneKnown = false;
        mHasSupport = false;
        // Wedged between surfaces: eight impacts in a row, each within a nanosecond or a
        // micrometre of the one before (the body rattles in place).
        const bool stalled = elapsed <= 1e-9 || glm::length(mBody.position - mLastImpactPosition) <= 1e-6;
        mConsecutiveStalls = stalled ? mConsecutiveStalls + 1 : 0;
        mLastImpactPosition = mBody.position;
        if (mConsecutiveStalls >= 8) {
            mAtRest = true;
            mContactNormal = n;
            return;
        }
        if (mResult.bounces >= mSettings.maxBounces) {
            mStopped = true;
            mResult.stoppedAtHit = true;
            mResult.hitNormal = toF(n);
            mResult.time = static_cast<float>(mTime);
            mRecorder.add(mTime, TrajectoryEvent::Hit, mBody.position, mBody.velocity, n);
            return;
        }
        DVec3 v = bounceVelocity(mBody.velocity, n, mSettings.restitution, mSettings.friction);
        ++mResult.bounces;
        mResult.hitNormal = toF(n);
        if (glm::dot(mGravity, n) < 0.0 && glm::dot(v, n) <= restSpeed(n)) {
            // Too slow to leave this surface: slide on it (the bounces would otherwise shrink
            // geometrically forever: Zeno).
            v -= glm::dot(v, n) * n;
            mInContact = true;
            mHadContact = true;
            mContactNormal = n;
            mContactPoint = mBody.position;
        } else if (mInContact) {
            const DVec3& floor = mContactNormal;
            if (glm::dot(v, floor) > restSpeed(floor)) {
                mInContact = false;  // bounced up off the surface it was sliding on
            } else {
                // Still on its surface: the obstacle (a wall, or an overhang leaning over the
                // surface) can only push along the surface.
                const DVec3 along = n - glm::dot(n, floor) * floor;
                const double length = glm::length(along);
                if (length > 1e-6)
                    v = bounceVelocity(mBody.velocity, along / length, mSettings.restitution, mSettings.friction);
                v -= glm::dot(v, floor) * floor;
            }
        }
        mBody.velocity = v;
        mHasLastSurface = !mInContact;
        rememberSurface(n, mBody.position);
        mHadImpact = true;
        mLastSurfaceNormal = n;
        mLastSurfacePoint = mBody.position;
        mRecorder.add(mTime, TrajectoryEvent::Bounce, mBody.position, v, n);
    }

    const ProjectileSettings& mSettings;
    const CollisionWorld& mWorld;
    Recorder& mRecorder;
    ProjectileResult& mResult;
    DVec3 mGravity;
    Body mBody{};
    double mTime = 0.0;
    bool mEndRecorded = false;
    bool mInContact = false;
    bool mHasLastSurface = false;
    DVec3 mLastSurfaceNormal{0.0};
    DVec3 mLastSurfacePoint{0.0};
    DVec3 mContactNormal{0.0};
    DVec3 mContactPoint{0.0};  // a point of the contact surface (the last probe's hit)
    bool mHadImpact = false;   // mLastSurfaceNormal and mLastSurfacePoint are set
    // The plane the world reported at the last impact (arriveAt's surfacePoint, a point of the
    // plane the body's centre touched), known from an impact that left the body in flight.
    DVec3 mHopPlane{0.0};
    bool mHopPlaneKnown = false;
    std::uint32_t mHopQueries = 0, mHopClears = 0;  // clearAhead's queries for hops, and those that cleared
    // InFrontOf::tolerance of clearAhead's queries [m]: well inside liftDistance(), the least
    // height of its chords over the plane, with the plane point's rounding to Real (half an ulp).
    static constexpr float kInFrontTolerance = 1e-5f;
    DVec3 mCastOffset{0.0};  // added to the chord casts of castPath (a slide lifted off an obstacle)
    // The surfaces of the last impacts (keepInFront), and how far from where it touched one the
    // body still heeds it [m].
    static constexpr int kRecentSurfaces = 4;
    static constexpr double kRecentReach = 0.05;
    struct Touched {
        DVec3 normal{0.0};
        DVec3 point{0.0};
    };
    std::array<Touched, kRecentSurfaces> mRecent{};
    int mRecentCount = 0;
    unsigned mRecentOldest = 0;
    bool mHadContact = false;  // mContactNormal and mContactPoint are set
    bool mRegionQueries;       // whether clearAhead and slideAhead may ask (CollisionWorld::regionQueryCost)
    // The step grid of run(), and what clearAhead keeps.
    double mStep = 0.0, mEndTime = 0.0;
    std::uint64_t mGridIndex = 0;
    // The longest stretches clearAhead and slideAhead ask about. A free-flight capsule's radius
    // grows with its bend, |g| T^2 / 8: 0.13 m over 0.32 s (16 steps at 50 Hz), 2 m over 1.28 s,
    // which touched a wall or a pillar early and cleared less (the demo level's throws: 8 %
    // faster at 16 steps than at 64, and the same between 8 and 24), so its stretch is bounded in
    // time (kMaxClearTime; the throw planner's coarse 0.1 s grid: 3 steps), from 0.16 s at the
    // start and at least 0.08 s after a touch. A slide's capsule does not grow so: 64 steps.
    static constexpr double kMaxClearTime = 0.32, kStartClearTime = 0.16, kMinClearTime = 0.08;  // [s]
    static constexpr std::uint64_t kMaxSlideSteps = 64;
    std::uint64_t mClearedGrid = 0;  // the chords of this free flight up to this grid point hit nothing
    std::uint64_t mClearSteps = 8, mClearWait = 0, mClearBackoff = 2;
    std::uint64_t mMaxClearSteps = 16, mMinClearSteps = 4;  // the times above in steps (run())
    // What slideAhead keeps: the last probe's hit, and the plane world of a cleared stretch.
    CastHit mSupport{};
    bool mHasSupport = false;
    PlaneWorld mPlaneWorld;
    std::uint64_t mSlidGrid = 0;  // the steps in contact up to this grid point ask mPlaneWorld
    std::uint64_t mSlideSteps = 8, mSlideWait = 0, mSlideBackoff = 2;
    bool mAtRest = false;
    bool mStopped = false;
    const DistanceCutoff* mCutoff;  // null: none
    double mNextCutoff = 0.0;       // the time of the next check [s]
    bool mAbandoned = false;
    std::uint32_t mEvents = 0;
    int mConsecutiveStalls = 0;
    DVec3 mLastImpactPosition{std::numeric_limits<double>::infinity()};
};

}  // namespace

Status validateProjectileSettings(const ProjectileSettings& settings) {
    if (!(settings.step > 0.0f) || !std::isfinite(settings.step)) return Status::InvalidStep;
    if (!isFinite(settings.gravity) || !std::isfinite(settings.restitution) || !std::isfinite(settings.friction) ||
        !std::isfinite(settings.radius))
        return Status::NonFiniteInput;
    if (!(settings.restitution >= 0.0f && settings.restitution <= 1.0f)) return Status::InvalidRestitution;
    if (!(settings.friction >= 0.0f)) return Status::InvalidFriction;
    if (!(settings.radius >= 0.0f)) return Status::InvalidRadius;
    if (settings.method == ProjectileMethod::Engine) return validateEngineProfile(settings.engine);
    if (static_cast<unsigned>(settings.method) > static_cast<unsigned>(ProjectileMethod::Engine))
        return Status::InvalidSetting;
    return Status::Ok;
}

float settingsStep(const ProjectileSettings& settings) {
    return settings.method == ProjectileMethod::Engine ? settings.engine.timestep : settings.step;
}

std::uint64_t steppedStepCount(float time, float step) {
    if (!(time > 0.0f) || !(step > 0.0f) || !std::isfinite(time) || !std::isfinite(step)) return 0;
    const double quotient = decimalValue(time) / decimalValue(step);
    if (!(quotient < 9.0e18)) return std::numeric_limits<std::uint64_t>::max();
    // Taken at their decimal values (3 / 0.02, not 3 / 0.0199999995), and quotients within 1e-6
    // (relative) of an integer are that integer, so that rounding never adds a step.
    const double nearest = std::nearbyint(quotient);
    if (std::abs(quotient - nearest) <= 1e-6 * std::max(1.0, quotient)) return static_cast<std::uint64_t>(nearest);
    return static_cast<std::uint64_t>(std::ceil(quotient));
}

std::size_t trajectoryCapacity(float time, const ProjectileSettings& settings, std::size_t expectedEvents) {
    const std::uint64_t steps = steppedStepCount(time, settingsStep(settings));
    const std::uint64_t capped = std::min<std::uint64_t>(steps, settings.maxSteps);
    return static_cast<std::size_t>(capped) + 3 + 2 * expectedEvents;
}

Status predictProjectile(RVec3 position, Vec3 velocity, float time, const ProjectileSettings& settings,
                         const CollisionWorld* world, std::span<TrajectoryPoint> trajectory, ProjectileResult& out) {
    bool abandoned = false;
    return predictProjectileWithCutoff(position, velocity, time, settings, world, trajectory, out, nullptr, abandoned);
}

Status detail::predictProjectileWithCutoff(RVec3 position, Vec3 velocity, float time,
                                           const ProjectileSettings& settings, const CollisionWorld* world,
                                           std::span<TrajectoryPoint> trajectory, ProjectileResult& out,
                                           const DistanceCutoff* cutoff, bool& abandoned) {
    abandoned = false;
    if (!detail::isFinite(position) || !detail::isFinite(velocity) || !std::isfinite(time))
        return Status::NonFiniteInput;
    if (Status s = validateProjectileSettings(settings); s != Status::Ok) return s;
    if (time < 0.0f) return Status::NegativeTime;
    const std::uint64_t steps = steppedStepCount(time, settingsStep(settings));
    if (steps > settings.maxSteps) return Status::TooManySteps;
    const DVec3 start = toD(position);
    if (std::max({std::abs(start.x), std::abs(start.y), std::abs(start.z)}) > kMaxCoordinate ||
        glm::length(toD(velocity)) > kMaxSpeed)
        return Status::OutOfRange;

    static const EmptyWorld emptyWorld;
    const CollisionWorld& collisionWorld = world ? *world : emptyWorld;
    Recorder recorder{trajectory};
    ProjectileResult result;
    Status status;
    if (settings.method == ProjectileMethod::Engine) {
        status = runEngineProjectile(toD(position), toD(velocity), steps, settings, collisionWorld, recorder, result);
    } else if (settings.method == ProjectileMethod::Stepped) {
        status = runStepped(toD(position), toD(velocity), steps, settings, collisionWorld, recorder, result);
    } else {
        ExactRun run(settings, collisionWorld, recorder, result, cutoff);
        status = run.run(toD(position), toD(velocity), decimalValue(time));
        abandoned = status == Status::Ok && run.abandoned();
        if (abandoned) return Status::Ok;
    }
    if (status != Status::Ok) return status;
    if (!resultIsFinite(result)) return Status::NonFiniteResult;
    const DVec3 end = toD(result.position);
    if (std::max({recorder.reach, std::abs(end.x), std::abs(end.y), std::abs(end.z)}) > kMaxCoordinate)
        return Status::OutOfRange;
    for (std::size_t i = 0; i < recorder.size; ++i)
        if (!detail::isFinite(trajectory[i].position) || !detail::isFinite(trajectory[i].velocity))
            return Status::NonFiniteResult;
    result.trajectorySize = recorder.size;
    result.trajectoryNeeded = recorder.needed;
    out = result;
    return Status::Ok;
}

RVec3 renderedPosition(std::span<const TrajectoryPoint> trajectory, float step, float renderTime,
                       RenderSmoothing smoothing) {
    if (trajectory.empty()) return RVec3(0);
    const double dt = decimalValue(step);
    if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(renderTime) || renderTime <= 0.0f)
        return trajectory.front().position;
    const double steps = static_cast<double>(renderTime) / dt;
    const std::size_t last = trajectory.size() - 1;
    std::size_t k = steps >= static_cast<double>(last) ? last : static_cast<std::size_t>(std::floor(steps));
    // A quotient within rounding of an integer is that step (0.1 s at 0.02 s is step 5).
    if (k < last && std::abs(steps - std::round(steps)) < 1e-9 * std::max(1.0, steps))
        k = static_cast<std::size_t>(std::round(steps));
    const double alpha = std::max(0.0, steps - static_cast<double>(k));
    const TrajectoryPoint& point = trajectory[k];
    switch (smoothing) {
        case RenderSmoothing::None:
            return point.position;
        case RenderSmoothing::Interpolate: {
            if (k == 0) return point.position;
            if (k == last && alpha > 0.0) return point.position;  // past the end: the last step
            const DVec3 previous = toD(trajectory[k - 1].position);
            return toR(previous + std::min(alpha, 1.0) * (toD(point.position) - previous));
        }
        case RenderSmoothing::Extrapolate:
            return toR(toD(point.position) + toD(point.velocity) * (alpha * dt));
    }
    return point.position;
}

FORESIGHT_NAMESPACE_END
