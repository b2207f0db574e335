// The C API (foresight_c.h, through the shared library) against direct calls of the C++ API on
// random inputs: statuses equal and results bit for bit, since the C API only converts types.
// This covers the marshalling (fields, order, enumerations); c_api_test.c checks the results
// against closed forms.
#include <foresight/aim.h>
#include <foresight/character.h>
#include <foresight/danger.h>
#include <foresight/dead_reckoning.h>
#include <foresight/foresight_c.h>
#include <foresight/projectile.h>
#include <foresight/replication.h>
#include <foresight/static_world.h>
#include <foresight/throw_planner.h>
#include <foresight/vehicle.h>
#include <gtest/gtest.h>
#if FORESIGHT_TEST_EMBREE
#include <foresight/embree_world.h>
#endif

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace foresight;

namespace {

constexpr int kCases = 300;

// Bit-identical (0 and -0 differ, as would two NaNs with different payloads).
bool same(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same(const fs_vec3& c, const Vec3& v) { return same(c.x, v.x) && same(c.y, v.y) && same(c.z, v.z); }
bool samePosition(const fs_dvec3& c, const RVec3& v) {
    return same(c.x, static_cast<double>(v.x)) && same(c.y, static_cast<double>(v.y)) &&
           same(c.z, static_cast<double>(v.z));
}
bool same(const fs_quat& c, const Quat& q) {
    return same(c.x, q.x) && same(c.y, q.y) && same(c.z, q.z) && same(c.w, q.w);
}

class Random {
public:
    explicit Random(std::uint32_t seed) : mEngine(seed) {}
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(mEngine); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(mEngine); }
    bool chance(double p) { return std::bernoulli_distribution(p)(mEngine); }
    Vec3 vec(float range) { return Vec3(uniform(-range, range), uniform(-range, range), uniform(-range, range)); }
    // A time, negative now and then (so that refusals are compared too).
    float time(float hi) { return chance(0.05) ? -uniform(0.01f, 1.0f) : uniform(0.0f, hi); }

private:
    std::mt19937 mEngine;
};

fs_vec3 toC(const Vec3& v) { return fs_vec3{v.x, v.y, v.z}; }
// Positions: the same float values as the C++ call gets, widened (exact).
fs_dvec3 toCPosition(const RVec3& v) {
    return fs_dvec3{static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}
fs_quat toC(const Quat& q) { return fs_quat{q.x, q.y, q.z, q.w}; }

Quat quat(float x, float y, float z, float w) {
    Quat q;
    q.x = x;
    q.y = y;
    q.z = z;
    q.w = w;
    return q;
}

}  // namespace

TEST(CApi, StatusesAndMessages) {
    EXPECT_EQ(fs_abi_version(), static_cast<std::uint32_t>(FS_ABI_VERSION));
    for (int s = 0; s <= static_cast<int>(Status::OutOfRange); ++s)
        EXPECT_STREQ(fs_status_message(s), statusMessage(static_cast<Status>(s))) << s;
}

TEST(CApi, Defaults) {
    const ProjectileSettings p;
    const fs_projectile_settings c = fs_projectile_settings_default();
    EXPECT_EQ(c.method, static_cast<int>(p.method));
    EXPECT_TRUE(same(c.gravity, p.gravity));
    EXPECT_TRUE(same(c.step, p.step));
    EXPECT_TRUE(same(c.restitution, p.restitution));
    EXPECT_TRUE(same(c.friction, p.friction));
    EXPECT_TRUE(same(c.radius, p.radius));
    EXPECT_EQ(c.max_bounces, p.maxBounces);
    EXPECT_EQ(c.max_steps, p.maxSteps);
    EXPECT_EQ(c.max_events, p.maxEvents);
    EXPECT_EQ(c.engine, static_cast<int>(p.engine.engine));
    const VehicleSettings v;
    const fs_vehicle_settings cv = fs_vehicle_settings_default();
    EXPECT_EQ(cv.frame, static_cast<int>(v.frame));
    EXPECT_TRUE(same(cv.forward, v.forward));
}

TEST(CApi, CharactersMatchCpp) {
    Random random(11);
    for (int i = 0; i < kCases; ++i) {
        const PointState start{RVec3(random.vec(1000.0f)), random.vec(50.0f)};
        const Vec3 acceleration = random.vec(20.0f);
        const float time = random.time(10.0f);
        const fs_point_state cStart{toCPosition(start.position), toC(start.velocity), 0.0f};

        PointState cpp;
        fs_point_state c{};
        Status s = predictLinear(start, time, cpp);
        ASSERT_EQ(fs_predict_linear(&cStart, time, &c), static_cast<fs_status>(s)) << i;
        if (s == Status::Ok) {
            EXPECT_TRUE(samePosition(c.position, cpp.position)) << i;
            EXPECT_TRUE(same(c.velocity, cpp.velocity)) << i;
        }
        s = predictAccelerated(start, acceleration, time, cpp);
        ASSERT_EQ(fs_predict_accelerated(&cStart, toC(acceleration), time, &c), static_cast<fs_status>(s)) << i;
        if (s == Status::Ok) {
            EXPECT_TRUE(samePosition(c.position, cpp.position)) << i;
            EXPECT_TRUE(same(c.velocity, cpp.velocity)) << i;
        }
    }
}

TEST(CApi, VehiclesMatchCpp) {
    Random random(12);
    for (int i = 0; i < kCases; ++i) {
        VehicleState start;
        start.position = RVec3(random.vec(1000.0f));
        start.velocity = random.vec(30.0f);
        start.orientation =
            quat(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        start.angularVelocity = random.vec(2.0f);
        VehicleSettings settings;
        settings.frame = random.chance(0.5) ? AngularFrame::Body : AngularFrame::World;
        settings.forward = random.chance(0.5) ? Vec3(0, 0, 1) : random.vec(1.0f);
        const float time = random.time(5.0f);
        const int iterations = random.integer(0, 16);

        const fs_vehicle_state cStart{toCPosition(start.position), toC(start.velocity), toC(start.orientation),
                                      toC(start.angularVelocity)};
        const fs_vehicle_settings cSettings{static_cast<std::int32_t>(settings.frame), toC(settings.forward)};
        const auto expectSame = [i](const fs_vehicle_state& c, const VehicleState& cpp) {
            EXPECT_TRUE(samePosition(c.position, cpp.position)) << i;
            EXPECT_TRUE(same(c.velocity, cpp.velocity)) << i;
            EXPECT_TRUE(same(c.orientation, cpp.orientation)) << i;
            EXPECT_TRUE(same(c.angular_velocity, cpp.angularVelocity)) << i;
        };

        VehicleState cpp;
        fs_vehicle_state c{};
        Status s = predictVehicleExact(start, time, settings, cpp);
        ASSERT_EQ(fs_predict_vehicle_exact(&cStart, time, &cSettings, &c), static_cast<fs_status>(s)) << i;
        if (s == Status::Ok) expectSame(c, cpp);
        s = predictVehicleIterative(start, time, iterations, settings, cpp);
        ASSERT_EQ(fs_predict_vehicle_iterative(&cStart, time, iterations, &cSettings, &c), static_cast<fs_status>(s))
            << i;
        if (s == Status::Ok) expectSame(c, cpp);
    }
}

TEST(CApi, ProjectilesMatchCpp) {
    Random random(13);
    std::vector<TrajectoryPoint> cppPoints(4096);
    std::vector<fs_trajectory_point> cPoints(4096);
    for (int i = 0; i < kCases; ++i) {
        // The same world both ways: a floor, and now and then a box, a sphere and a triangle,
        // some with their own material.
        StaticWorld world;
        fs_world* cWorld = fs_world_create();
        ASSERT_NE(cWorld, nullptr);
        const auto material = [&random]() {
            return random.chance(0.5) ? SurfaceMaterial{} : SurfaceMaterial{random.uniform(0, 1), random.uniform(0, 1)};
        };
        const auto cMaterial = [](const SurfaceMaterial& m) { return fs_material{m.restitution, m.friction}; };
        {
            const Plane plane{Vec3(random.uniform(-0.2f, 0.2f), 1.0f, random.uniform(-0.2f, 0.2f)),
                              static_cast<Real>(random.uniform(-1, 0))};
            const SurfaceMaterial m = material();
            const fs_plane cPlane{toC(plane.normal), 0.0f, static_cast<double>(plane.distance)};
            const fs_material cm = cMaterial(m);
            ASSERT_EQ(fs_world_add_plane(cWorld, &cPlane, &cm), static_cast<fs_status>(world.add(plane, m)));
        }
        if (random.chance(0.6)) {
            OrientedBox box;
            box.center = RVec3(random.vec(6.0f));
            box.halfExtents = Vec3(random.uniform(0.2f, 2), random.uniform(0.2f, 2), random.uniform(0.2f, 2));
            box.orientation = quat(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1), 1.0f);
            box.rounding = random.chance(0.3) ? 0.05f : 0.0f;
            const SurfaceMaterial m = material();
            const fs_box cBox{toCPosition(box.center), toC(box.halfExtents), toC(box.orientation), box.rounding};
            const fs_material cm = cMaterial(m);
            ASSERT_EQ(fs_world_add_box(cWorld, &cBox, &cm), static_cast<fs_status>(world.add(box, m)));
        }
        if (random.chance(0.6)) {
            const Sphere sphere{RVec3(random.vec(6.0f)), random.uniform(0.2f, 2)};
            const fs_sphere cSphere{toCPosition(sphere.center), sphere.radius, 0.0f};
            ASSERT_EQ(fs_world_add_sphere(cWorld, &cSphere, nullptr), static_cast<fs_status>(world.add(sphere)));
        }
        if (random.chance(0.6)) {
            const Triangle triangle{RVec3(random.vec(6.0f)), RVec3(random.vec(6.0f)), RVec3(random.vec(6.0f))};
            const fs_triangle cTriangle{toCPosition(triangle.a), toCPosition(triangle.b), toCPosition(triangle.c)};
            ASSERT_EQ(fs_world_add_triangle(cWorld, &cTriangle, nullptr), static_cast<fs_status>(world.add(triangle)));
        }

        ProjectileSettings settings;
        const int method = random.integer(0, 2);
        const int engine = random.integer(0, 7);
        settings.method = static_cast<ProjectileMethod>(method);
        settings.engine = engineProfile(static_cast<PhysicsEngine>(engine));
        settings.gravity = Vec3(0, -random.uniform(1, 20), 0);
        settings.step = random.chance(0.5) ? 0.02f : random.uniform(0.005f, 0.05f);
        settings.restitution = random.uniform(0, 1);
        settings.friction = random.chance(0.5) ? 0.0f : random.uniform(0, 1);
        settings.radius = random.chance(0.5) ? 0.0f : random.uniform(0, 0.3f);
        settings.maxBounces = random.chance(0.3) ? static_cast<std::uint32_t>(random.integer(0, 3)) : kUnlimitedBounces;
        fs_projectile_settings cSettings = fs_projectile_settings_default();
        cSettings.method = method;
        cSettings.engine = engine;
        cSettings.gravity = toC(settings.gravity);
        cSettings.step = settings.step;
        cSettings.restitution = settings.restitution;
        cSettings.friction = settings.friction;
        cSettings.radius = settings.radius;
        cSettings.max_bounces = settings.maxBounces;

        const RVec3 position(random.uniform(-3, 3), random.uniform(0.5f, 6), random.uniform(-3, 3));
        const Vec3 velocity = random.vec(15.0f);
        const float time = random.time(4.0f);
        // Now and then a buffer too small for the whole trajectory.
        const std::size_t capacity = random.chance(0.2) ? static_cast<std::size_t>(random.integer(0, 20)) : 4096;
        const bool withWorld = random.chance(0.9);

        ProjectileResult cpp;
        fs_projectile_result c{};
        const Status s = predictProjectile(position, velocity, time, settings, withWorld ? &world : nullptr,
                                           std::span(cppPoints.data(), capacity), cpp);
        const fs_status cs = fs_predict_projectile(toCPosition(position), toC(velocity), time, &cSettings,
                                                   withWorld ? cWorld : nullptr, cPoints.data(), capacity, &c);
        if (s == Status::Ok && capacity > 0 && cpp.trajectoryNeeded > cpp.trajectorySize)
            ASSERT_EQ(cs, FS_STATUS_BUFFER_TOO_SMALL) << i;
        else
            ASSERT_EQ(cs, static_cast<fs_status>(s)) << i;
        if (s == Status::Ok) {
            EXPECT_TRUE(samePosition(c.position, cpp.position)) << i;
            EXPECT_TRUE(same(c.velocity, cpp.velocity)) << i;
            EXPECT_TRUE(same(c.time, cpp.time)) << i;
            EXPECT_EQ(c.bounces, cpp.bounces) << i;
            EXPECT_EQ(c.at_rest, cpp.atRest ? 1 : 0) << i;
            EXPECT_EQ(c.stopped_at_hit, cpp.stoppedAtHit ? 1 : 0) << i;
            EXPECT_TRUE(same(c.hit_normal, cpp.hitNormal)) << i;
            ASSERT_EQ(c.trajectory_size, cpp.trajectorySize) << i;
            EXPECT_EQ(c.trajectory_needed, cpp.trajectoryNeeded) << i;
            for (std::size_t k = 0; k < cpp.trajectorySize; ++k) {
                const fs_trajectory_point& a = cPoints[k];
                const TrajectoryPoint& b = cppPoints[k];
                EXPECT_TRUE(same(a.time, b.time)) << i << " point " << k;
                EXPECT_EQ(a.event, static_cast<int>(b.event)) << i << " point " << k;
                EXPECT_TRUE(samePosition(a.position, b.position)) << i << " point " << k;
                EXPECT_TRUE(same(a.velocity, b.velocity)) << i << " point " << k;
                EXPECT_TRUE(same(a.normal, b.normal)) << i << " point " << k;
            }
        }
        // A callback world forwarding to the same StaticWorld's casts, against the C++
        // CallbackWorld doing the same: the casts cross the boundary (double positions, hits
        // checked) and must come back unchanged.
        if (withWorld && capacity == 4096 && i % 4 == 0) {
            const auto forward = [](void* context, const fs_segment_cast* cast, fs_cast_hit* hit) -> int32_t {
                const auto* target = static_cast<const StaticWorld*>(context);
                SegmentCast cppCast;
                cppCast.origin = RVec3(static_cast<Real>(cast->origin.x), static_cast<Real>(cast->origin.y),
                                       static_cast<Real>(cast->origin.z));
                cppCast.displacement = Vec3(cast->displacement.x, cast->displacement.y, cast->displacement.z);
                cppCast.radius = cast->radius;
                CastHit cppHit;
                if (!target->castSegment(cppCast, cppHit)) return 0;
                hit->fraction = cppHit.fraction;
                hit->position = toCPosition(cppHit.position);
                hit->normal = toC(cppHit.normal);
                hit->restitution = cppHit.restitution;
                hit->friction = cppHit.friction;
                return 1;
            };
            auto cppForward = [&world](const SegmentCast& cast, CastHit& hit) { return world.castSegment(cast, hit); };
            const CallbackWorld cppCallback = CallbackWorld::wrap(cppForward);
            fs_world* cCallback = fs_world_create_callback(forward, &world);
            ASSERT_NE(cCallback, nullptr);
            const Status sb = predictProjectile(position, velocity, time, settings, &cppCallback, cppPoints, cpp);
            const fs_status cb = fs_predict_projectile(toCPosition(position), toC(velocity), time, &cSettings,
                                                       cCallback, cPoints.data(), cPoints.size(), &c);
            fs_world_destroy(cCallback);
            ASSERT_EQ(cb, static_cast<fs_status>(sb)) << i << " (callback world)";
            if (sb == Status::Ok) {
                EXPECT_TRUE(samePosition(c.position, cpp.position)) << i << " (callback world)";
                EXPECT_TRUE(same(c.velocity, cpp.velocity)) << i << " (callback world)";
                EXPECT_EQ(c.bounces, cpp.bounces) << i << " (callback world)";
                EXPECT_EQ(c.trajectory_size, cpp.trajectorySize) << i << " (callback world)";
            }
        }
        EXPECT_EQ(fs_trajectory_capacity(time, &cSettings),
                  validateProjectileSettings(settings) == Status::Ok && time >= 0.0f
                      ? trajectoryCapacity(time, settings)
                      : std::size_t{0})
            << i;
        fs_world_destroy(cWorld);
    }
}

TEST(CApi, AimMatchesCpp) {
    Random random(14);
    const AimShot d;
    const fs_aim_shot cd = fs_aim_shot_default();
    EXPECT_TRUE(samePosition(cd.from, d.from));
    EXPECT_EQ(cd.constraint, static_cast<int>(d.constraint));
    EXPECT_TRUE(same(cd.speed, d.speed) && same(cd.apex_height, d.apexHeight) && same(cd.max_time, d.maxTime));
    EXPECT_TRUE(same(cd.gravity, d.gravity));
    for (int i = 0; i < kCases; ++i) {
        AimShot shot;
        shot.from = RVec3(random.vec(50.0f));
        shot.constraint = static_cast<AimConstraint>(random.integer(0, 3));
        shot.speed = random.uniform(-1, 60);
        shot.apexHeight = random.uniform(-1, 30);
        shot.gravity = random.chance(0.2) ? Vec3(0) : Vec3(0, -random.uniform(1, 20), 0);
        shot.maxTime = random.chance(0.05) ? -1.0f : random.uniform(0, 20);
        const AimTarget target{RVec3(random.vec(100.0f)), random.vec(20.0f),
                               random.chance(0.5) ? Vec3(0) : random.vec(5.0f)};
        const std::size_t capacity = static_cast<std::size_t>(random.integer(0, 4));

        std::array<FiringSolution, kMaxFiringSolutions> cpp;
        std::size_t cppCount = 0;
        const Status s = aimProjectile(shot, target, std::span(cpp.data(), capacity), cppCount);

        const fs_aim_shot cShot{toCPosition(shot.from),
                                static_cast<std::int32_t>(shot.constraint),
                                shot.speed,
                                shot.apexHeight,
                                toC(shot.gravity),
                                shot.maxTime,
                                0.0f};
        const fs_aim_target cTarget{toCPosition(target.position), toC(target.velocity), toC(target.acceleration)};
        std::array<fs_firing_solution, FS_MAX_FIRING_SOLUTIONS> c{};
        std::size_t cCount = 0;
        ASSERT_EQ(fs_aim_projectile(&cShot, &cTarget, c.data(), capacity, &cCount), static_cast<fs_status>(s)) << i;
        if (s != Status::Ok) continue;
        ASSERT_EQ(cCount, cppCount) << i;
        for (std::size_t k = 0; k < cCount; ++k) {
            EXPECT_TRUE(same(c[k].velocity, cpp[k].velocity)) << i;
            EXPECT_TRUE(same(c[k].time, cpp[k].time)) << i;
            EXPECT_TRUE(samePosition(c[k].hit, cpp[k].hit)) << i;
            EXPECT_TRUE(same(c[k].elevation, cpp[k].elevation)) << i;
        }
    }
}

TEST(CApi, DangerMatchesCpp) {
    Random random(29);
    std::vector<TrajectoryPoint> cppPoints(4096);
    std::vector<fs_trajectory_point> cPoints(4096);
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    fs_world* cWorld = fs_world_create();
    ASSERT_NE(cWorld, nullptr);
    const fs_plane cPlane{{0, 1, 0}, 0.0f, 0.0};
    ASSERT_EQ(fs_world_add_plane(cWorld, &cPlane, nullptr), FS_STATUS_OK);
    for (int i = 0; i < kCases; ++i) {
        // A grenade's trajectory, predicted both ways (ProjectilesMatchCpp checks they agree).
        ProjectileSettings settings;
        settings.friction = random.uniform(0, 0.6f);
        fs_projectile_settings cSettings = fs_projectile_settings_default();
        cSettings.friction = settings.friction;
        const RVec3 start(random.uniform(-3, 3), random.uniform(0.5f, 4), random.uniform(-3, 3));
        const Vec3 velocity = random.vec(12.0f);
        const float fuse = random.uniform(0.5f, 4.0f);
        ProjectileResult cpp;
        fs_projectile_result c{};
        ASSERT_EQ(predictProjectile(start, velocity, fuse, settings, &world, cppPoints, cpp), Status::Ok);
        ASSERT_EQ(fs_predict_projectile(toCPosition(start), toC(velocity), fuse, &cSettings, cWorld, cPoints.data(),
                                        cPoints.size(), &c),
                  FS_STATUS_OK);
        const std::span<const TrajectoryPoint> trajectory(cppPoints.data(), cpp.trajectorySize);
        const std::size_t n = c.trajectory_size;

        ProjectileDanger danger;
        danger.trajectory = trajectory;
        danger.fuseTime = random.chance(0.05) ? -1.0f : fuse;
        danger.blastRadius = random.uniform(0, 6);
        danger.contactRadius = random.chance(0.5) ? 0.0f : random.uniform(0, 1);
        const fs_projectile_danger cDanger{danger.fuseTime, danger.blastRadius, danger.contactRadius};
        const RVec3 point(random.uniform(-10, 10), random.uniform(0, 4), random.uniform(-10, 10));
        const float time = random.uniform(-0.5f, fuse + 0.5f);
        const float from = random.uniform(0, fuse), until = random.uniform(0, fuse);
        const float distance = random.chance(0.05) ? -1.0f : random.uniform(0, 3);

        RVec3 position;
        fs_dvec3 cPosition;
        Status st = positionOnTrajectory(trajectory, time, position);
        ASSERT_EQ(fs_position_on_trajectory(cPoints.data(), n, time, &cPosition), static_cast<fs_status>(st)) << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(samePosition(cPosition, position)) << i;
        }

        DangerZone zone;
        fs_danger_zone cZone{};
        st = computeDangerZone(danger, zone);
        ASSERT_EQ(fs_compute_danger_zone(cPoints.data(), n, &cDanger, &cZone), static_cast<fs_status>(st)) << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(samePosition(cZone.center, zone.center) && same(cZone.radius, zone.radius) &&
                        same(cZone.time, zone.time))
                << i;
        }

