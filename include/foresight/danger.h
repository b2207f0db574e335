#pragma once
/// @file danger.h
/// Danger for AI: where and when a grenade is dangerous, and when a vehicle reaches a character.
///
/// **Projectiles.** A predicted projectile is its trajectory (the points predictProjectile
/// writes) and a fuse time. Between two points of times t0 < t1 the projectile is taken on the
/// parabola `p(s) = p0 + v0 s + a s^2 / 2`, s = t - t0 in [0, t1 - t0], with the constant
/// acceleration `a = 2 (p1 - p0 - v0 (t1 - t0)) / (t1 - t0)^2` that joins the two points: it is
/// the gravity of the prediction in free flight (also up to a Bounce point, whose position is the
/// impact and whose velocity is the one after it), zero at rest, and the constant acceleration
/// of a straight slide (Exact method). Points of equal times are jumps (no segment). Before the
/// first point the projectile is at the first point, after the last point at the last point
/// (predict up to the fuse time: the End point is then the blast centre).
/// - The danger zone is the sphere of `blastRadius` around the position at the fuse time,
///   dangerous from the fuse time on (as `danger_zones` of docs/viewer-format.md).
/// - Before the fuse only the projectile itself can be dangerous, and only when
///   `contactRadius > 0`: a point within `contactRadius` of the projectile's position at time t
///   is unsafe at t, for t from the first point's time on. Before the first point's time the
///   projectile is not there yet (not thrown): every point is safe then, so isPointSafe and
///   findDangerStart agree (danger never starts before the first point's time).
/// - Distances to the path are exact per segment: the squared distance from a point to
///   `p(s)` is a quartic in s whose derivative is the cubic
///   `(q.v) + s (v.v + q.a) + s^2 (3/2 v.a) + s^3 (a.a / 2)`, q = p0 - point. All of its real
///   roots in the segment are found by isolation (the cubic is monotone between the roots of
///   its quadratic derivative) and bisection to double precision; the minimum is at one of them
///   or at an end. The earliest time within a distance r solves `|p(s) - point|^2 = r^2` on the
///   first monotone piece that reaches r^2, by bisection to double precision. No sampling.
///
/// **Vehicles.** A vehicle is an oriented box (half extents, a centre offset in the vehicle's
/// local axes) moving on the exact path of predictVehicleExact (constant signed speed on the
/// forward axis, constant angular velocity). A character is a sphere or a capsule (a segment of
/// constant direction with a radius) whose centre moves as `p + v t + a t^2 / 2`. The
/// separation `D(t)` is the exact distance between the box and the capsule's segment (closest
/// points on an OBB: the squared distance from the box to a point of the segment is a piecewise
/// quadratic, minimised exactly between the segment's crossings of the box's slabs) minus the
/// radius; it is <= 0 exactly when they overlap (down to -radius: depth is not measured).
///
/// Proof sketch of the bound. Seen from the character (which translates without turning), a
/// point r of the box (r from the vehicle's position, `|r| <= |centre offset| + |half extents|
/// = rho`) moves with `v_vehicle(t) + w x r - v_character(t)`, so the distance between the two
/// sets changes no faster than `L = |v_vehicle - v_character| + |w| rho` (the distance between
/// sets is 1-Lipschitz in the motion of their points). Over an interval [t0, t1]:
/// `|v_vehicle - v_character| <= |speed| + max(|v_c(t0)|, |v_c(t1)|)` (|v_c| is convex in t),
/// and without rotation `<= max over the two ends of |v_vehicle - v_c|` (also convex).
/// - First contact (conservative advancement): from t = 0, while `D(t) > tolerance`, step
///   t += D(t) / L (L over [t, horizon]). Since D(t') >= D(t) - L (t' - t) > 0 within the step, no
///   contact is ever skipped: the reported time T has D > 0 on [0, T) (it is never later than
///   the true first contact) and D(T) <= tolerance (the shapes are within `tolerance` there).
/// - Closest approach, in two passes. (1) Lipschitz branch and bound (Piyavskii's lower bound):
///   on [a, b], `D >= (D(a) + D(b) - L (b - a)) / 2`; intervals whose bound cannot beat the best
///   value m by more than `3 tolerance / 4` are dropped, others are halved, so the true minimum
///   mu is in [m - 3 tolerance / 4, m]. (2) Conservative advancement from t = 0 as for the first
///   contact, never stepping over a time where D <= m and stopping at the first time T where
///   D <= m + tolerance / 4 (each step is at least tolerance / (4 L)). So
///   `mu <= D(T) <= mu + tolerance`, and D > m >= mu on [0, T): T is no later than the first
///   time the true minimum is reached, and no earlier than the first time D comes within
///   `tolerance` of it. Both bounds are properties of the path, not of where pass 1 sampled:
///   among equal minima (a turning vehicle's period) the first is reported, whatever the
///   horizon.
/// Rounding: D is computed in double from float/Real inputs; its rounding (about 1e-7 of the
/// coordinates' magnitude in the float build) adds to `tolerance`.
///
/// No allocation, no exceptions; the same input gives the same output.

