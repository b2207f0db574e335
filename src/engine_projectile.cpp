// ProjectileMethod::Engine: a sphere stepped as a rigid-body engine steps it (engine_profile.h).
//
// One step, for every profile (the engines differ in the values, see engineProfile()):
//  1. velocity: gravity and damping in the profile's order (or its first-step rule); angular
//     damping; the engine's speed limit.
//  2. contacts at the start of the step: surfaces the sphere touched or approached before are
//     probed again along their normal; one cast along the step's free motion (lengthened by the
//     contact distance) finds new ones. The gap `s` to each (negative: penetration) decides
//     whether it acts: within contactDistance (speculative) or below 0 (penetration). Bullet
//     against a triangle mesh (EngineProfile::triangleMesh) has its own rules: meshContact().
//  3. velocity solve: sequential impulses with accumulated clamping, as the engines do; for one
//     contact this is the closed form. Normal target: a bounce (approach faster than the
//     threshold, and, for a speculative contact, reaching the surface within the step) leaves
//     with e times the restitution base's approach speed; otherwise the sphere may close the gap
//     (s / dt) and no more. A velocity correction adds `fraction * depth / dt`. Friction acts at
//     the contact point of a spinning solid sphere: tangential effective mass m / 3.5, clamped to
//     the friction cone of the normal impulse.
//  4. position: the step's free motion when nothing acted (the profile's recurrence, sub-steps
//     included); otherwise `p += v dt`. A position correction then moves the sphere out by
//     `fraction * (depth - slop)`. Rapier then sweeps a fast sphere (its continuous collision).

#include "bullet_gjk.h"
#include "bullet_pairs.h"
#include "engine_internal.h"
#include "local_world.h"
#include "path_capsule.h"

#include <foresight/projectile.h>
#include <foresight/static_world.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {
namespace {

// Surfaces followed at once (a sphere in a corner touches three).
constexpr int kMaxSurfaces = 6;
// Free-flight steps cleared by one world query at most (EngineRun::coast).
constexpr std::uint64_t kMaxCoastSteps = 64;
// How far beyond one step's queries the shapes gathered around a sphere in contact reach
// (EngineRun::nearWorld) [m]: the sphere takes several steps before they must be gathered again.
constexpr double kGatherMargin = 0.25;
// Velocity iterations of the contact solver (several contacts converge; one is exact at once).
constexpr int kSolverIterations = 10;
// PhysX position iterations that carry no friction (measured against the Cocos build).
constexpr int kPhysXFrictionSkip = 0;
// Points of one Bullet contact manifold (btPersistentManifold's cache).
constexpr int kManifoldPoints = 4;
// Two probes' normals agree when their dot product is above 1 minus this: a float cast's
// rounding of the normal (the Bullet profiles' closest points).
constexpr double kNormalSettle = 1e-8;
// Probes of EngineRun::closestPoint at most. Each shrinks the normal's error by about
// |gap| / (r + rounding): a sphere half its radius deep in a rounded edge needs a dozen (4 left
// the normal 1 degree off the closest points' in such a bounce).
constexpr int kClosestPointIterations = 16;
// Bullet's warm-starting factor (btContactSolverInfo::m_warmstartingFactor) for normal impulses.
constexpr double kBulletWarmStart = 0.85;
// Bullet's GJK stops when its separating axis gets shorter than this: sqrt(REL_ERROR2) [m].
constexpr double kBulletTooClose = 1e-3;

// Bullet 2.83 (ammo.js): one point of a shape's contact manifold. The point stays fixed on the
// static shape and on the sphere's material (its arm turns with the body); it carries its own
// impulses from step to step.
struct ManifoldPoint {
    DVec3 arm{0.0};                             // from the centre to the point on the sphere, turned with the body
    DVec3 onSurface{0.0};                       // the point on the static shape
    DVec3 normal{0.0};                          // the normal it was found with
    double distance = 0.0;                      // along the normal, as of the last refresh [m]; negative: penetration
    double normalImpulse = 0.0, lateral = 0.0;  // the last solve's accumulated impulses (per unit mass)
    DVec3 tangentImpulse{0.0};                  // GodotPhysics: the accumulated friction impulse
    // This step's solve.
    DVec3 direction{0.0};  // the friction direction
    double target = 0.0, normalMass = 1.0, frictionMass = 1.0;
};

struct Surface {
    DVec3 normal{0.0};                            // unit, towards the sphere
    DVec3 touch{0.0};                             // the sphere's centre where it touches the surface
    double gap = 0.0;                             // the sphere's gap at the step's start [m]; negative: penetration
    float restitution = -1.0f, friction = -1.0f;  // the surface's own material (negative: none)
    bool acting = false;
    double target = 0.0;  // the normal velocity the solver aims at [m/s]
    double normalImpulse = 0.0;
    DVec3 frictionImpulse{0.0};
    DVec3 tangent{0.0};  // PhysX: this step's first friction direction; Bullet 3: its only one
    double e = 0.0, mu = 0.0;
    double approach = 0.0;  // normal speed towards the surface before the solve [m/s]
    bool bounce = false;
    bool carried = false;     // applied an impulse in the previous step (Rapier: no new bounce)
    bool predictive = false;  // Godot 3 with Bullet: a continuous-collision contact at the centre, this step only
    bool settled = false;     // this step's probe along the normal from the centre found the same normal
    bool closest = false;     // this step's closest-point query (findNear) measured it
    double warmNormal = 0.0;  // Rapier: the last sub-step's impulses, warm-starting the next
    int color = -1;           // Rapier: the solver colour of the contact (solved lowest first)
    DVec3 warmFriction{0.0};
    // Triangle meshes (Bullet): the manifold point of this surface.
    bool persists = false;   // acted in the previous step: its point may still be in the manifold
    bool reversed = false;   // the triangle's back face acts: normal and gap are reversed this step
    bool fresh = false;      // the narrow phase found the triangle at this step's start
    double pointGap = 0.0;   // the point's gap when it was found [m]
    DVec3 pointMotion{0.0};  // how far the sphere's material point moved since [m]
    double pointDistance = 0.0, pointSlip = 0.0;  // its distance along and across the normal now [m]
    // Bullet up to 2.88 (EngineProfile::frictionWarmStart) against a triangle mesh: the friction
    // impulse along this step's friction direction, which the next step's solve starts from.
    double lateral = 0.0;
    DVec3 lateralDir{0.0};
    DVec3 lateralArm{0.0};     // the manifold point on the sphere at the next step's start, from the centre
    DVec3 lateralCentre{0.0};  // the centre when the point was found
    // Bullet 2.83 (ammo.js, see EngineRun::updateManifold): the shape's manifold points.
    std::array<ManifoldPoint, kManifoldPoints> points{};
    int pointCount = 0;
    // The Bullet profiles: this step's contact as Bullet's float GJK measured it
    // (EngineRun::measureAsBullet), or its point on the sphere only, next to the box shrunk by its
    // margin (EngineRun::narrowPhaseInsideBoxes).
    bool floatContact = false;
    int floatBox = -1;          // the gathered box (LocalWorld::boxes()) whose contact it is
    DVec3 floatArm{0.0};        // from the centre to the contact point on the sphere [m]
    DVec3 floatOnSurface{0.0};  // the contact point on the box [m]
};

// A surface's normal and the centre where the sphere touches it (what Surface says of its place).
struct SurfacePlace {
    DVec3 normal, touch;
};

class EngineRun {
public:
    EngineRun(const ProjectileSettings& settings, const CollisionWorld& world, TrajectoryRecorder& recorder,
              ProjectileResult& result)
        : mSettings(settings), mProfile(settings.engine), mFullWorld(&world), mWorld(&world), mRecorder(recorder),
          mResult(result), mRec(engineRecurrence(settings.engine)) {
        mGravity =
            DVec3(decimalValue(settings.gravity.x), decimalValue(settings.gravity.y), decimalValue(settings.gravity.z));
        if (mProfile.planar) mGravity.z = 0.0;
        mRadius = settings.radius;
        mRotates = mProfile.rotates && mRadius > 0.0;
        mAngularFactor = dampingFactor(mProfile.damping, mProfile.angularDamping, mRec.dt);
        mMeshContacts = mProfile.triangleMesh && mProfile.engine == PhysicsEngine::Bullet;
        // A world whose region queries are worth nothing (CallbackWorld) is never asked them.
        mRegionQueries = std::isfinite(world.regionQueryCost(static_cast<float>(mRadius)));
        // Bullet (2.83 in ammo.js, 3.24 native) and Godot 3's Bullet 2.89 keep several points
        // per manifold, each with its normal impulse warm-started (and its friction impulse, by
        // frictionWarmStart: ammo.js's). Against a triangle mesh, one point per surface.
        mManifold = (mProfile.engine == PhysicsEngine::Bullet && !mMeshContacts) ||
                    mProfile.engine == PhysicsEngine::Godot3Bullet;
        // GodotPhysics keeps up to four contacts per shape, each with its impulses.
        mGodotContacts = mProfile.engine == PhysicsEngine::Godot3;
        // The Bullet profiles' solve order follows Bullet's pairs where the world lists its shapes.
        mTrackPairs = mManifold && mRadius > 0.0 && mRegionQueries;
    }

    Status run(const DVec3& start, const DVec3& startVelocity, std::uint64_t steps) {
        mPosition = start;
        mVelocity = startVelocity;
        if (mProfile.planar) mVelocity.z = 0.0;
        startFloatFlight();
        if (mTrackPairs) mPairs.start(*mFullWorld, mPosition, mRadius);
        mRecorder.add(0.0, TrajectoryEvent::Start, mPosition, mVelocity);
        for (std::uint64_t k = 1; k <= steps; ++k) {
            if (const std::uint64_t taken = coast(k, steps); taken > 0) {
                k += taken - 1;
                if (!isFinite(mPosition) || !isFinite(mVelocity)) return Status::NonFiniteResult;
                continue;
            }
            StepOutcome outcome = StepOutcome::Next;
            if (const std::uint64_t taken = contactCoast(k, steps, outcome); taken > 0) {
                k += taken - 1;
                if (outcome == StepOutcome::Stopped) return Status::Ok;
                continue;
            }
            outcome = advance(k, steps);
            if (outcome == StepOutcome::Stopped) return Status::Ok;
            if (outcome == StepOutcome::NonFinite) return Status::NonFiniteResult;
        }
        mResult.position = toR(mPosition);
        mResult.velocity = toF(mVelocity);
        mResult.time = static_cast<float>(static_cast<double>(steps) * mRec.dt);
        mResult.atRest = mTouching && glm::length(mVelocity) < 0.01;
        if (mResult.bounces > 0) mResult.hitNormal = toF(mLastNormal);
        return Status::Ok;
    }

private:
    enum class StepOutcome { Next, Stopped, NonFinite };

    // Step k of `steps`, recorded: Stopped when it was the impact that maxBounces stops at (the
    // result is then complete), NonFinite when the state overflowed.
    StepOutcome advance(std::uint64_t k, std::uint64_t steps) {
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
            return StepOutcome::Stopped;
        }
        if (!isFinite(mPosition) || !isFinite(mVelocity)) return StepOutcome::NonFinite;
        // A step in which a contact changed the velocity is a bounce point, with the normal
        // of the contact that pushed hardest (resting and rolling steps too).
        TrajectoryEvent event = mTouching ? TrajectoryEvent::Bounce : TrajectoryEvent::Step;
        if (k == steps) event = TrajectoryEvent::End;
        mRecorder.add(t, event, mPosition, mVelocity, mTouching ? mContactNormal : DVec3(0.0));
        return StepOutcome::Next;
    }

    // What a step changes (contactCoast takes steps on trial and may have to undo them).
    struct Snapshot {
        DVec3 position, velocity, angular, pushVelocity, substepPosition, lastNormal, contactNormal;
        std::array<Surface, kMaxSurfaces> surfaces;
        int count;
        bool touching;
        ProjectileResult result;
        std::size_t recorderSize, recorderNeeded;
        double recorderReach;
        BulletPairs::State pairs;
    };
    Snapshot save() const {
        return Snapshot{mPosition,   mVelocity,      mAngular,         mPushVelocity,   mSubstepPosition,
                        mLastNormal, mContactNormal, mSurfaces,        mCount,          mTouching,
                        mResult,     mRecorder.size, mRecorder.needed, mRecorder.reach, mPairs.state()};
    }
    void restore(const Snapshot& s) {
        mPosition = s.position;
        mVelocity = s.velocity;
        mAngular = s.angular;
        mPushVelocity = s.pushVelocity;
        mSubstepPosition = s.substepPosition;
        mLastNormal = s.lastNormal;
        mContactNormal = s.contactNormal;
        mSurfaces = s.surfaces;
        mCount = s.count;
        mTouching = s.touching;
        mResult = s.result;
        mRecorder.size = s.recorderSize;
        mRecorder.needed = s.recorderNeeded;
        mRecorder.reach = s.recorderReach;
        mPairs.restore(s.pairs);
    }

    // Rolling, sliding or resting on one surface over several steps with one world query. While
    // the sphere touches only a plane, every query of a step stays within `extent` of its centre;
    // the steps are taken against a world that holds that plane alone, and kept when the world
    // promises (CollisionWorld::isOnlyPlane) that it is that plane and nothing else within the
    // capsule around their path: then each step's casts would have had the same answers. Else
    // they are undone and taken one by one. Returns the steps taken from step k on (0: none);
    // `outcome` is the last one's. The horizon doubles after a promise and halves after a refusal.
    std::uint64_t contactCoast(std::uint64_t k, std::uint64_t steps, StepOutcome& outcome) {
        if (!mRegionQueries || mCount != 1 || k == 1 || mRadius <= 0.0) return 0;
        const Surface& surface = mSurfaces[0];
        if (!surface.acting || surface.predictive || surface.reversed || !surface.carried) return 0;
        if (mContactWait > 0) {
            --mContactWait;
            return 0;
        }
        const std::uint64_t n = std::min<std::uint64_t>(mContactSteps, steps - k + 1);
        if (n < 2) return 0;
        PlaneRegion region;
        region.normal = toF(surface.normal);
        region.point = toR(surface.touch - surface.normal * mRadius);
        region.restitution = surface.restitution;
        region.friction = surface.friction;
        const DVec3 normal = toD(region.normal), point = toD(region.point);
        Plane plane;
        plane.normal = region.normal;
        plane.distance = static_cast<Real>(glm::dot(normal, point));
        const PlaneWorld planeWorld(plane, SurfaceMaterial{surface.restitution, surface.friction});

        // The largest sphere a step casts from the centre: Rapier's and Box2D's findNearby
        // casts one grown by the contact reach; it must stay clear of the plane too.
        const bool grown = mProfile.engine == PhysicsEngine::Rapier || mProfile.engine == PhysicsEngine::Box2D;
        const double clearance = mRadius + (grown ? contactReach() : 0.0);
        const auto sinking = [&](const DVec3& p) { return glm::dot(normal, p - point) < clearance; };
        if (sinking(mPosition)) return 0;  // see isOnlyPlane below

        const Snapshot before = save();
        const CollisionWorld* world = mWorld;
        mWorld = &planeWorld;
        mCoastPositions[0] = mPosition;
        std::size_t taken = 0;  // size_t: indexes mCoastPositions (32 bits on wasm32)
        double travel = 0.0;
        bool sunk = false;
        outcome = StepOutcome::Next;
        while (taken < n && outcome == StepOutcome::Next) {
            const DVec3 from = mPosition;
            outcome = advance(k + taken, steps);
            ++taken;
            mCoastPositions[taken] = mPosition;
            const double speed = std::max(glm::length(mVelocity), glm::length(mPosition - from) / mRec.dt);
            travel = std::max(travel, (speed + glm::length(mGravity) * mRec.dt) * mRec.dt);
            if (sinking(mPosition)) {
                sunk = true;
                break;  // refused below: no more steps wasted
            }
        }
        mWorld = world;

        // How far from the centre a step's queries reach: queryExtent.
        const std::span<const DVec3> path(mCoastPositions.data(), taken + 1);
        region.capsule = pathCapsule(path, queryExtent(travel));
        // isOnlyPlane promises the answers of casts that start clear of the plane: a sphere that
        // sinks into a floor of triangles meets their shared edges (and tilted normals there),
        // which the plane alone has not.
        const bool kept = outcome != StepOutcome::NonFinite && !sunk && mWorld->isOnlyPlane(region);
        if (!kept) {
            restore(before);
            mContactSteps = std::max<std::uint64_t>(mContactSteps / 2, 2);
            if (mContactSteps == 2) mContactWait = 4;  // near an edge or a wall: step a while
            return 0;
        }
        mContactSteps = std::min<std::uint64_t>(mContactSteps * 2, kMaxCoastSteps);
        return taken;
    }

    // One engine step; returns true when a contact stopped or reversed a real approach (an
    // impact: counted in `bounces`, and what maxBounces stops at).
    // The step's velocity and free motion before contacts (the profile's recurrence or its
    // first-step rule, then the speed limit).
    void freeStep(bool first, const DVec3& v0, DVec3& v, DVec3& freeMotion) const {
        const double dt = mRec.dt;
        if (first && mProfile.firstStep != FirstStepRule::Normal) {
            v = mProfile.firstStep == FirstStepRule::DampingOnly ? v0 * mRec.d : v0;
            freeMotion = v * dt;
        } else {
            v = mRec.d * v0 + mRec.b * dt * mGravity;
            freeMotion = mRec.a * dt * v0 + mRec.cg * dt * dt * mGravity;
        }
        const double speed = glm::length(v);
        if (speed > mProfile.maxLinearSpeed) {
            v *= mProfile.maxLinearSpeed / speed;
            freeMotion = v * dt;
        }
    }

    // Angular damping of one step, and Jolt's cap on the spin.
    void spinDown() {
        mAngular *= mAngularFactor;
        capSpin();
        if (mProfile.engine == PhysicsEngine::PhysX) {
            // PxRigidDynamic's default maximum angular velocity in PhysX 4: 100 rad/s.
            const double spin = glm::length(mAngular), maxSpin = 100.0;
            if (spin > maxSpin) mAngular *= maxSpin / spin;
        } else if (mProfile.engine == PhysicsEngine::Rapier) {
            // Rapier caps the spin in every sub-step at 45 degrees per step.
            const double spin = glm::length(mAngular), maxSpin = 0.25 * M_PI / mRec.dt;
            if (spin > maxSpin) mAngular *= maxSpin / spin;
        }
    }

    // Box2D 2.4's b2_maxRotation: a body turns at most a quarter turn in a step or a time-of-impact
    // sub-step of length h; b2Island scales the stored angular velocity down to that.
    void limitBox2DRotation(double h) {
        const double turn = glm::length(mAngular) * h, maxTurn = 0.5 * M_PI;
        if (turn > maxTurn) mAngular *= maxTurn / turn;
    }

