// simulateProjectileRigidBody (bullet_simulation.h): a projectile as a Bullet rigid body, against
// closed forms (drops, slides, reflections) and against predictProjectile's exact method on the
// same shapes. Bullet steps at `frequency`; the tolerances below are derived from its step
// dt = 1 / frequency, and the measured deviations are printed for the record.

#include "test_util.h"

#include <foresight/bullet_simulation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

using foresight::BulletScene;
using foresight::OrientedBox;
using foresight::Plane;
using foresight::ProjectileResult;
using foresight::ProjectileSettings;
using foresight::RigidBodySimulationResult;
using foresight::RigidBodySimulationSettings;
using foresight::RVec3;
using foresight::SimulatedImpact;
using foresight::StaticWorld;
using foresight::Status;
using foresight::TrajectoryEvent;
using foresight::TrajectoryPoint;
using foresight::Triangle;
using foresight::Vec3;
using ftest::DVec3;
using ftest::toD;
using ftest::toF;
using ftest::toR;

constexpr double kG = 9.8100004196166992;  // kDefaultGravity as float, as Bullet sees it

// The cases were drawn with xorshift64 (ftest::Random, test_util.h); keep the step.
constexpr ftest::Random::Step kRandomStep = ftest::Random::Step::XorShift64;

double step(const RigidBodySimulationSettings& simulation) {
    return static_cast<double>(static_cast<float>(1.0 / static_cast<double>(simulation.frequency)));
}

// Highest centre height among the samples in (from, to).
double apex(const RigidBodySimulationResult& r, double from, double to) {
    double best = -1e30;
    for (const TrajectoryPoint& p : r.samples)
        if (static_cast<double>(p.time) > from && static_cast<double>(p.time) < to)
            best = std::max(best, static_cast<double>(p.position.y));
    return best;
}