#include <foresight/projectile.h>
#include <foresight/vehicle.h>

#include <span>

FORESIGHT_NAMESPACE_BEGIN

// ---------------------------------------------------------------------------------------------
// Projectiles

/// A predicted projectile as a danger: its trajectory, fuse and blast.
struct ProjectileDanger {
    /// The predicted trajectory (e.g. points[0 .. result.trajectorySize) of predictProjectile),
    /// in time order [Limit: at least one point; times finite and non-decreasing]. Not owned.
    std::span<const TrajectoryPoint> trajectory;
    float fuseTime = 0;     ///< when it explodes [Units: s] [Limit: >= 0].
    float blastRadius = 0;  ///< radius of the blast around its centre [Units: m] [Limit: >= 0].
    /// Before the fuse, a point this close to the projectile is unsafe (the projectile itself is
    /// dangerous; include the projectile's own radius). 0: nothing is dangerous before the fuse.
    /// [Units: m] [Limit: >= 0]
    float contactRadius = 0;
};

/// Where and when a projectile explodes.
struct DangerZone {
    RVec3 center{0};   ///< the projectile's position at the fuse time [Units: m].
    float radius = 0;  ///< the blast radius [Units: m].
    float time = 0;    ///< the fuse time; dangerous from then on [Units: s].
};

/// When something starts (danger at a point, a path coming close).
struct DangerStart {
    bool ever = false;  ///< false: never (then `time` is 0).
    float time = 0;     ///< the earliest time [Units: s]; valid when `ever`.
};

/// The closest approach of a path to a point, or of a vehicle to a character.
struct ClosestApproach {
    /// The smallest distance [Units: m]. For vehicles: the separation (negative when
    /// overlapping, down to minus the character's radius).
    float distance = 0;
    /// When it happens [Units: s]. For paths: the earliest time of the smallest distance. For
    /// vehicles: a time no later than the first time of the minimum, where the separation is
    /// within the tolerance of it (see findClosestVehicleApproach): the first of equal minima.
    float time = 0;
};

/// Checks a trajectory: Ok; InvalidStep when it is empty or its times decrease; NonFiniteInput
/// when a time, position or velocity is not finite.
Status validateTrajectory(std::span<const TrajectoryPoint> trajectory);

/// Checks a projectile danger: validateTrajectory, then NonFiniteInput, InvalidFuse (fuse time
/// < 0) or InvalidRadius (a negative radius).
Status validateProjectileDanger(const ProjectileDanger& danger);

/// The projectile's position at `time` on the segment model of this header.
/// @param time  [Units: s] (finite; before the first point: the first point, after the last
///              point: the last point).
/// @return Ok, or validateTrajectory's refusals, NonFiniteInput or NonFiniteResult; `out` is
///         untouched unless Ok.
Status positionOnTrajectory(std::span<const TrajectoryPoint> trajectory, float time, RVec3& out);

/// The danger zone: the position at the fuse time, the blast radius, the fuse time.
/// @return Ok or validateProjectileDanger's refusals, NonFiniteResult.
Status computeDangerZone(const ProjectileDanger& danger, DangerZone& out);

/// Whether `point` is safe at `time`: from the fuse time on, outside the blast (a point at
/// exactly blastRadius is unsafe); before it, farther than contactRadius from the projectile
/// (always safe when contactRadius is 0, and before the trajectory's first time, when the
/// projectile is not there yet).
/// @param point  [Units: m] (finite).  @param time  [Units: s] (finite, any sign).
/// @return Ok or validateProjectileDanger's refusals, NonFiniteInput.
Status isPointSafe(const ProjectileDanger& danger, RVec3 point, float time, bool& safe);

/// When danger starts at `point`: the earliest time isPointSafe says false. The fuse time if the
/// point is within the blast; with contactRadius > 0, earlier if the projectile comes within
/// contactRadius before the fuse (findPathApproach); never otherwise.
/// @return Ok or validateProjectileDanger's refusals, NonFiniteInput.
Status findDangerStart(const ProjectileDanger& danger, RVec3 point, DangerStart& out);

/// The danger corridor: the earliest time in [fromTime, untilTime] at which the projectile comes
/// within `distance` of `point` (at most `distance`: exact, per segment, see the header).
/// @param distance   [Units: m] [Limit: >= 0].
/// @param fromTime, untilTime  the time window [Units: s] [Limit: finite, fromTime <= untilTime
///                   or the window is empty: never].
/// @return Ok, validateTrajectory's refusals, NonFiniteInput or InvalidRadius (distance < 0).
Status findPathApproach(std::span<const TrajectoryPoint> trajectory, RVec3 point, float distance, float fromTime,
                        float untilTime, DangerStart& out);