        bool safe = false;
        int32_t cSafe = -1;
        st = isPointSafe(danger, point, time, safe);
        ASSERT_EQ(fs_is_point_safe(cPoints.data(), n, &cDanger, toCPosition(point), time, &cSafe),
                  static_cast<fs_status>(st))
            << i;
        if (st == Status::Ok) {
            EXPECT_EQ(cSafe, safe ? 1 : 0) << i;
        }

        DangerStart begin;
        fs_danger_start cBegin{};
        st = findDangerStart(danger, point, begin);
        ASSERT_EQ(fs_find_danger_start(cPoints.data(), n, &cDanger, toCPosition(point), &cBegin),
                  static_cast<fs_status>(st))
            << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(cBegin.ever == (begin.ever ? 1 : 0) && same(cBegin.time, begin.time)) << i;
        }

        st = findPathApproach(trajectory, point, distance, from, until, begin);
        ASSERT_EQ(fs_find_path_approach(cPoints.data(), n, toCPosition(point), distance, from, until, &cBegin),
                  static_cast<fs_status>(st))
            << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(cBegin.ever == (begin.ever ? 1 : 0) && same(cBegin.time, begin.time)) << i;
        }

        ClosestApproach approach;
        fs_closest_approach cApproach{};
        st = findClosestPathApproach(trajectory, point, from, until, approach);
        ASSERT_EQ(fs_find_closest_path_approach(cPoints.data(), n, toCPosition(point), from, until, &cApproach),
                  static_cast<fs_status>(st))
            << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(same(cApproach.distance, approach.distance) && same(cApproach.time, approach.time)) << i;
        }

        // A vehicle and a character.
        VehicleBody vehicle;
        vehicle.state.position = RVec3(random.vec(10.0f));
        vehicle.state.velocity = random.vec(15.0f);
        vehicle.state.orientation = quat(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1), 1.0f);
        vehicle.state.angularVelocity = random.vec(1.0f);
        vehicle.settings.frame = random.chance(0.5) ? AngularFrame::Body : AngularFrame::World;
        vehicle.halfExtents = Vec3(random.uniform(0.3f, 2), random.uniform(0.3f, 2), random.uniform(0.3f, 3));
        vehicle.boxCenter = random.vec(0.5f);
        CharacterBody character;
        character.position = RVec3(random.vec(10.0f));
        character.velocity = random.vec(3.0f);
        character.acceleration = random.vec(1.0f);
        character.radius = random.uniform(0, 0.6f);
        character.halfAxis = random.chance(0.5) ? Vec3(0) : Vec3(0, random.uniform(0, 0.9f), 0);
        ApproachSettings approachSettings;
        approachSettings.tolerance = random.chance(0.05) ? 0.0f : random.uniform(1e-3f, 0.05f);
        const fs_vehicle_body cVehicle{
            fs_vehicle_state{toCPosition(vehicle.state.position), toC(vehicle.state.velocity),
                             toC(vehicle.state.orientation), toC(vehicle.state.angularVelocity)},
            fs_vehicle_settings{static_cast<int32_t>(vehicle.settings.frame), toC(vehicle.settings.forward)},
            toC(vehicle.halfExtents), toC(vehicle.boxCenter)};
        const fs_character_body cCharacter{toCPosition(character.position), toC(character.velocity),
                                           toC(character.acceleration), character.radius, toC(character.halfAxis)};
        const fs_approach_settings cApproachSettings{approachSettings.tolerance, approachSettings.maxEvaluations};
        const float horizon = random.time(4.0f);

        float separation = 0.0f, cSeparation = 0.0f;
        st = computeVehicleSeparation(vehicle, character, horizon, separation);
        ASSERT_EQ(fs_compute_vehicle_separation(&cVehicle, &cCharacter, horizon, &cSeparation),
                  static_cast<fs_status>(st))
            << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(same(cSeparation, separation)) << i;
        }

        VehicleContact contact;
        fs_vehicle_contact cContact{};
        st = findVehicleContact(vehicle, character, horizon, approachSettings, contact);
        ASSERT_EQ(fs_find_vehicle_contact(&cVehicle, &cCharacter, horizon, &cApproachSettings, &cContact),
                  static_cast<fs_status>(st))
            << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(cContact.contact == (contact.contact ? 1 : 0) && same(cContact.time, contact.time) &&
                        same(cContact.separation, contact.separation) && cContact.evaluations == contact.evaluations)
                << i;
        }

        st = findClosestVehicleApproach(vehicle, character, horizon, approachSettings, approach);
        ASSERT_EQ(fs_find_closest_vehicle_approach(&cVehicle, &cCharacter, horizon, &cApproachSettings, &cApproach),
                  static_cast<fs_status>(st))
            << i;
        if (st == Status::Ok) {
            EXPECT_TRUE(same(cApproach.distance, approach.distance) && same(cApproach.time, approach.time)) << i;
        }
    }
    fs_world_destroy(cWorld);
}

