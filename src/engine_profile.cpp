#include <foresight/engine_profile.h>

#include "engine_internal.h"
#include "internal.h"

#include <cmath>

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

EngineProfile engineProfile(PhysicsEngine engine) {
    EngineProfile p;
    p.engine = engine;
    switch (engine) {
        case PhysicsEngine::Custom:
            p.damping = DampingLaw::LinearClamped;
            p.restitutionCombine = CombineRule::Average;
            p.frictionCombine = CombineRule::Average;
            p.contactDistance = 0.0f;
            break;
        case PhysicsEngine::Jolt:
            // BodyCreationSettings: mLinearDamping 0.05, mAngularDamping 0.05; PhysicsSettings:
            // mSpeculativeContactDistance 0.02, mPenetrationSlop 0.02, mBaumgarte 0.2,
            // mMinVelocityForRestitution 1; MotionProperties: mMaxLinearVelocity 500.
            p.order = DampingOrder::GravityThenDamping;
            p.damping = DampingLaw::LinearClamped;
            p.linearDamping = 0.05f;
            p.angularDamping = 0.05f;
            p.restitutionThreshold = 1.0f;
            p.restitutionBase = RestitutionBase::StepStart;
            p.restitutionCombine = CombineRule::Max;
            p.frictionCombine = CombineRule::GeometricMean;
            p.contact = ContactMethod::Speculative;
            p.contactDistance = 0.02f;
            p.penetrationSlop = 0.02f;
            p.positionCorrection = 0.2f;
            p.correctionIsVelocity = false;
            p.maxLinearSpeed = 500.0f;
            break;
        case PhysicsEngine::PhysX:
            // PxRigidDynamic: linear damping 0 (Unity's drag 0), angular 0.05; bounce threshold
            // 2 m/s (Unity's default, 0.2 x the tolerance speed 10 in PhysX); contact offset 0.02.
            p.order = DampingOrder::GravityThenDamping;
            p.damping = DampingLaw::LinearClamped;
            p.linearDamping = 0.0f;
            p.angularDamping = 0.05f;
            p.restitutionThreshold = 2.0f;
            p.restitutionBase = RestitutionBase::AfterGravity;
            p.restitutionCombine = CombineRule::Average;
            p.frictionCombine = CombineRule::Average;
            p.contact = ContactMethod::Speculative;
            p.contactDistance = 0.04f;
            p.penetrationSlop = 0.0f;
            p.positionCorrection = 0.8f;
            p.correctionIsVelocity = true;
            break;
        case PhysicsEngine::Rapier:
            p.substeps = 4;
            p.order = DampingOrder::GravityThenDamping;
            p.damping = DampingLaw::Rational;
            p.linearDamping = 0.0f;
            p.angularDamping = 0.0f;
            p.restitutionThreshold = 0.0f;
            p.restitutionBase = RestitutionBase::StepStart;
            p.restitutionCombine = CombineRule::Average;
            p.frictionCombine = CombineRule::Average;
            p.contact = ContactMethod::Speculative;
            p.contactDistance = 0.02f;
            p.penetrationSlop = 0.005f;  // normalized_allowed_linear_error: the CCD stops this deep
            p.positionCorrection = 0.2f;
            p.correctionIsVelocity = false;
            break;
        case PhysicsEngine::Bullet:
            p.order = DampingOrder::DampingThenGravity;
            p.damping = DampingLaw::Power;
            p.restitutionThreshold = 0.2f;  // Bullet 2.87 and later (ammo.js's older Bullet has none)
            p.restitutionBase = RestitutionBase::StepStart;
            p.restitutionCombine = CombineRule::Multiply;
            p.frictionCombine = CombineRule::Multiply;
            p.contact = ContactMethod::Speculative;
            p.contactDistance = 0.02f;
            p.positionCorrection = 0.2f;
            p.correctionIsVelocity = true;
            break;
        case PhysicsEngine::Godot3:
            p.order = DampingOrder::DampingThenGravity;
            p.damping = DampingLaw::LinearClamped;
            p.linearDamping = 0.1f;  // the project default, which a body's own value replaces
            p.angularDamping = 0.1f;
            p.firstStep = FirstStepRule::NoGravity;
            p.restitutionBase = RestitutionBase::AfterGravity;
            p.restitutionCombine = CombineRule::SumClamped;
            p.frictionCombine = CombineRule::Min;
            p.contact = ContactMethod::Penetration;
            p.contactDistance = 0.0f;
            p.penetrationSlop = 0.01f;
            p.positionCorrection = 0.3f;
            p.correctionIsVelocity = true;
            break;
        case PhysicsEngine::Godot3Bullet:
            p.order = DampingOrder::DampingThenGravity;
            p.damping = DampingLaw::LinearClamped;
            p.linearDamping = 0.0f;
            p.addedLinearDamping = 0.1f;  // the project default, added to the body's own value
            p.angularDamping = 0.1f;
            p.restitutionThreshold = 0.2f;  // Godot 3.2 bundles Bullet 2.89
            p.firstStep = FirstStepRule::DampingOnly;
            p.restitutionBase = RestitutionBase::StepStart;
            p.restitutionCombine = CombineRule::SumClamped;
            p.frictionCombine = CombineRule::Min;
            p.contact = ContactMethod::Speculative;
            p.contactDistance = 0.02f;  // Bullet's gContactBreakingThreshold, scaled by the shape's bound
            p.positionCorrection = 0.2f;
            p.correctionIsVelocity = true;
            break;
        case PhysicsEngine::Box2D:
            // b2_linearSlop 0.005, b2_baumgarte 0.2, restitution threshold 1 m/s,
            // b2_maxTranslation 2 m per step; a circle touches a polygon within its skin (0.01 m).
            p.order = DampingOrder::GravityThenDamping;
            p.damping = DampingLaw::Rational;
            p.restitutionThreshold = 1.0f;
            p.restitutionBase = RestitutionBase::AfterGravity;
            p.restitutionCombine = CombineRule::Max;
            p.frictionCombine = CombineRule::GeometricMean;
            p.contact = ContactMethod::Speculative;
            p.contactDistance = 0.01f;
            p.penetrationSlop = 0.005f;
            p.positionCorrection = 0.2f;
            p.correctionIsVelocity = false;
            p.maxStepDistance = 2.0f;
            p.planar = true;
            break;
    }
    return p;
}

