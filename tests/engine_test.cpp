// Engine profiles (engine_profile.h) and ProjectileMethod::Engine: the closed form of each
// profile's free flight against a plain step loop written here from the engines' documented
// update rules, validation, combine rules, and contact behaviour on a floor. The comparison with
// the real engines is tests/engine_oracle_test.cpp.

#include <foresight/engine_profile.h>
#include <foresight/projectile.h>
#include <foresight/static_world.h>

#include "test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

using namespace foresight;

namespace {

struct State {
    long double p[3], v[3];
};

// The engines' free-flight step, written out per engine as each documents it (not through the
// library's recurrence), in long double.
State stepLoop(PhysicsEngine engine, float timestep, float damping, long double p0[3], long double v0[3],
               long double g[3], int steps, int substeps = 1) {
    State s{};
    for (int i = 0; i < 3; ++i) {
        s.p[i] = p0[i];
        s.v[i] = v0[i];
    }
    const long double h = static_cast<long double>(timestep);
    for (int k = 1; k <= steps; ++k) {
        for (int i = 0; i < 3; ++i) {
            long double& v = s.v[i];
            long double& p = s.p[i];
            switch (engine) {
                case PhysicsEngine::Jolt:
                case PhysicsEngine::PhysX:
                    v = (v + g[i] * h) * std::max(0.0L, 1.0L - damping * h);
                    p += v * h;
                    break;
                case PhysicsEngine::Rapier: {
                    const long double sub = h / substeps;
                    for (int j = 0; j < substeps; ++j) {
                        v += g[i] * sub;
                        p += v * sub;
                    }
                    v *= 1.0L / (1.0L + damping * h);
                    break;
                }
                case PhysicsEngine::Bullet:
                    v = v * std::pow(1.0L - std::min(1.0L, static_cast<long double>(damping)), h) + g[i] * h;
                    p += v * h;
                    break;
                case PhysicsEngine::Godot3:
                    if (k == 1) {
                        p += v * h;
                    } else {
                        v = v * std::max(0.0L, 1.0L - damping * h) + g[i] * h;
                        p += v * h;
                    }
                    break;
                case PhysicsEngine::Godot3Bullet:
                    // The body's damping plus the project default 0.1.
                    if (k == 1) {
                        v = v * (1.0L - (damping + 0.1L) * h);
                    } else {
                        v = v * (1.0L - (damping + 0.1L) * h) + g[i] * h;
                    }
                    p += v * h;
                    break;
                case PhysicsEngine::Box2D:
                    if (i == 2) {  // motion in the x-y plane
                        v = 0.0L;
                        break;
                    }
                    v = (v + g[i] * h) / (1.0L + damping * h);
                    p += v * h;
                    break;
                case PhysicsEngine::Custom:
                    break;
            }
        }
    }
    return s;
}

struct FlightCase {
    PhysicsEngine engine;
    float timestep;
    float damping;
    int steps;
};

}  // namespace

TEST(EngineProfile, FreeFlightClosedFormMatchesSteppingEveryEngine) {
    const FlightCase cases[] = {
        {PhysicsEngine::Jolt, 1.0f / 60.0f, 0.05f, 180},    {PhysicsEngine::Jolt, 1.0f / 30.0f, 1.5f, 90},
        {PhysicsEngine::PhysX, 1.0f / 120.0f, 0.7f, 360},   {PhysicsEngine::Rapier, 1.0f / 60.0f, 0.0f, 180},
        {PhysicsEngine::Rapier, 1.0f / 90.0f, 1.2f, 270},   {PhysicsEngine::Bullet, 1.0f / 60.0f, 0.3f, 180},
        {PhysicsEngine::Bullet, 1.0f / 60.0f, 0.0f, 180},   {PhysicsEngine::Godot3, 1.0f / 60.0f, 0.1f, 180},
        {PhysicsEngine::Godot3, 1.0f / 45.0f, 0.0f, 1},     {PhysicsEngine::Godot3Bullet, 1.0f / 60.0f, 0.0f, 180},
        {PhysicsEngine::Box2D, 1.0f / 60.0f, 0.5f, 180},    {PhysicsEngine::Jolt, 1.0f / 60.0f, 0.0f, 0},
        {PhysicsEngine::Jolt, 1.0f / 60.0f, 1e-7f, 100000},
    };
    long double p0[3] = {1.0L, 1.5L, -2.0L}, v0[3] = {3.0L, 4.0L, 5.0L}, g[3] = {0.0L, -9.81L, 0.0L};
    for (const FlightCase& c : cases) {
        EngineProfile profile = engineProfile(c.engine);
        profile.timestep = c.timestep;
        profile.linearDamping = c.damping;
        ASSERT_EQ(validateEngineProfile(profile), Status::Ok);
        // The loop takes the float timestep as it is; the library its decimal value. Use steps
        // whose float and decimal agree closely: the difference is below 1e-9 relative.
        const State s = stepLoop(c.engine, c.timestep, c.damping, p0, v0, g, c.steps, 4);
        const EngineFlightState f = engineFreeFlight(profile, RVec3(1.0f, 1.5f, -2.0f), Vec3(3, 4, 5),
                                                     Vec3(0, -9.81f, 0), static_cast<std::uint64_t>(c.steps));
        SCOPED_TRACE(engineName(c.engine));
        SCOPED_TRACE(c.steps);
        // Float output positions (up to ~1e5 m here) round at 2^-24 relative; the float
        // timestep's decimal reading changes dt by < 3e-8 relative: over 1e5 steps that moves a
        // position by under 1e-7 * |p| * 2.
        const double scale = std::max(1.0, std::abs(static_cast<double>(s.p[1])));
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(f.position[i], static_cast<double>(s.p[i]), 4e-7 * scale) << "axis " << i;
            EXPECT_NEAR(f.velocity[i], static_cast<double>(s.v[i]), 4e-7 * std::max(1.0, std::abs(double(s.v[i]))))
                << "axis " << i;
        }
    }
}

TEST(EngineProfile, MeasuredFreeFallOfTheReferenceThrow) {
    // Throw (0, 1.5, 0) at (3, 4, 5), 60 Hz, no damping, 3 s: the engines' float32 runs put y at
    // -30.890 (Jolt, PhysX, Bullet), -30.706 (Rapier), -30.400 (GodotPhysics) and -28.003 (Godot
    // with Bullet and its project damping 0.1). Measured by the harnesses in tests/engines; the
    // float32 engines round to about 1e-3 m over 180 steps.
    struct Expect {
        PhysicsEngine engine;
        float damping;
        double y;
    };
    const Expect expects[] = {{PhysicsEngine::Jolt, 0.0f, -30.890},   {PhysicsEngine::PhysX, 0.0f, -30.890},
                              {PhysicsEngine::Bullet, 0.0f, -30.890}, {PhysicsEngine::Rapier, 0.0f, -30.706},
                              {PhysicsEngine::Godot3, 0.0f, -30.400}, {PhysicsEngine::Godot3Bullet, 0.0f, -28.003}};
    for (const Expect& e : expects) {
        EngineProfile profile = engineProfile(e.engine);
        profile.linearDamping = e.damping;
        const EngineFlightState f =
            engineFreeFlight(profile, RVec3(0, 1.5f, 0), Vec3(3, 4, 5), Vec3(0, -9.81f, 0), 180);
        EXPECT_NEAR(f.position.y, e.y, 2e-3) << engineName(e.engine);
    }
}

