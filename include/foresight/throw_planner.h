#pragma once
/// @file throw_planner.h
/// Throw planning: launch velocities that put a grenade within a radius of a target point when
/// its fuse runs out, in a CollisionWorld, bank shots off walls included.
///
/// Method (a heuristic search, deterministic and bounded; the forward model is
/// predictProjectile with the request's settings, Exact by default):
/// 1. Seeds: throws towards the target in a flat-ground model (a plane through the target,
///    perpendicular to gravity, with the request's restitution and friction; no casts). Each
///    seed fixes the time of the first landing (ThrowPlanBudget::seedLandingFractions of the
///    fuse; 1 is the arc that arrives at the fuse time without bouncing) and solves the
///    horizontal speed for the distance covered at the fuse time. On open ground they are
///    solutions as they are.
/// 2. Refinement: damped Gauss-Newton (Levenberg-Marquardt) on the launch velocity, minimising
///    the distance from the position at the fuse time to the target, with forward-difference
///    Jacobians (4 predictions per iteration), the speed kept within [minSpeed, maxSpeed].
/// 3. When fewer plans than wanted were found: a grid of throws over azimuth x elevation x
///    speed (bank shots come from here), then refinement of the closest distinct cells.
/// The search stops when enough distinct plans are within the acceptance radius or when
/// ThrowPlanBudget::maxPredictions predictions were run. No guarantee: a throw that exists may
/// be missed (a narrow window, a cap too small); what is returned is always verified by the
/// forward model. Cost: at most maxPredictions predictions of `fuseTime` (on the demo level with
/// EmbreeWorld one 3 s prediction at 50 Hz takes about 13 us); open ground usually needs one
/// prediction per plan. With the Exact method, a grid cell or a refinement's trial step stops
/// early once it surely ends too far from the target to change anything (its distance now less
/// the most the grenade can still travel, |v| t + |g| t^2 / 2, beyond what could be kept): the
/// plans are those of the full predictions.
///
/// No allocation: plans go into caller storage, and the first impacts are read from a caller
/// scratch trajectory (throwPlanScratchSize). Not thread-safe across calls sharing scratch.

#include <foresight/projectile.h>
#include <foresight/world.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

FORESIGHT_NAMESPACE_BEGIN

/// The largest ThrowPlanBudget::refinements (the candidates live on the stack).
inline constexpr std::uint32_t kMaxThrowPlanRefinements = 32;

/// Caps on the work of planThrow. Every count must be >= 1 (maxPredictions too), except the
/// seed fractions, of which only those in (0, 1] are used (others are skipped).
struct ThrowPlanBudget {
    std::uint32_t azimuthSamples = 16;   ///< grid: directions around the up axis.
    std::uint32_t elevationSamples = 5;  ///< grid: elevations from -30 to +75 degrees.
    std::uint32_t speedSamples = 3;      ///< grid: speeds evenly in (minSpeed, maxSpeed].
    /// Candidates refined at most (seeds that missed, then grid cells) [Limit: 1 .. 32].
    std::uint32_t refinements = 6;
    std::uint32_t refinementPredictions = 24;  ///< predictions per refinement at most.
    std::uint32_t maxPredictions = 400;        ///< predictions per planThrow call at most, in total.
    /// The work of one call at most: maxPredictions x the steps of one prediction
    /// (`fuseTime / settings.step`, counted as for the Stepped method whatever the method: the
    /// exact method's chord casts also advance by `step`) [Limit: >= 1]. A request over it is
    /// refused (TooManySteps) instead of running for long. The default, 2^24 steps, allows
    /// e.g. a 838 s fuse at 0.02 s: an unreachable target then took 1.5 s with Stepped
    /// predictions over a floor and a box (0.2 s in free flight), where a 20000 s fuse ran
    /// 372 predictions of 10^6 steps for ~30 s. The default request (3 s fuse, 0.02 s step,
    /// 400 predictions) is 60 000 steps.
    std::uint64_t maxTotalSteps = std::uint64_t{1} << 24;
    /// Grid: the time step of the grid's predictions when it is longer than the request's step
    /// and the method is Exact [Units: s] [Limit: >= 0, finite; 0: the request's step]. The
    /// exact method stays on the true parabola whatever the step (only its chord casts get
    /// longer: a surface the arc grazes by less than g step^2 / 8, 1.2 cm at 0.1 s, may be
    /// missed), so a coarse grid ranks the cells almost as the fine one does, for less (on the
    /// demo level, planning behind cover takes 0.6 times as long). Grid results are never plans
    /// by themselves: a cell is predicted again with the request's settings before it is
    /// accepted or refined.
    float gridStep = 0.1f;
    /// Seeds: first landing at these fractions of the fuse time [Limit: (0, 1]; others are
    /// skipped]. 1 is the arc that arrives at the fuse time without touching the ground.
    std::array<float, 5> seedLandingFractions{0.12f, 0.25f, 0.4f, 0.6f, 1.0f};
};