TEST(CApi, PlanThrowMatchesCpp) {
    Random random(31);
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    OrientedBox wall;
    wall.center = RVec3(0, 1.5f, 6);
    wall.halfExtents = Vec3(4, 1.5f, 0.25f);
    ASSERT_EQ(world.add(wall), Status::Ok);
    fs_world* cWorld = fs_world_create();
    ASSERT_NE(cWorld, nullptr);
    const fs_plane cPlane{{0, 1, 0}, 0.0f, 0.0};
    const fs_box cWall{toCPosition(wall.center), toC(wall.halfExtents), fs_quat{0, 0, 0, 1}, 0.0f};
    ASSERT_EQ(fs_world_add_plane(cWorld, &cPlane, nullptr), FS_STATUS_OK);
    ASSERT_EQ(fs_world_add_box(cWorld, &cWall, nullptr), FS_STATUS_OK);
    std::vector<TrajectoryPoint> scratch(1024);
    std::vector<fs_trajectory_point> cScratch(1024);
    std::size_t plansCompared = 0;
    for (int i = 0; i < 12; ++i) {
        ThrowPlanRequest request;
        request.start = RVec3(random.uniform(-3, 3), 1.5f, random.uniform(-3, 3));
        request.target = RVec3(random.uniform(-8, 8), 0.0f, random.uniform(-8, 12));
        request.acceptanceRadius = random.chance(0.05) ? -1.0f : random.uniform(0.3f, 1.0f);
        request.settings.friction = random.uniform(0, 0.6f);
        request.settings.restitution = random.uniform(0.2f, 0.7f);
        request.maxPlans = static_cast<std::uint32_t>(random.integer(1, 4));
        request.budget.maxPredictions = 120;
        fs_throw_plan_request cRequest = fs_throw_plan_request_default();
        cRequest.start = toCPosition(request.start);
        cRequest.target = toCPosition(request.target);
        cRequest.acceptance_radius = request.acceptanceRadius;
        cRequest.settings.friction = request.settings.friction;
        cRequest.settings.restitution = request.settings.restitution;
        cRequest.max_plans = request.maxPlans;
        cRequest.budget.max_predictions = request.budget.maxPredictions;
        EXPECT_EQ(fs_throw_plan_scratch_size(&cRequest), throwPlanScratchSize(request)) << i;

        std::array<ThrowPlan, 4> plans;
        std::array<fs_throw_plan, 4> cPlans{};
        ThrowPlanResult result;
        fs_throw_plan_result cResult{};
        const Status st = planThrow(request, &world, plans, scratch, result);
        ASSERT_EQ(
            fs_plan_throw(&cRequest, cWorld, cPlans.data(), cPlans.size(), cScratch.data(), cScratch.size(), &cResult),
            static_cast<fs_status>(st))
            << i;
        if (st != Status::Ok) continue;
        ASSERT_EQ(cResult.plan_count, result.planCount) << i;
        plansCompared += result.planCount;
        EXPECT_EQ(cResult.predictions, result.predictions) << i;
        EXPECT_TRUE(same(cResult.closest_distance, result.closestDistance)) << i;
        EXPECT_TRUE(same(cResult.closest_velocity, result.closestVelocity)) << i;
        for (std::size_t k = 0; k < result.planCount; ++k) {
            const ThrowPlan& a = plans[k];
            const fs_throw_plan& b = cPlans[k];
            EXPECT_TRUE(same(b.launch_velocity, a.launchVelocity)) << i << " plan " << k;
            EXPECT_TRUE(samePosition(b.final_position, a.finalPosition)) << i << " plan " << k;
            EXPECT_TRUE(same(b.distance, a.distance) && b.bounces == a.bounces && b.at_rest == (a.atRest ? 1 : 0))
                << i << " plan " << k;
            EXPECT_TRUE(same(b.first_impact_time, a.firstImpactTime) &&
                        same(b.first_impact_normal, a.firstImpactNormal) &&
                        samePosition(b.first_impact_position, a.firstImpactPosition))
                << i << " plan " << k;
        }
    }
    EXPECT_GE(plansCompared, 12u);  // most requests are reachable: plans were compared, not only refusals
    fs_world_destroy(cWorld);
}