TEST(EngineProfile, ValidationRefusesBadSettings) {
    EngineProfile p = engineProfile(PhysicsEngine::Jolt);
    EXPECT_EQ(validateEngineProfile(p), Status::Ok);
    p.timestep = 0.0f;
    EXPECT_EQ(validateEngineProfile(p), Status::InvalidStep);
    p.timestep = NAN;
    EXPECT_EQ(validateEngineProfile(p), Status::NonFiniteInput);
    p = engineProfile(PhysicsEngine::Rapier);
    p.substeps = 0;
    EXPECT_EQ(validateEngineProfile(p), Status::InvalidSetting);
    p.substeps = 65;
    EXPECT_EQ(validateEngineProfile(p), Status::InvalidSetting);
    p = engineProfile(PhysicsEngine::Bullet);
    p.linearDamping = -0.1f;
    EXPECT_EQ(validateEngineProfile(p), Status::InvalidSetting);
    p = engineProfile(PhysicsEngine::PhysX);
    p.restitutionThreshold = -1.0f;
    EXPECT_EQ(validateEngineProfile(p), Status::InvalidSetting);
    p = engineProfile(PhysicsEngine::Box2D);
    p.positionCorrection = 1.5f;
    EXPECT_EQ(validateEngineProfile(p), Status::InvalidSetting);
    p = engineProfile(PhysicsEngine::Godot3);
    p.order = static_cast<DampingOrder>(7);
    EXPECT_EQ(validateEngineProfile(p), Status::InvalidSetting);
}

TEST(EngineProfile, CombineRules) {
    EXPECT_FLOAT_EQ(combineMaterial(CombineRule::Average, 0.2f, 0.6f), 0.4f);
    EXPECT_FLOAT_EQ(combineMaterial(CombineRule::Min, 0.2f, 0.6f), 0.2f);
    EXPECT_FLOAT_EQ(combineMaterial(CombineRule::Max, 0.2f, 0.6f), 0.6f);
    EXPECT_FLOAT_EQ(combineMaterial(CombineRule::Multiply, 0.5f, 0.6f), 0.3f);
    EXPECT_FLOAT_EQ(combineMaterial(CombineRule::GeometricMean, 0.25f, 0.64f), 0.4f);
    EXPECT_FLOAT_EQ(combineMaterial(CombineRule::SumClamped, 0.7f, 0.6f), 1.0f);
}

TEST(EngineProjectile, FreeFlightStepsAgreeWithTheClosedForm) {
    for (PhysicsEngine engine : {PhysicsEngine::Jolt, PhysicsEngine::Rapier, PhysicsEngine::Godot3,
                                 PhysicsEngine::Godot3Bullet, PhysicsEngine::Bullet}) {
        ProjectileSettings settings;
        settings.method = ProjectileMethod::Engine;
        settings.engine = engineProfile(engine);
        settings.engine.linearDamping = 0.3f;
        std::vector<TrajectoryPoint> points(200);
        ProjectileResult result;
        ASSERT_EQ(predictProjectile(RVec3(0, 1.5f, 0), Vec3(3, 4, 5), 3.0f, settings, nullptr, points, result),
                  Status::Ok);
        ASSERT_EQ(result.trajectorySize, 181u);  // start + 180 steps
        for (std::uint64_t k = 0; k <= 180; k += 30) {
            const EngineFlightState f =
                engineFreeFlight(settings.engine, RVec3(0, 1.5f, 0), Vec3(3, 4, 5), settings.gravity, k);
            // Stepping in double against the closed form: rounding only (positions ~30 m).
            EXPECT_NEAR(glm::length(glm::dvec3(points[k].position - f.position)), 0.0, 1e-5)
                << engineName(engine) << " step " << k;
        }
        EXPECT_NEAR(result.time, 3.0f, 1e-6f);
    }
}

TEST(EngineProjectile, RestsOnAFloorAndBouncesAboveTheThreshold) {
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    ProjectileSettings settings;
    settings.method = ProjectileMethod::Engine;
    settings.engine = engineProfile(PhysicsEngine::Jolt);
    settings.radius = 0.1f;
    settings.restitution = 0.5f;
    settings.friction = 0.0f;
    std::vector<TrajectoryPoint> points(400);
    ProjectileResult result;
    ASSERT_EQ(predictProjectile(RVec3(0, 2.0f, 0), Vec3(1, 0, 0), 5.0f, settings, &world, points, result), Status::Ok);
    EXPECT_GE(result.bounces, 1u);
    // Bounces below Jolt's 1 m/s threshold stop: the sphere ends on the floor (its slop 0.02 m
    // is the deepest it may rest), sliding at the start speed times the damping.
    EXPECT_NEAR(result.position.y, 0.1f, 0.021f);
    EXPECT_NEAR(result.velocity.y, 0.0f, 0.2f);
    EXPECT_GT(result.velocity.x, 0.7f);
}

// A ball rolling down a ramp onto the floor touches both at once where they meet. The floor's
// contact is found by the cast along the ramp, and measured by a probe from the centre
// straight down, which meets the ramp first: the floor must stay the floor (it turned into a
// second copy of the ramp, and the ball sank into the floor by up to 3 cm, where Jolt, PhysX
// and Rapier stop it at the floor's surface with their speculative contacts). Ramps of 10 to 30
// degrees, balls of 5 to 20 cm, 60 and 120 Hz.
TEST(EngineProjectile, BallRollingDownARampMeetsTheFloor) {
    std::size_t runs = 0;
    double deepest = 0.0;
    for (PhysicsEngine engine : {PhysicsEngine::Jolt, PhysicsEngine::PhysX, PhysicsEngine::Rapier}) {
        for (double degrees : {10.0, 20.0, 30.0}) {
            for (double radius : {0.05, 0.1, 0.2}) {
                for (int hz : {60, 120}) {
                    const double slope = degrees * M_PI / 180.0;
                    StaticWorld world;
                    OrientedBox floor;
                    floor.center = RVec3(0, -0.5f, 0);
                    floor.halfExtents = Vec3(20, 0.5f, 20);
                    // A ramp rising along -x from its lower edge at x = 0 on the floor: the box
                    // turned about z, its top face through (0, 0) with normal (sin, cos).
                    OrientedBox ramp;
                    const double hx = 2.0, hy = 0.4;
                    ramp.halfExtents = Vec3(static_cast<float>(hx), static_cast<float>(hy), 2.0f);
                    ramp.orientation = glm::angleAxis(static_cast<float>(-slope), Vec3(0, 0, 1));
                    ramp.center = RVec3(static_cast<float>(-hx * std::cos(slope) - hy * std::sin(slope)),
                                        static_cast<float>(hx * std::sin(slope) - hy * std::cos(slope)), 0.0f);
                    if (engine == PhysicsEngine::Jolt) floor.rounding = ramp.rounding = 0.05f;
                    ASSERT_EQ(world.add(floor), Status::Ok);
                    ASSERT_EQ(world.add(ramp), Status::Ok);
                    ProjectileSettings settings;
                    settings.method = ProjectileMethod::Engine;
                    settings.engine = engineProfile(engine);
                    settings.engine.timestep = 1.0f / static_cast<float>(hz);
                    settings.step = settings.engine.timestep;
                    settings.radius = static_cast<float>(radius);
                    settings.restitution = 0.3f;
                    settings.friction = 0.4f;
                    // Resting on the ramp 0.5 m up its face, rolling down at 1 m/s.
                    const double along = 0.5 / std::sin(slope);
                    const glm::dvec3 down(std::cos(slope), -std::sin(slope), 0.0),
                        normal(std::sin(slope), std::cos(slope), 0.0);
                    const glm::dvec3 start = -down * along + normal * radius;
                    std::vector<TrajectoryPoint> points(static_cast<std::size_t>(3 * hz) + 8);
                    ProjectileResult result;
                    ASSERT_EQ(predictProjectile(RVec3(start), Vec3(down), 3.0f, settings, &world, points, result),
                              Status::Ok);
                    ++runs;
                    double lowest = 1e9;
                    for (std::size_t i = 0; i < result.trajectorySize; ++i)
                        if (points[i].position.x > 0.0f)
                            lowest = std::min(lowest, static_cast<double>(points[i].position.y));
                    deepest = std::max(deepest, radius - lowest);
                    // The floor's speculative contact stops it at the surface (Rapier's continuous
                    // collision 5 mm deep at most; the deepest here is 4.8 mm, 18 mm without the
                    // floor's contact).
                    const double allowed = 0.006;
                    EXPECT_GT(lowest, radius - allowed)
                        << engineName(engine) << " " << degrees << " degrees, r " << radius << ", " << hz << " Hz";
                    EXPECT_GT(result.position.x, 0.5f) << "the ball rolled on along the floor";
                }
            }
        }
    }
    std::printf("[ ramp to floor ] %zu runs, deepest below the floor's surface %.4f m\n", runs, deepest);
}