const char* engineName(PhysicsEngine engine) {
    switch (engine) {
        case PhysicsEngine::Custom:
            return "custom";
        case PhysicsEngine::Jolt:
            return "jolt";
        case PhysicsEngine::PhysX:
            return "physx";
        case PhysicsEngine::Rapier:
            return "rapier";
        case PhysicsEngine::Bullet:
            return "bullet";
        case PhysicsEngine::Godot3:
            return "godot3";
        case PhysicsEngine::Godot3Bullet:
            return "godot3-bullet";
        case PhysicsEngine::Box2D:
            return "box2d";
    }
    return "unknown";
}

EngineProfile ammoJsProfile() {
    EngineProfile p = engineProfile(PhysicsEngine::Bullet);
    p.restitutionThreshold = 0.0f;
    p.frictionWarmStart = 0.85f;
    p.splitImpulseCorrection = 0.8f;
    return p;
}

Status validateEngineProfile(const EngineProfile& p) {
    const float values[] = {p.timestep,        p.linearDamping,        p.addedLinearDamping,
                            p.angularDamping,  p.restitutionThreshold, p.contactDistance,
                            p.penetrationSlop, p.positionCorrection,   p.maxLinearSpeed,
                            p.maxStepDistance, p.frictionWarmStart,    p.splitImpulseCorrection};
    for (float value : values)
        if (!std::isfinite(value)) return Status::NonFiniteInput;
    if (!(p.timestep >= 1e-5f && p.timestep <= 1.0f)) return Status::InvalidStep;
    if (p.substeps < 1 || p.substeps > kMaxEngineSubsteps) return Status::InvalidSetting;
    if (p.linearDamping < 0 || p.addedLinearDamping < 0 || p.angularDamping < 0 || p.restitutionThreshold < 0 ||
        p.contactDistance < 0 || p.penetrationSlop < 0)
        return Status::InvalidSetting;
    if (p.positionCorrection < 0 || p.positionCorrection > 1) return Status::InvalidSetting;
    if (p.frictionWarmStart < 0 || p.frictionWarmStart > 1) return Status::InvalidSetting;
    if (p.splitImpulseCorrection < 0 || p.splitImpulseCorrection > 1) return Status::InvalidSetting;
    if (!(p.maxLinearSpeed > 0) || !(p.maxStepDistance > 0)) return Status::InvalidSetting;
    if (static_cast<unsigned>(p.engine) > static_cast<unsigned>(PhysicsEngine::Box2D) ||
        static_cast<unsigned>(p.order) > static_cast<unsigned>(DampingOrder::DampingThenGravity) ||
        static_cast<unsigned>(p.damping) > static_cast<unsigned>(DampingLaw::Power) ||
        static_cast<unsigned>(p.restitutionCombine) > static_cast<unsigned>(CombineRule::SumClamped) ||
        static_cast<unsigned>(p.frictionCombine) > static_cast<unsigned>(CombineRule::SumClamped) ||
        static_cast<unsigned>(p.restitutionBase) > static_cast<unsigned>(RestitutionBase::AfterGravity) ||
        static_cast<unsigned>(p.firstStep) > static_cast<unsigned>(FirstStepRule::DampingOnly) ||
        static_cast<unsigned>(p.contact) > static_cast<unsigned>(ContactMethod::Penetration))
        return Status::InvalidSetting;
    return Status::Ok;
}

float combineMaterial(CombineRule rule, float a, float b) {
    switch (rule) {
        case CombineRule::Average:
            return 0.5f * (a + b);
        case CombineRule::Min:
            return std::min(a, b);
        case CombineRule::Max:
            return std::max(a, b);
        case CombineRule::Multiply:
            return a * b;
        case CombineRule::GeometricMean:
            return std::sqrt(std::max(0.0f, a * b));
        case CombineRule::SumClamped:
            return std::clamp(a + b, 0.0f, 1.0f);
    }
    return a;
}