// Meshes: a bumpy terrain of 2 x 16 x 16 triangles, in a StaticWorld and (when built) an
// EmbreeWorld, through fs_world_add_mesh against the C++ worlds.
TEST(CApi, MeshWorldsMatchCpp) {
    Random random(37);
    std::vector<RVec3> vertices;
    std::vector<fs_dvec3> cVertices;
    std::vector<std::uint32_t> indices;
    constexpr int kCells = 16;
    for (int z = 0; z <= kCells; ++z)
        for (int x = 0; x <= kCells; ++x) {
            vertices.emplace_back(static_cast<float>(x - kCells / 2), random.uniform(-0.3f, 0.3f),
                                  static_cast<float>(z - kCells / 2));
            cVertices.push_back(toCPosition(vertices.back()));
        }
    for (int z = 0; z < kCells; ++z)
        for (int x = 0; x < kCells; ++x) {
            const auto at = [](int i, int j) { return static_cast<std::uint32_t>(j * (kCells + 1) + i); };
            indices.insert(indices.end(),
                           {at(x, z), at(x, z + 1), at(x + 1, z + 1), at(x, z), at(x + 1, z + 1), at(x + 1, z)});
        }
    StaticWorld world;
    for (std::size_t t = 0; t < indices.size(); t += 3)
        ASSERT_EQ(world.add(Triangle{vertices[indices[t]], vertices[indices[t + 1]], vertices[indices[t + 2]]}),
                  Status::Ok);
    fs_world* cWorld = fs_world_create();
    ASSERT_NE(cWorld, nullptr);
    fs_mesh_report report{};
    ASSERT_EQ(fs_world_add_mesh(cWorld, cVertices.data(), cVertices.size(), indices.data(), indices.size(), &report),
              FS_STATUS_OK);
    EXPECT_EQ(report.triangles, indices.size() / 3);
    std::vector<const CollisionWorld*> cppWorlds{&world};
    std::vector<fs_world*> cWorlds{cWorld};
#if FORESIGHT_TEST_EMBREE
    EmbreeWorld embree;
    ASSERT_EQ(embree.addMesh(vertices, indices), Status::Ok);
    ASSERT_TRUE(embree.commit());
    fs_world* cEmbree = fs_world_create_embree();
    ASSERT_NE(cEmbree, nullptr);
    ASSERT_EQ(fs_world_add_mesh(cEmbree, cVertices.data(), cVertices.size(), indices.data(), indices.size(), nullptr),
              FS_STATUS_OK);
    ASSERT_EQ(fs_world_commit(cEmbree, nullptr, 0), FS_STATUS_OK);
    cppWorlds.push_back(&embree);
    cWorlds.push_back(cEmbree);
#else
    EXPECT_EQ(fs_embree_available(), 0);
#endif
    std::vector<TrajectoryPoint> cppPoints(4096);
    std::vector<fs_trajectory_point> cPoints(4096);
    int bounced = 0;
    for (int i = 0; i < 60; ++i) {
        ProjectileSettings settings;
        const int method = random.integer(0, 2);
        settings.method = static_cast<ProjectileMethod>(method);
        settings.friction = random.uniform(0, 0.6f);
        settings.radius = random.chance(0.5) ? 0.0f : random.uniform(0.02f, 0.3f);
        fs_projectile_settings cSettings = fs_projectile_settings_default();
        cSettings.method = method;
        cSettings.friction = settings.friction;
        cSettings.radius = settings.radius;
        const RVec3 start(random.uniform(-4, 4), random.uniform(1, 4), random.uniform(-4, 4));
        const Vec3 velocity(random.uniform(-5, 5), random.uniform(-2, 6), random.uniform(-5, 5));
        for (std::size_t w = 0; w < cppWorlds.size(); ++w) {
            ProjectileResult cpp;
            fs_projectile_result c{};
            const Status st = predictProjectile(start, velocity, 2.0f, settings, cppWorlds[w], cppPoints, cpp);
            ASSERT_EQ(fs_predict_projectile(toCPosition(start), toC(velocity), 2.0f, &cSettings, cWorlds[w],
                                            cPoints.data(), cPoints.size(), &c),
                      static_cast<fs_status>(st))
                << i << " world " << w;
            if (st != Status::Ok) continue;
            bounced += cpp.bounces > 0 ? 1 : 0;
            EXPECT_TRUE(samePosition(c.position, cpp.position)) << i << " world " << w;
            EXPECT_TRUE(same(c.velocity, cpp.velocity)) << i << " world " << w;
            EXPECT_EQ(c.bounces, cpp.bounces) << i << " world " << w;
            EXPECT_EQ(c.trajectory_size, cpp.trajectorySize) << i << " world " << w;
        }
    }
    EXPECT_GT(bounced, 30);  // the throws do meet the terrain
    for (fs_world* w : cWorlds) fs_world_destroy(w);
}