// A 10 m x 10 m floor at y = 0 of two triangles facing up (one-sided in StaticWorld).
void addTriangleFloor(StaticWorld& world) {
    ASSERT_EQ(world.add(Triangle{RVec3(-5, 0, -5), RVec3(-5, 0, 5), RVec3(5, 0, 5)}), Status::Ok);
    ASSERT_EQ(world.add(Triangle{RVec3(-5, 0, -5), RVec3(5, 0, 5), RVec3(5, 0, -5)}), Status::Ok);
}

ProjectileSettings bulletOnMesh(bool triangleMesh) {
    ProjectileSettings settings;
    settings.method = ProjectileMethod::Engine;
    settings.engine = engineProfile(PhysicsEngine::Bullet);
    settings.engine.triangleMesh = triangleMesh;
    settings.radius = 0.1f;
    settings.restitution = 0.5f;
    settings.friction = 0.3f;
    return settings;
}

TEST(EngineProjectile, BulletMeshTrianglesAreDoubleSided) {
    // 20 m/s down from 5 cm above: the first step (0.336 m) takes the centre 0.19 m below the
    // floor. A box pushes the sphere back out; a mesh triangle's back face pushes it on through.
    StaticWorld world;
    addTriangleFloor(world);
    std::vector<TrajectoryPoint> points(100);
    for (const bool mesh : {false, true}) {
        ProjectileResult result;
        ASSERT_EQ(
            predictProjectile(RVec3(0, 0.15f, 0), Vec3(0, -20, 0), 1.0f, bulletOnMesh(mesh), &world, points, result),
            Status::Ok);
        if (mesh)
            EXPECT_LT(result.position.y, -5.0f);
        else
            EXPECT_GT(result.position.y, 0.05f);
    }
}

TEST(EngineProjectile, BulletMeshContactsNeedTheBoundingBoxToReachTheTriangle) {
    // 2 mm above the floor, within Bullet's contact breaking threshold (0.02 sqrt(3) r = 3.5 mm),
    // falling slowly. Against a box the contact acts at once and the sphere stops on the surface;
    // a mesh triangle is not tested until the sphere's bounding box reaches it: a free step.
    StaticWorld world;
    addTriangleFloor(world);
    std::vector<TrajectoryPoint> points(10);
    const float dt = 1.0f / 60.0f;
    for (const bool mesh : {false, true}) {
        ProjectileResult result;
        ASSERT_EQ(predictProjectile(RVec3(0, 0.102f, 0), Vec3(0, -0.05f, 0), 2 * dt, bulletOnMesh(mesh), &world, points,
                                    result),
                  Status::Ok);
        const double free = 0.102 - (0.05 + 9.81 * dt) * dt;
        EXPECT_NEAR(points[1].position.y, mesh ? free : 0.1, 1e-6) << (mesh ? "mesh" : "box");
    }
    // A tilted triangle (45 degrees) is reached by the box first: speculative as for a box.
    StaticWorld slope;
    ASSERT_EQ(slope.add(Triangle{RVec3(-5, 5, -5), RVec3(-5, 5, 5), RVec3(5, -5, 5)}), Status::Ok);
    ASSERT_EQ(slope.add(Triangle{RVec3(-5, 5, -5), RVec3(5, -5, 5), RVec3(5, -5, -5)}), Status::Ok);
    const Vec3 n = glm::normalize(Vec3(1, 1, 0));
    std::vector<TrajectoryPoint> box(10), mesh(10);
    ProjectileResult result;
    const RVec3 start = RVec3(n * 0.102f);
    ASSERT_EQ(predictProjectile(start, -0.05f * n, 2 * dt, bulletOnMesh(false), &slope, box, result), Status::Ok);
    ASSERT_EQ(predictProjectile(start, -0.05f * n, 2 * dt, bulletOnMesh(true), &slope, mesh, result), Status::Ok);
    EXPECT_NEAR(glm::length(glm::dvec3(mesh[1].position - box[1].position)), 0.0, 1e-9);
    EXPECT_NEAR(glm::dot(glm::dvec3(box[1].position), glm::dvec3(n)), 0.1, 1e-5);
}

TEST(EngineProjectile, RenderedPositionBetweenSteps) {
    // A body moving along x at 1 m/s, stepped at 0.1 s: p[k] = (0.1 k, 0, 0).
    std::vector<TrajectoryPoint> points(4);
    for (std::size_t k = 0; k < points.size(); ++k) {
        points[k].time = 0.1f * static_cast<float>(k);
        points[k].position = RVec3(0.1f * static_cast<float>(k), 0, 0);
        points[k].velocity = Vec3(1, 0, 0);
    }
    // 0.25 s: 2 steps done, a half step into the third. Float positions: 1e-7 m.
    EXPECT_NEAR(renderedPosition(points, 0.1f, 0.25f, RenderSmoothing::None).x, 0.2f, 1e-7f);
    // Interpolation shows the state one step behind: halfway between p[1] and p[2].
    EXPECT_NEAR(renderedPosition(points, 0.1f, 0.25f, RenderSmoothing::Interpolate).x, 0.15f, 1e-7f);
    // Extrapolation runs p[2] on with its velocity: the true position of this motion.
    EXPECT_NEAR(renderedPosition(points, 0.1f, 0.25f, RenderSmoothing::Extrapolate).x, 0.25f, 1e-7f);
    // On a step time exactly, interpolation shows the previous step, the others that step.
    EXPECT_NEAR(renderedPosition(points, 0.1f, 0.2f, RenderSmoothing::Interpolate).x, 0.1f, 1e-7f);
    EXPECT_NEAR(renderedPosition(points, 0.1f, 0.2f, RenderSmoothing::None).x, 0.2f, 1e-7f);
    // Before the start and past the end.
    EXPECT_EQ(renderedPosition(points, 0.1f, -1.0f, RenderSmoothing::Extrapolate).x, 0.0f);
    EXPECT_NEAR(renderedPosition(points, 0.1f, 5.0f, RenderSmoothing::Interpolate).x, 0.3f, 1e-7f);
    EXPECT_EQ(renderedPosition({}, 0.1f, 1.0f, RenderSmoothing::None).x, 0.0f);
}

namespace {

// An engine's profile at 30, 60, 90 or 120 Hz, a sphere of 5 to 30 cm, restitution from
// `lowestRestitution` to lowestRestitution + 0.6, friction 0 to 0.6.
ProjectileSettings randomEngineSettings(ftest::Random& random, PhysicsEngine engine, double lowestRestitution) {
    ProjectileSettings settings;
    settings.method = ProjectileMethod::Engine;
    settings.engine = engineProfile(engine);
    settings.engine.timestep = static_cast<float>(1.0 / (30 + 30 * random.below(4)));
    settings.step = settings.engine.timestep;
    settings.radius = static_cast<float>(random.uniform(0.05, 0.3));
    settings.restitution = static_cast<float>(random.uniform(lowestRestitution, lowestRestitution + 0.6));
    settings.friction = static_cast<float>(random.uniform(0, 0.6));
    return settings;
}

}  // namespace

