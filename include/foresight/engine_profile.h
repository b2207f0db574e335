#pragma once
/// @file engine_profile.h
/// Engine profiles: how a game's physics engine steps a thrown sphere, so that a prediction
/// (ProjectileMethod::Engine in projectile.h) follows the flight the engine will compute, step
/// for step, instead of the ideal parabola.
///
/// Every rigid-body engine integrates in fixed steps of `timestep` seconds with semi-implicit
/// Euler, but each in its own way: where damping goes and by which law, whether a step is split
/// into sub-steps, what happens on a body's first step, when a contact starts to act
/// (speculative contacts before touching, or only once the sphere penetrates), which velocity a
/// bounce reflects, below which speed nothing bounces, how penetration is pushed out, and how
/// two materials combine. An EngineProfile writes those choices down; engineProfile() gives the
/// values measured on each engine's own build (see docs/engines.md for the measurements and the
/// harnesses that check them in the test suite).
///
/// Free flight of the engine's recurrence has a closed form (engineFreeFlight): the state after
/// any number of steps in O(1), identical (to rounding) to stepping.

#include <foresight/status.h>

#include <cstdint>

FORESIGHT_NAMESPACE_BEGIN

/// The engines with a named profile.
enum class PhysicsEngine : std::uint8_t {
    Custom,        ///< every field set by the caller (defaults: plain semi-implicit Euler).
    Jolt,          ///< Jolt Physics 5 (Godot 4.4+ "Jolt Physics", Horizon): discrete motion quality.
    PhysX,         ///< NVIDIA PhysX 4/5 rigid bodies with Unity's defaults (Rigidbody, drag 0).
    Rapier,        ///< Rapier (Bevy): 4 solver sub-steps.
    Bullet,        ///< Bullet's btDiscreteDynamicsWorld with its defaults.
    Godot3,        ///< Godot 3 with GodotPhysics.
    Godot3Bullet,  ///< Godot 3 with its default 3-D engine (Bullet), project damping added.
    Box2D,         ///< Box2D v2.4 (2-D: motion in the x-y plane, z kept at its start value).
};

/// Where the damping factor goes in a step.
enum class DampingOrder : std::uint8_t {
    GravityThenDamping,  ///< `v = (v + g dt) d` (Jolt, PhysX, Rapier after its sub-steps).
    DampingThenGravity,  ///< `v = v d + g dt` (Bullet, Godot 3, Box2D).
};

/// The damping factor `d` applied once per step to the linear velocity, for a coefficient `c`.
enum class DampingLaw : std::uint8_t {
    None,           ///< `d = 1` (the coefficient is ignored).
    LinearClamped,  ///< `d = max(0, 1 - c dt)` (Jolt, PhysX, Godot 3).
    Rational,       ///< `d = 1 / (1 + c dt)` (Rapier, Box2D).
    Power,          ///< `d = (1 - min(c, 1))^dt` (Bullet).
};

/// How an engine combines two materials' coefficients into the contact's value.
enum class CombineRule : std::uint8_t {
    Average,        ///< `(a + b) / 2` (PhysX and Rapier by default).
    Min,            ///< `min(a, b)` (Godot 3 friction).
    Max,            ///< `max(a, b)` (Jolt restitution, Box2D restitution).
    Multiply,       ///< `a b` (Bullet).
    GeometricMean,  ///< `sqrt(a b)` (Jolt friction, Box2D friction).
    SumClamped,     ///< `clamp(a + b, 0, 1)` (Godot 3 restitution).
};

/// Which velocity a bounce reflects (the normal speed that restitution multiplies).
enum class RestitutionBase : std::uint8_t {
    StepStart,     ///< the velocity at the start of the contact step (Jolt, Rapier, Bullet).
    AfterGravity,  ///< the velocity after that step's gravity and damping (PhysX, Godot 3, Box2D).
};

/// What a body's first step does (the step in which it enters the world).
enum class FirstStepRule : std::uint8_t {
    Normal,       ///< like every other step.
    NoGravity,    ///< `p += v dt` only: no gravity, no damping (Godot 3 GodotPhysics).
    DampingOnly,  ///< `v = v d; p += v dt`: no gravity (Godot 3 with Bullet).
};

