#pragma once
/// @file bullet_simulation.h
/// A projectile as a real Bullet rigid body: the reference the predictors are compared with
/// (`foresight compare`). A reference tool, not a per-frame API: it allocates (the sample and
/// impact vectors, Bullet's body and contact caches) and takes one step per 1/frequency s.
///
/// How Bullet is set up, and why (each choice brings Bullet closer to an ideal impulsive bounce,
/// `v_n -> -e v_n` at the instant of contact, which is what the predictors model):
/// - The body: a btSphereShape of the projectile's radius (RigidBodySimulationSettings::
///   pointRadius for a point), mass 1, restitution and friction from ProjectileSettings (the
///   scene's static objects have 1 and 1, and Bullet multiplies, see BulletScene), rolling and
///   spinning friction 0, linear and angular damping 0, no deactivation, its own gravity
///   (BT_DISABLE_WORLD_GRAVITY: the world's gravity is left alone). lockRotation sets the angular
///   factor to 0: the sphere slides as the predictors' point mass does.
/// - Contacts are solved only once they touch: the body's contact processing threshold is 0.
///   Bullet's default solves "speculative" contacts up to the contact breaking threshold (2 cm)
///   ahead, and for those it asks for `v_n = e * |v_n| - gap / dt`: the rebound loses gap/dt,
///   up to the whole approach speed (at 960 Hz almost every bounce would be damped).
/// - btContactSolverInfo, for the duration of the call (restored afterwards):
///   m_restitutionVelocityThreshold 0 (Bullet's default 0.2 m/s applies no restitution to slower
///   impacts, which would end every bounce series early); split impulse for every penetration
///   (m_splitImpulse on, m_splitImpulsePenetrationThreshold 0: penetration is removed by a
///   position-only push, never by Baumgarte velocity, which would add up to erp * depth / dt of
///   rebound speed); m_erp2 1 (the push removes the whole penetration in one step, so the
///   rebound starts from the surface); no warm starting (each step's impulses are solved from
///   zero, nothing carries over from an earlier contact); 30 iterations (a sphere has few
///   contacts; a single contact is exact after one).
/// - CCD: a sphere that moves more than half its radius in a step is swept (setCcdMotionThreshold
///   0.5 r) with a sphere of 0.8 r (setCcdSweptSphereRadius), and the world's
///   m_allowedCcdPenetration is 0 for the call: without it a small fast sphere passes through
///   thin triangles between two steps. A clamped step stops the sphere 0.2 r inside the surface
///   (so the next step's contact is solved, with restitution; a sweep with the full radius would
///   stop it just outside, where it would be clamped again every step) and loses the rest of the
///   step's motion.
/// - Integration: Bullet's steps are semi-implicit Euler (v += g dt, then x += v dt), which puts
///   a free flight below the parabola by |g| t dt / 2 (5 mm after 1 s at 960 Hz). With
///   leapfrogStart (default) the body starts with `velocity - gravity * dt / 2`, which makes the
///   same steps exact on a parabola (leapfrog); reported velocities add the half step back when
///   the step had no contact.
///
/// What remains (measured in tests/bullet_simulation_test.cpp): contacts are found at the start
/// of a step, so a bounce is applied in the step after the sphere reached the surface: its
/// rebound is late by 0 to 1 step (and starts with the normal speed measured up to one step
/// early, an error of up to |g| dt). SimulatedImpact::touchTime/touchPosition interpolate the
/// moment Bullet's path reached the surface.

#include <foresight/bullet_world.h>
#include <foresight/projectile.h>

#include <cstddef>
#include <vector>

FORESIGHT_NAMESPACE_BEGIN

