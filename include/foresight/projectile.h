#pragma once
/// @file projectile.h
/// Ballistic projectiles (grenades, thrown and fired objects) under constant gravity, bouncing
/// off a CollisionWorld with a coefficient of restitution.
///
/// Two methods (ProjectileMethod):
/// - Stepped: the reference article's loop, faithfully. Fixed steps; each moves on the exact
///   parabola, casts one segment from the previous to the new position, and on a hit takes the
///   velocity at the hit fraction, moves to the hit point and bounces:
///   `v += -(1 + e) dot(n, v) n`. `ceil(time / step)` steps (robust: 3 / 0.02 is 150). The
///   rest of a step after a hit is lost, and a grenade resting on a floor freezes. The next
///   chord from a hit point back into that surface hits it at fraction 0 on every kind of
///   surface (planes, boxes, two-sided mesh triangles), as a line cast from a point on a
///   collider does in an engine, and the same surface met from behind within rounding of the
///   start is not a hit: the loop never falls through a mesh floor.
/// - Exact (the default): event driven. The impact time is found on the true parabola (the
///   segment cast finds the surface, then the parabola is solved against the surface's tangent
///   plane), the rest of the step continues after the bounce, and the result is at exactly
///   `time`. When a bounce leaves too little normal speed to leave the surface (a hop under a
///   micrometre), the projectile slides on it (constant tangential gravity, Coulomb friction)
///   and comes to rest when static friction holds it: reported as `atRest`. Where the world
///   answers region queries (CollisionWorld::firstTouch, isOnlyPlane) and they cost no more
///   than two casts (CollisionWorld::regionQueryCost), one query clears many steps of free
///   flight (the same trajectory as casting every step) or of sliding on one plane (the same up
///   to the rounding of that plane).
///
/// - Engine: the flight a game's physics engine will compute (Jolt, PhysX, Rapier, Bullet,
///   Godot 3, Box2D or a custom profile: settings.engine, see engine_profile.h): its fixed steps
///   with its own damping, sub-steps and first-step rule, its contacts (speculative or
///   penetrating), bounce threshold, position correction and friction on a spinning sphere.
///   `ceil(time / engine.timestep)` steps; `step` is not used. One cast per step, as the
///   article's loop.
///
/// No allocation: the trajectory is written into caller-provided storage. Computation runs in
/// double; the float inputs `time`, `step` and `gravity` are taken at the decimal value they were
/// written as (0.02f means 0.02 s, so step 5 is at 0.1 s, not 0.099999994 s).

#include <foresight/engine_profile.h>
#include <foresight/world.h>

#include <cstddef>
#include <limits>
#include <span>

FORESIGHT_NAMESPACE_BEGIN

/// Which projectile integrator to run.
enum class ProjectileMethod : std::uint8_t {
    Exact,    ///< event-driven, exact impact times, contact handling (default).
    Stepped,  ///< the reference article's fixed-step loop, faithfully.
    Engine,   ///< step for step as a physics engine computes it (ProjectileSettings::engine).
};

/// What a TrajectoryPoint marks.
enum class TrajectoryEvent : std::uint8_t {
    Start,   ///< the initial state (t = 0).
    Step,    ///< the state at a step boundary (Exact: a multiple of `step`).
    Bounce,  ///< an impact (Exact: at its exact time; Stepped: the step that hit; Engine: a step in
             ///< which a contact changed the velocity, rolling included). Has a normal.
    Rest,    ///< the projectile came to rest (Exact only); it stays there until the end.
    Hit,     ///< the prediction stopped at this impact (maxBounces reached). Has a normal.
    End,     ///< the final state at the prediction time.
};

/// A point of a predicted trajectory.
struct TrajectoryPoint {
    float time = 0;  ///< since the start [Units: s].
    TrajectoryEvent event = TrajectoryEvent::Step;
    RVec3 position{0};  ///< [Units: m]
    Vec3 velocity{0};   ///< [Units: m/s]; after the bounce for Bounce points.
    Vec3 normal{0};     ///< surface normal for Bounce and Hit points (and a Stepped End
                        ///< whose step hit); zero otherwise.
};

/// Use as ProjectileSettings::maxBounces for no limit.
inline constexpr std::uint32_t kUnlimitedBounces = std::numeric_limits<std::uint32_t>::max();

/// How to predict a projectile. Defaults follow the reference article.
struct ProjectileSettings {
    ProjectileMethod method = ProjectileMethod::Exact;
    Vec3 gravity{0.0f, -kDefaultGravity, 0.0f};  ///< [Units: m/s^2], world axes.
    float step = 0.02f;                          ///< time step [Units: s] [Limit: > 0]; Exact records a point per step.
    float restitution = 0.5f;                    ///< coefficient of restitution [Limit: 0 .. 1].
    /// Coulomb friction coefficient [Limit: >= 0]. At an impact the tangential velocity loses
    /// `friction * (1 + e) * |normal speed|` (never reversing); while sliding (Exact) it
    /// decelerates by `friction * |normal gravity|`. 0 (the article) is frictionless.
    float friction = 0.0f;
    float radius = 0.0f;  ///< 0: a point (line casts); > 0: a sphere (sphere casts) [Units: m].
    /// Bounces allowed; the next impact ends the prediction there (TrajectoryEvent::Hit).
    /// 0 stops at the first hit, as Unreal's PredictProjectilePath does.
    std::uint32_t maxBounces = kUnlimitedBounces;
    /// Work cap: predictions needing more than this many steps are refused (TooManySteps).
    std::uint32_t maxSteps = 1u << 20;
    /// Work cap (Exact): impacts plus contact changes handled before TooManyEvents.
    std::uint32_t maxEvents = 1u << 16;
    /// The engine to follow (method Engine only): its timestep replaces `step`. The projectile's
    /// `restitution` and `friction` are the contact's values after the engine's combine rule
    /// (a world may report a shape's own material, see CastHit; then the rule combines them).
    EngineProfile engine = engineProfile(PhysicsEngine::Jolt);
};