// Coasting (one firstTouch query for many free-flight steps) must give exactly the steps of casting
// every step: the same arithmetic, only the queries are skipped. Random scenes, every profile.
TEST(EngineProjectile, CoastingGivesTheStepsOfCastingEveryStep) {
    ftest::Random random(2026);
    std::size_t castsEveryStep = 0, castsCoasting = 0;
    for (int round = 0; round < 40; ++round) {
        const StaticWorld world = ftest::randomScene(random);
        for (PhysicsEngine engine :
             {PhysicsEngine::Custom, PhysicsEngine::Jolt, PhysicsEngine::PhysX, PhysicsEngine::Rapier,
              PhysicsEngine::Bullet, PhysicsEngine::Godot3, PhysicsEngine::Godot3Bullet, PhysicsEngine::Box2D}) {
            const ProjectileSettings settings = randomEngineSettings(random, engine, 0.2);
            const RVec3 start(random.uniform(-1, 1), random.uniform(0.5, 2), random.uniform(-1, 1));
            const double heading = random.uniform(0, 2 * M_PI), speed = random.uniform(3, 15);
            const Vec3 velocity(static_cast<float>(speed * std::cos(heading)), static_cast<float>(random.uniform(1, 9)),
                                static_cast<float>(speed * std::sin(heading)));
            const float time = 3.0f;
            ftest::CountingWorld plain(world, false), coasting(world, true);
            std::vector<TrajectoryPoint> a(400), b(400);
            ProjectileResult ra, rb;
            ASSERT_EQ(predictProjectile(start, velocity, time, settings, &plain, a, ra), Status::Ok);
            ASSERT_EQ(predictProjectile(start, velocity, time, settings, &coasting, b, rb), Status::Ok);
            ASSERT_EQ(ra.trajectorySize, rb.trajectorySize);
            for (std::size_t i = 0; i < ra.trajectorySize; ++i) {
                // Bitwise: both runs do the same floating-point operations.
                ASSERT_EQ(a[i].position, b[i].position) << engineName(engine) << " round " << round << " point " << i;
                ASSERT_EQ(a[i].velocity, b[i].velocity) << engineName(engine) << " round " << round << " point " << i;
                ASSERT_EQ(a[i].event, b[i].event) << engineName(engine) << " round " << round << " point " << i;
            }
            EXPECT_EQ(ra.bounces, rb.bounces);
            EXPECT_EQ(ra.position, rb.position);
            castsEveryStep += plain.casts;
            castsCoasting += coasting.casts + coasting.touches;
        }
    }
    // About half the steps of these throws are free flight away from every surface (the rest
    // bounce, roll or pass near walls): coasting must save at least 45 % of the queries (it
    // saves 52 % today, taking the steps before the first touch; 43 % when a touched capsule
    // cleared nothing).
    EXPECT_LT(static_cast<double>(castsCoasting), 0.55 * static_cast<double>(castsEveryStep))
        << castsCoasting << " queries coasting against " << castsEveryStep << " casting every step";
}

// A world whose region queries are worth nothing (CollisionWorld::regionQueryCost infinite, as
// CallbackWorld's) is never asked them, neither for free flight nor for contact, and the steps
// are those of a world that answers them.
TEST(EngineProjectile, WorldWithoutRegionQueriesIsNotAskedThem) {
    ftest::Random random(77);
    std::size_t casts = 0;
    for (int round = 0; round < 10; ++round) {
        const StaticWorld world = ftest::randomScene(random);
        for (PhysicsEngine engine : {PhysicsEngine::Jolt, PhysicsEngine::Bullet, PhysicsEngine::Rapier}) {
            const ProjectileSettings settings = randomEngineSettings(random, engine, 0.2);
            const RVec3 start(random.uniform(-1, 1), random.uniform(0.5, 2), random.uniform(-1, 1));
            const Vec3 velocity(static_cast<float>(random.uniform(-8, 8)), static_cast<float>(random.uniform(1, 6)),
                                static_cast<float>(random.uniform(-8, 8)));
            ftest::CountingWorld answering(world, true, true), castOnly(world, true, true);
            castOnly.queryCost = std::numeric_limits<float>::infinity();
            std::vector<TrajectoryPoint> a(400), b(400);
            ProjectileResult ra, rb;
            ASSERT_EQ(predictProjectile(start, velocity, 3.0f, settings, &answering, a, ra), Status::Ok);
            ASSERT_EQ(predictProjectile(start, velocity, 3.0f, settings, &castOnly, b, rb), Status::Ok);
            EXPECT_EQ(castOnly.touches, 0u);
            EXPECT_EQ(castOnly.planeQueries, 0u);
            ASSERT_EQ(ra.trajectorySize, rb.trajectorySize);
            for (std::size_t i = 0; i < ra.trajectorySize; ++i) {
                // Bitwise: the region queries only skip casts.
                ASSERT_EQ(a[i].position, b[i].position) << engineName(engine) << " round " << round << " point " << i;
                ASSERT_EQ(a[i].velocity, b[i].velocity) << engineName(engine) << " round " << round << " point " << i;
            }
            casts += castOnly.casts;
        }
    }
    EXPECT_GT(casts, 0u);
}

namespace {

// A floor of 1 m tiles (two triangles each) from -half to half in x and z at height 0, and the
// box walls and the sphere of randomScene(): the floor is a mesh, not a plane.
StaticWorld tiledScene(ftest::Random& random, int half) {
    StaticWorld world;
    for (int x = -half; x < half; ++x) {
        for (int z = -half; z < half; ++z) {
            const RVec3 a(x, 0, z), b(x + 1, 0, z), c(x + 1, 0, z + 1), d(x, 0, z + 1);
            EXPECT_EQ(world.add(Triangle{a, c, b}), Status::Ok);
            EXPECT_EQ(world.add(Triangle{a, d, c}), Status::Ok);
        }
    }
    const StaticWorld scene = ftest::randomScene(random);
    for (const OrientedBox& box : scene.boxes()) EXPECT_EQ(world.add(box), Status::Ok);
    for (const Sphere& sphere : scene.spheres()) EXPECT_EQ(world.add(sphere), Status::Ok);
    return world;
}

}  // namespace