// A ball of radius 5 cm dropped from 1 m (lowest point) on a plane, restitution 0.6, no friction.
// Closed form: it reaches the floor at t0 = sqrt(2 h / g) with speed v0 = g t0; bounce k leaves
// with e^(k+1) v0, lands 2 e^(k+1) v0 / g later and rises to e^(2k+2) h.
//
// Tolerances, from Bullet's step dt (leapfrog flight is exact, so all of it comes from bounces):
// Bullet finds the contact at the start of the first step that begins in penetration, t_s, 0 to
// 1 step after the touch t_c, and sets the normal velocity to e times the velocity at t_s - dt/2.
// In leapfrog terms the rebound velocity then exceeds the ideal one by
// g (t_s - t_c) (1 + e) + g dt (1 - e) / 2, between 0 and 2 g dt. Carried from bounce to bounce
// (times e), rebound k is off by R_k <= e R_(k-1) + 2 g dt; approach k by R_(k-1) + 1.5 g dt
// (Bullet reports the speed at the end of its step, up to 1.5 g dt past the touch); apex k by
// (v_k R_k + R_k^2 / 2) / g (+ g dt^2 / 8 between samples); and each flight ends up to dt (the
// late start) + 2 R_k / g (the faster rebound) late.
TEST(BulletSimulation, DropMatchesClosedForm) {
    BulletScene scene;
    ASSERT_EQ(scene.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    ProjectileSettings settings;
    settings.restitution = 0.6f;
    settings.radius = 0.05f;
    const double e = static_cast<double>(settings.restitution), r = 0.05, h = 1.0;
    for (float frequency : {240.0f, 960.0f, 3840.0f}) {
        RigidBodySimulationSettings simulation;
        simulation.frequency = frequency;
        const double dt = step(simulation);
        RigidBodySimulationResult result;
        ASSERT_EQ(foresight::simulateProjectileRigidBody(scene, RVec3(0, h + r, 0), Vec3(0), 4.0f, settings, simulation,
                                                         result),
                  Status::Ok);
        const double t0 = std::sqrt(2.0 * h / kG), v0 = kG * t0;
        double expectedTouch = t0, touchTolerance = 1e-5, rebound = 0.0;
        double worstTouch = 0, worstApex = 0, worstApexTolerance = 0, worstRebound = 0, worstTime = 0;
        const std::size_t bounces = 6;  // e^6 v0 = 0.2 m/s: hops of 2 mm
        ASSERT_GE(result.impacts.size(), bounces) << frequency;
        for (std::size_t k = 0; k < bounces; ++k) {
            const SimulatedImpact& impact = result.impacts[k];
            const double speed = std::pow(e, static_cast<double>(k)) * v0;  // ideal approach of impact k
            EXPECT_NEAR(impact.touchTime, expectedTouch, touchTolerance) << frequency << " Hz, bounce " << k;
            worstTouch = std::max(worstTouch, std::abs(impact.touchTime - expectedTouch));
            // `time` is the end of the step that applied the impulse: 1 to 2 steps after the touch.
            EXPECT_GE(impact.time - impact.touchTime, dt - 1e-9);
            EXPECT_LE(impact.time - impact.touchTime, 2.0 * dt + 1e-9);
            worstTime = std::max(worstTime, impact.time - impact.touchTime);
            EXPECT_NEAR(static_cast<double>(impact.approachSpeed), speed, rebound + 1.5 * kG * dt + 1e-5)
                << frequency << " Hz, bounce " << k;
            EXPECT_NEAR(static_cast<double>(impact.normal.y), 1.0, 1e-6);
            rebound = e * rebound + 2.0 * kG * dt;
            const double next = k + 1 < result.impacts.size() ? result.impacts[k + 1].touchTime : 4.0;
            const double height = apex(result, impact.time, next) - r;
            const double expectedHeight = std::pow(e, 2.0 * static_cast<double>(k + 1)) * h;
            const double leaving = e * speed;
            const double apexTolerance = (leaving * rebound + 0.5 * rebound * rebound) / kG + kG * dt * dt / 8 + 1e-5;
            EXPECT_NEAR(height, expectedHeight, apexTolerance) << frequency << " Hz, bounce " << k;
            worstApex = std::max(worstApex, std::abs(height - expectedHeight));
            worstApexTolerance = std::max(worstApexTolerance, apexTolerance);
            // Rebound speed actually simulated, from the apex: sqrt(2 g height).
            worstRebound = std::max(worstRebound, std::abs(std::sqrt(2.0 * kG * height) - leaving) / (kG * dt));
            expectedTouch += 2.0 * leaving / kG;
            touchTolerance += dt + 2.0 * rebound / kG;
        }
        std::printf(
            "[ drop %5.0f Hz ] %zu impacts; first 6 bounces: max |touch time - closed form| %.3g s "
            "(%.2f steps; bound %.2f steps), max |apex - e^2k h| %.3g m (bound %.3g m), rebound speed "
            "off by up to %.2f g dt, impact time - touch %.2f steps at most\n",
            static_cast<double>(frequency), result.impacts.size(), worstTouch, worstTouch / dt, touchTolerance / dt,
            worstApex, worstApexTolerance, worstRebound, worstTime / dt);
        // The first touch is on the exact parabola (leapfrog start): float rounding only.
        EXPECT_NEAR(result.impacts[0].touchTime, t0, 1e-5);
        EXPECT_NEAR(static_cast<double>(result.impacts[0].touchPosition.y), r, 1e-5);
    }
}

// Without the leapfrog start, Bullet's semi-implicit Euler falls faster: the first touch comes
// early by about dt / 2 (|g| t dt / 2 lower after t).
TEST(BulletSimulation, PlainEulerStartLandsHalfAStepEarly) {
    BulletScene scene;
    ASSERT_EQ(scene.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    ProjectileSettings settings;
    settings.radius = 0.05f;
    RigidBodySimulationSettings simulation;
    simulation.leapfrogStart = false;
    const double dt = step(simulation);
    RigidBodySimulationResult result;
    ASSERT_EQ(
        foresight::simulateProjectileRigidBody(scene, RVec3(0, 1.05f, 0), Vec3(0), 1.0f, settings, simulation, result),
        Status::Ok);
    ASSERT_FALSE(result.impacts.empty());
    const double t0 = std::sqrt(2.0 / kG);
    // Height error g t dt / 2 at speed g t: dt / 2 early (to first order).
    EXPECT_NEAR(result.impacts[0].touchTime, t0 - dt / 2, 0.05 * dt);
}

// Restitution 0.5 on a frictionless floor: the horizontal velocity is never touched.
TEST(BulletSimulation, FrictionlessFloorKeepsHorizontalVelocity) {
    BulletScene scene;
    ASSERT_EQ(scene.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    ProjectileSettings settings;
    settings.radius = 0.1f;
    RigidBodySimulationSettings simulation;
    RigidBodySimulationResult result;
    ASSERT_EQ(foresight::simulateProjectileRigidBody(scene, RVec3(0, 2, 0), Vec3(3, 1, -2), 3.0f, settings, simulation,
                                                     result),
              Status::Ok);
    EXPECT_GE(result.impacts.size(), 4u);
    EXPECT_EQ(result.velocity.x, 3.0f);
    EXPECT_EQ(result.velocity.z, -2.0f);
    // 2880 float position updates of 3 * dt: rounding of ~1e-7 m each at most.
    EXPECT_NEAR(static_cast<double>(result.position.x), 9.0, 1e-3);
    EXPECT_NEAR(static_cast<double>(result.position.z), -6.0, 1e-3);
    EXPECT_NEAR(static_cast<double>(result.position.y), 0.1, 1e-3);  // settled on the floor
}

// Sliding on a floor with friction mu (rotation locked): Coulomb deceleration mu g, stops after
// v / (mu g) at v^2 / (2 mu g).
TEST(BulletSimulation, SlidingWithFrictionStopsAtClosedFormDistance) {
    BulletScene scene;
    ASSERT_EQ(scene.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    ProjectileSettings settings;
    settings.radius = 0.05f;
    settings.friction = 0.3f;
    RigidBodySimulationSettings simulation;
    const double dt = step(simulation);
    const double mu = static_cast<double>(settings.friction), v = 4.0;
    RigidBodySimulationResult result;
    ASSERT_EQ(foresight::simulateProjectileRigidBody(scene, RVec3(0, 0.05f, 0), Vec3(4, 0, 0), 2.0f, settings,
                                                     simulation, result),
              Status::Ok);
    const double stopTime = v / (mu * kG), distance = v * v / (2.0 * mu * kG);
    double worstSpeed = 0;
    for (const TrajectoryPoint& p : result.samples) {
        const double t = static_cast<double>(p.time);
        if (t <= 0.0 || t > stopTime - 2 * dt) continue;
        // v(t) = v - mu g t; each step's friction impulse is mu g dt (float).
        worstSpeed = std::max(worstSpeed, std::abs(static_cast<double>(p.velocity.x) - (v - mu * kG * t)));
    }
    std::printf("[ slide ] stop at %.6f m (closed form %.6f m), max speed deviation %.3g m/s\n",
                static_cast<double>(result.position.x), distance, worstSpeed);
    EXPECT_LE(worstSpeed, mu * kG * dt);  // within one step's friction
    // Friction acts per whole step (from the first): the distance is off by up to v dt.
    EXPECT_NEAR(static_cast<double>(result.position.x), distance, v * dt);
    EXPECT_TRUE(result.atRest);
    EXPECT_TRUE(result.impacts.empty());  // sliding is resting contact, not impacts
    EXPECT_NEAR(static_cast<double>(result.position.y), 0.05, 1e-4);
}

// A throw against a box's face: the normal velocity is reflected with e, the tangential kept
// (no friction), the impact normal is the face's.
TEST(BulletSimulation, WallReflectsWithRestitution) {
    BulletScene scene;
    ASSERT_EQ(scene.add(OrientedBox{RVec3(3, 0, 0), Vec3(0.5f, 5, 5)}), Status::Ok);  // face at x = 2.5
    ProjectileSettings settings;
    settings.radius = 0.05f;
    settings.restitution = 0.7f;
    settings.gravity = Vec3(0);
    RigidBodySimulationSettings simulation;
    RigidBodySimulationResult result;
    ASSERT_EQ(foresight::simulateProjectileRigidBody(scene, RVec3(0, 1, 0), Vec3(6, 0.5f, 1), 1.0f, settings,
                                                     simulation, result),
              Status::Ok);
    ASSERT_EQ(result.impacts.size(), 1u);
    EXPECT_NEAR(static_cast<double>(result.impacts[0].normal.x), -1.0, 1e-6);
    // Bullet's sphere-box contact in float: the normal is off by ~1e-6 rad, ~1e-5 of the speed
    // leaks between the components.
    EXPECT_NEAR(static_cast<double>(result.velocity.x), -0.7 * 6.0, 1e-4);
    EXPECT_NEAR(static_cast<double>(result.velocity.y), 0.5, 1e-4);
    EXPECT_NEAR(static_cast<double>(result.velocity.z), 1.0, 1e-4);
    // Touch at x = 2.45 after 2.45 / 6 s.
    EXPECT_NEAR(static_cast<double>(result.impacts[0].touchPosition.x), 2.45, 1e-5);
    EXPECT_NEAR(result.impacts[0].touchTime, 2.45 / 6.0, 1e-5);

    // With gravity: the normal component reflects (on the face), gravity goes on.
    settings.gravity = Vec3(0, -foresight::kDefaultGravity, 0);
    ASSERT_EQ(foresight::simulateProjectileRigidBody(scene, RVec3(0, 3, 0), Vec3(6, 2, 0), 0.6f, settings, simulation,
                                                     result),
              Status::Ok);
    ASSERT_EQ(result.impacts.size(), 1u);
    EXPECT_NEAR(static_cast<double>(result.velocity.x), -0.7 * 6.0, 1e-4);
    EXPECT_NEAR(static_cast<double>(result.velocity.y), 2.0 - kG * 0.6, 1e-4);
}

// Restitution 0: the ball lands, stays, and comes to rest; one impact.
TEST(BulletSimulation, RestitutionZeroLandsAndStays) {
    BulletScene scene;
    ASSERT_EQ(scene.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    ProjectileSettings settings;
    settings.restitution = 0.0f;
    RigidBodySimulationSettings simulation;
    RigidBodySimulationResult result;
    ASSERT_EQ(
        foresight::simulateProjectileRigidBody(scene, RVec3(0, 2, 0), Vec3(0), 2.0f, settings, simulation, result),
        Status::Ok);
    EXPECT_EQ(result.radius, static_cast<double>(0.02f));  // pointRadius
    ASSERT_EQ(result.impacts.size(), 1u);
    EXPECT_TRUE(result.atRest);
    EXPECT_NEAR(static_cast<double>(result.position.y), 0.02, 1e-5);
    EXPECT_LT(glm::length(result.velocity), 1e-4f);
    EXPECT_NEAR(result.impacts[0].touchTime, std::sqrt(2.0 * 1.98 / kG), 1e-5);
}

// The samples: Start at 0, one per step (a partial last step at `time`), End at `time`.
TEST(BulletSimulation, SamplesAndPartialLastStep) {
    BulletScene scene;
    ProjectileSettings settings;
    RigidBodySimulationSettings simulation;
    simulation.frequency = 240.0f;
    RigidBodySimulationResult result;
    // 0.1 s = 24 steps exactly; 0.101 s = 24 steps and one of 1 ms.
    ASSERT_EQ(
        foresight::simulateProjectileRigidBody(scene, RVec3(0), Vec3(1, 5, 0), 0.1f, settings, simulation, result),
        Status::Ok);
    ASSERT_EQ(result.samples.size(), 25u);
    EXPECT_EQ(result.samples.front().event, TrajectoryEvent::Start);
    EXPECT_EQ(result.samples.back().event, TrajectoryEvent::End);
    EXPECT_EQ(result.samples.back().time, 0.1f);
    for (float t : {0.1f, 0.101f, 0.0f}) {
        ASSERT_EQ(
            foresight::simulateProjectileRigidBody(scene, RVec3(0), Vec3(1, 5, 0), t, settings, simulation, result),
            Status::Ok);
        EXPECT_EQ(result.samples.size(), t == 0.101f ? 26u : t == 0.0f ? 2u : 25u);
        // Free flight on the exact parabola (leapfrog, including the short last step): float
        // rounding of ~25 position updates.
        const double td = ftest::decimal(t);
        EXPECT_NEAR(static_cast<double>(result.position.y), 5.0 * td - 0.5 * kG * td * td, 2e-6) << t;
        EXPECT_NEAR(static_cast<double>(result.position.x), td, 1e-6) << t;
        EXPECT_NEAR(static_cast<double>(result.velocity.y), 5.0 - kG * td, 2e-6) << t;
    }
}

// The scene is left as it was, and the same call gives the same result (bit for bit).
TEST(BulletSimulation, SceneUnchangedAndDeterministic) {
    BulletScene scene;
    ASSERT_EQ(scene.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    ASSERT_EQ(scene.add(OrientedBox{RVec3(2, 0.5f, 0), Vec3(0.5f), glm::angleAxis(0.3f, Vec3(0, 1, 0))}), Status::Ok);
    const std::vector<Triangle> ramp = {Triangle{RVec3(-3, 0, -1), RVec3(-1, 0, -1), RVec3(-1, 1, 1)},
                                        Triangle{RVec3(-3, 0, -1), RVec3(-1, 1, 1), RVec3(-3, 1, 1)}};
    ASSERT_EQ(scene.addMesh(ramp), Status::Ok);
    const std::size_t objects = scene.objectCount();
    const int bulletObjects = scene.world().getNumCollisionObjects();
    const btContactSolverInfo solverBefore = scene.dynamicsWorld().getSolverInfo();
    ProjectileSettings settings;
    settings.friction = 0.3f;
    RigidBodySimulationSettings simulation;
    RigidBodySimulationResult first, second;
    for (const RVec3& start : {RVec3(0, 2, 0), RVec3(-2, 2, 0)}) {
        ASSERT_EQ(
            foresight::simulateProjectileRigidBody(scene, start, Vec3(3, 2, 0.5f), 3.0f, settings, simulation, first),
            Status::Ok);
        ASSERT_EQ(
            foresight::simulateProjectileRigidBody(scene, start, Vec3(3, 2, 0.5f), 3.0f, settings, simulation, second),
            Status::Ok);
        EXPECT_EQ(scene.objectCount(), objects);
        EXPECT_EQ(scene.world().getNumCollisionObjects(), bulletObjects);
        EXPECT_EQ(scene.dynamicsWorld().getNumConstraints(), 0);
        EXPECT_FALSE(first.impacts.empty());
        ASSERT_EQ(first.samples.size(), second.samples.size());
        ASSERT_EQ(first.impacts.size(), second.impacts.size());
        for (std::size_t i = 0; i < first.samples.size(); ++i) {
            ASSERT_EQ(first.samples[i].position, second.samples[i].position) << i;
            ASSERT_EQ(first.samples[i].velocity, second.samples[i].velocity) << i;
        }
        for (std::size_t i = 0; i < first.impacts.size(); ++i) EXPECT_EQ(first.impacts[i].time, second.impacts[i].time);
        EXPECT_EQ(first.position, second.position);
    }
    const btContactSolverInfo& solverAfter = scene.dynamicsWorld().getSolverInfo();
    EXPECT_EQ(solverAfter.m_restitutionVelocityThreshold, solverBefore.m_restitutionVelocityThreshold);
    EXPECT_EQ(solverAfter.m_erp2, solverBefore.m_erp2);
    EXPECT_EQ(solverAfter.m_solverMode, solverBefore.m_solverMode);
    EXPECT_EQ(solverAfter.m_splitImpulsePenetrationThreshold, solverBefore.m_splitImpulsePenetrationThreshold);
    EXPECT_EQ(scene.dynamicsWorld().getDispatchInfo().m_allowedCcdPenetration, btScalar(0.04));
}

// Every refusal, and the result untouched by it.
TEST(BulletSimulation, RefusesBadInput) {
    BulletScene scene;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    ProjectileSettings settings;
    RigidBodySimulationSettings simulation;
    RigidBodySimulationResult result;
    result.radius = 123.0;
    const auto run = [&](RVec3 p, Vec3 v, float t, const ProjectileSettings& s,
                         const RigidBodySimulationSettings& sim) {
        return foresight::simulateProjectileRigidBody(scene, p, v, t, s, sim, result);
    };
    EXPECT_EQ(run(RVec3(nan), Vec3(0), 1.0f, settings, simulation), Status::NonFiniteInput);
    EXPECT_EQ(run(RVec3(0), Vec3(0, inf, 0), 1.0f, settings, simulation), Status::NonFiniteInput);
    EXPECT_EQ(run(RVec3(0), Vec3(0), nan, settings, simulation), Status::NonFiniteInput);
    EXPECT_EQ(run(RVec3(0), Vec3(0), -1.0f, settings, simulation), Status::NegativeTime);
    ProjectileSettings bad = settings;
    bad.restitution = 1.5f;
    EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, bad, simulation), Status::InvalidRestitution);
    bad = settings;
    bad.friction = -0.1f;
    EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, bad, simulation), Status::InvalidFriction);
    bad = settings;
    bad.radius = -0.1f;
    EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, bad, simulation), Status::InvalidRadius);
    bad = settings;
    bad.gravity = Vec3(0, nan, 0);
    EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, bad, simulation), Status::NonFiniteInput);
    bad = settings;
    bad.maxSteps = 959;  // 1 s at 960 Hz needs 960
    EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, bad, simulation), Status::TooManySteps);
    bad.maxSteps = 960;
    RigidBodySimulationResult ok;
    EXPECT_EQ(foresight::simulateProjectileRigidBody(scene, RVec3(0), Vec3(0), 1.0f, bad, simulation, ok), Status::Ok);
    EXPECT_EQ(ok.samples.size(), 961u);
    for (float frequency : {239.0f, 100001.0f, 0.0f, -960.0f}) {
        RigidBodySimulationSettings sim = simulation;
        sim.frequency = frequency;
        EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, settings, sim), Status::InvalidStep) << frequency;
    }
    for (float value : {nan, inf}) {
        RigidBodySimulationSettings sim = simulation;
        sim.frequency = value;
        EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, settings, sim), Status::NonFiniteInput);
        sim = simulation;
        sim.pointRadius = value;
        EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, settings, sim), Status::NonFiniteInput);
    }
    for (float radius : {0.0f, -0.02f}) {
        RigidBodySimulationSettings sim = simulation;
        sim.pointRadius = radius;
        EXPECT_EQ(run(RVec3(0), Vec3(0), 1.0f, settings, sim), Status::InvalidRadius);
    }
    EXPECT_EQ(result.radius, 123.0);
    EXPECT_TRUE(result.samples.empty());
    EXPECT_EQ(scene.world().getNumCollisionObjects(), 0);
}