    // Jolt's MotionProperties::mMaxAngularVelocity: 0.25 pi / (1/60 s) = 47.1 rad/s, applied
    // with the forces and again after the contact solve (JobIntegrateVelocity).
    void capSpin() {
        if (mProfile.engine != PhysicsEngine::Jolt) return;
        const double spin = glm::length(mAngular), maxSpin = 0.25 * M_PI * 60.0;
        if (spin > maxSpin) mAngular *= maxSpin / spin;
    }

    // Free flight over several steps with one world query. While no surface is known, step k's
    // only query is a cast of the sphere along its free motion, lengthened by the contact reach.
    // The next n positions (computed exactly as step() computes them) lie within `bend` of the
    // chord from the first to the last, so every one of those casts stays inside the capsule of
    // radius r + reach + bend around the chord: when the world says nothing touches that capsule,
    // the n steps are free flight, taken here without casts, with the same arithmetic and so the
    // same numbers as step by step. Where the world says how far along the capsule nothing
    // touches it (CollisionWorld::firstTouch), the steps whose chords lie wholly before that are
    // taken so. Returns the steps taken from step k on (0: step k must be stepped). The horizon
    // doubles after a clear capsule and halves after a touched one; next to a surface each step
    // asks again (a refused query costs a fraction of the step it could have saved).
    std::uint64_t coast(std::uint64_t k, std::uint64_t steps) {
        if (!mRegionQueries || mCount > 0 || (k == 1 && mProfile.firstStep != FirstStepRule::Normal)) return 0;
        // size_t: indexes mCoastPositions (32 bits on wasm32); at most kMaxCoastSteps.
        const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(mCoastSteps, steps - k + 1));
        if (n < 2) return 0;
        const double dt = mRec.dt;
        DVec3 position = mPosition, velocity = mVelocity;
        mCoastPositions[0] = position;
        for (std::size_t j = 1; j <= n; ++j) {
            DVec3 v, freeMotion;
            freeStep(false, velocity, v, freeMotion);
            if (glm::length(v) * dt > mProfile.maxStepDistance) return 0;  // Box2D's limit acts
            velocity = v;
            position += freeMotion;
            if (mProfile.planar) position.z = mPosition.z;
            mCoastPositions[j] = position;
            mCoastVelocities[j] = velocity;
        }
        const std::span<const DVec3> path(mCoastPositions.data(), n + 1);
        const SegmentCast capsule = pathCapsule(path, mRadius + contactReach());
        float fraction = 1.0f;
        const std::size_t clear = mWorld->firstTouch(capsule, fraction) ? clearChords(path, fraction) : n;
        if (clear < n)
            mCoastSteps = std::max<std::uint64_t>(mCoastSteps / 2, 2);
        else
            mCoastSteps = std::min<std::uint64_t>(mCoastSteps * 2, kMaxCoastSteps);
        if (clear == 0) return 0;
        for (std::size_t j = 1; j <= clear; ++j) {
            if (mTrackPairs) mPairs.step(mPosition, mPosition + mVelocity * (mRec.d * dt), false);
            spinDown();
            // No contact acts in free flight: Box2D's limit after the solve applies to the spin
            // as it is (a time of impact may have left it above the limit of a whole step).
            if (mProfile.engine == PhysicsEngine::Box2D) limitBox2DRotation(dt);
            mPosition = mCoastPositions[j];
            mVelocity = mCoastVelocities[j];
            advanceFloatFlight(false);
            const double t = static_cast<double>(k + j - 1) * dt;
            mRecorder.add(t, k + j - 1 == steps ? TrajectoryEvent::End : TrajectoryEvent::Step, mPosition, mVelocity);
        }
        mTouching = false;
        return clear;
    }

    // The world for the queries of the step from here: the shapes gathered around the sphere
    // (LocalWorld, which sends whatever reaches beyond them to the world), gathered again when a
    // step's queries could leave them; the world itself where it cannot gather (the answers are
    // the same either way: CollisionWorld::gatherShapes).
    const CollisionWorld* nearWorld() {
        if (mRadius <= 0.0 || mGatherFailures >= 3) return mFullWorld;
        const double dt = mRec.dt;
        const double extent = queryExtent((glm::length(mVelocity) + glm::length(mGravity) * dt) * dt);
        if (mLocal.holds(mPosition, mPosition, extent)) return &mLocal;
        SegmentCast region;
        region.origin = toR(mPosition);
        region.radius = static_cast<float>(extent + kGatherMargin);
        if (!mLocal.gather(*mFullWorld, region)) {
            ++mGatherFailures;
            return mFullWorld;
        }
        mGatherFailures = 0;
        return &mLocal;
    }

    // How far from the centre the queries of one step reach (findSurfaces and what it calls), for
    // a step's `travel` [m]: the probes along a surface's normal start 0.01 m off it and end the
    // contact reach and the step's travel into it; Jolt's axis probes reach 3 times the contact
    // reach; Rapier's and Box2D's closest-point probes start 0.05 m behind and reach r + reach +
    // 0.1 with a probe sphere as large. Twice the travel, and 0.01 m more.
    double queryExtent(double travel) const {
        const bool closest = mProfile.engine == PhysicsEngine::Rapier || mProfile.engine == PhysicsEngine::Box2D;
        const double reach = contactReach();
        return (closest ? 2.0 * mRadius + 2.0 * reach + 0.2 : mRadius + 3.0 * reach + 0.02) + 2.0 * travel + 0.01;
    }

    bool step(bool first) {
        // In contactCoast's trial steps the world is a plane already.
        const CollisionWorld* const world = mWorld;
        if (mWorld == mFullWorld) mWorld = nearWorld();
        const bool bounced = stepIn(first);
        mWorld = world;
        return bounced;
    }

    // Bullet 3.24 (and Godot 3's Bullet 2.89) steps the body in float. While the prediction's
    // steps are free flight (no contact has acted), the same float operations give Bullet's own
    // position to the bit, on which the rounding of its narrow phase depends (bullet_gjk.h):
    // btRigidBody::applyDamping (v times (1 - c)^dt), the solver's gravity impulse (g dt: the
    // total force times the inverse mass is g exactly for a body of mass 1, as in the engine
    // oracle) and btTransformUtil::integrateTransform (p + v dt).
    void startFloatFlight() {
        // Bullet 3.24 damps with btPow; Godot 3's Bullet 2.89 is built with its old damping method.
        // ammo.js (Bullet 2.83, frictionWarmStart) is asm.js that computes Bullet's float
        // expressions in JavaScript doubles and rounds them only where it stores them: its rounding
        // is not float's, and is not followed.
        const bool native = mProfile.engine == PhysicsEngine::Bullet && !mMeshContacts &&
                            mProfile.damping == DampingLaw::Power && mProfile.firstStep == FirstStepRule::Normal;
        const bool godot = mProfile.engine == PhysicsEngine::Godot3Bullet &&
                           mProfile.damping == DampingLaw::LinearClamped &&
                           mProfile.firstStep == FirstStepRule::DampingOnly;
        // Both are Bullet 2.89 or later, which warm-starts no friction (frictionWarmStart 0).
        mFloatFlight = (native || godot) && mProfile.frictionWarmStart == 0.0f && mRadius > 0.0 && !mProfile.planar &&
                       mProfile.substeps == 1 && mProfile.order == DampingOrder::DampingThenGravity;
        if (!mFloatFlight) return;
        const float dt = mProfile.timestep;
        const float c = std::clamp(mProfile.linearDamping + mProfile.addedLinearDamping, 0.0f, 1.0f);
        mFloatDamping = native ? std::pow(1.0f - c, dt) : std::max(1.0f - dt * c, 0.0f);
        mFloatFirstStep = godot;  // Godot's first step: no gravity
        mFloatGravityStep =
            detail::BulletVec{mSettings.gravity.x * dt, mSettings.gravity.y * dt, mSettings.gravity.z * dt};
        mFloatPosition = detail::BulletVec{static_cast<float>(mPosition.x), static_cast<float>(mPosition.y),
                                           static_cast<float>(mPosition.z)};
        mFloatVelocity = detail::BulletVec{static_cast<float>(mVelocity.x), static_cast<float>(mVelocity.y),
                                           static_cast<float>(mVelocity.z)};
    }
    void advanceFloatFlight(bool acted) {
        if (!mFloatFlight) return;
        if (acted) {
            mFloatFlight = false;  // Bullet's float solve is not followed
            return;
        }
        const float dt = mProfile.timestep;
        detail::BulletVec& v = mFloatVelocity;
        v = detail::BulletVec{v.x * mFloatDamping, v.y * mFloatDamping, v.z * mFloatDamping};
        if (!mFloatFirstStep)
            v = detail::BulletVec{v.x + mFloatGravityStep.x, v.y + mFloatGravityStep.y, v.z + mFloatGravityStep.z};
        mFloatFirstStep = false;
        detail::BulletVec& p = mFloatPosition;
        p = detail::BulletVec{p.x + v.x * dt, p.y + v.y * dt, p.z + v.z * dt};
        // The double prediction and the float one agree to rounding; anything else (a profile
        // field this does not follow) ends the float flight.
        const DVec3 gap = DVec3(p.x, p.y, p.z) - mPosition;
        const double tolerance = 1e-4 + 1e-5 * glm::length(mPosition);
        if (!(std::abs(gap.x) <= tolerance && std::abs(gap.y) <= tolerance && std::abs(gap.z) <= tolerance))
            mFloatFlight = false;
    }

    // Bullet meets a sphere and a box with GJK (bullet_gjk.h), whose float rounding over a
    // large box (a floor 30 m wide) tilts the normal by up to 1e-4 rad and moves the contact point
    // off the sphere's axis. While the float flight is Bullet's own, each known surface that is a
    // gathered box gets the contact Bullet's GJK finds for it: its normal, distance and points.
    void measureAsBullet() {
        for (int i = 0; i < mCount; ++i) mSurfaces[i].floatContact = false;
        if (!mFloatFlight || mWorld != &mLocal || mCount == 0) return;
        const auto radius = static_cast<float>(mRadius);
        const std::span<const OrientedBox> boxes = mLocal.boxes();
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            const detail::BulletBox box = bulletBoxOf(boxes[k]);
            const detail::BulletGjkContact c = detail::bulletBoxSphereGjk(
                box, mFloatPosition, radius, detail::bulletContactDistanceSquared(box, radius), true);
            if (!c.handled || !c.found) continue;
            const DVec3 normal = -DVec3(c.normalOnB.x, c.normalOnB.y, c.normalOnB.z);
            const double gap = c.distance;
            for (int i = 0; i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                if (s.predictive || glm::dot(s.normal, normal) < 0.99 || std::abs(s.gap - gap) > 1e-3) continue;
                const DVec3 centre(mFloatPosition.x, mFloatPosition.y, mFloatPosition.z);
                const DVec3 onSphere(c.pointOnB.x, c.pointOnB.y, c.pointOnB.z);
                const detail::BulletVec a{c.pointOnB.x + c.normalOnB.x * c.distance,
                                          c.pointOnB.y + c.normalOnB.y * c.distance,
                                          c.pointOnB.z + c.normalOnB.z * c.distance};  // btManifoldResult's point on A
                s.normal = normal;
                s.gap = gap;
                s.touch = mPosition - normal * gap;
                s.floatContact = true;
                s.floatBox = static_cast<int>(k);
                s.floatArm = onSphere - centre;
                s.floatOnSurface = DVec3(a.x, a.y, a.z);
                break;
            }
        }
    }

    // Where the sphere's centre lies against each gathered box, the engines' narrow phases answer
    // otherwise than the closest points the casts measure:
    // - Jolt, PhysX and GodotPhysics, the centre inside the box shrunk by its rounding (Jolt's
    //   convex radius; PhysX's and Godot's boxes are sharp): their penetration tests measure the
    //   overlap along the face nearest the centre (pushOutNearestFace). Box2D (planar) is left
    //   out: its time of impact stops the ball first.
    // - Bullet: its own narrow phase, ported (bulletPenetration).
    // Boxes measureAsBullet measured keep that.
    void narrowPhaseInsideBoxes(bool bullet) {
        if (mCount == 0 || mWorld != &mLocal) return;
        const std::span<const OrientedBox> boxes = mLocal.boxes();
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const OrientedBox& b = boxes[i];
            if (bullet) {
                const detail::BulletBox box = bulletBoxOf(b);
                const auto margin = static_cast<double>(box.margin);
                const double outside = centreOutside(b, margin);
                bulletPenetration(static_cast<int>(i), b, box, mLocal.boxMaterial(i), !(outside < kBulletTooClose),
                                  outside < margin + mRadius);
                continue;
            }
            if (centreOutside(b, static_cast<double>(b.rounding)) == 0.0) pushOutNearestFace(b);
        }
    }

    // GodotPhysics makes one contact per shape where the step starts (BodyPairSW::setup), along
    // its separating-axis test's axis of least overlap: with the centre outside a box, the
    // closest points' normal. A known surface probed again along its old normal can report
    // another face of the same box far deeper: a ball that flew past a box's -x face and then
    // overlapped the edge between its top and its -z face 5 cm deep was given the plane of the
    // corner it had passed 14 to 18 cm deep, and pushed back across the box, where Godot pushed
    // it off the edge. Of two surfaces on the same box (their contact points on its faces) the
    // deeper is dropped, when it holds no stored contacts and the centre is outside the box
    // (inside, the nearest face decides: narrowPhaseInsideBoxes).
    void oneContactPerBox() {
        if (mWorld != &mLocal || mCount < 2) return;
        const std::span<const OrientedBox> boxes = mLocal.boxes();
        // The box whose boundary holds the surface's contact point (within 0.1 mm) with its normal
        // pointing out of the box there (no part along an axis the point is inside of): a face's
        // normal, or one between the faces at an edge or a corner; -1 for none.
        const auto boxOf = [&](const Surface& s) {
            const DVec3 point = s.touch - s.normal * mRadius;
            for (std::size_t k = 0; k < boxes.size(); ++k) {
                const OrientedBox& b = boxes[k];
                const glm::dquat toLocal =
                    glm::conjugate(glm::dquat(b.orientation.w, b.orientation.x, b.orientation.y, b.orientation.z));
                const DVec3 local = toLocal * (point - DVec3(b.center)), n = toLocal * s.normal;
                const DVec3 over = glm::abs(local) - DVec3(b.halfExtents);
                bool on = glm::length(glm::max(over, 0.0)) <= 1e-4 && std::max({over.x, over.y, over.z}) >= -1e-4;
                for (int axis = 0; axis < 3 && on; ++axis)
                    on = over[axis] >= -1e-4 ? n[axis] * local[axis] >= -1e-3 * std::abs(local[axis])
                                             : std::abs(n[axis]) <= 1e-3;
                if (on && centreOutside(b, static_cast<double>(b.rounding)) > 0.0) return static_cast<int>(k);
            }
            return -1;
        };
        std::array<int, kMaxSurfaces> box{};
        for (int i = 0; i < mCount; ++i) box[static_cast<std::size_t>(i)] = boxOf(mSurfaces[i]);
        std::array<bool, kMaxSurfaces> drop{};
        for (int i = 0; i < mCount; ++i)
            for (int j = 0; j < mCount; ++j) {
                const Surface &a = mSurfaces[i], &b = mSurfaces[j];
                if (i != j && box[i] >= 0 && box[i] == box[j] && a.pointCount == 0 && a.gap < b.gap) drop[i] = true;
            }
        int kept = 0;
        for (int i = 0; i < mCount; ++i) {
            if (drop[static_cast<std::size_t>(i)]) continue;
            if (kept != i) mSurfaces[kept] = mSurfaces[i];
            ++kept;
        }
        mCount = kept;
    }

    // How far the sphere's centre lies outside box `b` shrunk by `shrink` [m]; 0 inside it.
    double centreOutside(const OrientedBox& b, double shrink) const {
        const glm::dquat q(b.orientation.w, b.orientation.x, b.orientation.y, b.orientation.z);
        const DVec3 local = glm::abs(glm::conjugate(q) * (mPosition - DVec3(b.center)));
        return glm::length(glm::max(local - (DVec3(b.halfExtents) - shrink), 0.0));
    }

    // The gap given to a surface whose box the sphere has passed (bulletPenetration) [m].
    static constexpr double kPassedThrough = 1.0;

    // Bullet's contact with box `b` (btGjkPairDetector, ported to the bit: bullet_gjk.h with
    // `epa`), from the centre as Bullet holds it (the float flight while it lasts, else rounded to
    // float), given to the surface of that box the casts found:
    // - where GJK hands the pair to its penetration depth solver (the centre inside the box shrunk
    //   by its margin, or within 1 mm of it: not `onlyWhereTheyDiffer`): always. EPA's point on
    //   the sphere's curved surface lies off the normal through the centre, by up to a hundredth
    //   of the radius, and GJK's "too close" exit puts it near the centre: the lever arm of the
    //   bounce, which sets the spin and so the friction's work;
    // - elsewhere, while the casts' surface penetrates: where Bullet's normal or depth differ from
    //   it (a fast ball that a step carried past the middle of a wall, or round its edge onto the
    //   next face: Bullet takes the face nearest the centre, and may see the ball leaving);
    // - a ball a step carried through the box: Bullet, which looks only where the step starts,
    //   has no contact; the surface is dropped (kPassedThrough);
    // - a box the ball penetrates (`penetrates`: its centre within the margin and the radius of the
    //   inner box) whose surface the casts did not find (they stopped at another surface first, a
    //   floor in front of a wall): Bullet's contact with it is added, with the box's `material`.
    void bulletPenetration(int index, const OrientedBox& b, const detail::BulletBox& box,
                           const SurfaceMaterial& material, bool onlyWhereTheyDiffer, bool penetrates) {
        const glm::dquat toLocal =
            glm::conjugate(glm::dquat(b.orientation.w, b.orientation.x, b.orientation.y, b.orientation.z));
        // The box shrunk by its margin, whose edges and corners the margin rounds.
        const auto margin = static_cast<double>(box.margin);
        const DVec3 inner = DVec3(b.halfExtents) - margin;
        Surface* found = nullptr;
        for (int i = 0; i < mCount && !found; ++i) {
            Surface& s = mSurfaces[i];
            if (s.predictive) continue;
            // Bullet's contact with this box already (measureAsBullet): nothing to do. With another
            // box: not this box's, wherever its point lies (boxes that meet or overlap).
            if (s.floatContact) {
                if (s.floatBox == index) return;
                continue;
            }
            // On that box's surface: the point the sphere touches lies a margin off the inner box.
            const DVec3 local = glm::abs(toLocal * (s.touch - s.normal * mRadius - DVec3(b.center)));
            const double out = glm::length(glm::max(local - inner, 0.0));
            const double room = std::min({inner.x - local.x, inner.y - local.y, inner.z - local.z});
            if (out > 0.0 ? std::abs(out - margin) <= 1e-3 : margin + room <= 1e-3) found = &s;
        }
        if (!found && (!penetrates || mCount == kMaxSurfaces)) return;
        if (found && onlyWhereTheyDiffer && found->gap >= 0.0) return;
        const detail::BulletVec centre =
            mFloatFlight ? mFloatPosition
                         : detail::BulletVec{static_cast<float>(mPosition.x), static_cast<float>(mPosition.y),
                                             static_cast<float>(mPosition.z)};
        const auto radius = static_cast<float>(mRadius);
        const detail::BulletGjkContact c = detail::bulletBoxSphereGjk(
            box, centre, radius, detail::bulletContactDistanceSquared(box, radius), true, true);
        if (!c.handled) return;
        if (!found) {
            if (!c.found || !(c.distance < 0.0f)) return;
            found = &mSurfaces[mCount++];
            *found = Surface{};
            found->restitution = material.restitution;
            found->friction = material.friction;
            onlyWhereTheyDiffer = false;
        }
        Surface& s = *found;
        if (!c.found) {
            if (s.gap >= 0.0) return;
            s.gap = kPassedThrough;
            s.touch = mPosition - s.normal * s.gap;
            return;
        }
        const DVec3 normal = -DVec3(c.normalOnB.x, c.normalOnB.y, c.normalOnB.z);
        if (onlyWhereTheyDiffer && glm::dot(normal, s.normal) >= 0.99 &&
            std::abs(s.gap - static_cast<double>(c.distance)) <= 1e-3)
            return;
        s.normal = normal;
        s.gap = c.distance;
        s.touch = mPosition - s.normal * s.gap;
        s.settled = false;
        s.floatContact = true;
        s.floatBox = index;
        s.floatArm = DVec3(c.pointOnB.x, c.pointOnB.y, c.pointOnB.z) - DVec3(centre.x, centre.y, centre.z);
        // btManifoldResult's point on the box: the sphere's point moved along the normal by the depth.
        s.floatOnSurface = DVec3(c.pointOnB.x + c.normalOnB.x * c.distance, c.pointOnB.y + c.normalOnB.y * c.distance,
                                 c.pointOnB.z + c.normalOnB.z * c.distance);
    }

    // A sphere whose centre a step left inside box `b` (narrowPhaseInsideBoxes): a surface of that
    // box found by the casts becomes the face nearest the centre, with the depth from there, so a
    // ball that went past a box's middle is pushed out of the far side.
    void pushOutNearestFace(const OrientedBox& b) {
        const glm::dquat q(b.orientation.w, b.orientation.x, b.orientation.y, b.orientation.z);
        const glm::dquat toLocal = glm::conjugate(q);
        const DVec3 local = toLocal * (mPosition - DVec3(b.center));
        int nearest = 0;
        double room = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 3; ++k) {
            const double r = static_cast<double>(b.halfExtents[k]) - std::abs(local[k]);
            if (r < room) {
                room = r;
                nearest = k;
            }
        }
        DVec3 axis(0.0);
        axis[nearest] = local[nearest] < 0.0 ? -1.0 : 1.0;
        const DVec3 n = q * axis;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (s.predictive || s.floatContact) continue;
            // One of this box's faces: along one of its axes, its plane through that face.
            const DVec3 along = toLocal * s.normal;
            int face = -1;
            for (int k = 0; k < 3; ++k)
                if (std::abs(along[k]) > 0.999) face = k;
            if (face < 0) continue;
            const DVec3 onFace = toLocal * (s.touch - s.normal * mRadius - DVec3(b.center));
            if (std::abs(std::abs(onFace[face]) - static_cast<double>(b.halfExtents[face])) > 1e-3) continue;
            if (glm::dot(s.normal, n) < 0.999) {
                s.normal = n;
                s.gap = -room - mRadius;
                s.touch = mPosition - n * s.gap;
                s.settled = false;
            }
            return;
        }
    }

    // A gathered box as Bullet builds and places it: Godot 3 sets its boxes' margin after
    // construction (the box's rounding, 0.04 m); a Bullet box keeps the constructor's (0.04 m, or
    // a tenth of the smallest half extent) unless its rounding says otherwise.
    detail::BulletBox bulletBoxOf(const OrientedBox& b) const {
        detail::BulletBox box;
        const detail::BulletVec h{b.halfExtents.x, b.halfExtents.y, b.halfExtents.z};
        detail::bulletBoxShape(h, -1.0f, box);
        if (mProfile.engine == PhysicsEngine::Godot3Bullet || std::abs(box.margin - b.rounding) > 1e-6f * box.margin)
            detail::bulletBoxShape(h, b.rounding, box);
        box.basis = detail::bulletBasis(b.orientation.x, b.orientation.y, b.orientation.z, b.orientation.w);
        box.origin = detail::BulletVec{static_cast<float>(b.center.x), static_cast<float>(b.center.y),
                                       static_cast<float>(b.center.z)};
        return box;
    }

    bool stepIn(bool first) {
        const double dt = mRec.dt;
        const DVec3 v0 = mVelocity;
        DVec3 v, freeMotion;
        freeStep(first, v0, v, freeMotion);
        spinDown();

        const DVec3 start = mPosition;
        findSurfaces(freeMotion);
        if (mTrackPairs) {
            bool predictive = false;
            for (int i = 0; i < mCount; ++i) predictive = predictive || mSurfaces[i].predictive;
            mPairs.step(start, start + v0 * (mRec.d * dt), predictive);
        }
        const bool acted = solve(v0, v);
        mVelocity = v;
        if (acted) capSpin();

        // Box2D's translation limit acts on the solved velocity, and so does its rotation limit.
        const double travel = glm::length(mVelocity) * dt;
        if (travel > mProfile.maxStepDistance) {
            mVelocity *= mProfile.maxStepDistance / travel;
            freeMotion = mVelocity * dt;
        }
        if (mProfile.engine == PhysicsEngine::Box2D) limitBox2DRotation(dt);
        const DVec3 before = mPosition;
        if (acted && mProfile.engine == PhysicsEngine::Rapier)
            mPosition = mSubstepPosition;
        else
            mPosition += acted ? (mVelocity + mPushVelocity) * dt : freeMotion;
        if (mProfile.planar) mPosition.z = before.z;
        if (mProfile.engine == PhysicsEngine::Rapier) rapierSweep(before);
        if (mProfile.engine == PhysicsEngine::Godot3Bullet) clampMotionCcd(before);
        if (mProfile.engine == PhysicsEngine::Box2D) {
            // The impulses this step's discrete solve stores for the next step's warm start.
            for (int i = 0; i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                s.warmNormal = s.acting ? s.normalImpulse : 0.0;
                s.warmFriction = s.acting ? s.frictionImpulse : DVec3(0.0);
            }
        }
        if (mProfile.engine == PhysicsEngine::Jolt && !mProfile.correctionIsVelocity)
            correctJoltPositions(before);
        else
            correctPositions();
        if (mProfile.engine == PhysicsEngine::Box2D) box2dTimeOfImpact(before);
        if (mMeshContacts) followManifoldPoints(mPosition - before);
        if (mManifold || mGodotContacts)
            turnManifoldPoints();
        else if (mProfile.frictionWarmStart > 0.0f)
            dropDriftedPoints(mPosition - before);

        bool bounced = false;
        mTouching = false;
        double strongest = 0.0;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            s.carried = s.acting && s.normalImpulse > 0.0;
            if (!s.acting) {
                s.warmNormal = 0.0;
                s.warmFriction = DVec3(0.0);
                s.color = -1;
            }
            if (!s.acting || s.normalImpulse <= 0.0) continue;
            mTouching = true;
            if (s.normalImpulse > strongest) {
                strongest = s.normalImpulse;
                mContactNormal = s.normal;
            }
            // A real impact, not resting contact: faster than twice what gravity adds in a step.
            const double resting = 2.0 * std::abs(glm::dot(mGravity, s.normal)) * dt + 1e-3;
            if (s.approach > resting) {
                bounced = true;
                mLastNormal = s.normal;
            }
        }
        if (bounced) ++mResult.bounces;
        advanceFloatFlight(acted);
        return bounced;
    }

    // Probes the surfaces already known, and casts the step's free motion for new ones.
    void findSurfaces(const DVec3& freeMotion) {
        const double reach = contactReach();
        // Where the surfaces were at the step's start (clearance() reads them; not the whole
        // Surfaces, which are large).
        std::array<SurfacePlace, kMaxSurfaces> known;
        const int knownCount = mCount;
        for (int i = 0; i < mCount; ++i) known[i] = SurfacePlace{mSurfaces[i].normal, mSurfaces[i].touch};
        int kept = 0;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];  // in place: kept <= i, and a dropped one is overwritten
            if (s.predictive) continue;
            if (s.reversed) {
                s.normal = -s.normal;
                s.reversed = false;
            }
            s.persists = s.acting;
            s.closest = false;
            // Probe from outside the surface, along its normal.
            const double gapNow = glm::dot(mPosition - s.touch, s.normal);
            if (gapNow > reach + glm::length(freeMotion) + 0.05) continue;  // far: forget it
            // A triangle whose plane the centre passed long ago: its back face is out of reach.
            if (mMeshContacts && gapNow < -(2.0 * mRadius + reach + glm::length(freeMotion) + 0.05)) continue;
            const double lift = std::max(0.0, -gapNow) + 0.01;
            const DVec3 clear = clearance(s.normal, known.data(), knownCount);
            const DVec3 from = mPosition + clear + s.normal * lift;
            const DVec3 to =
                mPosition + clear - s.normal * (reach + 0.01 + std::max(0.0, -glm::dot(freeMotion, s.normal)));
            CastHit hit;
            if (!cast(from, to, hit)) continue;
            DVec3 normal = glm::normalize(toD(hit.normal)), off(0.0);
            if (glm::dot(normal, s.normal) < 0.05) {
                // The probe grazed another surface the sphere touches (a wall beside the floor:
                // the probe runs along it and its rounding enters it at the start). Probe again
                // 1 mm off that surface.
                off = normal * 1e-3;
                if (!cast(from + off, to + off, hit)) continue;
                normal = glm::normalize(toD(hit.normal));
                if (glm::dot(normal, s.normal) < 0.05) continue;
            }
            DVec3 touch = toD(hit.position) - off - clear;
            if (mProfile.engine == PhysicsEngine::PhysX) nearestOnEdge(normal, touch);
            if (isKnown(normal, touch, kept)) continue;  // two probes found the same surface
            s.settled = glm::dot(normal, s.normal) > 1.0 - kNormalSettle;
            s.normal = normal;
            s.touch = touch;
            s.gap = glm::dot(mPosition - s.touch, s.normal);
            s.restitution = hit.restitution;
            s.friction = hit.friction;
            if (kept != i) mSurfaces[kept] = s;
            ++kept;
        }
        mCount = kept;

        const double length = glm::length(freeMotion);
        if (length > 0.0) {
            const DVec3 to = mPosition + freeMotion * ((length + reach) / length);
            CastHit hit;
            if (cast(mPosition, to, hit)) addSurface(hit);
            if (mProfile.engine == PhysicsEngine::Rapier || mProfile.engine == PhysicsEngine::Box2D)
                findNearby(freeMotion / length, reach);
        }
        // Bullet's narrow phase (native, ammo.js, Godot 3 with Bullet) tests every shape whose
        // bounds overlap the sphere's: a sphere rolling on the floor finds the wall ahead as PhysX
        // does (without this, a ball sliding into a wall of triangles went through it).
        const bool bullet = mProfile.engine == PhysicsEngine::Bullet || mProfile.engine == PhysicsEngine::Godot3Bullet;
        if (bullet || mProfile.engine == PhysicsEngine::PhysX || mProfile.engine == PhysicsEngine::Rapier)
            slideCast(freeMotion, reach);
        // Box2D's narrow phase makes a contact with every polygon within the skin, wherever the
        // circle heads: a ball rolling under a box's lower corner is wedged there, though no cast
        // along its motion (tilted down by the step's gravity, so it meets the floor first) meets
        // the corner. Bullet's makes one with every convex shape within the breaking threshold
        // where the step starts: a ball that flies up past a box's top edge 2.6 mm from it, the
        // edge never nearer along the motion, is pushed off it (ammo.js). Asked for Bullet when
        // the casts found nothing (a shape found both ways would count twice; measured worse).
        if (mProfile.engine == PhysicsEngine::Box2D || (bullet && !mMeshContacts && mCount == 0)) findNearShapes(reach);
        if (mProfile.engine == PhysicsEngine::Rapier || mProfile.engine == PhysicsEngine::Box2D) closestPoints(reach);
        // Bullet's narrow phase (GJK between the sphere's centre and the box's inner box, the
        // margins added) measures a contact at the closest points where the step starts, as
        // Jolt's does: on a rounded edge the normal there differs from the one a cast meets.
        // A surface whose probe from the centre found its normal again is measured there already.
        if (bullet)
            for (int i = 0; i < mCount; ++i)
                if (!mSurfaces[i].settled) closestPoint(mSurfaces[i], freeMotion, reach, kNormalSettle);
        if (mProfile.engine == PhysicsEngine::Bullet && !mMeshContacts) closestPointsNear(reach);
        if (bullet) closestPointsOnBoxes();
        if (bullet) measureAsBullet();
        // GodotPhysics' separating-axis test measures a box's contact along the closest points'
        // normal where the centre is outside it (in a corner's region, the axis from the corner
        // to the centre). A known surface probed along its old normal meets a corner where a
        // sphere moving that way would first touch it, whose normal is another: a ball that hit a
        // corner at 120 Hz bounced 1.5 degrees off Godot's. PhysX's contact is the closest points
        // at the step's start too (addSurface measures a new one so).
        if (mGodotContacts || mProfile.engine == PhysicsEngine::PhysX)
            for (int i = 0; i < mCount; ++i) closestPoint(mSurfaces[i], freeMotion, reach);
        if (!mProfile.planar) narrowPhaseInsideBoxes(bullet);
        if (mProfile.engine == PhysicsEngine::Jolt) {
            findSlideSurface(freeMotion, reach);
            for (int i = 0; i < mCount; ++i) closestPoint(mSurfaces[i], freeMotion, reach);
            findNearSurfaces(freeMotion, reach);
        }
        if (!mProfile.planar && mCount > 0) findNearShapes(0.0);
        if (mGodotContacts) oneContactPerBox();
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            s.acting = mProfile.contact == ContactMethod::Speculative ? s.gap < reach : s.gap < 0.0;
            if (mMeshContacts) meshContact(s, reach);
            if (mManifold) updateManifold(s, reach);
            if (mGodotContacts) updateGodotContacts(s);
        }
        if (mProfile.engine == PhysicsEngine::Godot3Bullet) predictiveContact();
    }

    // Bullet's narrow phase measures each box it holds a pair with at the closest points between
    // the centre and the box shrunk by its margin (GJK, the margins added back). The casts and
    // probes measure a surface where they meet it, which on a rounded edge, or where a probe along
    // a surface's old normal passes another box first, is elsewhere (a ball between two ramps
    // missed a contact 7.8 mm from one of them, which Bullet's breaking threshold of 8.4 mm took).
    // Each surface on a box the pairs know (BulletPairs) is measured again so, where the centre
    // is outside the shrunk box and the normal stays within 60 degrees of the surface's.
    void closestPointsOnBoxes() {
        if (!mTrackPairs || !mPairs.valid()) return;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (s.predictive) continue;
            const OrientedBox* box = mPairs.boxNear(s.touch - s.normal * mRadius);
            DVec3 n;
            double gap;
            if (!box || !closestOnBox(*box, mPosition, mRadius, n, gap) || glm::dot(n, s.normal) < 0.5) continue;
            s.normal = n;
            s.gap = gap;
            s.touch = mPosition - n * gap;
        }
    }

    // The casts above find the surfaces along the motion and the ones known from earlier steps.
    // A sphere pressed into one face of a narrow corner (a facet of a small icosphere, a box's
    // edge) can sink into the face beside it without any cast meeting it: casts ignore a surface
    // they start inside. An engine's narrow phase tests every shape that overlaps the sphere, so
    // the world's closest-point query (CollisionWorld::findNear, where the world answers it) adds
    // each surface the sphere penetrates that no cast found. Surfaces the casts found are kept as
    // they measured them: a surface near the plane of a known one is that one (its neighbour
    // triangle's edge seen from a ball resting across the edge).
    // Asked only while the sphere touches a surface: in free flight the cast along the motion
    // meets what lies ahead before the sphere can sink into it. `within`: the largest gap that
    // counts (0: the surfaces the sphere penetrates; Box2D: every one within its skin).
    void findNearShapes(double within) {
        if (mCount == kMaxSurfaces || mRadius <= 0.0) return;
        struct Collector final : NearCollector {
            std::array<NearSurface, kMaxSurfaces> found{};
            int count = 0;
            void add(const NearSurface& surface) override {
                // Keep the deepest: they matter most when there are more than room for.
                int slot = count < kMaxSurfaces ? count++ : -1;
                if (slot < 0) {
                    slot = 0;
                    for (int i = 1; i < kMaxSurfaces; ++i)
                        if (found[i].distance > found[slot].distance) slot = i;
                    if (found[slot].distance <= surface.distance) return;
                }
                found[slot] = surface;
            }
        } collector;
        NearQuery query;
        query.center = toR(mPosition);
        query.radius = static_cast<float>(mRadius + within);
        if (!mWorld->findNear(query, collector)) return;
        // Worlds report in their own order (a tree's, or the order added): the deepest first,
        // ties by point, so that the surfaces and their solve order do not depend on it.
        const auto before = [](const NearSurface& a, const NearSurface& b) {
            if (a.distance != b.distance) return a.distance < b.distance;
            if (a.point.x != b.point.x) return a.point.x < b.point.x;
            if (a.point.y != b.point.y) return a.point.y < b.point.y;
            if (a.point.z != b.point.z) return a.point.z < b.point.z;
            if (a.normal.x != b.normal.x) return a.normal.x < b.normal.x;
            if (a.normal.y != b.normal.y) return a.normal.y < b.normal.y;
            return a.normal.z < b.normal.z;
        };
        for (int j = 1; j < collector.count; ++j)  // at most kMaxSurfaces: insertion
            for (int k = j; k > 0 && before(collector.found[k], collector.found[k - 1]); --k)
                std::swap(collector.found[k], collector.found[k - 1]);
        for (int j = 0; j < collector.count && mCount < kMaxSurfaces; ++j) {
            const NearSurface& near = collector.found[j];
            const DVec3 n = glm::normalize(toD(near.normal));
            const DVec3 point = toD(near.point);
            const double gap = glm::dot(mPosition - point, n) - mRadius;
            if (!(gap < within)) continue;
            if (mProfile.planar && std::abs(n.z) > 0.5) continue;  // a face the plane of motion cuts
            bool known = false;
            for (int i = 0; i < mCount && !known; ++i) {
                const Surface& s = mSurfaces[i];
                const DVec3 onSurface = s.touch - s.normal * mRadius;
                known =
                    std::abs(glm::dot(s.normal, n)) > 0.99 && std::abs(glm::dot(point - onSurface, s.normal)) < 1e-3;
            }
            if (known) continue;
            Surface& s = mSurfaces[mCount++];
            s = Surface{};
            s.normal = n;
            s.touch = point + n * mRadius;
            s.gap = gap;
            s.restitution = near.restitution;
            s.friction = near.friction;
            s.closest = true;
        }
    }

    // Godot 3's Bullet bodies sweep for continuous collision (btRigidBody's CCD motion threshold
    // 1e-7 m, swept sphere 0.2 of the shape's bounding sphere: 0.2 sqrt(3) r for a sphere), so
    // btDiscreteDynamicsWorld::createPredictiveContacts adds a contact before the narrow phase:
    // the swept sphere is cast along the step's motion before gravity (damped velocity x dt);
    // a hit that approaches the surface by more than the allowed CCD penetration (0.04 m along
    // its normal) becomes a contact whose point on the body is the centre (no lever arm: its
    // friction stops the sliding without spinning the sphere), restitution 0, and distance the
    // motion's approach up to the hit (the solver lets the body close that and no more).
    void predictiveContact() {
        if (mCount == kMaxSurfaces || mRadius <= 0.0) return;
        const DVec3 motion = mVelocity * mRec.d * mRec.dt;
        const double length = glm::length(motion);
        if (length <= 0.0) return;
        CastHit hit;
        DVec3 n;
        if (!ccdSweep(mPosition, motion, hit, n)) return;
        Surface& s = mSurfaces[mCount++];
        s = Surface{};
        s.predictive = true;
        s.normal = n;
        s.gap = -static_cast<double>(hit.fraction) * glm::dot(motion, n);
        s.touch = mPosition - n * s.gap;
        s.restitution = 0.0f;
        s.friction = hit.friction;
        s.acting = true;
        if (mManifold) {
            // Its manifold lives for this step only: one point at the centre, no stored impulse.
            s.pointCount = 1;
            ManifoldPoint& p = s.points[0];
            p.normal = n;
            p.distance = s.gap;
            p.onSurface = s.touch - n * mRadius;
        }
    }

    // Bullet's continuous-collision sweep for Godot 3's bodies: the small CCD sphere (0.2 of the
    // shape's bounding sphere) cast along `motion` from `from`. True when it hits a surface within
    // the motion that it approaches by more than btClosestNotMeConvexResultCallback's allowed
    // penetration (0.04 m along the normal); `normal` is that surface's unit normal.
    bool ccdSweep(const DVec3& from, const DVec3& motion, CastHit& hit, DVec3& normal) const {
        SegmentCast c;
        c.origin = toR(from);
        c.displacement = toF(motion);
        c.radius = static_cast<float>(0.2 * std::sqrt(3.0) * mRadius);
        if (!mWorld->castSegment(c, hit) || hit.fraction >= 1.0f) return false;
        normal = glm::normalize(toD(hit.normal));
        if (!advanceConservatively(from, motion, static_cast<double>(c.radius), hit, normal)) return false;
        if (glm::dot(normal, motion) >= -0.04) return false;
        // btContinuousConvexCollision stops advancing once the shapes are within 1 mm: a sweep
        // that starts that close reports its hit at the start (the body does not move towards
        // it, and a predictive contact has distance 0).
        if (-static_cast<double>(hit.fraction) * glm::dot(motion, normal) <= 1e-3) hit.fraction = 0.0f;
        return true;
    }

    // btContinuousConvexCollision, the sweep's time of impact, advances conservatively: from the
    // start it moves by the gap over the approach speed along the closest points' normal, and
    // stops at the first place within 1 mm of the shape, reporting that place and the normal
    // there. On a face that is where the cast meets it; on a box's rounded edge or corner it stops
    // short, with a normal turned towards the motion (a ball that met a ramp's edge left 0.028
    // m/s off Godot's with the cast's normal). Redone here for the box the cast met (the gathered
    // boxes), `hit` and `normal` moved to where it stops; false where it finds no impact.
    bool advanceConservatively(const DVec3& from, const DVec3& motion, double radius, CastHit& hit,
                               DVec3& normal) const {
        if (mWorld != &mLocal) return true;
        const DVec3 centre = from + motion * static_cast<double>(hit.fraction);
        const OrientedBox* box = nullptr;
        double gap = 0.0;
        DVec3 n(0.0);
        for (const OrientedBox& b : mLocal.boxes())
            if (closestOnBox(b, centre, radius, n, gap) && std::abs(gap) < 1e-4) {
                box = &b;
                break;
            }
        if (!box) return true;
        double lambda = 0.0;
        if (!closestOnBox(*box, from, radius, n, gap)) return true;
        for (int iteration = 0; gap > 1e-3; ++iteration) {
            const double approach = -glm::dot(motion, n);
            if (approach <= 1.1920929e-7 || iteration > 64) return false;
            const double next = lambda + gap / approach;
            if (next > 1.0 || next <= lambda) return false;
            lambda = next;
            if (!closestOnBox(*box, from + motion * lambda, radius, n, gap)) return true;
        }
        hit.fraction = static_cast<float>(lambda);
        normal = n;
        return true;
    }

    // The closest points of a sphere of `radius` centred at `p` and box `b` (rounded by its
    // rounding, as Bullet's margin rounds a btBoxShape): the unit `normal` from the box towards
    // the centre and the `gap` between them [m]. False where the centre lies inside the box shrunk
    // by its rounding (GJK hands that case to the penetration depth solver).
    static bool closestOnBox(const OrientedBox& b, const DVec3& p, double radius, DVec3& normal, double& gap) {
        const DQuat q = glm::normalize(DQuat(b.orientation));
        const double r = static_cast<double>(b.rounding);
        const DVec3 inner = DVec3(b.halfExtents) - r, local = glm::conjugate(q) * (p - DVec3(b.center));
        DVec3 outward;
        const double outside = boxSignedDistance(local, inner, 0.0, outward);
        if (!(outside > 1e-9)) return false;
        gap = outside - r - radius;
        normal = q * outward;
        return true;
    }

    // Godot 3 with Bullet, after the solve: btDiscreteDynamicsWorld::integrateTransforms sweeps
    // the same small CCD sphere along the step's solved motion (from where the split impulse
    // left the body) and, when it hits a surface it approaches by more than the allowed 0.04 m,
    // moves the body only up to the hit. The velocity is left as the solver made it.
    void clampMotionCcd(const DVec3& before) {
        if (mRadius <= 0.0) return;
        const DVec3 from = before + mPushVelocity * mRec.dt;
        const DVec3 motion = mPosition - from;
        if (glm::dot(motion, motion) <= 1e-14) return;
        CastHit hit;
        DVec3 n;
        if (!ccdSweep(from, motion, hit, n)) return;
        mPosition = from + motion * static_cast<double>(hit.fraction);
        mFloatFlight = false;  // the float flight does not follow the sweep
    }

    // PhysX makes a contact with every shape within the contact distance at the step's start,
    // whatever the motion. A sphere that slides or rolls on a surface casts into that surface
    // first (or grazes it), so a second cast follows the motion without its part into the
    // surfaces touched, from 1 mm off them: it finds the walls ahead, and the floor below a ball
    // that slides down a wall.
    void slideCast(const DVec3& freeMotion, double reach) {
        DVec3 motion = freeMotion, off(0.0);
        bool touching = false;
        for (int i = 0; i < mCount; ++i) {
            const Surface& s = mSurfaces[i];
            if (s.gap >= reach) continue;
            touching = true;
            const double into = glm::dot(motion, s.normal);
            if (into < 0.0) motion -= into * s.normal;
            off += s.normal * 1e-3;
        }
        const double length = glm::length(motion);
        if (!touching || length <= 0.0) return;
        CastHit hit;
        if (cast(mPosition + off, mPosition + off + motion * ((length + reach) / length), hit)) {
            hit.position = toR(toD(hit.position) - off);
            addSurface(hit);
        }
    }

    // Rapier's contacts have the closest points' normal and distance (an edge's too): each
    // surface found is measured again along the direction that converges on its closest point.
    // Two surfaces that turn out to be the same one are merged.
    void closestPoints(double reach) {
        int kept = 0;
        for (int i = 0; i < mCount; ++i) {
            Surface s = mSurfaces[i];
            DVec3 axis = s.normal;
            double distance = 0.0;
            // A surface the world's closest-point query measured is measured already (probing
            // again could converge on a nearer shape beside it: a wall over the floor).
            if (!s.closest && closestDistance(mPosition, mRadius + reach + 0.1, axis, distance) &&
                !masks(axis, mPosition - axis * (distance - mRadius), SurfacePlace{s.normal, s.touch})) {
                s.normal = axis;
                s.gap = distance - mRadius;
                s.touch = mPosition - axis * s.gap;
            }
            bool same = false;
            for (int j = 0; j < kept; ++j)
                if (glm::dot(mSurfaces[j].normal, s.normal) > 0.999 && std::abs(mSurfaces[j].gap - s.gap) < 1e-4)
                    same = true;
            if (!same) mSurfaces[kept++] = s;
        }
        mCount = kept;
    }

    // Rapier's narrow phase keeps a contact with every shape within its prediction distance of
    // the sphere, wherever the sphere is heading: an edge it passes by, a face it already
    // penetrates. A sphere grown by that distance, cast from behind the sphere up to it, meets
    // such a shape; a probe along the hit's normal then measures the sphere's own gap to it.
    void findNearby(const DVec3& direction, double reach) {
        const double back = mRadius + reach + 0.05;
        SegmentCast grown;
        grown.origin = toR(mPosition - direction * back);
        grown.displacement = toF(mPosition + direction * 1e-3 - toD(grown.origin));
        grown.radius = static_cast<float>(mRadius + reach);
        CastHit hit;
        if (!mWorld->castSegment(grown, hit)) return;
        // Along the closest direction the probe meets the shape at the gap; an edge or corner
        // gives that direction after a few probes.
        DVec3 n = glm::normalize(toD(hit.normal));
        const double lift = 0.05;
        CastHit probe;
        bool found = false;
        for (int iteration = 0; iteration < 4; ++iteration) {
            CastHit next;
            if (!cast(mPosition + n * lift, mPosition - n * (reach + 0.01), next)) break;
            probe = next;
            found = true;
            const DVec3 m = glm::normalize(toD(next.normal));
            if (glm::dot(m, n) > 1.0 - 1e-9) break;
            n = m;
        }
        if (found) addSurface(probe);
    }

    // Jolt's narrow phase collides the sphere with every shape its (motion-swept) bounds reach,
    // not only with the first one along the motion: a sphere that slides or rolls on the floor
    // also finds the wall ahead, which the cast along the free motion (stopped by the floor it
    // presses into) cannot. So the motion is cast once more with its part into the surfaces
    // already touched taken out, from just outside them; a surface found so is measured along
    // its normal from the sphere's centre, as the narrow phase measures it.
    void findSlideSurface(const DVec3& freeMotion, double reach) {
        DVec3 slide = freeMotion, lift(0.0);
        bool touching = false;
        for (int i = 0; i < mCount; ++i) {
            const Surface& s = mSurfaces[i];
            // The surfaces this step's motion may reach: they hide whatever lies beyond them.
            if (s.gap >= reach + std::max(0.0, -glm::dot(freeMotion, s.normal))) continue;
            touching = true;
            const double into = glm::dot(slide, s.normal);
            if (into < 0.0) slide -= into * s.normal;
            lift += s.normal * (std::max(0.0, -s.gap) + 1e-4);
        }
        const double length = glm::length(slide);
        if (!touching || length <= 0.0) return;
        const DVec3 from = mPosition + lift;
        CastHit hit;
        if (!cast(from, from + slide * ((length + reach) / length), hit)) return;
        const DVec3 n = glm::normalize(toD(hit.normal));
        for (int i = 0; i < mCount; ++i)
            if (glm::dot(mSurfaces[i].normal, n) > 0.999) return;  // a surface already known
        Surface found;
        found.normal = n;
        found.touch = toD(hit.position) - lift;
        found.gap = glm::dot(mPosition - found.touch, n);
        found.restitution = hit.restitution;
        found.friction = hit.friction;
        closestPoint(found, freeMotion, reach);
        addFound(found);
    }

    // Adds a surface measured by closestPoint (addSurface takes a cast's hit).
    void addFound(const Surface& s) {
        CastHit hit;
        hit.position = toR(s.touch);
        hit.normal = toF(s.normal);
        hit.restitution = s.restitution;
        hit.friction = s.friction;
        addSurface(hit);
    }

    // Jolt: a probe along n starts clear of the other surfaces the sphere touches or is in (by
    // 0.1 mm), or it could report one of them at its start instead of the surface it looks for;
    // what it finds is moved back by as much. Other engines: no offset.
    template <class Place>  // Surface or SurfacePlace
    DVec3 clearance(const DVec3& n, const Place* surfaces, int count) const {
        DVec3 offset(0.0);
        if (mProfile.engine != PhysicsEngine::Jolt) return offset;
        for (int j = 0; j < count; ++j) {
            const Place& o = surfaces[j];
            if (glm::dot(o.normal, n) > 0.999) continue;
            const double gap = glm::dot(mPosition - o.touch, o.normal);
            if (gap < 1e-3) offset += o.normal * (std::max(0.0, -gap) + 1e-4);
        }
        return offset;
    }

    // A surface within the contact distance of the sphere is a contact in Jolt even when the
    // sphere's path only grazes past it (the end or the underside edge of a wall): its closest
    // point at the step's start makes the normal, and the solver stops the approach along it.
    // The cast along the motion misses such a surface, so short probes along the world axes
    // that the motion heads along look for it; what they find is measured at its closest point
    // and kept when within reach.
    void findNearSurfaces(const DVec3& freeMotion, double reach) {
        const double length = glm::length(freeMotion);
        if (length <= 0.0 || mCount == kMaxSurfaces) return;
        const DVec3 heading = freeMotion / length;
        for (int axis = 0; axis < 3; ++axis) {
            if (std::abs(heading[axis]) < 0.05) continue;
            DVec3 d(0.0);
            d[axis] = heading[axis] > 0.0 ? 1.0 : -1.0;
            const DVec3 clear = clearance(d, mSurfaces.data(), mCount);
            CastHit hit;
            if (!cast(mPosition + clear, mPosition + clear + d * (3.0 * reach), hit)) continue;
            Surface s;
            s.normal = glm::normalize(toD(hit.normal));
            bool known = false;
            for (int i = 0; i < mCount; ++i)
                if (glm::dot(mSurfaces[i].normal, s.normal) > 0.999) known = true;
            if (known) continue;
            s.touch = toD(hit.position) - clear;
            s.gap = glm::dot(mPosition - s.touch, s.normal);
            s.restitution = hit.restitution;
            s.friction = hit.friction;
            closestPoint(s, freeMotion, reach);
            if (s.gap >= reach) continue;
            addFound(s);
            if (mCount == kMaxSurfaces) return;
        }
    }

    // Bullet's GJK measures a deep contact at the closest points too, where probing along the
    // normal converges slowly (each probe shrinks the normal's error by about |gap| / (r +
    // rounding): near 1 when the centre is near the surface, as in a fast glancing hit that
    // ends a step half inside a box). For a surface whose centre lies within half the radius
    // of it, the world's closest-point query answers at once, where the world has one: the
    // shape whose normal there is nearest the probed one (within about 25 degrees) gives the
    // contact. A centre inside a solid is not answered (Bullet's EPA case): the probes stay.
    void closestPointsNear(double reach) {
        if (mCount == 0 || mRadius <= 0.0) return;
        bool deep = false;
        for (int i = 0; i < mCount; ++i) deep = deep || mSurfaces[i].gap < -0.5 * mRadius;
        if (!deep) return;
        // The best match per surface as the world reports, in whatever order: the nearest
        // normal, ties to the nearer shape.
        struct Collector final : NearCollector {
            const Surface* surfaces = nullptr;
            int count = 0;
            double radius = 0.0;
            std::array<NearSurface, kMaxSurfaces> best{};
            std::array<double, kMaxSurfaces> bestDot{};
            void add(const NearSurface& near) override {
                const DVec3 n = glm::normalize(toD(near.normal));
                for (int i = 0; i < count; ++i) {
                    if (!(surfaces[i].gap < -0.5 * radius)) continue;
                    const double d = glm::dot(n, surfaces[i].normal);
                    if (d > bestDot[i] || (d == bestDot[i] && near.distance < best[i].distance)) {
                        bestDot[i] = d;
                        best[i] = near;
                    }
                }
            }
        } collector;
        collector.surfaces = mSurfaces.data();
        collector.count = mCount;
        collector.radius = mRadius;
        collector.bestDot.fill(0.9);
        NearQuery query;
        query.center = toR(mPosition);
        query.radius = static_cast<float>(mRadius + reach);
        if (!mWorld->findNear(query, collector)) return;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!(s.gap < -0.5 * mRadius) || !(collector.bestDot[i] > 0.9)) continue;
            const NearSurface& near = collector.best[i];
            s.normal = glm::normalize(toD(near.normal));
            s.gap = static_cast<double>(near.distance) - mRadius;
            s.touch = toD(near.point) + s.normal * mRadius;
            s.restitution = near.restitution;
            s.friction = near.friction;
        }
    }

    // Jolt's and Bullet's narrow phases measure a contact between the closest points of the
    // sphere and the shape at the step's start (GJK), where the cast found the surface at the
    // point the motion reaches. On a face the two agree; on a rounded edge or corner the normal
    // differs. Probing along the normal again until it settles finds the closest point (each probe
    // shrinks the normal's error by about |gap| / (r + rounding)). `settle`: how
    // close to 1 the dot product of two probes' normals must come (a world of float casts, such
    // as BulletWorld, needs more room than the 1e-12 of one in double).
    void closestPoint(Surface& s, const DVec3& freeMotion, double reach, double settle = 1e-12) const {
        const DVec3 clear = clearance(s.normal, mSurfaces.data(), mCount);
        for (int iteration = 0; iteration < kClosestPointIterations; ++iteration) {
            const DVec3 from = mPosition + clear + s.normal * (std::max(0.0, -s.gap) + 0.01);
            const DVec3 to =
                mPosition + clear -
                s.normal * (std::max(0.0, s.gap) + reach + 0.01 + std::max(0.0, -glm::dot(freeMotion, s.normal)));
            CastHit hit;
            if (!cast(from, to, hit)) return;
            const DVec3 n = glm::normalize(toD(hit.normal));
            if (glm::dot(n, s.normal) < 0.9) return;  // another surface
            // Another surface the sphere touches, met first, in front of this one (a ramp over
            // the floor it runs into; the probe's centre is on that surface's offset plane):
            // the surface keeps the measure it has.
            if (masks(n, toD(hit.position), SurfacePlace{s.normal, s.touch})) return;
            const bool settled = glm::dot(n, s.normal) > 1.0 - settle;
            s.normal = n;
            s.touch = toD(hit.position) - clear;
            s.gap = glm::dot(mPosition - s.touch, n);
            s.restitution = hit.restitution;
            s.friction = hit.friction;
            if (settled) return;
        }
    }

    // Bullet against a triangle mesh (btBvhTriangleMeshShape): btConvexConcaveCollisionAlgorithm
    // hands each triangle near the sphere to btSphereTriangleCollisionAlgorithm, whose
    // SphereTriangleDetector::collide differs from a convex shape's contact in two ways.
    void meshContact(Surface& s, double reach) const {
        // Triangles are double-sided: collide() measures from the side of the triangle's plane
        // the centre is on. A centre that has passed the plane (a fast sphere in one step) is
        // pushed on through the triangle, by its back face, with the gap |distance| - r.
        if (s.gap < -mRadius) {
            s.reversed = true;
            s.normal = -s.normal;
            s.gap = -s.gap - 2.0 * mRadius;
            s.acting = s.gap < reach;
        }
        // btConvexTriangleCallback::processTriangle tests a triangle only when its bounding box
        // overlaps the sphere's (centre +- r, grown by the mesh's margin, 0 by default), so the
        // contact breaking threshold makes a new contact early only where that box reaches the
        // plane first: not at all on an axis-aligned face, where the sphere must touch. A contact
        // already in the manifold may stay without that (followManifoldPoints).
        const double reachOfBox = std::abs(s.normal.x) + std::abs(s.normal.y) + std::abs(s.normal.z) - 1.0;
        s.fresh = s.acting && s.gap <= mRadius * reachOfBox;
        if (s.acting && !s.fresh) s.acting = s.persists && s.pointDistance <= reach && s.pointSlip <= reach;
    }

    // A manifold point stays where it was found on the triangle and on the sphere: the sphere's
    // material point moves with the body (rotation included). refreshContactPoints drops it once
    // its distance along the normal, or its slip across it, exceeds the contact breaking
    // threshold; a new contact found near it replaces it.
    void followManifoldPoints(const DVec3& moved) {
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            const DVec3 arm = -mRadius * s.normal;
            const DVec3 turned = turnedByStep(arm);
            const DVec3 motion = moved + turned - arm;
            if (s.fresh) {
                s.pointGap = s.gap;
                s.pointMotion = motion;
            } else {
                s.pointMotion += motion;
            }
            const double along = glm::dot(s.pointMotion, s.normal);
            s.pointDistance = s.pointGap + along;
            s.pointSlip = glm::length(s.pointMotion - along * s.normal);
        }
    }

    // A vector fixed in the body (a material point's arm from the centre), turned by this step's
    // rotation (Rodrigues).
    DVec3 turnedByStep(const DVec3& arm) const {
        // GodotPhysics turns the body by its bias rows' spin too (BodySW::integrate_velocities).
        const DVec3 turn = (mAngular + mBiasedSpin) * mRec.dt;
        const double angle = glm::length(turn);
        if (!(angle > 0.0)) return arm;
        const DVec3 k = turn / angle;
        return arm * std::cos(angle) + glm::cross(k, arm) * std::sin(angle) +
               k * (glm::dot(k, arm) * (1.0 - std::cos(angle)));
    }

    // Bullet's refreshContactPoints: a manifold point stays on the sphere's material point (which
    // moves with the body, rotation included) and on the surface where it was found; it is
    // dropped, and its friction impulse with it, once its distance along the normal or its slip
    // across it exceeds the contact breaking threshold.
    void dropDriftedPoints(const DVec3& moved) {
        const double reach = contactReach();
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (s.lateral == 0.0) continue;
            const DVec3 arm = -mRadius * s.normal;
            const DVec3 turned = turnedByStep(arm);
            const DVec3 motion = moved + turned - arm;
            const double along = glm::dot(motion, s.normal);
            if (s.gap + along > reach || glm::length(motion - along * s.normal) > reach) s.lateral = 0.0;
            s.lateralArm = turned;
            s.lateralCentre = mPosition - moved;
        }
    }

    // Bullet 2.83's persistent manifold (btPersistentManifold), for ammo.js. Each step the narrow
    // phase (GJK for a sphere and a box: the dedicated sphere-box algorithm is compiled out) reports
    // the closest point when it is within the contact breaking threshold. The manifold's first
    // body is the static shape (added to the world before the sphere), so the new point replaces
    // the cached point whose point on the shape lies nearest to its own (within the threshold),
    // keeping that point's impulses, or is added beside the others (up to four; a fifth displaces
    // one chosen by displacedPoint). Then every cached point is measured again where the body now
    // stands: one whose distance along its normal exceeds the threshold, or whose material point
    // on the sphere has slipped across the surface from its point on the shape by more than it,
    // is dropped. A sphere that slides or rolls faster than the threshold per step so keeps older
    // points (its material point turned away from the surface) beside the newest one, each with
    // its own impulses; the surface acts while any point is left.
    void updateManifold(Surface& s, double reach) {
        if (s.acting) {
            ManifoldPoint p;
            p.arm = s.floatContact ? s.floatArm : -mRadius * s.normal;
            // The closest point, not the cast's.
            p.onSurface = s.floatContact ? s.floatOnSurface : mPosition - (mRadius + s.gap) * s.normal;
            p.normal = s.normal;
            p.distance = s.gap;
            int nearest = -1;
            double shortest = reach * reach;
            for (int j = 0; j < s.pointCount; ++j) {
                const DVec3 d = s.points[j].onSurface - p.onSurface;
                const double d2 = glm::dot(d, d);
                if (d2 < shortest) {
                    shortest = d2;
                    nearest = j;
                }
            }
            if (nearest >= 0) {
                p.normalImpulse = s.points[nearest].normalImpulse;
                p.lateral = s.points[nearest].lateral;
                s.points[nearest] = p;
            } else if (s.pointCount < kManifoldPoints) {
                s.points[s.pointCount++] = p;
            } else {
                s.points[displacedPoint(s, p)] = p;
            }
        }
        for (int j = s.pointCount - 1; j >= 0; --j) {
            ManifoldPoint& p = s.points[j];
            const DVec3 onSphere = mPosition + p.arm;
            p.distance = glm::dot(onSphere - p.onSurface, p.normal);
            const DVec3 slip = p.onSurface - (onSphere - p.normal * p.distance);
            if (p.distance > reach || glm::dot(slip, slip) > reach * reach) {
                // The last point takes the removed one's place.
                s.points[j] = s.points[s.pointCount - 1];
                --s.pointCount;
            }
        }
        s.acting = s.pointCount > 0;
    }

    // How deep a contact point's material point on the sphere lies behind its point on the shape,
    // along its normal, where the body now stands [m]; negative: apart.
    double overlapOf(const ManifoldPoint& p) const { return glm::dot(p.normal, p.onSurface - (mPosition + p.arm)); }

    // GodotPhysics 3 (BodyPairSW): up to four contacts per shape pair, each fixed on the sphere's
    // material (its arm turns with the body) and on the shape. Every step the contacts that
    // separated by more than 0.05 m or slid apart by more than that go; the narrow phase's new
    // contact (while the sphere overlaps the shape) takes the place of one whose points both lie
    // within 0.01 m of its own, keeping its impulses, or is added (a fifth: the least deep goes).
    void updateGodotContacts(Surface& s) {
        constexpr double kMaxSeparation = 0.05, kRecycle = 0.01;
        for (int j = 0; j < s.pointCount; ++j) {
            ManifoldPoint& p = s.points[j];
            const double depth = overlapOf(p);
            const DVec3 apart = p.onSurface - p.normal * depth - (mPosition + p.arm);
            if (depth < -kMaxSeparation || glm::length(apart) > kMaxSeparation) {
                s.points[j] = s.points[s.pointCount - 1];
                --s.pointCount;
                --j;
            }
        }
        if (s.acting) {
            ManifoldPoint p;
            p.arm = -mRadius * s.normal;
            p.onSurface = mPosition - (mRadius + s.gap) * s.normal;
            p.normal = s.normal;
            int slot = s.pointCount;
            for (int j = 0; j < s.pointCount; ++j) {
                const ManifoldPoint& q = s.points[j];
                if (glm::length(q.arm - p.arm) < kRecycle && glm::length(q.onSurface - p.onSurface) < kRecycle) {
                    p.normalImpulse = q.normalImpulse;
                    p.tangentImpulse = q.tangentImpulse;
                    slot = j;
                    break;
                }
            }
            if (slot == kManifoldPoints) {
                // The least deep of the five goes (the first of equal ones; the new one last).
                int least = 0;
                for (int j = 1; j < s.pointCount; ++j)
                    if (overlapOf(s.points[j]) < overlapOf(s.points[least])) least = j;
                if (!(overlapOf(p) < overlapOf(s.points[least]))) s.points[least] = p;
            } else {
                s.points[slot] = p;
                if (slot == s.pointCount) ++s.pointCount;
            }
        }
        s.acting = false;
        for (int j = 0; j < s.pointCount; ++j)
            if (overlapOf(s.points[j]) > 0.0) s.acting = true;
    }

    // GodotPhysics 3's solve (BodyPairSW::setup and solve) over the persistent contacts. Setup:
    // a contact acts while it overlaps; its stored impulses are applied first (warm starting),
    // and its bounce target is the restitution times its normal velocity after that. Each of the
    // 8 iterations then solves per contact a bias row (the overlap beyond 0.01 m, 0.3 of it per
    // step, on a separate velocity that moves the body without staying in its velocity: at the
    // contact point, then at the centre), the normal row and the friction row (along the
    // contact's current slip, bounded by the normal impulse times the friction); a contact none
    // of whose rows moved by more than 1e-4 m/s rests for the step's remaining iterations.
    void solveGodotContacts(DVec3& v) {
        const double dt = mRec.dt;
        const double invInertia = armInverseInertia();
        constexpr double kMinVelocity = 1e-4;
        constexpr int kIterations = 8;
        const auto applyAt = [&](const DVec3& impulse, const DVec3& arm) { applyAtArm(impulse, arm, v); };
        const auto massAlong = [&](const DVec3& arm, const DVec3& d) { return rowMass(arm, d); };
        DVec3 biased(0.0), biasedSpin(0.0);
        struct Row {
            ManifoldPoint* p;
            Surface* s;
            double bias, bounce, mass, biasImpulse, centreImpulse;
            bool active;
        };
        std::array<Row, kMaxSurfaces * kManifoldPoints> rows{};
        int count = 0;
        // Newest shape first (the surfaces here are oldest first): solved the other way round, two
        // of 3300 oracle throws that meet a wall while rolling on the floor parted from Godot.
        // Godot's own order is its pairs' addresses (StepSW::_populate_island walks a map keyed
        // by pointer), which follow the allocator's reuse of freed pairs: on ramp scenes (a ball
        // in the crease of a ramp and the floor) the two orders trade 2 to 4 throws per 100 either
        // way (seven sets: 682 newest first, 679 oldest first).
        for (int i = mCount - 1; i >= 0; --i) {
            Surface& s = mSurfaces[i];
            for (int j = 0; j < s.pointCount; ++j) {
                ManifoldPoint& p = s.points[j];
                const double depth = overlapOf(p);
                if (!(depth > 0.0)) continue;
                Row& r = rows[static_cast<std::size_t>(count++)];
                r = Row{&p, &s, 0.0, 0.0, massAlong(p.arm, p.normal), 0.0, 0.0, true};
                r.bias = mProfile.positionCorrection * std::max(0.0, depth - mProfile.penetrationSlop) / dt;
                applyAt(p.normal * p.normalImpulse + p.tangentImpulse, p.arm);
                if (s.e > 0.0) r.bounce = s.e * glm::dot(v + glm::cross(mAngular, p.arm), p.normal);
            }
        }
        for (int iteration = 0; iteration < kIterations; ++iteration) {
            for (int k = 0; k < count; ++k) {
                Row& r = rows[static_cast<std::size_t>(k)];
                if (!r.active) continue;
                r.active = false;
                ManifoldPoint& p = *r.p;
                const DVec3& n = p.normal;
                double vbn = glm::dot(biased + glm::cross(biasedSpin, p.arm), n);
                if (std::abs(r.bias - vbn) > kMinVelocity) {
                    const double total = std::max(0.0, r.biasImpulse + (r.bias - vbn) * r.mass);
                    const DVec3 j = n * (total - r.biasImpulse);
                    r.biasImpulse = total;
                    biased += j;
                    DVec3 turn = invInertia * glm::cross(p.arm, j);
                    const double most = (M_PI / 8.0) / dt, size = glm::length(turn);
                    if (size > most) turn *= most / size;
                    biasedSpin += turn;
                    vbn = glm::dot(biased + glm::cross(biasedSpin, p.arm), n);
                    if (std::abs(r.bias - vbn) > kMinVelocity) {
                        const double centre = std::max(0.0, r.centreImpulse + (r.bias - vbn));
                        biased += n * (centre - r.centreImpulse);
                        r.centreImpulse = centre;
                    }
                    r.active = true;
                }
                const double vn = glm::dot(v + glm::cross(mAngular, p.arm), n);
                if (std::abs(vn) > kMinVelocity) {
                    const double total = std::max(0.0, p.normalImpulse - (r.bounce + vn) * r.mass);
                    applyAt(n * (total - p.normalImpulse), p.arm);
                    p.normalImpulse = total;
                    r.active = true;
                }
                DVec3 slip = v + glm::cross(mAngular, p.arm);
                slip -= n * glm::dot(n, slip);
                const double speed = glm::length(slip);
                if (speed > kMinVelocity) {
                    const DVec3 dir = slip / speed;
                    const DVec3 before = p.tangentImpulse;
                    p.tangentImpulse += dir * (-speed * massAlong(p.arm, dir));
                    const double size = glm::length(p.tangentImpulse), limit = p.normalImpulse * r.s->mu;
                    if (size > 1e-5 && size > limit) p.tangentImpulse *= limit / size;  // CMP_EPSILON
                    applyAt(p.tangentImpulse - before, p.arm);
                    r.active = true;
                }
            }
        }
        mPushVelocity = biased;
        mBiasedSpin = biasedSpin;
        // Each surface's impulses this step: its overlapping contacts'.
        for (int k = 0; k < count; ++k) {
            const Row& r = rows[static_cast<std::size_t>(k)];
            r.s->normalImpulse += r.p->normalImpulse;
            r.s->frictionImpulse += r.p->tangentImpulse;
        }
    }

    // A full manifold keeps its deepest point (when deeper than the new one) and otherwise the
    // points that span the largest area with the new one: the cached point whose replacement by
    // the new one leaves the largest area (Bullet's three-point estimate, on the shape's points;
    // the first of equal ones) gives way.
    static int displacedPoint(const Surface& s, const ManifoldPoint& p) {
        int deepest = -1;
        double depth = p.distance;
        for (int i = 0; i < kManifoldPoints; ++i) {
            if (s.points[i].distance < depth) {
                deepest = i;
                depth = s.points[i].distance;
            }
        }
        const auto& q = s.points;
        const auto area = [&](const ManifoldPoint& other, const ManifoldPoint& a, const ManifoldPoint& b) {
            const DVec3 cross = glm::cross(p.onSurface - other.onSurface, a.onSurface - b.onSurface);
            return glm::dot(cross, cross);
        };
        double areas[kManifoldPoints] = {0.0, 0.0, 0.0, 0.0};
        if (deepest != 0) areas[0] = area(q[1], q[3], q[2]);
        if (deepest != 1) areas[1] = area(q[0], q[3], q[2]);
        if (deepest != 2) areas[2] = area(q[0], q[3], q[1]);
        if (deepest != 3) areas[3] = area(q[0], q[2], q[1]);
        int largest = 0;
        for (int i = 1; i < kManifoldPoints; ++i)
            if (areas[i] > areas[largest]) largest = i;
        return largest;
    }

    // The body's turn in this step carries every manifold point's material point with it.
    void turnManifoldPoints() {
        for (int i = 0; i < mCount; ++i)
            for (int j = 0; j < mSurfaces[i].pointCount; ++j)
                mSurfaces[i].points[j].arm = turnedByStep(mSurfaces[i].points[j].arm);
    }

    // The largest gap that makes a contact. Bullet scales its contact breaking threshold by the
    // shape's bounding radius (sqrt(3) r for a sphere's box bound).
    double contactReach() const {
        const double distance = mProfile.contactDistance;
        if (mProfile.engine == PhysicsEngine::Bullet || mProfile.engine == PhysicsEngine::Godot3Bullet)
            return distance * std::sqrt(3.0) * mRadius;
        return distance;
    }

    // A probe along a box edge's normal touches the edge at the point nearest to the centre (the
    // probe moves across the edge), but reports the normal where it touched: the contact that
    // PhysX makes (sphere against box: the closest point) has the normal from that point to the
    // centre. A face keeps its normal.
    void nearestOnEdge(DVec3& normal, DVec3& touch) const {
        const DVec3 point = touch - normal * mRadius;  // on the box
        const DVec3 towards = mPosition - point;
        const double distance = glm::length(towards);
        if (glm::dot(towards, normal) < 0.5 * mRadius) return;  // deep: the face's normal
        const DVec3 n = towards / distance;
        if (glm::dot(n, normal) > 1.0 - 1e-6) return;
        normal = n;
        touch = point + n * mRadius;
    }

    // Whether surface `s` is the plane through `touch` with normal `n`.
    static bool isPlane(const Surface& s, const DVec3& n, const DVec3& touch) {
        return glm::dot(s.normal, n) > 0.999 && std::abs(glm::dot(touch - s.touch, n)) < 1e-4;
    }

    // Whether one of the first `count` surfaces is the plane through `touch` with normal `n`.
    bool isKnown(const DVec3& n, const DVec3& touch, int count) const {
        for (int i = 0; i < count; ++i)
            if (isPlane(mSurfaces[i], n, touch)) return true;
        return false;
    }

    // Whether a probe for the surface `self` (normal, and the centre where the sphere touches
    // it) that met the plane through `touch` with normal `n` met another surface the sphere
    // touches, whose contact lies in front of self's plane: two surfaces that meet in a hollow
    // (a ramp rising from a floor), not two sides of one convex shape, whose probe converges on
    // the edge between them. A probe that met self's own normal again met self: false (self
    // may be one of mSurfaces; with another normal it matches none of them).
    bool masks(const DVec3& n, const DVec3& touch, const SurfacePlace& self) const {
        if (glm::dot(n, self.normal) >= 0.999) return false;
        const DVec3 selfPoint = self.touch - self.normal * mRadius;
        for (int i = 0; i < mCount; ++i) {
            const Surface& s = mSurfaces[i];
            if (isPlane(s, n, touch) && glm::dot(s.touch - s.normal * mRadius - selfPoint, self.normal) > 1e-4)
                return true;
        }
        return false;
    }

    void addSurface(CastHit hit) {
        DVec3 n = glm::normalize(toD(hit.normal));
        DVec3 touch = toD(hit.position);
        if (mProfile.engine == PhysicsEngine::PhysX) {
            // PhysX's contact is the closest point at the step's start, not where the motion
            // first touches: probe along the hit's normal from where the sphere is.
            const double gap = glm::dot(mPosition - touch, n);
            CastHit probe;
            if (gap > -mRadius &&
                cast(mPosition + n * 0.01, mPosition - n * (std::max(gap, 0.0) + contactReach() + 0.01), probe)) {
                const DVec3 probeNormal = glm::normalize(toD(probe.normal));
                const DVec3 probeTouch = toD(probe.position);
                if (masks(probeNormal, probeTouch, SurfacePlace{n, touch})) {
                    // The probe met another surface the sphere touches, not the one hit (a
                    // floor below a ball on a ramp that runs into it): the hit's face is
                    // measured in its own plane, straight from the centre.
                    touch = mPosition - n * gap;
                } else if (glm::dot(probeNormal, n) > 0.5) {
                    n = probeNormal;
                    touch = probeTouch;
                    nearestOnEdge(n, touch);
                    hit.restitution = probe.restitution;
                    hit.friction = probe.friction;
                }
            }
        }
        if (isKnown(n, touch, mCount)) return;
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
        return mWorld->castSegment(c, hit);
    }

    // The contact solve; returns true when any contact applied an impulse. Each engine's own rule
    // for a sphere against static surfaces (the per-engine notes are in docs/engines.md).
    bool solve(const DVec3& v0, DVec3& v) {
        bool any = false;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            s.normalImpulse = 0.0;
            s.frictionImpulse = DVec3(0.0);
            s.bounce = false;
            s.approach = -glm::dot(v, s.normal);
            if (!s.acting) {
                s.lateral = 0.0;  // the manifold point is gone
                continue;
            }
            any = true;
            s.e = s.restitution >= 0.0f
                      ? combineMaterial(mProfile.restitutionCombine, mSettings.restitution, s.restitution)
                      : mSettings.restitution;
            s.mu = s.friction >= 0.0f ? combineMaterial(mProfile.frictionCombine, mSettings.friction, s.friction)
                                      : mSettings.friction;
        }
        mPushVelocity = DVec3(0.0);
        mBiasedSpin = DVec3(0.0);
        if (!any) return false;
        switch (mProfile.engine) {
            case PhysicsEngine::Rapier:
                solveRapier(v0, v);
                break;
            case PhysicsEngine::PhysX:
                solvePhysX(v);
                break;
            case PhysicsEngine::Box2D:
                solveBox2D(v, false);
                break;
            default:
                solveSequential(v0, v);
                break;
        }
        return true;
    }

    // Jolt, Bullet, Box2D and custom profiles: targets set once, then sequential
    // impulses (friction first, bounded by the normal impulse so far, then the normal row).
    void solveSequential(const DVec3& v0, DVec3& v) {
        if (mManifold) {
            solveBulletManifold(v0, v);
            return;
        }
        if (mGodotContacts) {
            solveGodotContacts(v);
            return;
        }
        const double dt = mRec.dt;
        const PhysicsEngine engine = mProfile.engine;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            const double vn = glm::dot(v, s.normal);
            const double speculative = std::max(0.0, s.gap / dt);
            double base = mProfile.restitutionBase == RestitutionBase::StepStart ? glm::dot(v0, s.normal) : vn;
            if (engine == PhysicsEngine::Jolt) {
                // Jolt 5.6: the post-gravity normal velocity with this step's gravity taken out.
                base = vn + std::max(0.0, -glm::dot(mGravity, s.normal)) * dt;
            } else if (engine == PhysicsEngine::Bullet || engine == PhysicsEngine::Godot3Bullet) {
                base = glm::dot(v0 * mRec.d, s.normal);  // damped, before this step's gravity
            }
            const bool overThreshold = engine == PhysicsEngine::Jolt || engine == PhysicsEngine::Box2D
                                           ? vn < -mProfile.restitutionThreshold
                                           : -base > mProfile.restitutionThreshold;
            // Bullet sets its restitution target whether or not the sphere would reach the
            // surface within the step (btSequentialImpulseConstraintSolver::setupContactConstraint):
            // a sphere that approaches faster than the threshold is pushed back even while the
            // speculative gap is still open.
            const bool reaches = s.gap <= 0.0 || vn < -speculative || engine == PhysicsEngine::Bullet;
            s.bounce = s.e > 0.0 && overThreshold && reaches && base < 0.0;
            switch (engine) {
                case PhysicsEngine::Bullet:
                case PhysicsEngine::Godot3Bullet: {
                    if (s.predictive) s.bounce = false;
                    double target = s.bounce ? -s.e * base : 0.0;
                    if (s.gap > 0.0)
                        target -= s.gap / dt;
                    else if (s.gap > -0.04)
                        target += mProfile.positionCorrection * -s.gap / dt;
                    else
                        mPushVelocity += s.normal * (mProfile.splitImpulseCorrection * -s.gap / dt);
                    s.target = target;
                    break;
                }
                case PhysicsEngine::Box2D:
                    s.target = s.bounce ? -s.e * vn : 0.0;
                    break;
                default:
                    s.target = s.bounce ? -s.e * base : -speculative;
                    if (mProfile.correctionIsVelocity) {
                        const double depth = -s.gap - mProfile.penetrationSlop;
                        if (depth > 0.0) s.target += mProfile.positionCorrection * depth / dt;
                    }
                    break;
            }
        }
        if (mProfile.frictionWarmStart > 0.0f && engine == PhysicsEngine::Bullet) {
            solveBulletWarmStarted(v);
            return;
        }
        const bool bullet = engine == PhysicsEngine::Bullet;
        if (bullet)
            for (int i = 0; i < mCount; ++i)
                if (mSurfaces[i].acting) chooseBulletTangent(mSurfaces[i], v);
        // An iteration that changes nothing (bit for bit) leaves the next ones nothing to change:
        // the rows read only the velocities and the impulses besides what stays fixed.
        for (int iteration = 0; iteration < kSolverIterations; ++iteration) {
            const DVec3 linearBefore = v, angularBefore = mAngular;
            bool changed = false;
            for (int i = 0; i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                const double normalBefore = s.normalImpulse;
                const DVec3 frictionBefore = s.frictionImpulse;
                if (!bullet) frictionRow(s, v, 1.0);
                normalRow(s, v, s.target);
                changed = changed || s.normalImpulse != normalBefore || s.frictionImpulse != frictionBefore;
            }
            // Bullet 3 solves every normal row first, then every friction row whose contact
            // pushes (btSequentialImpulseConstraintSolver::solveSingleIteration, default mode).
            for (int i = 0; bullet && i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                if (!s.acting || !(s.normalImpulse > 0.0)) continue;
                const DVec3 frictionBefore = s.frictionImpulse;
                frictionRowBullet(s, v);
                changed = changed || s.frictionImpulse != frictionBefore;
            }
            if (!changed && v == linearBefore && mAngular == angularBefore) break;
        }
    }

    // Bullet up to 2.88 (btSequentialImpulseConstraintSolver with its default mode flags: one
    // friction direction, warm starting). convertContact sets the friction direction along the
    // contact point's tangential velocity (after gravity; any direction in the plane when it is
    // still) and applies the contact's last friction impulse times the warm-starting factor along
    // it; every iteration then solves all normal rows, and a friction row only while its
    // contact's normal impulse is positive. A contact that pushes no more (a sphere leaving the
    // surface, its point still in the manifold) so keeps the warm-started friction, and hands
    // it on to the next step. One point per surface: used against a triangle mesh; convex shapes
    // have the manifold's several points (solveBulletManifold).
    void solveBulletWarmStarted(DVec3& v) {
        const double reach = contactReach();
        auto direction = [&](const Surface& s, const DVec3& arm) {
            return bulletFrictionDirection(v + glm::cross(mAngular, arm), s.normal);
        };
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            const double radius = contactArm(s);
            s.lateralDir = direction(s, -radius * s.normal);
            if (s.lateral == 0.0) continue;
            // The new closest point replaces the old one (keeping its impulses) when it lies within
            // the breaking threshold of it on the surface; otherwise the old point stays a
            // contact of its own, where the sphere's material point has turned to.
            const DVec3 shift = mPosition - s.lateralCentre;
            const bool replaced = glm::length(shift - glm::dot(shift, s.normal) * s.normal) <= reach;
            const DVec3 dir = replaced ? s.lateralDir : direction(s, s.lateralArm);
            const DVec3 warm = static_cast<double>(mProfile.frictionWarmStart) * s.lateral * dir;
            applyTangential(warm, s.normal, radius, v);
            if (replaced) s.frictionImpulse = warm;
        }
        for (int iteration = 0; iteration < kSolverIterations; ++iteration) {
            for (int i = 0; i < mCount; ++i)
                if (mSurfaces[i].acting) normalRow(mSurfaces[i], v, mSurfaces[i].target);
            for (int i = 0; i < mCount; ++i)
                if (mSurfaces[i].acting && mSurfaces[i].normalImpulse > 0.0) frictionRow(mSurfaces[i], v, 1.0);
        }
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (s.acting) s.lateral = glm::dot(s.frictionImpulse, s.lateralDir);
        }
    }

    // The acting surfaces in the order Bullet's solver meets their manifolds (BulletPairs), the
    // newer first of two on one shape. False where the pairs are not followed or a surface's
    // shape has no pair.
    bool pairOrder(int* order, int& count) const {
        if (!mTrackPairs || !mPairs.valid()) return false;
        std::array<int, kMaxSurfaces> shape{};
        int acting = 0;
        for (int i = 0; i < mCount; ++i) {
            const Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            ++acting;
            shape[i] = s.predictive ? BulletPairs::kPredictive : mPairs.shapeOn(s.touch - s.normal * mRadius);
            if (shape[i] < 0) return false;
        }
        std::array<std::uint8_t, BulletPairs::kMaxPairs + 1> manifolds{};
        const std::size_t n = mPairs.solveOrder(manifolds);
        count = 0;
        for (std::size_t m = 0; m < n; ++m)
            for (int i = mCount - 1; i >= 0; --i)
                if (mSurfaces[i].acting && shape[i] == manifolds[m]) order[count++] = i;
        return count == acting;
    }

    // Bullet 2.83's solve over every manifold point (btSequentialImpulseConstraintSolver, default
    // mode: one friction direction, warm starting). Each point is a contact of its own at its
    // material point's arm (an older point's arm is turned away from the normal, so its impulses
    // also turn the sphere): its restitution reflects the approach of that point before gravity,
    // its target closes its own distance, and its friction direction follows that point's slip
    // after gravity (before any impulse of this step). The stored normal and friction impulses of
    // every point are applied first, times Bullet's warm-starting factor (0.85 for the normal;
    // frictionWarmStart for friction); then every iteration solves all normal rows and after them
    // every friction row whose point pushes (clamped to mu times that point's normal impulse). A
    // point that ends with no normal impulse keeps its warm-started friction.
    void solveBulletManifold(const DVec3& v0, DVec3& v) {
        const double dt = mRec.dt;
        const double warmNormal = kBulletWarmStart;
        const double warmFriction = static_cast<double>(mProfile.frictionWarmStart);
        const DVec3 before = v0 * mRec.d, after = v, spin = mAngular;
        // The solver meets the manifolds in the order of the dispatcher's array after
        // btSimulationIslandManager's sort by island (btAlignedObjectArray::quickSort, unstable:
        // all of the sphere's manifolds have its island). That array holds a manifold for every
        // pair the broadphase keeps, empty ones too, and Godot 3's predictive contact's:
        // BulletPairs follows it (pairOrder). Where it cannot (a world that does not list its
        // shapes), the order it most often gives: the predictive contact's manifold first (made
        // before the narrow phase's), then the others newest first, as the sort leaves two or three
        // (a ball that met two boxes in one step ended 0.17 m/s off the engine with the older
        // first, and within 4e-5 m/s with the newer first; ammo.js, 30 Hz). The surfaces here are
        // oldest first.
        int order[kMaxSurfaces] = {}, count = 0;
        if (!pairOrder(order, count)) {
            count = 0;
            for (int i = 0; i < mCount; ++i)
                if (mSurfaces[i].acting && mSurfaces[i].predictive) order[count++] = i;
            for (int i = mCount - 1; i >= 0; --i)
                if (mSurfaces[i].acting && !mSurfaces[i].predictive) order[count++] = i;
        }
        const auto applyAt = [&](const DVec3& impulse, const DVec3& arm) { applyAtArm(impulse, arm, v); };
        const auto massAlong = [&](const DVec3& arm, const DVec3& d) { return rowMass(arm, d); };
        for (int q = 0; q < count; ++q) {
            Surface& s = mSurfaces[order[q]];
            // The predictive contact never bounces (restitution 0).
            const double e = s.predictive ? 0.0 : s.e;
            for (int j = 0; j < s.pointCount; ++j) {
                ManifoldPoint& p = s.points[j];
                const DVec3 n = p.normal;
                const double approach = glm::dot(before + glm::cross(spin, p.arm), n);
                // No bounce below the restitution threshold (Bullet 2.87 and later; ammo.js: 0).
                const bool slow = std::abs(approach) < mProfile.restitutionThreshold;
                double target = slow ? 0.0 : std::max(0.0, -e * approach);
                // A gap is the most the point may close; a shallow penetration is pushed out
                // through the velocity (erp), a deeper one by the split impulse, which moves the body
                // without staying in its velocity (solved below).
                if (p.distance > 0.0)
                    target -= p.distance / dt;
                else if (p.distance > -0.04)
                    target += mProfile.positionCorrection * -p.distance / dt;
                p.target = target;
                p.normalMass = massAlong(p.arm, n);
                p.direction = bulletFrictionDirection(after + glm::cross(spin, p.arm), n);
                p.frictionMass = massAlong(p.arm, p.direction);
            }
            for (int j = 0; j < s.pointCount; ++j) {
                ManifoldPoint& p = s.points[j];
                p.normalImpulse *= warmNormal;
                p.lateral *= warmFriction;
                applyAt(p.normalImpulse * p.normal, p.arm);
                applyAt(p.lateral * p.direction, p.arm);
            }
        }
        for (int iteration = 0; iteration < kSolverIterations; ++iteration) {
            for (int q = 0; q < count; ++q) {
                Surface& s = mSurfaces[order[q]];
                for (int j = 0; j < s.pointCount; ++j) {
                    ManifoldPoint& p = s.points[j];
                    const double vn = glm::dot(v + glm::cross(mAngular, p.arm), p.normal);
                    const double total = std::max(0.0, p.normalImpulse + p.normalMass * (p.target - vn));
                    applyAt((total - p.normalImpulse) * p.normal, p.arm);
                    p.normalImpulse = total;
                }
            }
            for (int q = 0; q < count; ++q) {
                Surface& s = mSurfaces[order[q]];
                for (int j = 0; j < s.pointCount; ++j) {
                    ManifoldPoint& p = s.points[j];
                    if (p.normalImpulse <= 0.0) continue;
                    const double limit = s.mu * p.normalImpulse;
                    const double vt = glm::dot(v + glm::cross(mAngular, p.arm), p.direction);
                    const double total = std::clamp(p.lateral - p.frictionMass * vt, -limit, limit);
                    applyAt((total - p.lateral) * p.direction, p.arm);
                    p.lateral = total;
                }
            }
        }
        // The split impulse (btSequentialImpulseConstraintSolver::
        // solveGroupCacheFriendlySplitImpulseIterations): the push velocity of every point deeper
        // than 0.04 m, solved as the velocity rows are (the same iterations and order, each
        // point's accumulated push at least 0); the shallower points take no part. Points of one
        // surface share a normal, where this is the deepest one's push; two boxes at an angle
        // share the push between them (summed, the ball ended a step 3.4 cm off ammo.js's).
        double pushed[kMaxSurfaces][kManifoldPoints] = {};
        DVec3 push(0.0);
        for (int iteration = 0; iteration < kSolverIterations; ++iteration) {
            for (int q = 0; q < count; ++q) {
                const Surface& s = mSurfaces[order[q]];
                for (int j = 0; j < s.pointCount; ++j) {
                    const ManifoldPoint& p = s.points[j];
                    if (!(p.distance <= -0.04)) continue;
                    const double target = mProfile.splitImpulseCorrection * -p.distance / dt;
                    double& accumulated = pushed[order[q]][j];
                    const double total = std::max(0.0, accumulated + target - glm::dot(push, p.normal));
                    push += (total - accumulated) * p.normal;
                    accumulated = total;
                }
            }
        }
        mPushVelocity += push;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            s.normalImpulse = 0.0;
            s.frictionImpulse = DVec3(0.0);
            for (int j = 0; j < s.pointCount; ++j) {
                s.normalImpulse += s.points[j].normalImpulse;
                s.frictionImpulse += s.points[j].lateral * s.points[j].direction;
            }
        }
    }

    // Box2D 2.4 b2ContactSolver: every touching contact (within the polygon skin) bounces when
    // its relative normal velocity before the solve, after gravity, approaches faster than the
    // restitution threshold (velocityBias = -e vRel), else its target is 0; there is no
    // speculative allowance. The impulses stored by the previous step warm-start the solve
    // (applied to the velocity first); then 8 velocity iterations, friction before the normal
    // row. The time-of-impact sub-step (`toi`) starts its accumulated impulses at zero: b2World::
    // SolveTOI's sub-step turns warm starting off (with the stored impulses as the start, a
    // ball that bounced in the discrete solve lost that bounce again in a time of impact).
    void solveBox2D(DVec3& v, bool toi) {
        // b2ContactSolver::InitializeVelocityConstraints: every target from the velocity before
        // any warm start is applied (applied first, the floor's stored impulse would lift a ball
        // wedged under a corner into a bounce off the corner).
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            const double vn = glm::dot(v, s.normal);
            s.bounce = vn < -mProfile.restitutionThreshold && s.e > 0.0;
            s.target = s.bounce ? -s.e * vn : 0.0;
            s.normalImpulse = toi ? 0.0 : s.warmNormal;
            s.frictionImpulse = toi ? DVec3(0.0) : s.warmFriction - glm::dot(s.warmFriction, s.normal) * s.normal;
        }
        for (int i = 0; i < mCount && !toi; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            v += s.normalImpulse * s.normal;
            applyTangential(s.frictionImpulse, s.normal, contactArm(s), v);
        }
        // The island lists a body's contacts newest first (b2ContactManager puts a new contact at
        // the head of the body's list), and the surfaces here are oldest first.
        for (int iteration = 0; iteration < 8; ++iteration) {
            for (int i = mCount - 1; i >= 0; --i) {
                Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                frictionRow(s, v, 1.0);
                normalRow(s, v, s.target);
            }
        }
    }

    // Box2D 2.4's continuous collision (b2World::SolveTOI): every dynamic body is swept against
    // the static shapes from its position at the step's start to where the step left it. The
    // time of impact (b2TimeOfImpact, conservative advancement) is where the distance between
    // the circle's centre and the polygon's core reaches target = r + skin - 3 slop (within a
    // quarter slop); on a face the separation is linear in time and the root finder returns the
    // midpoint of the sweep when that is within the tolerance, else the exact root. The body
    // is moved there, pushed out by up to 20 position iterations (Baumgarte 0.75, until no
    // contact is deeper than 1.5 slop), the velocity is solved again (8 iterations, restitution
    // from the velocity at that moment) and moves the body for the rest of the step. Further
    // impacts in that rest are handled alike (b2_maxSubSteps 8).
    void box2dTimeOfImpact(const DVec3& start) {
        const double dt = mRec.dt, slop = 0.005, skin = 0.01, tolerance = 0.25 * slop;
        const double target = std::max(slop, mRadius + skin - 3.0 * slop);
        DVec3 c0 = start;
        double alpha0 = 0.0;
        for (int event = 0; event < 8; ++event) {
            const DVec3 motion = mPosition - c0;
            if (glm::length(motion) <= 0.0) return;
            SegmentCast c;
            c.origin = toR(c0);
            c.displacement = toF(motion);
            c.radius = static_cast<float>(target);
            CastHit hit;
            // A shape already within the target (plus the tolerance) where the sweep starts is
            // touched at once: b2TimeOfImpact's first distance settles it (a ball that a step
            // left sunk into the floor is pushed out from there before it moves on). A cast
            // would start inside it and pass.
            if (!touchedAtStart(c0, target, tolerance, hit) && !mWorld->castSegment(c, hit)) return;
            const DVec3 n = glm::normalize(toD(hit.normal));
            const DVec3 at = toD(hit.position);
            // The separation function: along the face normal, or, at a corner, along the
            // direction from the corner to the centre where the advancement stands (e_points).
            const DVec3 corner = at - n * target;
            const bool vertex = isCorner(at, n, target);
            double t = 0.0;
            bool impact = false;
            for (int iteration = 0; iteration < 20; ++iteration) {
                const DVec3 from = c0 + motion * t;
                const double distance = vertex ? glm::length(from - corner) : target + glm::dot(from - at, n);
                if (distance < target + tolerance) {
                    impact = true;
                    break;
                }
                const DVec3 axis = vertex ? (from - corner) / distance : n;
                auto separation = [&](double u) {
                    return glm::dot(c0 + motion * u - corner, axis) +
                           (vertex ? 0.0 : target - glm::dot(at - corner, n));
                };
                const double s1 = separation(t), s2 = separation(1.0);
                if (s2 > target + tolerance) break;  // separated
                if (s2 > target - tolerance) {
                    t = 1.0;
                    continue;
                }
                // b2TimeOfImpact's root finder: bisection first, then the secant rule (exact
                // for a separation linear in time).
                const double middle = 0.5 * (t + 1.0);
                if (std::abs(separation(middle) - target) < tolerance)
                    t = middle;
                else
                    t = t + (target - s1) * (1.0 - t) / (s2 - s1);
            }
            if (!impact) return;
            const double alpha = alpha0 + (1.0 - alpha0) * t;
            if (alpha >= 1.0 - 10.0 * 1.1920929e-7) return;
            DVec3 p = c0 + motion * t;
            if (mProfile.planar) p.z = start.z;

            // The contacts touching there: the one hit, and the others within the skin.
            CastHit surface = hit;
            surface.position = toR(at + n * (mRadius - target));
            DVec3 touch = toD(surface.position), normal = n;
            if (vertex && glm::length(p - corner) > 0.0) {
                // b2CollidePolygonAndCircle in a vertex region: the normal from the corner to
                // the centre where the time of impact left it.
                normal = glm::normalize(p - corner);
                touch = corner + normal * mRadius;
            }
            // Box2D keeps one manifold point per polygon (b2CollidePolygonAndCircle), in a vertex
            // region with the normal from the corner to the centre where the contact is updated.
            // The same corner measured earlier (from where the step started, with another normal),
            // or a face through that corner known from earlier, is that one contact.
            bool merged = false;
            for (int i = 0; vertex && i < mCount;) {
                Surface& o = mSurfaces[i];
                const DVec3 point = o.touch - o.normal * mRadius;
                // 0.1 mm: both come from float casts (rounding of about 1e-6 of the coordinates).
                const bool sameCorner = glm::length(point - corner) <= 1e-4;
                const bool throughCorner = std::abs(glm::dot(corner - point, o.normal)) <= 1e-4;
                if (!sameCorner && !throughCorner) {
                    ++i;
                    continue;
                }
                if (merged) {  // a second surface of the same polygon: gone
                    o = mSurfaces[--mCount];
                    continue;
                }
                o.normal = normal;
                o.touch = touch;
                merged = true;
                ++i;
            }
            if (!merged && !isKnown(normal, touch, mCount) && mCount < kMaxSurfaces) {
                Surface& s = mSurfaces[mCount++];
                s = Surface{};
                s.normal = normal;
                s.touch = touch;
                s.restitution = hit.restitution;
                s.friction = hit.friction;
            }
            for (int i = 0; i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                s.gap = glm::dot(p - s.touch, s.normal);
                const bool touching = s.gap < skin;
                if (touching && !s.acting) {
                    s.warmNormal = 0.0;
                    s.warmFriction = DVec3(0.0);
                }
                s.acting = touching;
                if (!touching) continue;
                s.e = s.restitution >= 0.0f
                          ? combineMaterial(mProfile.restitutionCombine, mSettings.restitution, s.restitution)
                          : mSettings.restitution;
                s.mu = s.friction >= 0.0f ? combineMaterial(mProfile.frictionCombine, mSettings.friction, s.friction)
                                          : mSettings.friction;
            }
            // b2ContactSolver::SolveTOIPositionConstraints.
            for (int iteration = 0; iteration < 20; ++iteration) {
                double deepest = 0.0;
                for (int i = 0; i < mCount; ++i) {
                    const Surface& s = mSurfaces[i];
                    if (!s.acting) continue;
                    const double sep = glm::dot(p - s.touch, s.normal) - skin;
                    deepest = std::min(deepest, sep);
                    p -= s.normal * std::clamp(0.75 * (sep + slop), -0.2, 0.0);
                }
                // Done once no contact was deeper than 1.5 slop. After a time of impact on a face
                // the first iteration leaves exactly that depth, which Box2D's float arithmetic
                // finds not quite reached: one more iteration follows.
                if (deepest > -1.5 * slop + 1e-9) break;
            }
            c0 = p;
            // The velocity constraints are set up where the position solve left the body.
            for (int i = 0; i < mCount; ++i) mSurfaces[i].gap = glm::dot(p - mSurfaces[i].touch, mSurfaces[i].normal);
            DVec3 v = mVelocity;
            double approach[kMaxSurfaces] = {}, impulse[kMaxSurfaces] = {};
            for (int i = 0; i < mCount; ++i) {
                approach[i] = -glm::dot(v, mSurfaces[i].normal);
                impulse[i] = mSurfaces[i].normalImpulse;
            }
            solveBox2D(v, true);
            // The step's impulse on a surface is the largest of its solves: a second impact at
            // once (a point, whose target lies above where the push-out stops) solves an already
            // leaving velocity to nothing.
            for (int i = 0; i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                if (s.acting) s.approach = std::max(s.approach, approach[i]);
                s.normalImpulse = std::max(s.normalImpulse, impulse[i]);
            }
            const double h = (1.0 - alpha) * dt;
            const double travel = glm::length(v) * h;
            if (travel > mProfile.maxStepDistance) v *= mProfile.maxStepDistance / travel;
            limitBox2DRotation(h);
            p += v * h;
            if (mProfile.planar) p.z = start.z;
            mVelocity = v;
            mPosition = p;
            alpha0 = alpha;
        }
    }

    // For Box2D's time of impact: the nearest shape whose closest point lies within
    // `target + tolerance` of `centre` but not at it (b2TimeOfImpact gives up on shapes that
    // overlap the centre), as the hit of a cast of radius `target` that stopped there: `hit`'s
    // position is the closest point moved `target` out along the normal. False when there is
    // none or the world does not answer closest-point queries.
    bool touchedAtStart(const DVec3& centre, double target, double tolerance, CastHit& hit) const {
        const double limit = target + tolerance;
        NearSurface nearest;
        const bool found = nearestSurface(centre, limit, nearest, [&](const NearSurface& surface) {
            if (!(surface.distance > 0.0f) || !(surface.distance < limit)) return false;
            return !(mProfile.planar && std::abs(surface.normal.z) > 0.5f);
        });
        if (!found) return false;
        const DVec3 n = glm::normalize(toD(nearest.normal));
        hit.position = toR(toD(nearest.point) + n * target);
        hit.normal = toF(n);
        hit.restitution = nearest.restitution;
        hit.friction = nearest.friction;
        return true;
    }

    // The nearest surface within `radius` of `centre` that `accept` takes (the first of equally
    // near ones, in the world's order), by the world's closest-point query. False when there is
    // none, or the world does not answer the query.
    template <class Accept>
    bool nearestSurface(const DVec3& centre, double radius, NearSurface& nearest, Accept&& accept) const {
        struct Collector final : NearCollector {
            Accept& accept;
            NearSurface& nearest;
            bool found = false;
            Collector(Accept& a, NearSurface& n) : accept(a), nearest(n) {}
            void add(const NearSurface& surface) override {
                if (!accept(surface) || (found && !(surface.distance < nearest.distance))) return;
                nearest = surface;
                found = true;
            }
        } collector(accept, nearest);
        NearQuery query;
        query.center = toR(centre);
        query.radius = static_cast<float>(radius);
        return mWorld->findNear(query, collector) && collector.found;
    }

    // Whether a sphere cast (radius `radius`) that stopped with its centre at `centre` and the
    // normal n touched a corner: probes beside it, along -n, find the same face or not.
    bool isCorner(const DVec3& centre, const DVec3& n, double radius) const {
        DVec3 side = glm::cross(n, DVec3(0.0, 0.0, 1.0));
        if (glm::length(side) < 1e-6) side = glm::cross(n, DVec3(1.0, 0.0, 0.0));
        side = glm::normalize(side) * 1e-3;
        for (const double sign : {-1.0, 1.0}) {
            SegmentCast probe;
            probe.origin = toR(centre + n * 0.01 + side * sign);
            probe.displacement = toF(-n * 0.02);
            probe.radius = static_cast<float>(radius);
            CastHit hit;
            if (!mWorld->castSegment(probe, hit)) return true;
            if (glm::dot(glm::normalize(toD(hit.normal)), n) < 1.0 - 1e-6) return true;
        }
        return false;
    }

    // PhysX 4.1 PGS: biased rows (push-out, speculative allowance) in 4 position iterations with
    // friction in the last 3 at 0.8 relaxation; the position moves with that velocity; one
    // unbiased velocity iteration gives the stored velocity.
    void solvePhysX(DVec3& v) {
        const double dt = mRec.dt;
        double biased[kMaxSurfaces] = {}, unbiased[kMaxSurfaces] = {};
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            const double vn = glm::dot(v, s.normal);
            choosePhysXTangent(s, v);
            s.bounce = s.e > 0.0 && vn < -mProfile.restitutionThreshold && -vn > s.gap / dt;
            const double target = s.bounce ? -s.e * vn : 0.0;
            const double bias = s.bounce ? 0.0 : mProfile.positionCorrection * s.gap / dt;
            biased[i] = target - bias;
            unbiased[i] = s.bounce ? target : target - std::max(bias, 0.0);
        }
        for (int iteration = 0; iteration < 4; ++iteration) {
            for (int i = 0; i < mCount; ++i) {
                Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                normalRow(s, v, biased[i]);
                if (iteration > kPhysXFrictionSkip) frictionRowsPhysX(s, v);
            }
        }
        const DVec3 positionVelocity = v;
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            normalRow(s, v, unbiased[i]);
            frictionRowsPhysX(s, v);
        }
        mPushVelocity = positionVelocity - v;
    }

    // Rapier 0.21 (rapier.js; the Rust solver's TGS-soft): the contacts of the step start,
    // solved in each of its `substeps` sub-steps h = dt / n. A sub-step adds gravity, re-applies
    // the impulses of the previous sub-step (warm start), solves the normal rows with soft
    // push-out (no friction in this biased pass), moves the body, then solves once more without
    // bias: normal rows, then friction (two tangent rows at the contact point, clamped to the
    // disk of mu times this sub-step's normal impulse). The contact point is frozen on both
    // bodies at the step start (midway between the surfaces); the sphere's anchor turns with
    // it, so a rolling sphere's separation grows within the step. After the sub-steps a contact
    // that is new (no impulse in the previous step) and pushed in this one bounces: its normal
    // velocity becomes e times the approach at the step start. Damping comes last.
    void solveRapier(const DVec3& v0, DVec3& v) {
        const double dt = mRec.dt;
        const int n = static_cast<int>(mProfile.substeps);
        const double h = dt / n;
        // Contacts against fixed bodies (IntegrationParameters::static_contact_softness): a
        // 60 Hz spring with damping ratio 10, evaluated for the sub-step.
        const double omega = 2.0 * M_PI * 60.0, zeta = 10.0;
        const double erpInvDt = omega / (h * omega + 2.0 * zeta);
        const double erp = h * erpInvDt;
        const double cfmCoefficient = (1.0 / erp - 1.0) * (1.0 / erp - 1.0) / ((1.0 / erp) * 4.0 * zeta * zeta);
        const double cfmFactor = 1.0 / (1.0 + cfmCoefficient);
        const double maxCorrective = 3.0;         // normalized_max_corrective_velocity [m/s]
        const double maxSpin = 0.25 * M_PI / dt;  // at most 45 degrees of rotation per step
        // Per unit mass; 0 when the sphere does not turn (rotation locked, or a point).
        const double invInertia = mRotates ? inverseInertiaFactor() / (mRadius * mRadius) : 0.0;
        DVec3 vel = v0;  // undamped: damping is applied after the sub-steps
        const DVec3 start = mPosition;
        DVec3 x = mPosition;
        double lambda[kMaxSurfaces] = {}, total[kMaxSurfaces] = {}, seed[kMaxSurfaces] = {}, arm[kMaxSurfaces] = {};
        DVec3 anchor[kMaxSurfaces] = {};  // the sphere's contact point from its centre, turning with it
        // The solver's order: a contact with a static body takes the highest colour its body
        // has free when it appears (narrow_phase::assign_pair_solver_color) and keeps it while
        // it lasts; colours are solved in increasing order, so the newest contact comes first.
        int order[kMaxSurfaces] = {};
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            order[i] = i;
            if (!s.acting || s.color >= 0) continue;
            int color = 127;
            for (bool taken = true; taken && color > 0;) {
                taken = false;
                for (int j = 0; j < mCount; ++j)
                    if (j != i && mSurfaces[j].color == color) taken = true;
                if (taken) --color;
            }
            s.color = color;
        }
        for (int i = 1; i < mCount; ++i)
            for (int j = i; j > 0 && mSurfaces[order[j - 1]].color > mSurfaces[order[j]].color; --j)
                std::swap(order[j - 1], order[j]);
        for (int i = 0; i < mCount; ++i) {
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            const double vn0 = glm::dot(v0, s.normal);
            s.bounce = (!s.carried || s.e >= 1.0) && s.e > 0.0 && vn0 < 0.0;
            seed[i] = s.bounce ? s.e * vn0 : 0.0;
            arm[i] = mRotates ? std::max(0.0, mRadius + 0.5 * s.gap) : 0.0;
            anchor[i] = -arm[i] * s.normal;
            lambda[i] = s.warmNormal;
            s.warmFriction -= glm::dot(s.warmFriction, s.normal) * s.normal;
        }
        for (int sub = 0; sub < n; ++sub) {
            vel += mGravity * h;
            // Warm start: the previous sub-step's impulses once more.
            for (int q = 0; q < mCount; ++q) {
                const int i = order[q];
                Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                vel += lambda[i] * s.normal;
                applyRapierFriction(s.warmFriction, anchor0(s, arm[i]), invInertia, vel);
            }
            // Biased pass: normal rows only.
            for (int q = 0; q < mCount; ++q) {
                const int i = order[q];
                Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                const double dist =
                    s.gap + glm::dot(x - start, s.normal) + glm::dot(anchor[i] - anchor0(s, arm[i]), s.normal);
                const double rhs = std::max(dist, 0.0) / h + std::clamp(dist * erpInvDt, -maxCorrective, 0.0);
                const double cf = dist <= 0.0 ? cfmFactor : 1.0;
                const double next = cf * std::max(0.0, lambda[i] - (glm::dot(vel, s.normal) + rhs));
                vel += (next - lambda[i]) * s.normal;
                lambda[i] = next;
            }
            if (mRotates) {
                const double spin = glm::length(mAngular);
                if (spin > maxSpin) mAngular *= maxSpin / spin;
            }
            x += vel * h;
            if (mRotates) turnAnchors(anchor, h);
            // Unbiased pass: normal rows, then friction.
            for (int q = 0; q < mCount; ++q) {
                const int i = order[q];
                Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                const double dist =
                    s.gap + glm::dot(x - start, s.normal) + glm::dot(anchor[i] - anchor0(s, arm[i]), s.normal);
                const double next = std::max(0.0, lambda[i] - (glm::dot(vel, s.normal) + std::max(dist, 0.0) / h));
                vel += (next - lambda[i]) * s.normal;
                lambda[i] = next;
                const DVec3 r = anchor0(s, arm[i]);
                DVec3 slip = vel + glm::cross(mAngular, r);
                slip -= glm::dot(slip, s.normal) * s.normal;
                const double k = 1.0 + (mRotates ? invInertia * arm[i] * arm[i] : 0.0);
                DVec3 impulse = s.warmFriction - slip / k;
                const double limit = s.mu * lambda[i], size = glm::length(impulse);
                if (size > limit) impulse *= size > 0.0 ? limit / size : 0.0;
                applyRapierFriction(impulse - s.warmFriction, r, invInertia, vel);
                s.warmFriction = impulse;
                total[i] += lambda[i];
            }
        }
        // Restitution, once after the sub-steps.
        for (int q = 0; q < mCount; ++q) {
            const int i = order[q];
            Surface& s = mSurfaces[i];
            if (!s.acting) continue;
            if (seed[i] < 0.0 && total[i] > 0.0) {
                const double next = std::max(0.0, lambda[i] - (glm::dot(vel, s.normal) + seed[i]));
                vel += (next - lambda[i]) * s.normal;
                total[i] += next - lambda[i];
                lambda[i] = next;
            }
            s.warmNormal = lambda[i];
            s.normalImpulse = total[i];
            s.frictionImpulse = s.warmFriction;
        }
        mSubstepPosition = x;
        v = vel * mRec.d;
    }

    // The sphere's contact point on surface s at the step start, from the centre.
    static DVec3 anchor0(const Surface& s, double arm) { return -arm * s.normal; }

    // The contact anchors turn with the sphere: a sub-step's rotation, linearised as Rapier
    // integrates it (the quaternion (w h / 2, 1), normalised).
    void turnAnchors(DVec3* anchor, double h) const {
        const double spin = glm::length(mAngular);
        if (spin <= 0.0) return;
        const double angle = 2.0 * std::atan(0.5 * spin * h);
        const DVec3 k = mAngular / spin;
        const double c = std::cos(angle), sn = std::sin(angle);
        for (int i = 0; i < mCount; ++i) {
            if (!mSurfaces[i].acting) continue;
            const DVec3 a = anchor[i];
            anchor[i] = a * c + glm::cross(k, a) * sn + k * (glm::dot(k, a) * (1.0 - c));
        }
    }

    // A friction impulse (per unit mass) at the contact point r from the centre.
    void applyRapierFriction(const DVec3& impulse, const DVec3& r, double invInertia, DVec3& v) {
        v += impulse;
        if (mRotates) mAngular += invInertia * glm::cross(r, impulse);
    }

    // Rapier's continuous collision detection (CCDSolver::solve_continuous): a body that moved
    // more than half its radius in the step (its centre, plus the rotation at its surface) is
    // swept from the step's start to its end against the static shapes, and stops at the first
    // pose where it penetrates one by the allowed linear error. The time of impact is parry's
    // (Box2D's conservative advancement): from the closest points at the time reached so far,
    // the motion advances until the separation along that axis reaches the target, until the
    // distance is within a quarter of the allowed error above the target (on a face exactly the
    // target; past an edge up to that much less deep). A sweep that starts within that tolerance
    // finds the impact at once and is ignored, as is one whose end does not reach below the
    // target by the tolerance. The velocity is left alone: the contact found at the next step's
    // start deals with it.
    void rapierSweep(const DVec3& before) {
        const DVec3 motion = mPosition - before;
        const double turn =
            2.0 * std::atan(0.5 * glm::length(mAngular) * mRec.dt / mProfile.substeps) * mProfile.substeps * mRadius;
        if (glm::length(motion) + (mRotates ? turn : 0.0) <= 0.5 * mRadius) return;
        const double slop = mProfile.penetrationSlop, tolerance = 0.25 * slop;
        if (mRadius <= 2.0 * slop) return;
        SegmentCast c;
        c.origin = toR(before);
        c.displacement = toF(motion);
        c.radius = static_cast<float>(mRadius - slop - tolerance);
        CastHit hit;
        if (!mWorld->castSegment(c, hit) || hit.fraction <= 0.0f) return;
        const double target = mRadius - slop;
        DVec3 axis = glm::normalize(toD(hit.normal));
        double t = 0.0, distance = 0.0;
        const double range = mRadius + glm::length(motion) + 0.05;
        if (!closestDistance(before, range, axis, distance)) return;
        for (int iteration = 0; iteration < 20; ++iteration) {
            if (distance < target + tolerance) {
                if (t > 0.0 && t < 1.0) mPosition = before + motion * t;
                return;
            }
            // The separation along the axis is linear in time: where does it reach the target?
            const DVec3 at = before + motion * t;
            const double end = distance + glm::dot(mPosition - at, axis);
            if (end > target - tolerance) return;
            t += (1.0 - t) * (distance - target) / (distance - end);
            if (!closestDistance(before + motion * t, range, axis, distance)) return;
        }
    }

    // The distance from centre `c` to the nearest surface near direction -`axis`, within `range`;
    // `axis` becomes the direction from that surface's closest point to c (a few probes converge
    // on an edge or corner). False when a probe finds nothing.
    bool closestDistance(const DVec3& c, double range, DVec3& axis, double& distance) const {
        // Each probe's distance is a lower bound (the contact's tangent plane supports the
        // shape); a probe sphere just smaller than the distance touches at the closest point.
        double probe = 0.5 * mRadius;
        const double lift = 0.05;
        for (int iteration = 0; iteration < 6; ++iteration) {
            SegmentCast cast;
            cast.origin = toR(c + axis * lift);
            cast.displacement = toF(c - axis * range - toD(cast.origin));
            cast.radius = static_cast<float>(probe);
            CastHit hit;
            if (!mWorld->castSegment(cast, hit)) return nearestInFront(c, range, axis, distance);
            const DVec3 n = glm::normalize(toD(hit.normal));
            const bool settled = glm::dot(n, axis) > 1.0 - 1e-10;
            axis = n;
            distance = glm::dot(c - toD(hit.position), n) + probe;
            if (settled && iteration > 0) break;
            probe = std::max(0.1 * mRadius, distance - 1e-3);
        }
        return true;
    }

    // closestDistance where its probe along -`axis` passes beside the shape (a ball that a step
    // carries into the underside of a tilted box's edge: the sweep meets the edge, the probe from
    // the step's start along the edge's normal misses the box): the world's closest points within
    // `range` of `c`, the nearest of those facing `axis` (normal within 90 degrees of it).
    bool nearestInFront(const DVec3& c, double range, DVec3& axis, double& distance) const {
        NearSurface nearest;
        if (!nearestSurface(c, range, nearest,
                            [&](const NearSurface& surface) { return glm::dot(toD(surface.normal), axis) > 0.0; }))
            return false;
        axis = glm::normalize(toD(nearest.normal));
        distance = static_cast<double>(nearest.distance);
        return true;
    }

    // One friction row at the contact point, clamped to the disk of mu times the normal impulse.
    // The tangential effective mass per unit mass is 1 / (1 + arm^2 / (k R^2)) for a body of
    // inertia k m R^2 (solid sphere k = 2/5: 1 / 3.5 at the surface; Box2D's disk k = 1/2: 1 / 3),
    // 1 without rotation.
    void frictionRow(Surface& s, DVec3& v, double relaxation) {
        const double radius = contactArm(s);
        const DVec3 arm = -radius * s.normal;
        const double tangentialMass =
            mRotates ? 1.0 / (1.0 + inverseInertiaFactor() * (radius * radius) / (mRadius * mRadius)) : 1.0;
        DVec3 slip = v + glm::cross(mAngular, arm);
        slip -= glm::dot(slip, s.normal) * s.normal;
        DVec3 total = s.frictionImpulse - slip * (tangentialMass * relaxation);
        const double limit = s.mu * s.normalImpulse;
        const double size = glm::length(total);
        if (size > limit) total *= size > 0.0 ? limit / size : 0.0;
        applyTangential(total - s.frictionImpulse, s.normal, radius, v);
        s.frictionImpulse = total;
    }

    // PhysX 4.1 patch friction (DyContactPrep.cpp): two 1-D rows along orthogonal tangents t0 and
    // t1 = n x t0 at the friction anchor, each clamped on its own to +- mu times the normal
    // impulse (a box, not the disk), with the velocity multiplier 0.8 / response. t0 is the
    // tangential part of the body's linear velocity when the step's contacts are prepared (after
    // gravity), or, when that is below 0.01 m/s, (1, 0, 0) x n ((0, 0, 1) x n when |n.x| >= 0.7071).
    void frictionRowsPhysX(Surface& s, DVec3& v) {
        const DVec3 n = s.normal;
        const double radius = contactArm(s);
        const DVec3 arm = -radius * n;
        const double mass =
            mRotates ? 0.8 / (1.0 + inverseInertiaFactor() * (radius * radius) / (mRadius * mRadius)) : 0.8;
        const DVec3 tangents[2] = {s.tangent, glm::cross(n, s.tangent)};
        const double limit = s.mu * s.normalImpulse;
        for (int row = 0; row < 2; ++row) {
            const DVec3& t = tangents[row];
            const double applied = glm::dot(s.frictionImpulse, t);
            const double slip = glm::dot(v + glm::cross(mAngular, arm), t);
            const double total = std::clamp(applied - mass * slip, -limit, limit);
            applyTangential((total - applied) * t, n, radius, v);
            s.frictionImpulse += (total - applied) * t;
        }
    }

    // Bullet's friction direction for a contact with normal `n` whose point moves with
    // `velocity` (btSequentialImpulseConstraintSolver::convertContact, default solver mode): the
    // tangential part of that velocity, or btPlaneSpace1's first axis when its square is below
    // SIMD_EPSILON (float).
    static DVec3 bulletFrictionDirection(const DVec3& velocity, const DVec3& n) {
        const DVec3 slip = velocity - glm::dot(velocity, n) * n;
        const double length2 = glm::dot(slip, slip);
        if (length2 > 1.1920929e-07) return slip / std::sqrt(length2);
        if (std::abs(n.z) > 0.70710678) return glm::normalize(DVec3(0.0, -n.z, n.y));
        return glm::normalize(DVec3(-n.y, n.x, 0.0));
    }

    // Bullet 3: one friction direction per contact, set once per step from the contact point's
    // velocity when the solve starts (gravity included). With two contacts (a wall beside the
    // floor) the slip at one turns while the other acts; the row stays on its direction, where
    // a disk would follow the slip.
    void chooseBulletTangent(Surface& s, const DVec3& v) const {
        s.tangent = bulletFrictionDirection(v + glm::cross(mAngular, -contactArm(s) * s.normal), s.normal);
    }

    // Bullet 3's friction row along the contact's one direction, clamped to +- mu times the
    // contact's normal impulse so far.
    void frictionRowBullet(Surface& s, DVec3& v) {
        const double radius = contactArm(s);
        const DVec3 arm = -radius * s.normal;
        const double mass =
            mRotates ? 1.0 / (1.0 + inverseInertiaFactor() * (radius * radius) / (mRadius * mRadius)) : 1.0;
        const double applied = glm::dot(s.frictionImpulse, s.tangent);
        const double slip = glm::dot(v + glm::cross(mAngular, arm), s.tangent);
        const double limit = s.mu * s.normalImpulse;
        const double total = std::clamp(applied - mass * slip, -limit, limit);
        applyTangential((total - applied) * s.tangent, s.normal, radius, v);
        s.frictionImpulse = total * s.tangent;
    }

    // PhysX sets the friction directions up again in every step's contact preparation.
    static void choosePhysXTangent(Surface& s, const DVec3& v) {
        const DVec3 n = s.normal;
        const DVec3 fallback = std::abs(n.x) < 0.70710678 ? DVec3(0.0, -n.z, n.y) : DVec3(-n.y, n.x, 0.0);
        const DVec3 t0 = v - glm::dot(n, v) * n;
        s.tangent = glm::normalize(glm::dot(t0, t0) > 1e-4 ? t0 : fallback);
    }

    // The lever arm of the contact point from the centre: the sphere's surface, except in Jolt,
    // whose contact point is midway between the two surfaces (half the gap further out, or in),
    // and in PhysX, whose contact point (the friction anchor) lies on the static shape's surface.
    double contactArm(const Surface& s) const {
        // Jolt: deeper than the diameter's half that point lies beyond the centre: the lever
        // turns over.
        if (mProfile.engine == PhysicsEngine::Jolt) return mRadius + 0.5 * s.gap;
        if (mProfile.engine == PhysicsEngine::PhysX) return mRadius + s.gap;  // negative: centre inside the box
        if (s.predictive) return 0.0;
        // Box2D: midway between the circle's surface and the polygon's skin (0.01 m).
        if (mProfile.engine == PhysicsEngine::Box2D) return mRadius + 0.5 * (s.gap - 0.01);
        return mRadius;
    }

    void applyTangential(const DVec3& impulse, const DVec3& normal, double arm, DVec3& v) {
        v += impulse;
        if (mRotates) {
            // dw = I^-1 (r x P) with r = -arm n and I = k m R^2 (k = 2/5 sphere, 1/2 disk).
            mAngular += -(inverseInertiaFactor() * arm / (mRadius * mRadius)) * glm::cross(normal, impulse);
        }
    }

    // An impulse (per unit mass) at `arm` from the centre: the velocity and the spin it adds.
    void applyAtArm(const DVec3& impulse, const DVec3& arm, DVec3& v) {
        v += impulse;
        mAngular += armInverseInertia() * glm::cross(arm, impulse);
    }

    // The mass (per unit mass) that a row along `d` at `arm` from the centre meets.
    double rowMass(const DVec3& arm, const DVec3& d) const {
        const DVec3 c = glm::cross(arm, d);
        return 1.0 / (1.0 + armInverseInertia() * glm::dot(c, c));
    }

    // The inverse inertia per unit mass [1/m^2]; 0 when the body does not turn.
    double armInverseInertia() const { return mRotates ? inverseInertiaFactor() / (mRadius * mRadius) : 0.0; }

    // 1 / k for the body's inertia k m R^2: a solid sphere (k = 2/5), Box2D's disk (k = 1/2).
    double inverseInertiaFactor() const { return mProfile.planar ? 2.0 : 2.5; }

    // One normal row with accumulated clamping: the sphere leaves the surface at `target` or
    // faster, and the total impulse never pulls.
    static void normalRow(Surface& s, DVec3& v, double target) {
        const double accumulated = std::max(0.0, s.normalImpulse + (target - glm::dot(v, s.normal)));
        v += (accumulated - s.normalImpulse) * s.normal;
        s.normalImpulse = accumulated;
    }

    // Rotates v by the rotation vector `turn` (axis times angle), as Jolt's Body::AddRotationStep.
    static DVec3 rotated(const DVec3& v, const DVec3& turn) {
        const double angle = glm::length(turn);
        if (angle <= 1e-6) return v;
        const DVec3 k = turn / angle;
        return v * std::cos(angle) + glm::cross(k, v) * std::sin(angle) +
               k * (glm::dot(k, v) * (1.0 - std::cos(angle)));
    }

    // Jolt's ContactConstraintManager::SolvePositionConstraints (mNumPositionSteps = 2, Baumgarte
    // 0.2, slop 0.02, at most mMaxPenetrationDistance 0.2 per iteration). The contact points were
    // found at the step's start: one on the surface, fixed in the world, one on the sphere
    // (centre - r n), which moves and turns with the body. The separation is measured between
    // them, and the correction acts at their midpoint: once the sphere has slid along the
    // surface that point is off the normal through the centre, so part of the correction turns
    // the sphere instead of moving it (effective mass 1 / (1/m + |r x n|^2 / I)).
    void correctJoltPositions(const DVec3& start) {
        std::array<DVec3, kMaxSurfaces> anchor{}, arm{};
        const DVec3 turn = mAngular * mRec.dt;
        for (int i = 0; i < mCount; ++i) {
            const Surface& s = mSurfaces[i];
            anchor[i] = start - (s.gap + mRadius) * s.normal;
            arm[i] = rotated(-mRadius * s.normal, turn);
        }
        // Per unit mass; 0 when the sphere does not turn (rotation locked, or a point: radius 0
        // would divide by zero).
        const double invInertia = mRotates ? inverseInertiaFactor() / (mRadius * mRadius) : 0.0;
        for (int iteration = 0; iteration < 2; ++iteration) {
            for (int i = 0; i < mCount; ++i) {
                const Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                const DVec3 p2 = mPosition + arm[i];
                const double separation = std::max(glm::dot(p2 - anchor[i], s.normal) + mProfile.penetrationSlop, -0.2);
                if (separation >= 0.0) continue;
                const DVec3 r2 = 0.5 * (anchor[i] + p2) - mPosition;
                const DVec3 r2xn = glm::cross(r2, s.normal);
                const double lambda =
                    -mProfile.positionCorrection * separation / (1.0 + invInertia * glm::dot(r2xn, r2xn));
                mPosition += lambda * s.normal;
                const DVec3 spin = lambda * invInertia * r2xn;
                for (int j = 0; j < mCount; ++j) arm[j] = rotated(arm[j], spin);
            }
        }
    }

    // Position-based correction after the move (Jolt: 2 iterations of 0.2 beyond the 0.02 slop,
    // capped at 0.2 m; Box2D: 3 iterations of 0.2 towards a 0.005 m gap; custom: one of
    // positionCorrection beyond penetrationSlop).
    void correctPositions() {
        if (mProfile.correctionIsVelocity || mProfile.positionCorrection <= 0.0f) return;
        const PhysicsEngine engine = mProfile.engine;
        if (engine == PhysicsEngine::Rapier) return;  // its sub-steps pushed out already
        const int iterations = engine == PhysicsEngine::Jolt ? 2 : engine == PhysicsEngine::Box2D ? 3 : 1;
        for (int iteration = 0; iteration < iterations; ++iteration) {
            double deepest = 0.0;  // Box2D: the deepest separation met in this iteration
            for (int i = 0; i < mCount; ++i) {
                const Surface& s = mSurfaces[i];
                if (!s.acting) continue;
                const double gap = glm::dot(mPosition - s.touch, s.normal);
                deepest = std::min(deepest, gap - 0.01);
                if (engine == PhysicsEngine::Jolt) {
                    const double c = std::max(gap + mProfile.penetrationSlop, -0.2);
                    if (c < 0.0) mPosition -= s.normal * (mProfile.positionCorrection * c);
                } else if (engine == PhysicsEngine::Box2D) {
                    const double c = std::clamp(mProfile.positionCorrection * (gap - 0.005), -0.2, 0.0);
                    mPosition -= s.normal * c;
                } else {
                    const double depth = -gap - mProfile.penetrationSlop;
                    if (depth > 0.0) mPosition += s.normal * (mProfile.positionCorrection * depth);
                }
            }
            // b2ContactSolver::SolvePositionConstraints: done once no contact was deeper than
            // 3 slop (separation below the skin) when the iteration began.
            if (engine == PhysicsEngine::Box2D && deepest >= -3.0 * 0.005) break;
        }
    }

    const ProjectileSettings& mSettings;
    const EngineProfile& mProfile;
    const CollisionWorld* mFullWorld;  // the world the prediction runs in
    const CollisionWorld* mWorld;      // mFullWorld, mLocal in a step, or a PlaneWorld while contactCoast tries steps
    LocalWorld mLocal;                 // the shapes gathered around the sphere (nearWorld)
    BulletPairs mPairs;                // the Bullet profiles: Bullet's pairs and manifolds
    bool mTrackPairs = false;
    int mGatherFailures = 0;  // gathers refused in a row (3: the world cannot, stop asking)
    TrajectoryRecorder& mRecorder;
    ProjectileResult& mResult;
    EngineRecurrence mRec;
    DVec3 mGravity{0.0};
    double mRadius = 0.0;
    bool mRotates = false;
    bool mRegionQueries = true;   // whether coast and contactCoast may ask the world's region queries
    bool mMeshContacts = false;   // Bullet's rules for a triangle mesh (EngineProfile::triangleMesh)
    bool mManifold = false;       // Bullet 2.83's multi-point manifolds (updateManifold)
    bool mGodotContacts = false;  // GodotPhysics' persistent contacts (updateGodotContacts)
    DVec3 mBiasedSpin{0.0};       // GodotPhysics: the bias rows' spin of this step [rad/s]
    double mAngularFactor = 1.0;
    DVec3 mPosition{0.0}, mVelocity{0.0}, mAngular{0.0};
    std::array<Surface, kMaxSurfaces> mSurfaces{};
    DVec3 mPushVelocity{0.0};     // moves the position this step but is not kept in the velocity
    DVec3 mSubstepPosition{0.0};  // Rapier: the position its sub-steps reached
    int mCount = 0;
    bool mTouching = false;
    // Bullet's own float state (Bullet 3.24, Godot 3's Bullet) while the flight is free (startFloatFlight).
    bool mFloatFlight = false;
    float mFloatDamping = 1.0f;
    bool mFloatFirstStep = false;  // the next float step is Godot's first: no gravity
    detail::BulletVec mFloatGravityStep, mFloatPosition, mFloatVelocity;
    std::uint64_t mCoastSteps = 8;    // the next coast's horizon [steps]
    std::uint64_t mContactSteps = 8;  // the next contactCoast's horizon [steps]
    int mContactWait = 0;             // steps to take one at a time before contactCoast again
    std::array<DVec3, kMaxCoastSteps + 1> mCoastPositions{}, mCoastVelocities{};
    DVec3 mLastNormal{0.0};     // the last real impact's normal
    DVec3 mContactNormal{0.0};  // this step's strongest contact's normal
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