// Contact coasting (steps on one surface taken against that plane alone, kept when the world
// promises with isOnlyPlane that nothing else is near) must give the steps of casting every
// step: the same arithmetic, against a plane instead of the floor's own shapes, so the same
// numbers up to their rounding. A plane floor, and a floor of tiles that ends (a ball that rolls
// off its border falls: the promise must not hold there), with walls and a sphere; every profile.
TEST(EngineProjectile, ContactCoastingGivesTheStepsOfCastingEveryStep) {
    ftest::Random random(4242);
    std::size_t castsEveryStep = 0, castsCoasting = 0, promises = 0, fell = 0;
    double worst = 0.0;
    constexpr int kRounds = ftest::roundsForBuild(24, 8);  // the 24 took 105 s under ASan
    for (int round = 0; round < kRounds; ++round) {
        const bool tiled = round % 2 == 1;
        const StaticWorld world = tiled ? tiledScene(random, 7) : ftest::randomScene(random);
        for (PhysicsEngine engine :
             {PhysicsEngine::Custom, PhysicsEngine::Jolt, PhysicsEngine::PhysX, PhysicsEngine::Rapier,
              PhysicsEngine::Bullet, PhysicsEngine::Godot3, PhysicsEngine::Godot3Bullet, PhysicsEngine::Box2D}) {
            ProjectileSettings settings = randomEngineSettings(random, engine, 0.0);
            settings.engine.triangleMesh = tiled && random.below(2) == 1;
            // Low, fast throws: most of the 4 s is rolling and sliding.
            const RVec3 start(random.uniform(-1, 1), random.uniform(0.3, 1), random.uniform(-1, 1));
            const double heading = random.uniform(0, 2 * M_PI), speed = random.uniform(2, 9);
            const Vec3 velocity(static_cast<float>(speed * std::cos(heading)),
                                static_cast<float>(random.uniform(-2, 2)),
                                static_cast<float>(speed * std::sin(heading)));
            const float time = 4.0f;
            ftest::CountingWorld plain(world, true, false), coasting(world, true, true);
            std::vector<TrajectoryPoint> a(600), b(600);
            ProjectileResult ra, rb;
            ASSERT_EQ(predictProjectile(start, velocity, time, settings, &plain, a, ra), Status::Ok);
            ASSERT_EQ(predictProjectile(start, velocity, time, settings, &coasting, b, rb), Status::Ok);
            ASSERT_EQ(ra.trajectorySize, rb.trajectorySize);
            for (std::size_t i = 0; i < ra.trajectorySize; ++i) {
                const double gap = glm::length(glm::dvec3(a[i].position) - glm::dvec3(b[i].position));
                worst = std::max(worst, gap);
                // The plane's offset and normal come from a cast's float hit (1e-7 m); the steps
                // carry such differences along without growing them past 1e-5 m in 4 s.
                ASSERT_LT(gap, 1e-5) << engineName(engine) << " round " << round << " point " << i;
                ASSERT_EQ(a[i].event, b[i].event) << engineName(engine) << " round " << round << " point " << i;
            }
            EXPECT_EQ(ra.bounces, rb.bounces) << engineName(engine) << " round " << round;
            castsEveryStep += plain.casts;
            castsCoasting += coasting.casts + coasting.planeQueries;
            promises += coasting.planePromises;
            fell += ra.position.y < -1.0f ? 1 : 0;
        }
    }
    std::printf(
        "[ contact coasting ] %zu queries against %zu casting every step, %zu promises, %zu balls off the "
        "tiles, largest difference %.2e m\n",
        castsCoasting, castsEveryStep, promises, fell, worst);
    EXPECT_GT(fell, 0u) << "no ball left the tiled floor: its border was never tested";
    // Many of these steps roll or slide in the open: contact coasting must save at least a fifth
    // of the queries (a third today; Rapier and Box2D rarely coast: their resting sphere sits
    // within the contact reach of the floor, where their grown probe sinks into it).
    EXPECT_LT(static_cast<double>(castsCoasting), 0.8 * static_cast<double>(castsEveryStep))
        << castsCoasting << " queries coasting against " << castsEveryStep << " casting every step";
}

namespace {
// A region on the floor y = 0 (normal +Y) along the segment from `origin` by `displacement`.
PlaneRegion floorRegion(const RVec3& origin, const Vec3& displacement, float radius) {
    PlaneRegion region;
    region.capsule.origin = origin;
    region.capsule.displacement = displacement;
    region.capsule.radius = radius;
    region.point = RVec3(0, 0, 0);
    region.normal = Vec3(0, 1, 0);
    return region;
}
}  // namespace

// PlaneRegionTester::passesFlatGroup: a group passes only once the cross-section is anchored,
// and only where each of its triangles would pass test(): its box within the plane's tolerance
// (1e-6 m here, near the origin) and its normal along the plane's.
TEST(StaticWorldPlane, PassesAFlatGroupOnlyWhereEachTriangleWould) {
    PlaneRegion region = floorRegion(RVec3(0.3f, 0.01f, 0.2f), Vec3(1.5f, 0.0f, 0.4f), 0.05f);
    const glm::dvec3 up(0, 1, 0), lo(1, 0, -1), hi(3, 0, 1);
    foresight::PlaneRegionTester tester(region);
    EXPECT_FALSE(tester.passesFlatGroup(lo, hi, up, 0.0)) << "not anchored yet";
    tester.test(Triangle{RVec3(0, 0, 0), RVec3(0, 0, 1), RVec3(1, 0, 0)}, {}, 7);  // holds the anchor
    EXPECT_TRUE(tester.passesFlatGroup(lo, hi, up, 0.0)) << "a flat group in the plane";
    EXPECT_TRUE(tester.passesFlatGroup(lo, hi, -up, 1e-14)) << "normals up to sign, within the largest spread";
    EXPECT_FALSE(tester.passesFlatGroup(lo, hi, up, 2e-14)) << "a spread over 1e-14";
    EXPECT_TRUE(tester.passesFlatGroup(lo, glm::dvec3(3, 5e-7, 1), up, 0.0)) << "0.5 um up: within the tolerance";
    EXPECT_FALSE(tester.passesFlatGroup(lo, glm::dvec3(3, 2e-6, 1), up, 0.0)) << "2 um up: beyond it";
    EXPECT_FALSE(tester.passesFlatGroup(glm::dvec3(1, -2e-6, -1), hi, up, 0.0)) << "2 um down";
    const glm::dvec3 tilted = glm::normalize(glm::dvec3(1e-6, 1, 0));  // 1e-6 rad
    EXPECT_FALSE(tester.passesFlatGroup(lo, hi, tilted, 0.0)) << "a normal 1e-6 rad off";
    const glm::dvec3 slight = glm::normalize(glm::dvec3(1e-7, 1, 0));  // 1 - cos = 5e-15: test() passes it
    EXPECT_TRUE(tester.passesFlatGroup(lo, hi, slight, 0.0)) << "a normal 1e-7 rad off";
    tester.test(foresight::Sphere{RVec3(0.5f, 0.0f, 0.2f), 0.1f});  // fails the region
    ASSERT_TRUE(tester.failed());
    EXPECT_FALSE(tester.passesFlatGroup(lo, hi, up, 0.0)) << "after a failure";

    // A region with its own material passes no group of mesh triangles (which have none).
    region.restitution = 0.3f;
    foresight::PlaneRegionTester withMaterial(region);
    withMaterial.test(Triangle{RVec3(0, 0, 0), RVec3(0, 0, 1), RVec3(1, 0, 0)}, {0.3f, -1.0f}, 7);
    EXPECT_FALSE(withMaterial.failed());
    EXPECT_FALSE(withMaterial.passesFlatGroup(lo, hi, up, 0.0)) << "the group has no material";
}