// A closed box room of triangles (two-sided, no thickness), 200 throws of small spheres
// (pointRadius 2 cm) at up to 40 m/s, 4 cm per step: without CCD they pass through the walls.
TEST(BulletSimulation, FastThrowsStayInATriangleRoom) {
    BulletScene scene;
    const double lo = -2.0, hi = 2.0, top = 3.0;
    const RVec3 c[8] = {toR(DVec3(lo, 0, lo)),   toR(DVec3(hi, 0, lo)),   toR(DVec3(hi, 0, hi)),
                        toR(DVec3(lo, 0, hi)),   toR(DVec3(lo, top, lo)), toR(DVec3(hi, top, lo)),
                        toR(DVec3(hi, top, hi)), toR(DVec3(lo, top, hi))};
    const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}};
    std::vector<Triangle> room;
    for (const auto& f : faces) {
        room.push_back(Triangle{c[f[0]], c[f[1]], c[f[2]]});
        room.push_back(Triangle{c[f[0]], c[f[2]], c[f[3]]});
    }
    ASSERT_EQ(scene.addMesh(room), Status::Ok);
    ProjectileSettings settings;
    settings.restitution = 0.8f;
    settings.friction = 0.2f;
    RigidBodySimulationSettings simulation;
    const double r = static_cast<double>(simulation.pointRadius);
    ftest::Random random(99, kRandomStep);
    long escaped = 0, impacts = 0;
    double deepest = 0;
    for (int i = 0; i < 200; ++i) {
        const DVec3 start(random.uniform(lo + 0.5, hi - 0.5), random.uniform(0.5, top - 0.5),
                          random.uniform(lo + 0.5, hi - 0.5));
        const DVec3 velocity = random.direction() * random.uniform(10.0, 40.0);
        RigidBodySimulationResult result;
        ASSERT_EQ(foresight::simulateProjectileRigidBody(scene, toR(start), toF(velocity), 2.0f, settings, simulation,
                                                         result),
                  Status::Ok);
        impacts += static_cast<long>(result.impacts.size());
        bool outside = false;
        for (const TrajectoryPoint& p : result.samples) {
            const DVec3 q = toD(p.position);
            // Depth of the centre behind the nearest wall (positive: inside the wall's skin).
            const double depth = std::max({lo - q.x, q.x - hi, lo - q.z, q.z - hi, -q.y, q.y - top});
            deepest = std::max(deepest, depth + r);
            if (depth > 0.0) outside = true;
        }
        if (outside) {
            ++escaped;
            ADD_FAILURE() << "throw " << i << " from " << ftest::describe(start) << " at " << ftest::describe(velocity)
                          << " left the room";
        }
    }
    std::printf(
        "[ room ] 200 throws at 10 to 40 m/s, %ld escaped, %ld impacts; deepest penetration %.3g m "
        "(radius %.3g m)\n",
        escaped, impacts, deepest, r);
    EXPECT_EQ(escaped, 0);
    // CCD stops a fast sphere 0.2 r inside a surface (see bullet_simulation.h); the discrete
    // steps at most 0.5 r (its threshold) plus float rounding.
    EXPECT_LE(deepest, 0.5 * r + 1e-4);
}