// Every field of an engine profile crosses the boundary: random profiles (each field in its
// range) predict the same flights bit for bit, and the drawn positions between steps agree.
TEST(CApi, EngineProfilesMatchCpp) {
    Random random(41);
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    OrientedBox box;
    box.center = RVec3(3, 1, 0);
    box.halfExtents = Vec3(0.5f, 1, 2);
    ASSERT_EQ(world.add(box, SurfaceMaterial{0.7f, 0.2f}), Status::Ok);
    fs_world* cWorld = fs_world_create();
    ASSERT_NE(cWorld, nullptr);
    const fs_plane cPlane{{0, 1, 0}, 0.0f, 0.0};
    const fs_box cBox{toCPosition(box.center), toC(box.halfExtents), fs_quat{0, 0, 0, 1}, 0.0f};
    const fs_material cMaterial{0.7f, 0.2f};
    ASSERT_EQ(fs_world_add_plane(cWorld, &cPlane, nullptr), FS_STATUS_OK);
    ASSERT_EQ(fs_world_add_box(cWorld, &cBox, &cMaterial), FS_STATUS_OK);
    std::vector<TrajectoryPoint> cppPoints(4096);
    std::vector<fs_trajectory_point> cPoints(4096);
    for (int i = 0; i < kCases; ++i) {
        const int named = random.integer(0, 7);
        EngineProfile profile = engineProfile(static_cast<PhysicsEngine>(named));
        fs_engine_profile c = fs_engine_profile_default(named);
        // Now and then change every field (valid ranges, a bad value 1 time in 20).
        if (random.chance(0.7)) {
            profile.timestep = random.chance(0.05) ? 0.0f : random.uniform(1.0f / 240, 1.0f / 20);
            profile.substeps = static_cast<std::uint32_t>(random.integer(1, 6));
            profile.order = static_cast<DampingOrder>(random.integer(0, 1));
            profile.damping = static_cast<DampingLaw>(random.integer(0, 3));
            profile.linearDamping = random.uniform(0, 2);
            profile.addedLinearDamping = random.chance(0.5) ? 0.0f : random.uniform(0, 0.5f);
            profile.angularDamping = random.uniform(0, 1);
            profile.firstStep = static_cast<FirstStepRule>(random.integer(0, 2));
            profile.restitutionThreshold = random.uniform(0, 2);
            profile.restitutionBase = static_cast<RestitutionBase>(random.integer(0, 1));
            profile.restitutionCombine = static_cast<CombineRule>(random.integer(0, 5));
            profile.frictionCombine = static_cast<CombineRule>(random.integer(0, 5));
            profile.contact = static_cast<ContactMethod>(random.integer(0, 1));
            profile.contactDistance = random.uniform(0, 0.05f);
            profile.penetrationSlop = random.uniform(0, 0.01f);
            profile.positionCorrection = random.uniform(0, 1);
            profile.correctionIsVelocity = random.chance(0.5);
            profile.splitImpulseCorrection = random.uniform(0, 1);
            profile.frictionWarmStart = random.chance(0.5) ? 0.0f : random.uniform(0, 1);
            profile.maxLinearSpeed = random.uniform(5, 600);
            profile.maxStepDistance = random.uniform(0.5f, 5);
            profile.planar = random.chance(0.2);
            profile.rotates = random.chance(0.7);
            profile.triangleMesh = random.chance(0.2);
            c = fs_engine_profile{static_cast<int32_t>(profile.engine),
                                  profile.timestep,
                                  profile.substeps,
                                  static_cast<int32_t>(profile.order),
                                  static_cast<int32_t>(profile.damping),
                                  profile.linearDamping,
                                  profile.addedLinearDamping,
                                  profile.angularDamping,
                                  static_cast<int32_t>(profile.firstStep),
                                  profile.restitutionThreshold,
                                  static_cast<int32_t>(profile.restitutionBase),
                                  static_cast<int32_t>(profile.restitutionCombine),
                                  static_cast<int32_t>(profile.frictionCombine),
                                  static_cast<int32_t>(profile.contact),
                                  profile.contactDistance,
                                  profile.penetrationSlop,
                                  profile.positionCorrection,
                                  profile.correctionIsVelocity ? 1 : 0,
                                  profile.splitImpulseCorrection,
                                  profile.frictionWarmStart,
                                  profile.maxLinearSpeed,
                                  profile.maxStepDistance,
                                  profile.planar ? 1 : 0,
                                  profile.rotates ? 1 : 0,
                                  profile.triangleMesh ? 1 : 0};
        }
        EXPECT_EQ(fs_validate_engine_profile(&c), static_cast<fs_status>(validateEngineProfile(profile))) << i;
        ProjectileSettings settings;
        settings.method = ProjectileMethod::Engine;
        settings.engine = profile;
        settings.restitution = random.uniform(0, 1);
        settings.friction = random.uniform(0, 0.8f);
        settings.radius = random.uniform(0.02f, 0.3f);
        fs_projectile_settings cSettings = fs_projectile_settings_default();
        cSettings.method = FS_METHOD_ENGINE;
        cSettings.restitution = settings.restitution;
        cSettings.friction = settings.friction;
        cSettings.radius = settings.radius;
        const RVec3 start(random.uniform(-2, 2), random.uniform(0.5f, 3), random.uniform(-2, 2));
        const Vec3 velocity(random.uniform(-3, 8), random.uniform(-2, 6), random.uniform(-3, 3));
        const float time = random.uniform(0.2f, 3.0f);
        ProjectileResult cpp;
        fs_projectile_result cResult{};
        const Status st = validateEngineProfile(profile) == Status::Ok
                              ? predictProjectile(start, velocity, time, settings, &world, cppPoints, cpp)
                              : validateEngineProfile(profile);
        ASSERT_EQ(fs_predict_projectile_with_profile(toCPosition(start), toC(velocity), time, &cSettings, &c, cWorld,
                                                     cPoints.data(), cPoints.size(), &cResult),
                  static_cast<fs_status>(st))
            << i;
        EXPECT_EQ(fs_trajectory_capacity_with_profile(time, &cSettings, &c),
                  st == Status::Ok ? trajectoryCapacity(time, settings) : std::size_t{0})
            << i;
        if (st != Status::Ok) continue;
        EXPECT_TRUE(samePosition(cResult.position, cpp.position)) << i;
        EXPECT_TRUE(same(cResult.velocity, cpp.velocity)) << i;
        EXPECT_EQ(cResult.bounces, cpp.bounces) << i;
        ASSERT_EQ(cResult.trajectory_size, cpp.trajectorySize) << i;
        const float renderTime = random.uniform(-0.1f, time + 0.1f);
        const int smoothing = random.integer(0, 2);
        fs_dvec3 drawn{};
        ASSERT_EQ(fs_rendered_position(cPoints.data(), cResult.trajectory_size, profile.timestep, renderTime, smoothing,
                                       &drawn),
                  FS_STATUS_OK)
            << i;
        EXPECT_TRUE(samePosition(
            drawn, renderedPosition(std::span<const TrajectoryPoint>(cppPoints.data(), cpp.trajectorySize),
                                    profile.timestep, renderTime, static_cast<RenderSmoothing>(smoothing))))
            << i;
    }
    fs_world_destroy(cWorld);
}

