#include <foresight/bullet_simulation.h>

#include "bullet_convert.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

FORESIGHT_NAMESPACE_BEGIN

namespace {

using bullet_detail::toBt;
using bullet_detail::toD;

RVec3 toR(const btVector3& v) {
    return RVec3(static_cast<Real>(v.x()), static_cast<Real>(v.y()), static_cast<Real>(v.z()));
}

Vec3 toF(const btVector3& v) {
    return Vec3(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()));
}

template <class T>
bool finite3(const glm::vec<3, T, glm::defaultp>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finiteBt(const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

// The decimal value a float was written as (3.0f -> 3, 0.02f -> 0.02), as predictProjectile
// takes its times: the shortest round-trip representation read back as a double.
double decimalValue(float value) {
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer - 1, value);
    *r.ptr = '\0';
    return std::strtod(buffer, nullptr);
}

// Reaches btDiscreteDynamicsWorld::releasePredictiveContacts (protected). The predictive
// manifolds of a CCD step live until the next step begins; they are released before the body
// leaves, so that none keeps a pointer to it.
struct PredictiveContactRelease : btDiscreteDynamicsWorld {
    static void release(btDiscreteDynamicsWorld& world) {
        (world.*(&PredictiveContactRelease::releasePredictiveContacts))();
    }
};

// What the scene's world had before the call, restored on every exit.
class WorldSettingsGuard {
public:
    explicit WorldSettingsGuard(btDiscreteDynamicsWorld& world)
        : mWorld(world), mSolverInfo(world.getSolverInfo()),
          mAllowedCcdPenetration(world.getDispatchInfo().m_allowedCcdPenetration),
          mUseContinuous(world.getDispatchInfo().m_useContinuous) {}
    ~WorldSettingsGuard() {
        static_cast<btContactSolverInfoData&>(mWorld.getSolverInfo()) = mSolverInfo;
        mWorld.getDispatchInfo().m_allowedCcdPenetration = mAllowedCcdPenetration;
        mWorld.getDispatchInfo().m_useContinuous = mUseContinuous;
    }
    WorldSettingsGuard(const WorldSettingsGuard&) = delete;
    WorldSettingsGuard& operator=(const WorldSettingsGuard&) = delete;

private:
    btDiscreteDynamicsWorld& mWorld;
    btContactSolverInfoData mSolverInfo;
    btScalar mAllowedCcdPenetration;
    bool mUseContinuous;
};

// A contact of the body found in the manifolds after a step.
struct StepContact {
    bool touching = false;      // a contact was solved in the step (distance <= 0)
    bool found = false;         // the fastest approach among them, below
    btVector3 normal{0, 0, 0};  // facing the sphere
    btScalar approach = 0;      // -dot(velocity the solver started from, normal)
    btScalar depth = 0;         // penetration at the start of the step (>= 0)
};

StepContact findContact(btDispatcher& dispatcher, const btRigidBody& body, const btVector3& startVelocity) {
    StepContact contact;
    const int manifolds = dispatcher.getNumManifolds();
    for (int i = 0; i < manifolds; ++i) {
        const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
        btScalar side;
        if (manifold->getBody0() == &body)
            side = btScalar(1);  // normalWorldOnB points from B towards A, the sphere
        else if (manifold->getBody1() == &body)
            side = btScalar(-1);
        else
            continue;
        for (int j = 0; j < manifold->getNumContacts(); ++j) {
            const btManifoldPoint& point = manifold->getContactPoint(j);
            // The contact processing threshold is 0: only these were given to the solver
            // (predictive CCD points and points still ahead have a positive distance).
            if (point.getDistance() > btScalar(0)) continue;
            contact.touching = true;
            const btVector3 normal = point.m_normalWorldOnB * side;
            const btScalar approach = -startVelocity.dot(normal);
            if (!contact.found || approach > contact.approach) {
                contact.found = true;
                contact.normal = normal;
                contact.approach = approach;
                contact.depth = -point.getDistance();
            }
        }
    }
    return contact;
}

}  // namespace

