// ProjectileMethod::Engine: a sphere stepped as a rigid-body engine steps it (engine_profile.h).
//
// One step, for every profile (the engines differ in the values, see engineProfile()):
//  1. velocity: gravity and damping in the profile's order (or its first-step rule); angular
//     damping; the engine's speed limit.
//  2. contacts at the start of the step: surfaces the sphere touched or approached before are
//     probed again along their normal; one cast along the step's free motion (lengthened by the
//     contact distance) finds new ones. The gap `s` to each (negative: penetration) decides
//     whether it acts: within contactDistance (speculative) or below 0 (penetration).
//  3. velocity solve: sequential impulses with accumulated clamping, as the engines do; for one
//     contact this is the closed form. Normal target: a bounce (approach faster than the
//     threshold, and, for a speculative contact, reaching the surface within the step) leaves
//     with e times the restitution base's approach speed; otherwise the sphere may close the gap
//     (s / dt) and no more. A velocity correction adds `fraction * depth / dt`. Friction acts at
//     the contact point of a spinning solid sphere: tangential effective mass m / 3.5, clamped to
//     the friction cone of the normal impulse.
//  4. position: the step's free motion when nothing acted (the profile's recurrence, sub-steps
//     included); otherwise `p += v dt`. A position correction then moves the sphere out by
//     `fraction * (depth - slop)`.

#include "engine_internal.h"

#include <foresight/projectile.h>

#include <algorithm>
#include <array>
#include <cmath>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {
namespace {

// Surfaces followed at once (a sphere in a corner touches three).
constexpr int kMaxSurfaces = 6;
// Velocity iterations of the contact solver (several contacts converge; one is exact at once).
constexpr int kSolverIterations = 10;

struct Surface {
    DVec3 normal{0.0};  // unit, towards the sphere
    DVec3 touch{0.0};   // the sphere's centre where it touches the surface
    double gap = 0.0;   // the sphere's gap at the step's start [m]; negative: penetration
    float restitution = -1.0f, friction = -1.0f;  // the surface's own material (negative: none)
    bool acting = false;
    double target = 0.0;     // the normal velocity the solver aims at [m/s]
    double normalImpulse = 0.0;
    DVec3 frictionImpulse{0.0};
    double e = 0.0, mu = 0.0;
    double approach = 0.0;   // normal speed towards the surface before the solve [m/s]
    bool bounce = false;
};

class EngineRun {
public:
    EngineRun(const ProjectileSettings& settings, const CollisionWorld& world, TrajectoryRecorder& recorder,
              ProjectileResult& result)
        : mSettings(settings), mProfile(settings.engine), mWorld(world), mRecorder(recorder), mResult(result),
          mRec(engineRecurrence(settings.engine)) {
        mGravity = DVec3(decimalValue(settings.gravity.x), decimalValue(settings.gravity.y),
                         decimalValue(settings.gravity.z));
        if (mProfile.planar) mGravity.z = 0.0;
        mRadius = settings.radius;
        mRotates = mProfile.rotates && mRadius > 0.0;
        mAngularFactor = dampingFactor(mProfile.damping, mProfile.angularDamping, mRec.dt);
    }