namespace {

// A random dead-reckoning update: any of the nine models, now and then an invalid field.
DeadReckoningState randomDeadReckoning(Random& random, std::int32_t& algorithm) {
    DeadReckoningState s;
    algorithm = random.chance(0.03) ? random.integer(-1, 300) : random.integer(1, kDeadReckoningAlgorithmCount);
    s.algorithm = static_cast<DeadReckoningAlgorithm>(algorithm >= 1 && algorithm <= 9 ? algorithm : 0);
    s.position = RVec3(random.vec(1000.0f));
    s.velocity = random.vec(50.0f);
    s.acceleration = random.vec(10.0f);
    s.orientation = glm::normalize(quat(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1), 1.0f));
    if (random.chance(0.03)) s.orientation = quat(0, 0, 0, 0);
    s.angularVelocity = random.chance(0.1) ? Vec3(0.0f) : random.vec(3.0f);
    if (random.chance(0.03)) s.velocity.y = std::numeric_limits<float>::quiet_NaN();
    return s;
}

fs_dr_state toC(const DeadReckoningState& s, std::int32_t algorithm) {
    return fs_dr_state{toCPosition(s.position), toC(s.velocity),        toC(s.acceleration),
                       toC(s.orientation),      toC(s.angularVelocity), algorithm};
}