/// Settings of the rigid-body reference simulation.
struct RigidBodySimulationSettings {
    float frequency = 960.0f;   ///< Bullet's fixed internal step rate [Units: Hz] [Limit: 240 .. 100000]
    float pointRadius = 0.02f;  ///< sphere radius used when the projectile's radius is 0 [Units: m] [Limit: > 0]
    /// No spin: the sphere slides like the predictor's point mass (false: it may roll; rolling
    /// friction stays 0).
    bool lockRotation = true;
    std::size_t maxImpacts = 4096;  ///< impacts recorded at most (later ones are simulated, not recorded)
    /// Start Bullet's velocity half a step of gravity early (`velocity - gravity * dt / 2`), so
    /// that its semi-implicit Euler steps follow the exact parabola in free flight (false:
    /// Bullet's plain start, below the parabola by |g| t dt / 2).
    bool leapfrogStart = true;
    /// A contact impulse that stops or reverses an approach slower than this, or slower than
    /// twice the normal speed gravity adds in one step, is resting contact, not an impact
    /// [Units: m/s] [Limit: >= 0].
    float minImpactSpeed = 0.05f;
    /// atRest: the sphere touched a surface in the last step and is slower than this
    /// [Units: m/s] [Limit: >= 0].
    float restSpeed = 0.01f;
};

/// One contact event of the simulated sphere (a step in which the solver applied a contact
/// impulse that stopped or reversed the approach: the normal velocity gained at least 99% of the
/// approach speed, which restitution 0 gives exactly). At most one per step: the contact normal
/// with the fastest approach.
struct SimulatedImpact {
    double time = 0;          ///< [Units: s] end of the internal step in which the impulse was applied
    RVec3 position{0};        ///< sphere centre at that time
    Vec3 normal{0};           ///< contact normal (unit, facing the sphere)
    float approachSpeed = 0;  ///< normal speed before the impulse [Units: m/s]
    /// When Bullet's path reached the surface [Units: s]: the centre's motion in the previous
    /// step, taken as straight, interpolated back from the depth Bullet measured at the start of
    /// the impulse step. Between 2 steps and 1 step before `time`.
    double touchTime = 0;
    RVec3 touchPosition{0};  ///< sphere centre at touchTime (the landing point of a first impact)
};

/// Result of simulateProjectileRigidBody.
struct RigidBodySimulationResult {
    RVec3 position{0};  ///< sphere centre at `time`
    Vec3 velocity{0};   ///< at `time` [Units: m/s]
    /// Bounces in time order. Resting contact is not recorded: an impact needs an approach faster
    /// than RigidBodySimulationSettings::minImpactSpeed and than twice the normal speed gravity
    /// adds in one step (see SimulatedImpact).
    std::vector<SimulatedImpact> impacts;
    /// Centre at every internal step (for drawing / comparing paths): Start (t = 0, the given
    /// state), then one point per step, Bounce for a step with an impact (with its normal), Step
    /// otherwise, the last one End (at `time`).
    std::vector<TrajectoryPoint> samples;
    bool atRest = false;  ///< touching a surface in the last step and slower than restSpeed
    double radius = 0;    ///< radius actually simulated [m]
};

/// Runs a projectile as a Bullet rigid body (a btSphereShape of settings.radius, or
/// simulation.pointRadius if that is 0) in `scene`'s static world, with gravity settings.gravity,
/// restitution settings.restitution and friction settings.friction (Bullet clamps friction to 10),
/// for `time` seconds. settings.method, step, maxBounces and maxEvents are not used; maxSteps caps
/// the internal steps.
///
/// Steps: floor(time * frequency) steps of 1/frequency (btScalar), then one shorter step for the
/// rest of `time` (not interpolated: Bullet steps it, so `position` is Bullet's state at `time`;
/// a rest under 1 microsecond is dropped). `time` is taken at its decimal value (3.0f, 0.02f), as
/// predictProjectile does.
///
/// The scene is left as it was: the body is added, stepped and removed; the solver and dispatch
/// settings changed for the call are restored. Repeated calls give identical results. Not thread
/// safe (it steps the scene's world).
///
/// @return Ok; NonFiniteInput (position, velocity, time or a simulation setting); NegativeTime;
///         InvalidStep (frequency outside 240 .. 100000 Hz); InvalidRadius (pointRadius <= 0);
///         what validateProjectileSettings refuses; TooManySteps (more internal steps than
///         settings.maxSteps); NonFiniteResult. `result` is untouched unless Ok.
Status simulateProjectileRigidBody(BulletScene& scene, const RVec3& position, const Vec3& velocity, float time,
                                   const ProjectileSettings& settings, const RigidBodySimulationSettings& simulation,
                                   RigidBodySimulationResult& result);

FORESIGHT_NAMESPACE_END