    Status run(const DVec3& start, const DVec3& startVelocity, std::uint64_t steps) {
        mPosition = start;
        mVelocity = startVelocity;
        if (mProfile.planar) mVelocity.z = 0.0;
        mRecorder.add(0.0, TrajectoryEvent::Start, mPosition, mVelocity);
        for (std::uint64_t k = 1; k <= steps; ++k) {
            const bool bounced = step(k == 1);
            const double t = static_cast<double>(k) * mRec.dt;
            if (bounced && mResult.bounces > mSettings.maxBounces) {
                --mResult.bounces;
                mResult.stoppedAtHit = true;
                mResult.time = static_cast<float>(t);
                mResult.hitNormal = toF(mLastNormal);
                mRecorder.add(t, TrajectoryEvent::Hit, mPosition, mVelocity, mLastNormal);
                mResult.position = toR(mPosition);
                mResult.velocity = toF(mVelocity);
                return Status::Ok;
            }
            if (!isFinite(mPosition) || !isFinite(mVelocity)) return Status::NonFiniteResult;
            TrajectoryEvent event = bounced ? TrajectoryEvent::Bounce : TrajectoryEvent::Step;
            if (k == steps) event = TrajectoryEvent::End;
            mRecorder.add(t, event, mPosition, mVelocity, bounced ? mLastNormal : DVec3(0.0));
        }
        mResult.position = toR(mPosition);
        mResult.velocity = toF(mVelocity);
        mResult.time = static_cast<float>(static_cast<double>(steps) * mRec.dt);
        mResult.atRest = mTouching && glm::length(mVelocity) < 0.01;
        if (mResult.bounces > 0) mResult.hitNormal = toF(mLastNormal);
        return Status::Ok;
    }

private:
    // One engine step; returns true when a contact stopped or reversed a real approach.
    bool step(bool first) {
        const double dt = mRec.dt;
        const DVec3 v0 = mVelocity;
        DVec3 v, freeMotion;
        if (first && mProfile.firstStep != FirstStepRule::Normal) {
            v = mProfile.firstStep == FirstStepRule::DampingOnly ? v0 * mRec.d : v0;
            freeMotion = v * dt;
        } else {
            v = mRec.d * v0 + mRec.b * dt * mGravity;
            freeMotion = mRec.a * dt * v0 + mRec.cg * dt * dt * mGravity;
        }
        mAngular *= mAngularFactor;
        const double speed = glm::length(v);
        if (speed > mProfile.maxLinearSpeed) {
            v *= mProfile.maxLinearSpeed / speed;
            freeMotion = v * dt;
        }

        findSurfaces(freeMotion, v);
        const bool acted = solve(v0, v);
        mVelocity = v;

        // Box2D's translation limit acts on the solved velocity.
        const double travel = glm::length(mVelocity) * dt;
        if (travel > mProfile.maxStepDistance) {
            mVelocity *= mProfile.maxStepDistance / travel;
            freeMotion = mVelocity * dt;
        }
        const DVec3 before = mPosition;
        mPosition += acted ? mVelocity * dt : freeMotion;
        if (mProfile.planar) mPosition.z = before.z;
        correctPositions(before);

        bool bounced = false;
        mTouching = false;
        for (int i = 0; i < mCount; ++i) {
            const Surface& s = mSurfaces[i];
            if (!s.acting || s.normalImpulse <= 0.0) continue;
            mTouching = true;
            // A real impact, not resting contact: faster than twice what gravity adds in a step.
            const double resting = 2.0 * std::abs(glm::dot(mGravity, s.normal)) * dt + 1e-3;
            if (s.approach > resting) {
                bounced = true;
                mLastNormal = s.normal;
            }
        }
        if (bounced) ++mResult.bounces;
        return bounced;
    }

    // Probes the surfaces already known, and casts the step's free motion for new ones.
    void findSurfaces(const DVec3& freeMotion, const DVec3& velocity) {
        const double reach = std::max<double>(mProfile.contactDistance, 0.0);
        int kept = 0;
        for (int i = 0; i < mCount; ++i) {
            Surface s = mSurfaces[i];
            // Probe from outside the surface, along its normal.
            const double gapNow = glm::dot(mPosition - s.touch, s.normal);
            if (gapNow > reach + glm::length(freeMotion) + 0.05) continue;  // far: forget it
            const double lift = std::max(0.0, -gapNow) + 0.01;
            const DVec3 from = mPosition + s.normal * lift;
            const DVec3 to = mPosition - s.normal * (reach + 0.01 + std::max(0.0, -glm::dot(freeMotion, s.normal)));
            CastHit hit;
            if (!cast(from, to, hit)) continue;
            s.normal = glm::normalize(toD(hit.normal));
            s.touch = toD(hit.position);
            s.gap = glm::dot(mPosition - s.touch, s.normal);
            s.restitution = hit.restitution;
            s.friction = hit.friction;
            mSurfaces[kept++] = s;
        }
        mCount = kept;

        const double length = glm::length(freeMotion);
        const DVec3 direction = length > 0.0 ? freeMotion / length : glm::normalize(velocity + DVec3(0, 0, 0));
        if (length > 0.0) {
            const DVec3 to = mPosition + direction * (length + reach);
            CastHit hit;
            if (cast(mPosition, to, hit)) addSurface(hit);
        }
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            s.acting = mProfile.contact == ContactMethod::Speculative ? s.gap < reach : s.gap < 0.0;
        }
    }