bool same(const fs_dr_result& c, const DeadReckoningResult& r) {
    return samePosition(c.position, r.position) && same(c.velocity, r.velocity) && same(c.orientation, r.orientation);
}

}  // namespace

TEST(CApi, DeadReckoningMatchesCpp) {
    Random random(23);
    std::vector<DeadReckoningState> states;
    std::vector<fs_dr_state> cStates;
    std::vector<double> timestamps;
    for (int i = 0; i < kCases; ++i) {
        std::int32_t algorithm = 0;
        const DeadReckoningState state = randomDeadReckoning(random, algorithm);
        const fs_dr_state cState = toC(state, algorithm);
        const float time = random.time(5.0f);
        DeadReckoningResult cpp;
        fs_dr_result c{};
        const Status s = predictDeadReckoning(state, time, cpp);
        ASSERT_EQ(fs_dr_predict(&cState, time, &c), static_cast<fs_status>(s)) << i;
        if (s == Status::Ok) {
            EXPECT_TRUE(same(c, cpp)) << i;
        }
        states.push_back(state);
        cStates.push_back(cState);
        timestamps.push_back(random.uniform(0.0f, 10.0f));
    }
    std::vector<DeadReckoningResult> cpp(states.size());
    std::vector<fs_dr_result> c(states.size());
    const std::size_t cppRefused = predictDeadReckoningBatch(states, timestamps, 6.0, cpp);
    std::size_t refused = 0;
    ASSERT_EQ(fs_dr_predict_batch(cStates.data(), timestamps.data(), c.size(), 6.0, c.data(), &refused), FS_STATUS_OK);
    EXPECT_EQ(refused, cppRefused);
    EXPECT_GT(refused, 0u);  // the random invalid fields are exercised
    for (std::size_t i = 0; i < c.size(); ++i) EXPECT_TRUE(same(c[i], cpp[i])) << i;
}