namespace detail {

double dampingFactor(DampingLaw law, double c, double dt) {
    switch (law) {
        case DampingLaw::None:
            return 1.0;
        case DampingLaw::LinearClamped:
            return std::max(0.0, 1.0 - c * dt);
        case DampingLaw::Rational:
            return 1.0 / (1.0 + c * dt);
        case DampingLaw::Power:
            return std::pow(1.0 - std::min(c, 1.0), dt);
    }
    return 1.0;
}

EngineRecurrence engineRecurrence(const EngineProfile& profile) {
    EngineRecurrence r;
    r.dt = decimalValue(profile.timestep);
    const double c = static_cast<double>(profile.linearDamping) + profile.addedLinearDamping;
    r.d = dampingFactor(profile.damping, c, r.dt);
    // 1 - d without cancellation for the laws whose d is close to 1.
    switch (profile.damping) {
        case DampingLaw::None:
            r.oneMinusD = 0.0;
            break;
        case DampingLaw::LinearClamped:
            r.oneMinusD = std::min(1.0, c * r.dt);
            break;
        case DampingLaw::Rational:
            r.oneMinusD = c * r.dt / (1.0 + c * r.dt);
            break;
        case DampingLaw::Power:
            r.oneMinusD = c >= 1.0 ? 1.0 : -std::expm1(r.dt * std::log1p(-c));
            break;
    }
    const double n = profile.substeps;
    // One step as v' = d v + b g dt, p' = p + a v dt + cg g dt^2 (see engine_internal.h).
    const bool gravityFirst = profile.order == DampingOrder::GravityThenDamping;
    if (profile.substeps == 1) {
        r.a = r.d;
        r.b = gravityFirst ? r.d : 1.0;
        r.cg = gravityFirst ? r.d : 1.0;
    } else {
        // Sub-steps move with the undamped velocity; the damping of a gravity-first profile
        // comes after them, that of a damping-first profile before them.
        r.a = gravityFirst ? 1.0 : r.d;
        r.b = gravityFirst ? r.d : 1.0;
        r.cg = (n + 1.0) / (2.0 * n);
    }
    return r;
}

void geometricSums(double d, double oneMinusD, std::uint64_t k, double& g, double& h) {
    const double kd = static_cast<double>(k);
    if (k == 0) {
        g = h = 0.0;
        return;
    }
    if (oneMinusD == 0.0) {
        g = kd;
        h = kd * (kd - 1.0) * 0.5;
        return;
    }
    if (d == 0.0) {  // everything damped away after one step
        g = 1.0;
        h = kd - 1.0;
        return;
    }
    const double x = oneMinusD;
    if (kd * x < 1e-6) {
        // Series in x: G = k - C(k,2) x + C(k,3) x^2, H = C(k,2) - C(k,3) x + C(k,4) x^2; the
        // next terms are below (k x)^3 / 24 relative, under 1e-19.
        const double c2 = kd * (kd - 1.0) / 2.0, c3 = c2 * (kd - 2.0) / 3.0, c4 = c3 * (kd - 3.0) / 4.0;
        g = kd - c2 * x + c3 * x * x;
        h = c2 - c3 * x + c4 * x * x;
        return;
    }
    // d^k - 1 = expm1(k log d), with log d = log1p(-x) exact for d near 1.
    g = -std::expm1(kd * std::log1p(-x)) / x;
    h = (kd - g) / x;
}

}  // namespace detail

EngineFlightState engineFreeFlight(const EngineProfile& profile, RVec3 position, Vec3 velocity, Vec3 gravity,
                                   std::uint64_t steps) {
    const EngineRecurrence r = engineRecurrence(profile);
    DVec3 p = toD(position), v = toD(velocity);
    DVec3 g(decimalValue(gravity.x), decimalValue(gravity.y), decimalValue(gravity.z));
    if (profile.planar) {
        v.z = 0.0;
        g.z = 0.0;
    }
    if (steps > 0 && profile.firstStep != FirstStepRule::Normal) {
        if (profile.firstStep == FirstStepRule::DampingOnly) v *= r.d;
        p += v * r.dt;
        --steps;
    }
    double sumG = 0.0, sumH = 0.0;
    geometricSums(r.d, r.oneMinusD, steps, sumG, sumH);
    const double dk = r.oneMinusD == 0.0 ? 1.0 : (steps == 0 ? 1.0 : std::pow(r.d, static_cast<double>(steps)));
    const double kd = static_cast<double>(steps);
    EngineFlightState out;
    out.position = toR(p + r.a * r.dt * (v * sumG + r.b * r.dt * g * sumH) + kd * r.cg * r.dt * r.dt * g);
    out.velocity = toF(dk * v + r.b * r.dt * g * sumG);
    return out;
}

FORESIGHT_NAMESPACE_END