/// What to plan.
struct ThrowPlanRequest {
    RVec3 start{0};                 ///< launch position (the sphere's centre) [Units: m].
    RVec3 target{0};                ///< where the grenade should be at the fuse time [Units: m].
    float acceptanceRadius = 0.5f;  ///< a plan ends within this of target [Units: m] [Limit: > 0].
    float fuseTime = 3.0f;          ///< time from the launch to the blast [Units: s] [Limit: > 0].
    float maxSpeed = 20.0f;         ///< launch speed cap [Units: m/s] [Limit: > 0].
    float minSpeed = 0.0f;          ///< lowest launch speed [Units: m/s] [Limit: 0 .. maxSpeed].
    /// Gravity, restitution, friction, radius, step, method and caps of the forward model.
    ProjectileSettings settings;
    std::uint32_t maxPlans = 3;  ///< plans wanted (also capped by the output span) [Limit: >= 1].
    /// Two plans are distinct when their launch directions differ by at least this angle or
    /// their first impacts are on surfaces whose normals differ by more than it
    /// [Units: rad] [Limit: 0 .. pi; values outside are clamped].
    float distinctAngle = 0.1f;
    ThrowPlanBudget budget;  ///< caps on the work.
};

/// One throw that works.
struct ThrowPlan {
    Vec3 launchVelocity{0};     ///< [Units: m/s], world axes; speed within [minSpeed, maxSpeed].
    RVec3 finalPosition{0};     ///< where the grenade is at the fuse time [Units: m].
    float distance = 0;         ///< |finalPosition - target| [Units: m] [Limit: <= acceptanceRadius].
    std::uint32_t bounces = 0;  ///< bounces until the fuse time.
    bool atRest = false;        ///< the grenade rests on a surface at the fuse time.
    /// Time of the first impact [Units: s]; < 0 when there is none (or it was not recorded:
    /// scratch smaller than throwPlanScratchSize).
    float firstImpactTime = -1.0f;
    Vec3 firstImpactNormal{0};     ///< unit normal of the first impact; zero when there is none.
    RVec3 firstImpactPosition{0};  ///< where the first impact is [Units: m]; start when none.
};

/// What planThrow did.
struct ThrowPlanResult {
    std::size_t planCount = 0;      ///< plans written, best (closest) first.
    std::uint32_t predictions = 0;  ///< forward predictions run.
    /// The closest any tried throw came to the target at the fuse time [Units: m] (also when
    /// no plan was found: how far out of reach the target is, as far as the search saw);
    /// FLT_MAX when no throw finished or the distance is beyond a float (a target ~1e38 m
    /// away or more): then closestVelocity is zero. `foresight plan` prints null for both.
    float closestDistance = 0;
    Vec3 closestVelocity{0};  ///< the launch velocity of that throw [Units: m/s].
};

/// Checks a request as planThrow does: Ok, NonFiniteInput (any NaN or infinity), InvalidFuse
/// (fuseTime <= 0: a zero fuse is refused too), InvalidRadius (acceptanceRadius <= 0),
/// InvalidSpeed (maxSpeed <= 0, or minSpeed outside [0, maxSpeed]: no launch velocity exists),
/// InvalidIterations (maxPlans or a budget count is 0, maxTotalSteps included, or refinements
/// over kMaxThrowPlanRefinements), InvalidStep (budget.gridStep negative or not finite),
/// what validateProjectileSettings returns for the settings, or TooManySteps (fuseTime / step
/// over settings.maxSteps, or budget.maxPredictions x fuseTime / step over
/// budget.maxTotalSteps: a fuse too long for its step; see throwPlanWork).
Status validateThrowPlanRequest(const ThrowPlanRequest& request);

/// The work bound validateThrowPlanRequest compares with budget.maxTotalSteps:
/// budget.maxPredictions x the steps of one prediction (fuseTime / settings.step, as
/// steppedStepCount counts them); 0 when fuseTime or step is not positive and finite.
std::uint64_t throwPlanWork(const ThrowPlanRequest& request);

/// Scratch points that let planThrow record every first impact:
/// `trajectoryCapacity(fuseTime, settings, 1)` (0 for an invalid request).
std::size_t throwPlanScratchSize(const ThrowPlanRequest& request);

/// Plans throws.
/// @param request  what to plan (validateThrowPlanRequest).
/// @param world    what the grenade bounces off; may be null (free flight).
/// @param plans    output: up to min(maxPlans, plans.size()) distinct plans, closest first.
///                 Entries past `out.planCount` are untouched.
/// @param scratch  trajectory scratch, throwPlanScratchSize(request) points to record every
///                 first impact; may be smaller (even empty), then late first impacts are
///                 reported as none and distinctness uses the launch direction only.
/// @param out      what was done; untouched unless Ok.
/// @return Ok (also when nothing was found: planCount 0), or why the request was refused
///         (validateThrowPlanRequest). Forward predictions that fail during the search (work
///         caps, overflow) count as misses.
Status planThrow(const ThrowPlanRequest& request, const CollisionWorld* world, std::span<ThrowPlan> plans,
                 std::span<TrajectoryPoint> scratch, ThrowPlanResult& out);

/// Predicts the trajectory of a plan (or of any launch velocity) with the request's settings
/// until its fuse time: predictProjectile(request.start, plan.launchVelocity,
/// request.fuseTime, request.settings, world, trajectory, out). Size the storage with
/// trajectoryCapacity(request.fuseTime, request.settings, plan.bounces + 8).
/// @return as predictProjectile.
Status predictThrowPlan(const ThrowPlanRequest& request, const ThrowPlan& plan, const CollisionWorld* world,
                        std::span<TrajectoryPoint> trajectory, ProjectileResult& out);

FORESIGHT_NAMESPACE_END
