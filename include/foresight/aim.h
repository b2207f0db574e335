#pragma once
/// @file aim.h
/// Firing solutions: the launch velocities with which a projectile leaving `from` meets a
/// target that moves as `position + velocity t + acceleration t^2 / 2`.
///
/// The projectile flies in free space under constant gravity (no drag, no collisions), as
/// predictProjectile flies it without a world: `from + v t + gravity t^2 / 2`. With zero
/// gravity it flies in a straight line. A solution is a time t in (0, maxTime] and the launch
/// velocity `v = d(t) / t`, where `d(t) = target(t) - from - gravity t^2 / 2` is the relative
/// displacement the launch velocity must cover. What fixes t is the constraint (AimConstraint):
/// - Speed: `|d(t)| = speed t`, a quartic in t (every solution: up to 4);
/// - HorizontalSpeed: the same across gravity only (Unreal's "lateral speed"), up to 4;
/// - ApexAboveStart / ApexAboveTarget: the arc's highest point at a given height, up to 2.
///
/// Methods: a static target at a fixed speed uses the closed form for the flight time (both
/// roots without cancellation, the range limit as a double root); a straight-line shot at a
/// target without acceleration relative to the projectile, the stable quadratic formula;
/// everything else finds the real roots of its polynomial on (0, maxTime] by bracketing
/// between the roots of its derivatives (found the same way, recursively), each bracket
/// solved by safeguarded Newton in double (quadratics by the cancellation-free formula). When
/// a value that decides a bracket or a touch is within a guard band of zero (1e-13 of the
/// magnitude of the products the coefficients are made of: a grazing shot, roots closer than
/// ~1e-6 of the flight time), the polynomial is solved again in long double, as before that
/// double path existed. A grazing contact, where the polynomial
/// touches zero without crossing it (the target exactly at the range limit), is a double root
/// and reported once. "Touches" means the polynomial's residual is within 1e-14 of the
/// magnitude of its terms there (the rounding of double inputs): the shot misses by a few
/// 1e-14 of the distances involved. Two roots further apart than about 1e-6 s are kept apart.
///
/// Time 0 is never a solution: a target at the shooter is hit only by a shot that flies and
/// comes back (straight up under gravity), or by none. Nor is a time so small that it rounds
/// to 0 as a float (a target 1e-30 m away at 3e38 m/s): such solutions are dropped, so every
/// reported FiringSolution::time is a positive float. No allocation; computation in double
/// (long double for the doubtful roots above). Gravity is taken at the decimal value it was written as (9.81f is
/// 9.81), as predictProjectile takes it, so that a solution flown by predictProjectile meets
/// the target.

#include <foresight/status.h>

#include <cstddef>
#include <span>

FORESIGHT_NAMESPACE_BEGIN

/// The most firing solutions any constraint has (the quartic's four roots): a span of this
/// size never loses a solution.
inline constexpr std::size_t kMaxFiringSolutions = 4;

/// What fixes the launch velocity besides meeting the target.
enum class AimConstraint : std::uint8_t {
    /// `|velocity| = AimShot::speed`: a gun or a throw of fixed strength. Against a static
    /// target under gravity: the low and the high arc, the same velocity at the range limit,
    /// none beyond.
    Speed,
    /// The velocity's component across gravity has length `AimShot::speed` (a fixed lateral
    /// speed, as Unreal's lateral-speed solvers); the vertical component follows. With zero
    /// gravity, "vertical" is +Y.
    HorizontalSpeed,
    /// The arc's highest point is `AimShot::apexHeight` above `from`; the shot meets the target
    /// at or after its apex (descending), as a lob does. Needs gravity.
    ApexAboveStart,
    /// The arc's highest point is `AimShot::apexHeight` above the hit point (as Unreal's
    /// SuggestProjectileVelocity_CustomArc shapes an arc over a wall); the shot meets the
    /// target at or after its apex. Needs gravity.
    ApexAboveTarget,
};

/// The shooter and the shot's constraint.
struct AimShot {
    RVec3 from{0};                                    ///< launch point [Units: m].
    AimConstraint constraint = AimConstraint::Speed;  ///< what fixes the velocity.
    /// Speed or HorizontalSpeed: the launch speed (of the horizontal part for HorizontalSpeed)
    /// [Units: m/s] [Limit: finite]. 0 drops the projectile; a negative speed reaches nothing
    /// (no solutions, not an error).
    float speed = 0.0f;
    /// ApexAboveStart / ApexAboveTarget: the apex's height above the start or the hit point,
    /// along -gravity [Units: m] [Limit: finite]. Below 0 nothing is reachable (no solutions).
    float apexHeight = 0.0f;
    Vec3 gravity{0.0f, -kDefaultGravity, 0.0f};  ///< [Units: m/s^2], world axes.
    /// Latest flight time reported [Units: s] [Limit: >= 0, finite]; 0 gives no solutions.
    float maxTime = 60.0f;
};

/// A target moving with constant acceleration: `position + velocity t + acceleration t^2 / 2`.
struct AimTarget {
    RVec3 position{0};     ///< at t = 0 [Units: m].
    Vec3 velocity{0};      ///< [Units: m/s].
    Vec3 acceleration{0};  ///< [Units: m/s^2].
};

/// One way to hit the target.
struct FiringSolution {
    Vec3 velocity{0};   ///< launch velocity [Units: m/s]; for Speed, of length `speed`.
    float time = 0.0f;  ///< flight time to the hit [Units: s] [Limit: (0, maxTime]].
    RVec3 hit{0};       ///< where projectile and target meet at `time` [Units: m].
    /// Launch angle above the plane across gravity [Units: rad] [Limit: -pi/2 .. pi/2]; with
    /// zero gravity above the XZ plane; 0 for a zero velocity.
    float elevation = 0.0f;
};

/// Checks a shot and a target as aimProjectile does: Ok, NonFiniteInput (a NaN or infinite
/// number anywhere, including maxTime), NegativeTime (maxTime < 0) or ZeroVector (an apex
/// constraint with zero gravity: there is no apex).
Status validateAim(const AimShot& shot, const AimTarget& target);

/// Every firing solution with a flight time in (0, shot.maxTime], sorted by time: the first is
/// the earliest (the low arc, or the straight-line intercept), the last the latest (the high
/// arc).
/// @param shot       launch point, constraint, gravity and time limit.
/// @param target     the target's motion.
/// @param solutions  caller storage; kMaxFiringSolutions entries hold every solution. When it
///                   is smaller, the earliest solutions are written.
/// @param count      receives the number of solutions written (0: unreachable, which is not an
///                   error); untouched unless Ok.
/// @return Ok, what validateAim refuses, or NonFiniteResult (the inputs are finite but so
///         large that a velocity overflows a float); `solutions` and `count` are untouched
///         unless Ok.
Status aimProjectile(const AimShot& shot, const AimTarget& target, std::span<FiringSolution> solutions,
                     std::size_t& count);

FORESIGHT_NAMESPACE_END