/// When a contact starts to act on the velocity.
enum class ContactMethod : std::uint8_t {
    /// A contact whose gap at the start of a step is within `contactDistance` acts in that step:
    /// the solver lets the sphere close the gap, and no more (Jolt, PhysX, Rapier, Bullet, Box2D).
    Speculative,
    /// A contact acts only once the sphere overlaps the surface at the start of a step (it
    /// penetrates by up to one step's motion first) (Godot 3 GodotPhysics).
    Penetration,
};

/// How an engine steps a sphere and answers its contacts. Named profiles come from
/// engineProfile(); every field can be overridden (a project's own damping, bounce threshold).
/// Coefficients are as the engine's API takes them.
struct EngineProfile {
    PhysicsEngine engine = PhysicsEngine::Custom;  ///< which engine the values describe.
    float timestep = 1.0f / 60.0f;                 ///< the engine's fixed step [Units: s] [Limit: 1e-5 .. 1].
    /// Equal sub-steps per step, each `v += g h; p += v h` with `h = timestep / substeps`; the
    /// damping factor is then applied once with the whole step (Rapier: 4) [Limit: 1 .. 64].
    std::uint32_t substeps = 1;
    DampingOrder order = DampingOrder::GravityThenDamping;  ///< where damping goes in a step.
    DampingLaw damping = DampingLaw::LinearClamped;         ///< the linear damping law.
    float linearDamping = 0.0f;  ///< the body's linear damping coefficient [Units: 1/s] [Limit: >= 0].
    /// Added to linearDamping before the law is applied: a project-wide default the engine adds
    /// to every body's own value (Godot 3 with Bullet: 0.1) [Units: 1/s] [Limit: >= 0].
    float addedLinearDamping = 0.0f;
    /// The body's angular damping coefficient, same law as the linear one [Units: 1/s] [Limit: >= 0].
    float angularDamping = 0.0f;
    FirstStepRule firstStep = FirstStepRule::Normal;  ///< the body's first step.
    /// Impacts whose normal approach speed is not above this do not bounce [Units: m/s] [Limit: >= 0].
    float restitutionThreshold = 0.0f;
    RestitutionBase restitutionBase = RestitutionBase::StepStart;  ///< what a bounce reflects.
    CombineRule restitutionCombine = CombineRule::Max;             ///< rule for a shape's own restitution.
    CombineRule frictionCombine = CombineRule::GeometricMean;      ///< rule for a shape's own friction.
    ContactMethod contact = ContactMethod::Speculative;            ///< when a contact starts to act.
    /// Speculative contacts: the largest gap that makes a contact [Units: m] [Limit: >= 0].
    float contactDistance = 0.02f;
    /// Penetration that is left alone (not pushed out) [Units: m] [Limit: >= 0].
    float penetrationSlop = 0.0f;
    /// Fraction of the penetration (beyond the slop) removed per step [Limit: 0 .. 1].
    float positionCorrection = 0.0f;
    /// true: the correction is a velocity (`fraction * depth / dt` added to the normal velocity,
    /// so the sphere keeps it: Bullet, Godot 3); false: the position is moved and the velocity is
    /// left alone (Jolt, Box2D).
    bool correctionIsVelocity = false;
    /// Bullet's split impulse (erp2): fraction of a penetration deeper than 4 cm pushed out per
    /// step by a separate velocity that moves the sphere but is not kept. Bullet 2.85 and later:
    /// 0.2; ammo.js 0.0.10 (Bullet 2.83): 0.8. Only the Bullet profiles use it [Limit: 0 .. 1].
    float splitImpulseCorrection = 0.2f;
    /// Fraction of a contact's previous friction impulse that the solver applies first when the
    /// contact persists into the next step (warm starting of friction), along that step's new
    /// friction direction; a contact whose normal impulse then comes out zero keeps it
    /// uncorrected. Bullet up to 2.88 (ammo.js 0.0.10 carries 2.83): 0.85; Bullet 2.89 and later
    /// and the other engines' profiles: 0 [Limit: 0 .. 1]. The Bullet profiles keep Bullet's
    /// contact manifolds against convex shapes (not against a triangleMesh): up to four points per
    /// surface, each with its own normal impulse warm-started (by Bullet's 0.85) and its friction
    /// impulse by this factor (docs/engines.md); so does the Godot 3 with Bullet profile. With
    /// 0 (Bullet 2.89 and later) these two profiles also compute the first contact with a box as
    /// Bullet's float arithmetic does, from Bullet's own float position (docs/engines.md).
    float frictionWarmStart = 0.0f;
    /// Largest linear speed the engine allows; faster bodies are slowed to it each step
    /// (Jolt: 500) [Units: m/s] [Limit: > 0].
    float maxLinearSpeed = 3.0e38f;
    /// Largest distance a body may move in one step; a faster one is slowed so that it moves
    /// exactly this far (Box2D: 2) [Units: m] [Limit: > 0].
    float maxStepDistance = 3.0e38f;
    /// Motion in the x-y plane only (Box2D): velocities' z and gravity's z are ignored.
    bool planar = false;
    /// Solid sphere (I = 2/5 m r^2) when true; false: rotation locked (the sphere slides).
    bool rotates = true;
    /// The world's surfaces are triangles of the engine's triangle-mesh shape, which the engine
    /// collides triangle by triangle, rather than convex shapes (boxes, spheres, planes). Used by
    /// the Bullet profile (a btBvhTriangleMeshShape with its default margin 0): a triangle is only
    /// tested once the sphere's bounding box reaches it (no early contact on an axis-aligned
    /// face), and triangles are double-sided (a sphere whose centre has passed a triangle's plane
    /// is pushed on through it). Other profiles ignore it (Godot 3 with Bullet gives its meshes a
    /// margin and internal-edge information, not modelled).
    bool triangleMesh = false;
};