TEST(CApi, DeadReckoningReceiverMatchesCpp) {
    // Every mode and smoothing, a stream of noisy, late, duplicated and invalid updates, sampled
    // every frame: outcomes, statuses, poses and counters equal.
    for (int mode = FS_DR_MODE_EXTRAPOLATE; mode <= FS_DR_MODE_INTERPOLATE; ++mode) {
        for (int smoothing = FS_DR_SMOOTH_SNAP; smoothing <= FS_DR_SMOOTH_EXPONENTIAL_DECAY; ++smoothing) {
            Random random(static_cast<std::uint32_t>(100 + mode * 10 + smoothing));
            fs_dr_receiver_settings cSettings = fs_dr_receiver_settings_default();
            cSettings.mode = mode;
            cSettings.smoothing = smoothing;
            ReceiverSettings settings;
            settings.mode = static_cast<ReceiverMode>(mode);
            settings.smoothing = static_cast<Smoothing>(smoothing);
            DeadReckoningReceiver cpp(settings);
            fs_dr_receiver* c = nullptr;
            ASSERT_EQ(fs_dr_receiver_create(&cSettings, &c), FS_STATUS_OK);
            double time = 0.0;
            for (int frame = 0; frame < 400; ++frame) {
                time += 1.0 / 60.0;
                if (random.chance(0.2)) {
                    std::int32_t algorithm = 0;
                    const DeadReckoningState state = randomDeadReckoning(random, algorithm);
                    const fs_dr_state cState = toC(state, algorithm);
                    const double stamp = time - random.uniform(0.0f, 0.3f);
                    std::int32_t outcome = -1;
                    const UpdateOutcome o = cpp.receive(stamp, state, time);
                    ASSERT_EQ(fs_dr_receiver_receive(c, stamp, &cState, time, &outcome), FS_STATUS_OK);
                    EXPECT_EQ(outcome, static_cast<std::int32_t>(o)) << frame;
                }
                ReceivedPose pose;
                fs_dr_pose cPose{};
                const Status s = cpp.sample(time, pose);
                ASSERT_EQ(fs_dr_receiver_sample(c, time, &cPose), static_cast<fs_status>(s)) << frame;
                if (s == Status::Ok) {
                    EXPECT_TRUE(samePosition(cPose.position, pose.position)) << frame;
                    EXPECT_TRUE(same(cPose.velocity, pose.velocity)) << frame;
                    EXPECT_TRUE(same(cPose.orientation, pose.orientation)) << frame;
                    EXPECT_EQ(cPose.held, pose.held ? 1 : 0) << frame;
                }
            }
            fs_dr_receiver_counters counters{};
            ASSERT_EQ(fs_dr_receiver_get_counters(c, &counters), FS_STATUS_OK);
            const ReceiverCounters& k = cpp.counters();
            EXPECT_EQ(counters.accepted, k.accepted);
            EXPECT_EQ(counters.snaps, k.snaps);
            EXPECT_EQ(counters.teleports, k.teleports);
            EXPECT_EQ(counters.out_of_order, k.outOfOrder);
            EXPECT_EQ(counters.duplicates, k.duplicates);
            EXPECT_EQ(counters.invalid, k.invalid);
            EXPECT_EQ(counters.held, k.held);
            EXPECT_EQ(counters.future_updates, k.futureUpdates);
            EXPECT_EQ(counters.too_far_ahead, k.tooFarAhead);
            EXPECT_EQ(counters.clock_restarts, k.clockRestarts);
            EXPECT_GT(k.accepted, 0u);
            fs_dr_receiver_destroy(c);
        }
    }
}

TEST(CApi, DeadReckoningDefaults) {
    const ReceiverSettings d;
    const fs_dr_receiver_settings c = fs_dr_receiver_settings_default();
    EXPECT_EQ(c.mode, static_cast<int>(d.mode));
    EXPECT_EQ(c.smoothing, static_cast<int>(d.smoothing));
    EXPECT_TRUE(same(c.blend_time, d.blendTime));
    EXPECT_TRUE(same(c.decay_half_life, d.decayHalfLife));
    EXPECT_TRUE(same(c.teleport_distance, d.teleportDistance));
    EXPECT_TRUE(same(c.extrapolation_limit, d.extrapolationLimit));
    EXPECT_TRUE(same(c.interpolation_delay, d.interpolationDelay));
    EXPECT_TRUE(same(c.max_future_skew, d.maxFutureSkew));
    EXPECT_TRUE(same(c.restart_after, d.restartAfter));
    for (int a = 1; a <= kDeadReckoningAlgorithmCount; ++a)
        EXPECT_STREQ(fs_dr_algorithm_name(a), deadReckoningAlgorithmName(static_cast<DeadReckoningAlgorithm>(a)));
}

// A ball that bounces hundreds of times (restitution 0.95 on a floor): more events than the C API
// prepares at first (trajectoryCapacity's 64), so it predicts again on the whole buffer. Its
// trajectory must still be the C++ one, point for point, and a buffer one point too small must
// say how many are needed.
TEST(CApi, LongExactTrajectoryMatchesCpp) {
    StaticWorld world;
    ASSERT_EQ(world.add(Plane{Vec3(0, 1, 0), 0}), Status::Ok);
    fs_world* cWorld = fs_world_create();
    ASSERT_NE(cWorld, nullptr);
    const fs_plane cPlane{{0, 1, 0}, 0.0f, 0.0};
    ASSERT_EQ(fs_world_add_plane(cWorld, &cPlane, nullptr), FS_STATUS_OK);
    ProjectileSettings settings;
    settings.restitution = 0.95f;
    fs_projectile_settings cSettings = fs_projectile_settings_default();
    cSettings.restitution = 0.95f;
    std::vector<TrajectoryPoint> cppPoints(8192);
    std::vector<fs_trajectory_point> cPoints(8192);
    ProjectileResult cpp;
    ASSERT_EQ(predictProjectile(RVec3(0, 1, 0), Vec3(1, 0, 0), 20.0f, settings, &world, cppPoints, cpp), Status::Ok);
    ASSERT_GT(cpp.bounces, 64u);
    ASSERT_GT(cpp.trajectorySize, trajectoryCapacity(20.0f, settings));
    fs_projectile_result c{};
    ASSERT_EQ(fs_predict_projectile(fs_dvec3{0, 1, 0}, fs_vec3{1, 0, 0}, 20.0f, &cSettings, cWorld, cPoints.data(),
                                    cPoints.size(), &c),
              FS_STATUS_OK);
    EXPECT_EQ(c.bounces, cpp.bounces);
    ASSERT_EQ(c.trajectory_size, cpp.trajectorySize);
    for (std::size_t k = 0; k < cpp.trajectorySize; ++k) {
        EXPECT_TRUE(same(cPoints[k].time, cppPoints[k].time)) << k;
        EXPECT_TRUE(samePosition(cPoints[k].position, cppPoints[k].position)) << k;
    }
    EXPECT_EQ(fs_predict_projectile(fs_dvec3{0, 1, 0}, fs_vec3{1, 0, 0}, 20.0f, &cSettings, cWorld, cPoints.data(),
                                    cpp.trajectorySize - 1, &c),
              FS_STATUS_BUFFER_TOO_SMALL);
    EXPECT_EQ(c.trajectory_needed, cpp.trajectoryNeeded);
    EXPECT_EQ(c.trajectory_size, cpp.trajectorySize - 1);
    fs_world_destroy(cWorld);
}