// PlaneRegionTester's answers on shapes whose cover is known by construction.
TEST(StaticWorldPlane, IsOnlyPlaneKnowsHolesBordersAndNeighbours) {
    PlaneRegion region = floorRegion(RVec3(0.3f, 0.1f, 0.2f), Vec3(1.5f, 0.0f, 0.4f), 0.3f);
    const auto tiles = [](int half, int holeX, int holeZ) {
        StaticWorld world;
        for (int x = -half; x < half; ++x) {
            for (int z = -half; z < half; ++z) {
                const RVec3 a(x, 0, z), b(x + 1, 0, z), c(x + 1, 0, z + 1), d(x, 0, z + 1);
                if (x == holeX && z == holeZ) {
                    EXPECT_EQ(world.add(Triangle{a, d, c}), Status::Ok);  // half a tile: a hole
                    continue;
                }
                EXPECT_EQ(world.add(Triangle{a, c, b}), Status::Ok);
                EXPECT_EQ(world.add(Triangle{a, d, c}), Status::Ok);
            }
        }
        return world;
    };
    EXPECT_TRUE(tiles(4, 100, 100).isOnlyPlane(region)) << "a whole tiled floor";
    EXPECT_FALSE(tiles(4, 1, 0).isOnlyPlane(region)) << "a missing triangle under the path";
    EXPECT_TRUE(tiles(4, -3, -3).isOnlyPlane(region)) << "a missing triangle far from the path";
    EXPECT_FALSE(tiles(2, 100, 100).isOnlyPlane(region)) << "the floor's border (x = 2) within the region";
    region.point = RVec3(0, 0.001f, 0);
    EXPECT_FALSE(tiles(4, 100, 100).isOnlyPlane(region)) << "a plane 1 mm above the tiles";
    region.point = RVec3(0, 0, 0);

    StaticWorld world = tiles(4, 100, 100);
    EXPECT_EQ(world.add(OrientedBox{RVec3(0.3, 0.5, 1.5), Vec3(2, 0.5, 0.1)}), Status::Ok);
    EXPECT_TRUE(world.isOnlyPlane(region)) << "a wall 0.8 m beside the path, out of the region";
    region.capsule.radius = 0.9f;
    EXPECT_FALSE(world.isOnlyPlane(region)) << "the same wall within a wider region";
    region.capsule.radius = 0.3f;

    // A floor plane, a box whose top face is the floor, materials.
    StaticWorld plane;
    ASSERT_EQ(plane.add(Plane{Vec3(0, 1, 0), 0}, SurfaceMaterial{0.5f, 0.2f}), Status::Ok);
    EXPECT_FALSE(plane.isOnlyPlane(region)) << "the plane's material differs";
    region.restitution = 0.5f;
    region.friction = 0.2f;
    EXPECT_TRUE(plane.isOnlyPlane(region));
    region.restitution = region.friction = -1.0f;
    StaticWorld slab;
    ASSERT_EQ(slab.add(OrientedBox{RVec3(1, -1, 0.5), Vec3(3, 1, 3)}), Status::Ok);
    EXPECT_TRUE(slab.isOnlyPlane(region)) << "a box's top face under the whole region";
    StaticWorld narrow;
    ASSERT_EQ(narrow.add(OrientedBox{RVec3(1, -1, 0.3), Vec3(3, 1, 0.4)}), Status::Ok);
    EXPECT_FALSE(narrow.isOnlyPlane(region)) << "a box whose top face ends inside the region";
    StaticWorld ball = tiles(4, 100, 100);
    ASSERT_EQ(ball.add(Sphere{RVec3(1, 0.3, 0.4), 0.2f}), Status::Ok);
    EXPECT_FALSE(ball.isOnlyPlane(region)) << "a sphere on the path";
    StaticWorld tilted;
    ASSERT_EQ(tilted.add(Triangle{RVec3(-5, 0, -5), RVec3(5, 0.01, 5), RVec3(5, 0, -5)}), Status::Ok);
    ASSERT_EQ(tilted.add(Triangle{RVec3(-5, 0, -5), RVec3(-5, 0, 5), RVec3(5, 0.01, 5)}), Status::Ok);
    EXPECT_FALSE(tilted.isOnlyPlane(region)) << "a floor that rises 1 cm across 14 m";
    StaticWorld loose(StaticWorldSettings{1e-3f});
    ASSERT_EQ(loose.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    EXPECT_FALSE(loose.isOnlyPlane(region)) << "a world whose surface tolerance is not the default";
}

namespace {

// A swept sphere inside the capsule from `a` along `d` of radius `radius`: smaller, between two
// points of the axis within `along` of its length, pushed sideways by what the radius difference
// leaves.
SegmentCast castInside(ftest::Random& random, const ftest::DVec3& a, const ftest::DVec3& d, float radius,
                       double along) {
    const double r = radius * random.uniform(0, 0.9);
    const double slack = (radius - r) * 0.9;
    const ftest::DVec3 side =
        glm::normalize(ftest::DVec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1))) *
        random.uniform(0, slack);
    const ftest::DVec3 from = a + d * random.uniform(0, along) + side, to = a + d * random.uniform(0, along) + side;
    SegmentCast cast;
    cast.origin = RVec3(from);
    cast.displacement = Vec3(to - from);
    cast.radius = static_cast<float>(r);
    return cast;
}

}  // namespace

// mayTouch's promise, checked against the casts: when it says no surface comes within the
// capsule, no sphere cast inside the capsule (along it, across it, back) hits anything.
TEST(StaticWorldTouch, NoCastInsideAClearCapsuleHits) {
    ftest::Random random(77);
    int clear = 0, touched = 0;
    for (int round = 0; round < 200; ++round) {
        const StaticWorld world = ftest::randomScene(random);
        for (int i = 0; i < 50; ++i) {
            SegmentCast capsule;
            capsule.origin = RVec3(random.uniform(-10, 10), random.uniform(-1, 8), random.uniform(-10, 10));
            capsule.displacement =
                Vec3(static_cast<float>(random.uniform(-3, 3)), static_cast<float>(random.uniform(-3, 3)),
                     static_cast<float>(random.uniform(-3, 3)));
            capsule.radius = static_cast<float>(random.uniform(0, 0.8));
            if (world.mayTouch(capsule)) {
                ++touched;
                continue;
            }
            ++clear;
            const ftest::DVec3 a = ftest::toD(capsule.origin), d = ftest::toD(capsule.displacement);
            for (int k = 0; k < 8; ++k) {
                const SegmentCast cast = castInside(random, a, d, capsule.radius, 1.0);
                CastHit hit;
                EXPECT_FALSE(world.castSegment(cast, hit)) << "round " << round << " capsule " << i << " cast " << k;
            }
        }
    }
    // Both answers occur (the test exercises both sides).
    EXPECT_GT(clear, 1000);
    EXPECT_GT(touched, 1000);
}

// firstTouch's promise, checked against the casts: no sphere cast inside the capsule cut at the
// fraction it gives (along it, across it, back) hits anything; when it says false, none inside
// the whole capsule does.
TEST(StaticWorldTouch, NoCastBeforeTheFirstTouchHits) {
    ftest::Random random(78);
    int clear = 0, cut = 0, atOnce = 0;
    for (int round = 0; round < 200; ++round) {
        const StaticWorld world = ftest::randomScene(random);
        for (int i = 0; i < 50; ++i) {
            SegmentCast capsule;
            capsule.origin = RVec3(random.uniform(-10, 10), random.uniform(-1, 8), random.uniform(-10, 10));
            capsule.displacement =
                Vec3(static_cast<float>(random.uniform(-6, 6)), static_cast<float>(random.uniform(-6, 6)),
                     static_cast<float>(random.uniform(-6, 6)));
            capsule.radius = static_cast<float>(random.uniform(0, 0.8));
            float fraction = -1.0f;
            double reach = 1.0;
            if (world.firstTouch(capsule, fraction)) {
                ASSERT_GE(fraction, 0.0f);
                ASSERT_LE(fraction, 1.0f);
                EXPECT_TRUE(world.mayTouch(capsule)) << "a touch that mayTouch rules out";
                reach = fraction;
                if (fraction == 0.0f) {
                    ++atOnce;
                    continue;
                }
                ++cut;
            } else {
                ++clear;
            }
            const ftest::DVec3 a = ftest::toD(capsule.origin), d = ftest::toD(capsule.displacement) * reach;
            for (int k = 0; k < 8; ++k) {
                // 0.999: the cut's own end is where the first surface may touch.
                const SegmentCast cast = castInside(random, a, d, capsule.radius, 0.999);
                CastHit hit;
                EXPECT_FALSE(world.castSegment(cast, hit)) << "round " << round << " capsule " << i << " cast " << k;
            }
        }
    }
    // Every answer occurs (the test exercises each).
    EXPECT_GT(clear, 500);
    EXPECT_GT(cut, 500);
    EXPECT_GT(atOnce, 500);
}