/// The named profile of `engine` with its own defaults: the default damping of a new body, its
/// first-step rule, bounce threshold, combine rules and contact handling; timestep 1/60 s.
/// PhysicsEngine::Custom gives plain semi-implicit Euler with nothing else.
EngineProfile engineProfile(PhysicsEngine engine);

/// Bullet as ammo.js 0.0.10 carries it (Bullet 2.83 compiled to asm.js, the Bullet of many web
/// games): engineProfile(PhysicsEngine::Bullet) with no restitution threshold (Bullet 2.87 added
/// it), friction warm-started by 0.85 (frictionWarmStart; removed in Bullet 2.89) and deep
/// penetrations pushed out with erp2 = 0.8 (splitImpulseCorrection; 0.2 from Bullet 2.85 on).
/// The scenario format's profile "ammo"; timestep 1/60 s.
EngineProfile ammoJsProfile();

/// The profile's name as the scenario format writes it ("jolt", "physx", "rapier", "bullet",
/// "godot3", "godot3-bullet", "box2d", "custom"). Never null.
const char* engineName(PhysicsEngine engine);

/// Checks a profile: Ok, NonFiniteInput, InvalidStep (timestep outside 1e-5 .. 1 s) or
/// InvalidSetting (substeps outside 1 .. 64, a negative coefficient or distance, a correction
/// outside 0 .. 1, a non-positive speed or step distance, an enumerator out of range).
Status validateEngineProfile(const EngineProfile& profile);

/// The coefficient a contact uses for two materials under `rule` (e.g. a projectile's and a
/// shape's restitution).
float combineMaterial(CombineRule rule, float a, float b);

/// A free-flying body's state after a whole number of engine steps.
struct EngineFlightState {
    RVec3 position{0};  ///< [Units: m]
    Vec3 velocity{0};   ///< [Units: m/s]
};

/// The state after `steps` engine steps of free flight (no contact) from `position`, `velocity`
/// under `gravity`, in closed form: O(1) whatever `steps`, equal to stepping the profile's
/// recurrence (first-step rule, sub-steps, damping) to within rounding. Speed limits
/// (maxLinearSpeed, maxStepDistance) are not applied: stepping is needed when they bind.
/// The profile must be valid (validateEngineProfile).
EngineFlightState engineFreeFlight(const EngineProfile& profile, RVec3 position, Vec3 velocity, Vec3 gravity,
                                   std::uint64_t steps);

FORESIGHT_NAMESPACE_END