/// The time step a prediction with these settings runs: `engine.timestep` for the Engine method,
/// `step` otherwise [Units: s].
float settingsStep(const ProjectileSettings& settings);

/// Checks settings as predictProjectile does: Ok, NonFiniteInput, InvalidStep,
/// InvalidRestitution, InvalidFriction, InvalidRadius, or (method Engine) what
/// validateEngineProfile refuses.
Status validateProjectileSettings(const ProjectileSettings& settings);

/// Number of steps the Stepped method runs for `time`: `ceil(time / step)` on the decimal values
/// of both (0.02f is taken as 0.02), with quotients within 1e-6 (relative) of an integer rounded
/// to it, so that rounding never adds a step (3 / 0.02 is 150 steps, not 151).
std::uint64_t steppedStepCount(float time, float step);

/// Trajectory storage that is always enough for the Stepped method, and for Exact when there
/// are at most `expectedEvents` bounces and contact changes: `steps + 3 + 2 * expectedEvents`.
std::size_t trajectoryCapacity(float time, const ProjectileSettings& settings, std::size_t expectedEvents = 64);

/// The outcome of a projectile prediction.
struct ProjectileResult {
    RVec3 position{0};                 ///< final position [Units: m].
    Vec3 velocity{0};                  ///< final velocity [Units: m/s].
    float time = 0;                    ///< time reached [Units: s]: `time` (Exact), steps * step
                                       ///< (Stepped), or the impact time when stoppedAtHit.
    std::uint32_t bounces = 0;         ///< bounces applied.
    bool atRest = false;               ///< Exact: the projectile came to rest on a surface.
    bool stoppedAtHit = false;         ///< the prediction ended at an impact (maxBounces).
    Vec3 hitNormal{0};                 ///< normal of the last impact (zero if none).
    std::size_t trajectorySize = 0;    ///< points written into the trajectory storage.
    std::size_t trajectoryNeeded = 0;  ///< points the whole trajectory has; > size if truncated.
};

/// Predicts a projectile.
/// @param position    start position [Units: m] (the sphere's centre when radius > 0).
/// @param velocity    start velocity [Units: m/s].
/// @param time        prediction time, e.g. a grenade's fuse [Units: s] [Limit: >= 0].
/// @param settings    method and physical parameters.
/// @param world       what to bounce off; may be null (free flight).
/// @param trajectory  storage for the trajectory (may be empty). Stepped: Start, then one point
///                    per step (Step, Bounce or Hit; the last step's is End), as the article
///                    draws it. Exact: Start, Step points at multiples of `step`, Bounce, Rest
///                    and Hit points at their exact times, then End at `time`. When full, the
///                    prediction continues and only `trajectoryNeeded` keeps counting.
/// @param out         the result; untouched unless Ok.
/// @return Ok, or why the input was refused (see validateProjectileSettings), TooManySteps,
///         TooManyEvents (out is untouched) or NonFiniteResult.
Status predictProjectile(RVec3 position, Vec3 velocity, float time, const ProjectileSettings& settings,
                         const CollisionWorld* world, std::span<TrajectoryPoint> trajectory, ProjectileResult& out);

/// How a game shows a body between its fixed physics steps.
enum class RenderSmoothing : std::uint8_t {
    None,         ///< the state of the last completed step (no smoothing).
    Interpolate,  ///< between the last two completed steps, one step behind (Unity's Rigidbody
                  ///< interpolation, Godot 4's physics interpolation).
    Extrapolate,  ///< the last completed step moved on with its velocity (Unity's extrapolation).
};

/// The position a game will draw at `renderTime` for a fixed-step trajectory (Engine or Stepped:
/// Start, then one point per step of `step` seconds, as predictProjectile writes it). With
/// k = floor(renderTime / step) steps completed and alpha = renderTime / step - k:
/// None gives p[k]; Interpolate p[k-1] + alpha (p[k] - p[k-1]) (p[0] before the first step);
/// Extrapolate p[k] + v[k] alpha step. Times before 0 give the start; times past the last step
/// give the last point (extrapolated by its velocity for Extrapolate).
/// @param trajectory  the points (at least one); an empty span gives the origin.
/// @param step        the trajectory's step [Units: s] [Limit: > 0].
/// @param renderTime  the frame's time since the start [Units: s].
RVec3 renderedPosition(std::span<const TrajectoryPoint> trajectory, float step, float renderTime,
                       RenderSmoothing smoothing);

FORESIGHT_NAMESPACE_END