// firstTouch is exact for spheres and planes, and for a box or a triangle met face on: the
// fraction where the segment's point first comes within the radius, computed here in closed form
// (the distance to a sphere's centre, a plane's height), less the tests' documented margin of
// 1e-4 m (and 1e-6 of the coordinates) for rounding.
TEST(StaticWorldTouch, FirstTouchIsExactForSpheresPlanesAndFacesMetHeadOn) {
    ftest::Random random(79);
    for (int i = 0; i < 2000; ++i) {
        const double radius = random.uniform(0.0, 0.5), length = random.uniform(1.0, 10.0);
        const ftest::DVec3 direction =
            glm::normalize(ftest::DVec3(random.uniform(-1, 1), random.uniform(-1, -0.2), random.uniform(-1, 1)));
        const ftest::DVec3 start(random.uniform(-2, 2), random.uniform(3, 6), random.uniform(-2, 2));
        SegmentCast capsule;
        capsule.origin = RVec3(start);
        capsule.displacement = Vec3(direction * length);
        capsule.radius = static_cast<float>(radius);
        const ftest::DVec3 a = ftest::toD(capsule.origin), d = ftest::toD(capsule.displacement);
        const double margin = 1e-4 + 1e-6 * 16.0 + 1e-9;

        // The floor plane y = 0: the height a.y + t d.y falls to the radius.
        const Plane plane{Vec3(0, 1, 0), 0};
        float fraction = -1.0f;
        const double planeEntry = (a.y - radius) / -d.y;
        if (planeEntry <= 1.0) {
            ASSERT_TRUE(firstTouch(capsule, plane, fraction));
            EXPECT_NEAR(fraction, std::max(0.0, planeEntry), margin / -d.y + 1e-6) << i;
            EXPECT_LE(fraction, std::max(0.0, planeEntry) + 1e-6) << i;
        }

        // A sphere on the segment's way, 0.3 m off its line: |a + t d - c| = R + s.
        const Sphere sphere{RVec3(a + d * random.uniform(0.3, 0.9) + ftest::DVec3(0.3, 0, 0)),
                            static_cast<float>(random.uniform(0.1, 1))};
        const ftest::DVec3 c = ftest::toD(sphere.center), offset = a - c;
        const double reach = radius + static_cast<double>(sphere.radius);
        const double A = glm::dot(d, d), B = glm::dot(d, offset), C = glm::dot(offset, offset) - reach * reach;
        const double disc = B * B - A * C;
        if (disc > 0.0) {
            const double entry = (-B - std::sqrt(disc)) / A;
            ASSERT_TRUE(firstTouch(capsule, sphere, fraction)) << i;
            // A margin m in the reach moves the entry by about m / (the distance's rate of
            // change there, sqrt(disc) / reach per unit of t); twice that for the second order.
            const double rate = std::sqrt(disc) / reach;
            EXPECT_LE(fraction, std::max(0.0, entry) + 1e-6) << i;
            EXPECT_GE(fraction, std::max(0.0, entry) - 2.0 * (margin + 1e-6 * reach) / rate - 1e-6) << i;
        }

        // A box below, its top face at y = 0.5, and a triangle in the plane y = 1, both far wider
        // than the path: met face on, their first touch is the plane's.
        const OrientedBox box{RVec3(0, 0, 0), Vec3(100, 0.5f, 100), Quat(1, 0, 0, 0)};
        const double boxEntry = (a.y - 0.5 - radius) / -d.y;
        if (boxEntry <= 1.0) {
            ASSERT_TRUE(firstTouch(capsule, box, fraction));
            EXPECT_NEAR(fraction, std::max(0.0, boxEntry), margin / -d.y + 1e-5) << i;
            EXPECT_LE(fraction, std::max(0.0, boxEntry) + 1e-6) << i;
        }
        const Triangle triangle{RVec3(-100, 1, -100), RVec3(0, 1, 100), RVec3(100, 1, -100)};
        const double triangleEntry = (a.y - 1.0 - radius) / -d.y;
        if (triangleEntry <= 1.0) {
            ASSERT_TRUE(firstTouch(capsule, triangle, fraction));
            EXPECT_NEAR(fraction, std::max(0.0, triangleEntry), margin / -d.y + 1e-5) << i;
            EXPECT_LE(fraction, std::max(0.0, triangleEntry) + 1e-6) << i;
        } else {
            EXPECT_FALSE(firstTouch(capsule, triangle, fraction)) << i;
        }
    }
}

// A shape's own material reaches the cast that hits it (and only that one), and the engine
// method combines it with the projectile's by the profile's rule: a floor of restitution 0.9
// under Jolt's max rule makes a projectile of 0.1 bounce with 0.9.
TEST(StaticWorldMaterial, CastsReportTheHitShapesMaterial) {
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0, 1, 0), 0}, SurfaceMaterial{0.9f, 0.2f}), Status::Ok);
    ASSERT_EQ(world.add(Sphere{RVec3(0, 0, 5), 1.0f}), Status::Ok);  // no material
    EXPECT_EQ(world.add(Plane{Vec3(1, 0, 0), 0}, SurfaceMaterial{1.5f, 0.0f}), Status::InvalidRestitution);
    EXPECT_EQ(world.add(Plane{Vec3(1, 0, 0), 0}, SurfaceMaterial{0.5f, std::nanf("")}), Status::NonFiniteInput);
    EXPECT_EQ(world.shapeCount(), 2u);
    CastHit hit;
    ASSERT_TRUE(world.castSegment(SegmentCast{RVec3(0, 1, -3), Vec3(0, -2, 0), 0.0f}, hit));
    EXPECT_EQ(hit.restitution, 0.9f);
    EXPECT_EQ(hit.friction, 0.2f);
    ASSERT_TRUE(world.castSegment(SegmentCast{RVec3(0, 0.5f, 0), Vec3(0, 0, 6), 0.0f}, hit));  // the sphere
    EXPECT_LT(hit.restitution, 0.0f);
    EXPECT_LT(hit.friction, 0.0f);

    ProjectileSettings settings;
    settings.method = ProjectileMethod::Engine;
    settings.engine = engineProfile(PhysicsEngine::Jolt);
    settings.engine.linearDamping = 0.0f;
    settings.radius = 0.1f;
    settings.restitution = 0.1f;
    std::vector<TrajectoryPoint> points(200);
    ProjectileResult result;
    ASSERT_EQ(predictProjectile(RVec3(-3, 2, -3), Vec3(0, -5, 0), 1.0f, settings, &world, points, result), Status::Ok);
    // The first point after the impact leaves upwards at about 0.9 of the approach (Jolt:
    // restitution times the approach without that step's gravity).
    double approach = 0.0, leave = 0.0;
    for (std::size_t i = 1; i < result.trajectorySize; ++i) {
        if (points[i].event != TrajectoryEvent::Bounce) continue;
        approach = -static_cast<double>(points[i - 1].velocity.y);
        leave = static_cast<double>(points[i].velocity.y);
        break;
    }
    ASSERT_GT(approach, 5.0);
    EXPECT_NEAR(leave / approach, 0.9, 0.03);  // 0.03: a step of gravity (0.16 m/s) against ~6 m/s
}

// ProjectileMethod::Engine with `engine`'s profile at `hz`, steps of the engine's timestep.
ProjectileSettings engineThrow(PhysicsEngine engine, float hz, float damping, float radius, float restitution,
                               float friction) {
    ProjectileSettings settings;
    settings.method = ProjectileMethod::Engine;
    settings.engine = engineProfile(engine);
    settings.engine.timestep = 1.0f / hz;
    settings.engine.linearDamping = damping;
    settings.step = settings.engine.timestep;
    settings.radius = radius;
    settings.restitution = restitution;
    settings.friction = friction;
    return settings;
}