Status simulateProjectileRigidBody(BulletScene& scene, const RVec3& position, const Vec3& velocity, float time,
                                   const ProjectileSettings& settings, const RigidBodySimulationSettings& simulation,
                                   RigidBodySimulationResult& result) {
    if (!finite3(position) || !finite3(velocity) || !std::isfinite(time)) return Status::NonFiniteInput;
    if (time < 0.0f) return Status::NegativeTime;
    if (Status s = validateProjectileSettings(settings); s != Status::Ok) return s;
    if (!std::isfinite(simulation.frequency) || !std::isfinite(simulation.pointRadius) ||
        !std::isfinite(simulation.minImpactSpeed) || !std::isfinite(simulation.restSpeed))
        return Status::NonFiniteInput;
    if (!(simulation.frequency >= 240.0f && simulation.frequency <= 100000.0f)) return Status::InvalidStep;
    if (!(simulation.pointRadius > 0.0f)) return Status::InvalidRadius;

    // Bullet steps in btScalar: the step is the btScalar nearest 1/frequency, and times are
    // counted in multiples of exactly that value.
    const btScalar stepBt = static_cast<btScalar>(1.0 / static_cast<double>(simulation.frequency));
    const double step = static_cast<double>(stepBt);
    const double total = decimalValue(time);
    const double quotient = total / step;
    std::uint64_t fullSteps = static_cast<std::uint64_t>(std::floor(quotient));
    // A quotient within 1e-9 (relative) below an integer is that integer: rounding never adds a
    // sliver of a step.
    if (std::floor(quotient) + 1.0 - quotient <= 1e-9 * std::max(1.0, quotient)) ++fullSteps;
    double rest = total - static_cast<double>(fullSteps) * step;
    if (rest < 1e-6) rest = 0.0;  // under a microsecond: dropped (documented)
    const std::uint64_t stepCount = fullSteps + (rest > 0.0 ? 1u : 0u);
    if (stepCount > settings.maxSteps) return Status::TooManySteps;

    const double radius =
        settings.radius > 0.0f ? static_cast<double>(settings.radius) : static_cast<double>(simulation.pointRadius);
    const btScalar radiusBt = static_cast<btScalar>(radius);
    const btVector3 gravity = toBt(glm::dvec3(decimalValue(settings.gravity.x), decimalValue(settings.gravity.y),
                                              decimalValue(settings.gravity.z)));

    btDiscreteDynamicsWorld& world = scene.dynamicsWorld();
    const WorldSettingsGuard guard(world);
    btContactSolverInfo& solver = world.getSolverInfo();
    // Why each value: see bullet_simulation.h.
    solver.m_restitutionVelocityThreshold = btScalar(0);
    solver.m_splitImpulse = 1;
    solver.m_splitImpulsePenetrationThreshold = btScalar(0);
    solver.m_erp2 = btScalar(1);
    solver.m_solverMode &= ~(SOLVER_USE_WARMSTARTING | SOLVER_RANDMIZE_ORDER);
    solver.m_numIterations = 30;
    solver.m_leastSquaresResidualThreshold = btScalar(0);
    world.getDispatchInfo().m_useContinuous = true;
    world.getDispatchInfo().m_allowedCcdPenetration = btScalar(0);

    btSphereShape shape(radiusBt);
    btVector3 inertia(0, 0, 0);
    shape.calculateLocalInertia(btScalar(1), inertia);
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(1), nullptr, &shape, inertia);
    info.m_restitution = static_cast<btScalar>(settings.restitution);
    info.m_friction = static_cast<btScalar>(settings.friction);
    info.m_rollingFriction = btScalar(0);
    info.m_spinningFriction = btScalar(0);
    info.m_linearDamping = btScalar(0);
    info.m_angularDamping = btScalar(0);
    info.m_additionalDamping = false;
    info.m_startWorldTransform.setIdentity();
    info.m_startWorldTransform.setOrigin(toBt(glm::dvec3(position)));
    btRigidBody body(info);
    body.setActivationState(DISABLE_DEACTIVATION);
    body.setFlags(body.getFlags() | BT_DISABLE_WORLD_GRAVITY);
    if (simulation.lockRotation) body.setAngularFactor(btScalar(0));
    body.setContactProcessingThreshold(btScalar(0));
    body.setCcdMotionThreshold(btScalar(0.5) * radiusBt);
    body.setCcdSweptSphereRadius(btScalar(0.8) * radiusBt);
    world.addRigidBody(&body);
    body.setGravity(gravity);
    const btScalar half(0.5);
    const btVector3 startVelocity = toBt(glm::dvec3(velocity));
    body.setLinearVelocity(simulation.leapfrogStart ? startVelocity - gravity * (half * stepBt) : startVelocity);

    RigidBodySimulationResult out;
    out.radius = radius;
    out.samples.reserve(static_cast<std::size_t>(stepCount) + 1);
    out.samples.push_back(TrajectoryPoint{0.0f, TrajectoryEvent::Start, position, velocity, Vec3(0)});

    btDispatcher& dispatcher = *world.getDispatcher();
    double now = 0.0;
    btVector3 previousStart = body.getWorldTransform().getOrigin();
    double previousLength = step;
    btVector3 reported = startVelocity;
    bool touching = false;
    for (std::uint64_t k = 0; k < stepCount; ++k) {
        const bool partial = k == fullSteps;
        const btScalar length = partial ? static_cast<btScalar>(rest) : stepBt;
        if (partial && simulation.leapfrogStart) {
            // Leapfrog with a shorter step h: the velocity must be the one at h/2 before the
            // step's start, not dt/2 (exact on the parabola again).
            body.setLinearVelocity(body.getLinearVelocity() + gravity * (half * (stepBt - length)));
        }
        const btVector3 start = body.getWorldTransform().getOrigin();
        const btVector3 before = body.getLinearVelocity();
        // One step of exactly `length` (maxSubSteps 0: Bullet's variable step, no accumulator).
        world.stepSimulation(length, 0);
        now += static_cast<double>(length);
        const btVector3 after = body.getLinearVelocity();
        const btVector3 solverStart = before + gravity * length;
        const StepContact contact = findContact(dispatcher, body, solverStart);
        touching = contact.touching;
        const btVector3 end = body.getWorldTransform().getOrigin();
        reported = (touching || !simulation.leapfrogStart) ? after : after + gravity * (half * length);

        TrajectoryPoint sample{static_cast<float>(now), TrajectoryEvent::Step, toR(end), toF(reported), Vec3(0)};
        if (contact.found) {
            const btScalar gravityNormal = btFabs(gravity.dot(contact.normal)) * length;
            const btScalar threshold =
                std::max(static_cast<btScalar>(simulation.minImpactSpeed), btScalar(2) * gravityNormal);
            const btScalar gained = (after - solverStart).dot(contact.normal);
            if (contact.approach > threshold && gained >= btScalar(0.99) * contact.approach) {
                sample.event = TrajectoryEvent::Bounce;
                sample.normal = toF(contact.normal);
                if (out.impacts.size() < simulation.maxImpacts) {
                    SimulatedImpact impact;
                    impact.time = now;
                    impact.position = toR(end);
                    impact.normal = toF(contact.normal);
                    impact.approachSpeed = static_cast<float>(contact.approach);
                    // Back along the previous step's straight motion to depth 0.
                    const glm::dvec3 motion = toD(start) - toD(previousStart);
                    const double closing = -glm::dot(motion, toD(contact.normal));
                    const double fraction =
                        closing > 0.0 ? std::clamp(static_cast<double>(contact.depth) / closing, 0.0, 1.0) : 0.0;
                    const glm::dvec3 touch = toD(start) - motion * fraction;
                    impact.touchTime = now - static_cast<double>(length) - fraction * previousLength;
                    impact.touchPosition =
                        RVec3(static_cast<Real>(touch.x), static_cast<Real>(touch.y), static_cast<Real>(touch.z));
                    out.impacts.push_back(impact);
                }
            }
        }
        out.samples.push_back(sample);
        previousStart = start;
        previousLength = static_cast<double>(length);
    }
    if (stepCount == 0) out.samples.push_back(out.samples.front());
    out.samples.back().event = TrajectoryEvent::End;
    out.samples.back().time = time;

    const btVector3 finalPosition = body.getWorldTransform().getOrigin();
    PredictiveContactRelease::release(world);
    world.removeRigidBody(&body);

    if (!finiteBt(finalPosition) || !finiteBt(reported)) return Status::NonFiniteResult;
    out.position = stepCount == 0 ? position : toR(finalPosition);
    out.velocity = stepCount == 0 ? velocity : toF(reported);
    out.atRest = stepCount > 0 && touching && reported.length() < static_cast<btScalar>(simulation.restSpeed);
    result = std::move(out);
    return Status::Ok;
}

FORESIGHT_NAMESPACE_END