    void addSurface(const CastHit& hit) {
        const DVec3 n = glm::normalize(toD(hit.normal));
        const DVec3 touch = toD(hit.position);
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (glm::dot(s.normal, n) > 0.999 && std::abs(glm::dot(touch - s.touch, n)) < 1e-4) return;
        }
        if (mCount == kMaxSurfaces) return;
        Surface& s = mSurfaces[mCount++];
        s = Surface{};
        s.normal = n;
        s.touch = touch;
        s.gap = glm::dot(mPosition - touch, n);
        s.restitution = hit.restitution;
        s.friction = hit.friction;
    }

    bool cast(const DVec3& from, const DVec3& to, CastHit& hit) const {
        SegmentCast c;
        c.origin = toR(from);
        c.displacement = toF(to - toD(c.origin));
        c.radius = static_cast<float>(mRadius);
        return mWorld.castSegment(c, hit);
    }

    // The contact solve; returns true when any contact applied an impulse.
    bool solve(const DVec3& v0, DVec3& v) {
        const double dt = mRec.dt;
        bool any = false;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            s.normalImpulse = 0.0;
            s.frictionImpulse = DVec3(0.0);
            s.bounce = false;
            if (!s.acting) continue;
            any = true;
            s.e = s.restitution >= 0.0f
                      ? combineMaterial(mProfile.restitutionCombine, mSettings.restitution, s.restitution)
                      : mSettings.restitution;
            s.mu = s.friction >= 0.0f ? combineMaterial(mProfile.frictionCombine, mSettings.friction, s.friction)
                                      : mSettings.friction;
            const double vn = glm::dot(v, s.normal);
            s.approach = -vn;
            const double base = mProfile.restitutionBase == RestitutionBase::StepStart ? glm::dot(v0, s.normal) : vn;
            const double speculative = std::max(0.0, s.gap / dt);
            const bool reaches = s.gap <= 0.0 || vn < -speculative;
            s.bounce = s.e > 0.0 && -base > mProfile.restitutionThreshold && reaches;
            s.target = s.bounce ? -s.e * base : -speculative;
            if (mProfile.correctionIsVelocity) {
                const double depth = -s.gap - mProfile.penetrationSlop;
                if (depth > 0.0) s.target += mProfile.positionCorrection * depth / dt;
            }
        }
        if (!any) return false;
        const double tangentialMass = mRotates ? 1.0 / 3.5 : 1.0;
        for (int iteration = 0; iteration < kSolverIterations; ++iteration) {
            for (int i = 0; i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                // Friction first, bounded by the normal impulse so far (as Jolt and Box2D order it).
                const DVec3 arm = -mRadius * s.normal;
                DVec3 slip = v + glm::cross(mAngular, arm);
                slip -= glm::dot(slip, s.normal) * s.normal;
                DVec3 total = s.frictionImpulse - slip * tangentialMass;
                const double limit = s.mu * s.normalImpulse;
                const double size = glm::length(total);
                if (size > limit) total *= size > 0.0 ? limit / size : 0.0;
                applyTangential(total - s.frictionImpulse, s.normal, v);
                s.frictionImpulse = total;
                // Normal row.
                const double vn = glm::dot(v, s.normal);
                const double accumulated = std::max(0.0, s.normalImpulse + (s.target - vn));
                v += (accumulated - s.normalImpulse) * s.normal;
                s.normalImpulse = accumulated;
            }
        }
        return true;
    }

    void applyTangential(const DVec3& impulse, const DVec3& normal, DVec3& v) {
        v += impulse;
        if (mRotates) mAngular += -(2.5 / mRadius) * glm::cross(normal, impulse);
    }

    // Position-based correction (Jolt, Box2D, Rapier): out of each surface by a fraction of the
    // depth beyond the slop.
    void correctPositions(const DVec3& before) {
        (void)before;
        if (mProfile.correctionIsVelocity || mProfile.positionCorrection <= 0.0f) return;
        for (int i = 0; i < mCount; ++i) {
            const Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            const double gap = glm::dot(mPosition - s.touch, s.normal);
            const double depth = -gap - mProfile.penetrationSlop;
            if (depth > 0.0) mPosition += s.normal * (mProfile.positionCorrection * depth);
        }
    }

    const ProjectileSettings& mSettings;
    const EngineProfile& mProfile;
    const CollisionWorld& mWorld;
    TrajectoryRecorder& mRecorder;
    ProjectileResult& mResult;
    EngineRecurrence mRec;
    DVec3 mGravity{0.0};
    double mRadius = 0.0;
    bool mRotates = false;
    double mAngularFactor = 1.0;
    DVec3 mPosition{0.0}, mVelocity{0.0}, mAngular{0.0};
    std::array<Surface, kMaxSurfaces> mSurfaces{};
    int mCount = 0;
    bool mTouching = false;
    DVec3 mLastNormal{0.0};
};

}  // namespace

Status runEngineProjectile(const DVec3& position, const DVec3& velocity, std::uint64_t steps,
                           const ProjectileSettings& settings, const CollisionWorld& world,
                           TrajectoryRecorder& recorder, ProjectileResult& result) {
    EngineRun run(settings, world, recorder, result);
    return run.run(position, velocity, steps);
}

}  // namespace detail
FORESIGHT_NAMESPACE_END