// The same throws in Bullet and through predictProjectile (Exact) on a StaticWorld with the
// same shapes, a sphere of 5 cm in both: the first landing point, the bounce times and the final
// position. Planes and boxes are exact in both worlds.
TEST(BulletSimulation, MatchesTheExactPredictor) {
    BulletScene scene;
    StaticWorld reference;
    const auto add = [&](const auto& shape) {
        ASSERT_EQ(scene.add(shape), Status::Ok);
        ASSERT_EQ(reference.add(shape), Status::Ok);
    };
    add(Plane{Vec3(0, 1, 0), 0});
    add(Plane{Vec3(-1, 0, 0), -8});
    add(Plane{Vec3(1, 0, 0), -8});
    add(Plane{Vec3(0, 0, -1), -8});
    add(Plane{Vec3(0, 0, 1), -8});
    add(OrientedBox{RVec3(3, 0.5f, 2), Vec3(1, 0.5f, 1.5f), glm::angleAxis(0.4f, Vec3(0, 1, 0))});
    ProjectileSettings settings;
    settings.radius = 0.05f;
    settings.restitution = 0.5f;
    RigidBodySimulationSettings simulation;
    const double dt = step(simulation);
    ftest::Random random(2024, kRandomStep);
    std::vector<double> landing, firstTime, secondTime;
    std::vector<TrajectoryPoint> points(4096);
    for (int i = 0; i < 100; ++i) {
        const DVec3 start(random.uniform(-6, -2), random.uniform(1, 3), random.uniform(-6, 6));
        DVec3 velocity = random.direction() * random.uniform(2.0, 12.0);
        velocity.y = std::abs(velocity.y);
        RigidBodySimulationResult simulated;
        ASSERT_EQ(foresight::simulateProjectileRigidBody(scene, toR(start), toF(velocity), 3.0f, settings, simulation,
                                                         simulated),
                  Status::Ok);
        ProjectileResult predicted;
        ASSERT_EQ(
            foresight::predictProjectile(toR(start), toF(velocity), 3.0f, settings, &reference, points, predicted),
            Status::Ok);
        std::vector<TrajectoryPoint> bounces;
        for (std::size_t k = 0; k < predicted.trajectorySize; ++k)
            if (points[k].event == TrajectoryEvent::Bounce) bounces.push_back(points[k]);
        ASSERT_FALSE(bounces.empty());
        ASSERT_FALSE(simulated.impacts.empty());
        landing.push_back(glm::length(toD(simulated.impacts[0].touchPosition) - toD(bounces[0].position)));
        firstTime.push_back(std::abs(simulated.impacts[0].touchTime - static_cast<double>(bounces[0].time)));
        if (bounces.size() > 1 && simulated.impacts.size() > 1)
            secondTime.push_back(std::abs(simulated.impacts[1].touchTime - static_cast<double>(bounces[1].time)));
    }
    const auto summary = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return std::array<double, 3>{v[v.size() / 2], v[v.size() * 9 / 10], v.back()};
    };
    const auto l = summary(landing), t1 = summary(firstTime), t2 = summary(secondTime);
    std::printf(
        "[ vs exact ] 100 throws: first landing point median %.3g m, 90%% %.3g m, max %.3g m; first bounce "
        "time median %.3g s, max %.3g s; second bounce time median %.3g s, 90%% %.3g s, max %.3g s (dt %.3g s)\n",
        l[0], l[1], l[2], t1[0], t1[2], t2[0], t2[1], t2[2], dt);
    // Before the first bounce both follow the same parabola (leapfrog: exact), so the first
    // landing point differs by float rounding of Bullet's positions (~1e-6 m per step).
    EXPECT_LE(l[2], 2e-3);
    EXPECT_LE(t1[2], 2e-4);
    // The second bounce carries Bullet's late and fast rebound from the first (see
    // DropMatchesClosedForm: up to dt + 2 R / g with R <= 2 g dt).
    EXPECT_LE(t2[2], 5.0 * dt);
}

}  // namespace