/// The closest approach of the projectile to `point` over [fromTime, untilTime] (exact per
/// segment). An empty window (fromTime > untilTime) is treated as the single time fromTime.
/// @return Ok, validateTrajectory's refusals, NonFiniteInput or NonFiniteResult.
Status findClosestPathApproach(std::span<const TrajectoryPoint> trajectory, RVec3 point, float fromTime,
                               float untilTime, ClosestApproach& out);

// ---------------------------------------------------------------------------------------------
// Vehicles against characters

/// A vehicle as an oriented box moving on the exact path of predictVehicleExact.
struct VehicleBody {
    VehicleState state;                  ///< at t = 0 (as predictVehicleExact takes it).
    VehicleSettings settings;            ///< frame of the angular velocity, forward axis.
    Vec3 halfExtents{0.9f, 0.7f, 2.2f};  ///< the box [Units: m] [Limit: each > 0], local axes.
    /// The box's centre in the vehicle's local axes, from VehicleState::position [Units: m].
    Vec3 boxCenter{0};
};

/// A character: a sphere, or a capsule of constant direction, moving with constant acceleration.
struct CharacterBody {
    RVec3 position{0};     ///< the centre at t = 0 [Units: m].
    Vec3 velocity{0};      ///< [Units: m/s], world axes.
    Vec3 acceleration{0};  ///< [Units: m/s^2], world axes; 0 for constant velocity.
    float radius = 0.4f;   ///< [Units: m] [Limit: >= 0].
    /// Half of the capsule's inner segment (centre - halfAxis to centre + halfAxis), world axes
    /// [Units: m]; zero for a sphere (e.g. (0, 0.5, 0): a standing capsule 1 m + 2 radii tall).
    Vec3 halfAxis{0};
};

/// Tolerance and work cap of the vehicle queries.
struct ApproachSettings {
    /// Distance tolerance [Units: m] [Limit: > 0, finite]: a contact is reported where the
    /// separation is at most this; closest distances are within this of the true minimum.
    float tolerance = 1e-3f;
    /// Separation evaluations allowed per query before TooManySteps [Limit: >= 1].
    std::uint32_t maxEvaluations = 1u << 16;
};

/// The first contact of a vehicle and a character.
struct VehicleContact {
    bool contact = false;           ///< whether they come within `tolerance` before the horizon.
    float time = 0;                 ///< the time of first contact [Units: s]; valid when `contact`:
                                    ///< never later than the true first overlap, and the separation
                                    ///< there is <= tolerance.
    float separation = 0;           ///< the separation at `time` (at the horizon if no contact) [Units: m].
    std::uint32_t evaluations = 0;  ///< separations computed.
};

/// Checks a vehicle body and a character: Ok, NonFiniteInput, ZeroQuaternion, ZeroVector (the
/// forward axis), DegenerateShape (a half extent <= 0) or InvalidRadius.
Status validateVehicleCharacter(const VehicleBody& vehicle, const CharacterBody& character);

/// The separation of the vehicle and the character at `time` (exact: OBB to segment minus the
/// radius; <= 0 when they overlap).
/// @param time  [Units: s] [Limit: >= 0, finite].
/// @return Ok, validateVehicleCharacter's refusals, NegativeTime or NonFiniteResult.
Status computeVehicleSeparation(const VehicleBody& vehicle, const CharacterBody& character, float time,
                                float& separation);

/// The first time in [0, horizon] at which the vehicle and the character touch (conservative
/// advancement with the proven bound of the header).
/// @param horizon  [Units: s] [Limit: >= 0, finite]; 0 checks t = 0 only.
/// @return Ok, validateVehicleCharacter's refusals, NegativeTime, InvalidStep (a tolerance <= 0
///         or not finite, or maxEvaluations 0), TooManySteps (maxEvaluations reached: a horizon
///         too long for the tolerance, the work growing with horizon / tolerance, or a long
///         grazing pass) or NonFiniteResult. `out` is untouched unless Ok.
Status findVehicleContact(const VehicleBody& vehicle, const CharacterBody& character, float horizon,
                          const ApproachSettings& settings, VehicleContact& out);

/// The closest approach in [0, horizon] (Lipschitz branch and bound, then conservative
/// advancement; see the header): `distance` is the separation at `time`, and the true minimum
/// mu satisfies `mu <= distance <= mu + tolerance`; `time` is no later than the first time
/// the separation reaches mu (before it the separation stays above mu) and no earlier than
/// the first time it comes within `tolerance` of mu. Among equal minima (a vehicle turning in
/// circles) the first is reported, whatever the horizon.
/// @return as findVehicleContact (both passes share maxEvaluations).
Status findClosestVehicleApproach(const VehicleBody& vehicle, const CharacterBody& character, float horizon,
                                  const ApproachSettings& settings, ClosestApproach& out);

FORESIGHT_NAMESPACE_END