// Box2D: a ball that strikes a wall's corner in a time-of-impact sub-step bounces off one contact,
// the corner's, with the normal from the corner to the centre at the time of impact. The corner
// was also known from the step's start (measured from there, with another normal); counting it
// twice sent the ball off at (-1.88, 2.31) m/s. Expected: Box2D 2.4.1's own velocity after that
// step for this throw (the native harness, seed 1234 of the engine oracle, scene 94).
TEST(EngineProfile, Box2DCornerImpactIsOneContact) {
    StaticWorld world;
    ASSERT_EQ(world.add(OrientedBox{RVec3(0, -0.5, 0), Vec3(30, 0.5f, 0.5f)}), Status::Ok);
    const Quat turn = glm::angleAxis(0.23140578689809102f, Vec3(0, 0, 1));
    ASSERT_EQ(world.add(OrientedBox{RVec3(4.318956763050331, 0.950081856483026, 0),
                                    Vec3(0.24230782867993655f, 1.7076510795815962f, 0.5f), turn}),
              Status::Ok);
    const ProjectileSettings settings = engineThrow(PhysicsEngine::Box2D, 60.0f, 0.31319439628370754f,
                                                    0.13746144396976628f, 0.4994581686351563f, 0.48499563174823224f);
    std::vector<TrajectoryPoint> points(100);
    ProjectileResult result;
    ASSERT_EQ(predictProjectile(RVec3(0.850002796431921, 1.828711504093277, 0),
                                Vec3(6.5594001334573795f, 4.270954195642485f, 0), 28.0f / 60.0f, settings, &world,
                                points, result),
              Status::Ok);
    ASSERT_GE(result.trajectorySize, 28u);
    // Step 26 is free flight (the engine: 5.72896, -0.235258); step 27 holds the impact.
    EXPECT_NEAR(points[26].velocity.x, 5.728960037231445, 1e-4);
    // 2e-3 m/s: the engine's float32 arithmetic over 27 steps and one contact solve; the double
    // count was off by 1.3 m/s.
    EXPECT_NEAR(points[27].velocity.x, -0.6033774614334106, 2e-3);
    EXPECT_NEAR(points[27].velocity.y, 3.1008617877960205, 2e-3);
}

// Godot 3.2 with Bullet (godot3-server, tests/engines/godot): a ball of 8.6 cm falls onto the
// floor box at 5.9 m/s, 60 Hz. The step before, Bullet's continuous-collision clamp stopped it
// with its swept sphere 0.47 mm above the floor, so this step's predictive contact starts within
// Bullet's 1 mm and has distance 0. How much friction that contact keeps at the centre depends on
// its distance: with the exact 0.47 mm the bounce left 0.13 m/s slower along the floor.
TEST(EngineProfile, Godot3BulletSweepStartingWithinAMillimetreHasNoDistance) {
    StaticWorld world;
    OrientedBox floor{RVec3(0, -0.5, 0), Vec3(30, 0.5f, 30)};
    floor.rounding = 0.04f;  // Godot's collision margin
    ASSERT_EQ(world.add(floor, SurfaceMaterial{0.0f, 0.1351111617334058f}), Status::Ok);
    const ProjectileSettings settings = engineThrow(PhysicsEngine::Godot3Bullet, 60.0f, 0.018758512200314936f,
                                                    0.0863051447357989f, 0.2553984674946413f, 0.1351111617334058f);
    std::vector<TrajectoryPoint> points(100);
    ProjectileResult result;
    ASSERT_EQ(predictProjectile(RVec3(-0.7911169035817118, 1.3027404263373508, 0.18160017989581223),
                                Vec3(-1.1437711553806986f, 3.4726100788823553f, -3.2384903282434165f), 1.0f, settings,
                                &world, points, result),
              Status::Ok);
    ASSERT_EQ(result.trajectorySize, 61u);
    // Godot after 60 steps: (-0.724307, 1.498187, -2.050610) m/s. 3e-4 m/s: float32 rounding
    // over 59 steps of flight (the prediction is 8e-5 m/s off); 0.13 m/s without the rule.
    EXPECT_NEAR(points[60].velocity.x, -0.724306583404541, 3e-4);
    EXPECT_NEAR(points[60].velocity.y, 1.4981873035430908, 3e-4);
    EXPECT_NEAR(points[60].velocity.z, -2.050609588623047, 3e-4);
}

// Bullet's narrow phase (GJK) measures a contact between the closest points at the step's start.
// A ball of 0.24 m thrown into a rounded vertical edge at 30 Hz is 0.137 m deep in it there; the
// probes along the normal must converge on the closest point (4 probes left it 1.1 degrees off).
// The expected normal is worked out here from the box's geometry.
TEST(EngineProfile, DeepEdgeContactHasTheClosestPointsNormal) {
    const double rounding = 0.04;
    OrientedBox wall{RVec3(1.865556323277267, 1.0599718976007781, -3.059019122648473),
                     Vec3(0.6001701888987231f, 1.3111229628995307f, 2.7644010418075986f),
                     Quat(0.9974179267883301f, 0.0f, 0.07181565463542938f, 0.0f)};
    wall.rounding = static_cast<float>(rounding);
    StaticWorld world;
    ASSERT_EQ(world.add(wall), Status::Ok);
    const ProjectileSettings settings = engineThrow(PhysicsEngine::Godot3Bullet, 30.0f, 0.0f, 0.24003828821627987f,
                                                    0.6559180026580591f, 0.16482505110216183f);
    std::vector<TrajectoryPoint> points(16);
    ProjectileResult result;
    ASSERT_EQ(predictProjectile(RVec3(0.24720565083596413, 0.9544455368552576, -0.3752205251606757),
                                Vec3(8.246629809135586f, 3.9529201572631543f, 1.214916767327371f), 6.0f / 30.0f,
                                settings, &world, points, result),
              Status::Ok);
    ASSERT_EQ(result.trajectorySize, 7u);
    ASSERT_EQ(points[6].event, TrajectoryEvent::End);  // the last step, a contact step: its normal is kept
    // The closest point of the rounded box to the centre where step 6 starts: the closest point
    // of the box shrunk by the rounding, pushed out by it.
    const glm::dmat3 rotation = glm::mat3_cast(glm::dquat(wall.orientation));
    const glm::dvec3 center(wall.center), half = glm::dvec3(wall.halfExtents) - rounding;
    const glm::dvec3 local = glm::transpose(rotation) * (glm::dvec3(points[5].position) - center);
    const glm::dvec3 inner = glm::clamp(local, -half, half);
    const glm::dvec3 expected = rotation * glm::normalize(local - inner);
    const double gap = glm::length(local - inner) - rounding - static_cast<double>(settings.radius);
    ASSERT_LT(gap, -0.1);  // deep: where the probes converge slowly
    // 2e-4: the casts' float normals (the probes stop when two agree to 1e-8 in their dot
    // product); 4 probes were 0.02 off.
    EXPECT_LT(glm::length(glm::dvec3(points[6].normal) - expected), 2e-4)
        << points[6].normal.x << " " << points[6].normal.z << " vs " << expected.x << " " << expected.z;
}

TEST(EngineProfile, PointProjectileOnASlopedTriangleStaysFinite) {
    // A point (radius 0) that lands and slides on a sloped two-sided triangle. Jolt's position
    // correction divided by the sphere's inertia, r^2 = 0 for a point, and every such throw was
    // refused as NonFiniteResult. A point does not turn: it is corrected like a sphere whose
    // rotation is locked. Every profile must give a finite answer that stays near the triangle.
    StaticWorld world;
    ASSERT_EQ(world.add(Triangle{RVec3(-3, 0, 3), RVec3(-1, 0, 3), RVec3(-2, 1, 6)}), Status::Ok);
    for (int engine = 0; engine <= static_cast<int>(PhysicsEngine::Box2D); ++engine) {
        ProjectileSettings settings;
        settings.method = ProjectileMethod::Engine;
        settings.engine = engineProfile(static_cast<PhysicsEngine>(engine));
        std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(1.0f, settings));
        ProjectileResult result;
        ASSERT_EQ(predictProjectile(RVec3(0, 1.6f, 0), Vec3(-2, 3, 5), 1.0f, settings, &world, trajectory, result),
                  Status::Ok)
            << engineName(settings.engine.engine);
        // Free flight alone would be at y = 1.6 + 3 - 4.9 = -0.3 after 1 s (Box2D: in the x-y
        // plane, where the triangle is never met); on the triangle the point stays above y = 0.
        if (settings.engine.planar) continue;
        EXPECT_GT(result.bounces, 0u) << engineName(settings.engine.engine);
        EXPECT_GT(result.position.y, 0.0f) << engineName(settings.engine.engine);
    }
}
