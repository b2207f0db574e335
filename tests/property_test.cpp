// Property suite at scale: seeded random cases of five properties, each checked on every case.
//
// 1. NoTunnelling: projectiles launched inside a closed triangle mesh (a box of 12 triangles or
//    an icosphere of 80, random size, orientation and place in a StaticWorld) stay inside it:
//    methods Exact and Stepped (points and spheres) and Engine (spheres, the profiles with
//    speculative contacts), random restitution, friction, step, gravity and speeds up to 300 m/s.
// 2. EnergyNeverIncreases: Exact and Stepped, restitution <= 1, friction >= 0 (no damping: those
//    methods have none): |v|^2/2 - g.p at every trajectory point is at most its start value plus
//    float rounding.
// 3. Determinism: determinism_test.cpp runs one fixed scenario twice and on a second thread.
//    Here, per random case, two predictions A and B (every method, every engine profile) in a
//    random world of every shape kind give bit-identical trajectories alone in a fresh world,
//    A then B, B then A in one shared world, and A and B at once on two threads.
// 4. AimSolutionsHit: random problems for all four constraints, moving and accelerating targets,
//    any gravity direction; every solution flown by predictProjectile meets the target, obeys its
//    constraint, and is in (0, maxTime], sorted. aim_test.cpp's brute-force scan covers Speed
//    with gravity along -Y; here a time scan of HorizontalSpeed, ApexAboveStart and
//    ApexAboveTarget checks that no crossing root is missed.
// 5. DeadReckoningHalfSteps: two steps of t/2 (the first output fed back) equal one step of t,
//    for all nine models, random states, in the float build (dead_reckoning_test.cpp checks two
//    states per model in the double build).
//
// Environment:
//   FORESIGHT_PROPERTY_CASES  cases per property (default 5000: the CI sample, 25 000 cases;
//                             500 in builds without NDEBUG)
//   FORESIGHT_PROPERTY_SEED   the seed, decimal or 0x-prefixed hex (default 0x5eed2026)
//   FORESIGHT_PROPERTY_CASE   run only this case index of each property (to reproduce a failure;
//                             NoTunnelling then prints the trajectory)
// Every failure prints the seed, the case index and the command line that runs that case alone.
// Each case draws its inputs from its own generator, seeded from (seed, property, index), so a
// case does not depend on the cases before it.
//
// Long run (1 000 000 cases: 5 properties x 200 000, 2 minutes), from the build directory:
//   FORESIGHT_PROPERTY_CASES=200000 nice tests/foresight_property_tests
// (FORESIGHT_PROPERTY_CASES=1000000: 10^6 per property, 8 minutes, the known failures included.)

#include "test_util.h"

#include <foresight/aim.h>
#include <foresight/dead_reckoning.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using foresight::AimConstraint;
using foresight::AimShot;
using foresight::AimTarget;
using foresight::DeadReckoningAlgorithm;
using foresight::DeadReckoningResult;
using foresight::DeadReckoningState;
using foresight::FiringSolution;
using foresight::PhysicsEngine;
using foresight::ProjectileMethod;
using foresight::ProjectileResult;
using foresight::ProjectileSettings;
using foresight::Real;
using foresight::StaticWorld;
using foresight::Status;
using foresight::TrajectoryPoint;
using foresight::Vec3;
using ftest::DQuat;
using ftest::DVec3;

constexpr double kPi = 3.14159265358979323846;

// =============================================================================================
// Configuration, per-case seeds and the case loop.

struct Config {
    std::uint64_t seed = 0x5eed2026u;
#ifdef NDEBUG
    std::int64_t cases = 5000;
#else
    std::int64_t cases = 500;  // Debug and sanitizer builds are ~20x slower
#endif
    std::int64_t only = -1;  ///< >= 0: run only this case index
};

std::int64_t parseInteger(const char* text, std::int64_t fallback) {
    if (text == nullptr || *text == '\0') return fallback;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text, &end, 0);
    if (end == text || *end != '\0') {
        ADD_FAILURE() << "not an integer: '" << text << "'";
        return fallback;
    }
    return static_cast<std::int64_t>(value);
}

const Config& config() {
    static const Config c = [] {
        Config r;
        r.seed = static_cast<std::uint64_t>(
            parseInteger(std::getenv("FORESIGHT_PROPERTY_SEED"), static_cast<std::int64_t>(r.seed)));
        r.cases = parseInteger(std::getenv("FORESIGHT_PROPERTY_CASES"), r.cases);
        r.only = parseInteger(std::getenv("FORESIGHT_PROPERTY_CASE"), -1);
        return r;
    }();
    return c;
}

/// The seed of case `index` of a property: independent of the other cases.
std::uint64_t caseSeed(std::uint64_t seed, std::uint64_t property, std::int64_t index) {
    ftest::Random mix(seed ^ (property * 0xd1b54a32d192ed03ull));
    const std::uint64_t base = mix.next();
    ftest::Random perCase(base + static_cast<std::uint64_t>(index) * 0x9e3779b97f4a7c15ull);
    return perCase.next();
}

/// Runs `check(index, random)` for every case of a property; `check` returns an empty string on
/// success, else what failed. The first failures are reported with their reproduction line.
/// Known failures of the library (the default seed's case indices, see the property): they
/// are run and reported, expected to fail still (when one passes, the test says to remove it),
/// and not counted as new failures. Other seeds count every failure; the long run (the default
/// seed) counts every failure but these.
using KnownFailures = std::vector<std::int64_t>;

/// Past failures: the default seed's case indices that failed once and were fixed. Every run at
/// the default seed runs them too (after its own cases, when they lie beyond them), so that CI's
/// sample keeps the long run's findings fixed.
using PastFailures = std::vector<std::int64_t>;

void runCases(const char* test, std::uint64_t property,
              const std::function<std::string(std::int64_t, ftest::Random&)>& check, const KnownFailures& known = {},
              const PastFailures& past = {}) {
    const Config& c = config();
    const std::int64_t begin = c.only >= 0 ? c.only : 0;
    const std::int64_t end = c.only >= 0 ? c.only + 1 : c.cases;
    std::vector<std::int64_t> extra;
    if (c.only < 0 && c.seed == Config().seed)
        for (const std::int64_t i : past)
            if (i >= end) extra.push_back(i);
    const auto started = std::chrono::steady_clock::now();
    std::int64_t failures = 0;
    std::int64_t knownFailing = 0;
    const std::int64_t total = end - begin + static_cast<std::int64_t>(extra.size());
    for (std::int64_t n = 0; n < total; ++n) {
        const std::int64_t i = begin + n < end ? begin + n : extra[static_cast<std::size_t>(begin + n - end)];
        ftest::Random random(caseSeed(c.seed, property, i));
        const std::string why = check(i, random);
        const bool isKnown = c.seed == Config().seed && std::find(known.begin(), known.end(), i) != known.end();
        if (isKnown) {
            ++knownFailing;
            if (why.empty()) {
                ADD_FAILURE() << test << ": known failure case " << i << " now passes: remove it from the list";
            } else {
                std::printf("[ known    ] %s case %lld still fails: %s\n", test, static_cast<long long>(i),
                            why.c_str());
            }
            continue;
        }
        if (why.empty()) continue;
        // Every failure on one line (the long run's tally); the first ten in full as failures.
        std::printf("[ failing  ] %s case %lld: %.300s\n", test, static_cast<long long>(i), why.c_str());
        if (++failures <= 10) {
            ADD_FAILURE() << test << ": seed 0x" << std::hex << c.seed << std::dec << " case " << i
                          << " failed (run it alone: FORESIGHT_PROPERTY_SEED=0x" << std::hex << c.seed << std::dec
                          << " FORESIGHT_PROPERTY_CASE=" << i << " foresight_property_tests --gtest_filter='*" << test
                          << "*')\n  " << why;
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::printf("[ property ] %s: %lld cases from seed 0x%" PRIx64 ", %lld failing (and %lld known), %.2f s\n", test,
                static_cast<long long>(total), c.seed, static_cast<long long>(failures),
                static_cast<long long>(knownFailing), seconds);
    EXPECT_EQ(failures, 0) << test << ": failing cases (seed 0x" << std::hex << c.seed << ")";
}

// =============================================================================================
// Random geometry.

DVec3 randomUnit(ftest::Random& r) {
    for (;;) {
        const DVec3 v(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
        const double l2 = glm::dot(v, v);
        if (l2 > 1e-4 && l2 <= 1.0) return v / std::sqrt(l2);
    }
}

DQuat randomRotation(ftest::Random& r) { return ftest::dAxisAngle(randomUnit(r), r.uniform(0, 2 * kPi)); }

/// log-uniform in [lo, hi).
double logUniform(ftest::Random& r, double lo, double hi) { return std::exp(r.uniform(std::log(lo), std::log(hi))); }

/// One ulp of a float at magnitude `x` (the spacing of float positions there).
double floatUlp(double x) {
    const float f = static_cast<float>(std::fabs(x));
    return static_cast<double>(std::nextafter(f, std::numeric_limits<float>::infinity()) - f);
}

/// Gravity as the library takes it: each float component at its decimal value (projectile.h).
DVec3 decimalGravity(const Vec3& g) { return DVec3(ftest::decimal(g.x), ftest::decimal(g.y), ftest::decimal(g.z)); }

std::string str(const DVec3& v) { return ftest::describe(v); }

/// A closed triangle mesh in a StaticWorld, with its faces' outward planes in double (from the
/// same float vertices the world holds).
struct ClosedMesh {
    struct Face {
        DVec3 normal;  ///< outward, unit
        DVec3 point;   ///< a vertex
    };
    StaticWorld world;
    std::vector<Face> faces;
    DVec3 center{0.0};
    DVec3 halfExtents{0.0};  ///< box: its half sizes; icosphere: the radius thrice
    DQuat rotation = ftest::dquatWXYZ(1, 0, 0, 0);
    bool box = true;
    double inradius = 0.0;  ///< the largest ball about `center` inside every face
    double reach = 0.0;     ///< largest |coordinate| of a vertex

    /// Signed distance of p outside the mesh (the largest over the faces; < 0 inside: the mesh
    /// is convex, up to the rounding of its float vertices).
    double outside(const DVec3& p) const {
        double m = -std::numeric_limits<double>::infinity();
        for (const Face& f : faces) m = std::max(m, glm::dot(f.normal, p - f.point));
        return m;
    }
    std::string describe() const {
        std::ostringstream s;
        s.precision(9);
        s << (box ? "box half extents " : "icosphere radius ")
          << (box ? str(halfExtents) : std::to_string(halfExtents.x)) << " centre " << str(center) << " rotation "
          << ftest::describe(rotation);
        return s.str();
    }
};

/// The unit icosphere (the icosahedron subdivided once: 80 triangles), built once.
const std::vector<std::array<DVec3, 3>>& unitIcosphere() {
    static const std::vector<std::array<DVec3, 3>> triangles = [] {
        const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
        std::vector<DVec3> v;
        for (const double a : {-1.0, 1.0}) {
            for (const double b : {-phi, phi}) {
                v.push_back(DVec3(0, a, b));
                v.push_back(DVec3(a, b, 0));
                v.push_back(DVec3(b, 0, a));
            }
        }
        std::vector<std::array<DVec3, 3>> faces;
        // The icosahedron's faces: the vertex triples at mutual distance 2 (its edge).
        auto edge = [](const DVec3& p, const DVec3& q) { return std::fabs(glm::length(p - q) - 2.0) < 1e-9; };
        for (std::size_t i = 0; i < v.size(); ++i)
            for (std::size_t j = i + 1; j < v.size(); ++j)
                for (std::size_t k = j + 1; k < v.size(); ++k)
                    if (edge(v[i], v[j]) && edge(v[j], v[k]) && edge(v[i], v[k]))
                        faces.push_back({glm::normalize(v[i]), glm::normalize(v[j]), glm::normalize(v[k])});
        std::vector<std::array<DVec3, 3>> out;
        for (const auto& f : faces) {
            // Midpoints from (p + q) are the same doubles from either face (addition commutes),
            // so neighbouring triangles share their vertices bit for bit: the mesh is closed.
            const DVec3 ab = glm::normalize(f[0] + f[1]), bc = glm::normalize(f[1] + f[2]),
                        ca = glm::normalize(f[2] + f[0]);
            out.push_back({f[0], ab, ca});
            out.push_back({ab, f[1], bc});
            out.push_back({ca, bc, f[2]});
            out.push_back({ab, bc, ca});
        }
        return out;
    }();
    return triangles;
}

/// A random closed mesh: a box (half extents 0.2 .. 5 m) or an icosphere (radius 0.3 .. 5 m),
/// randomly rotated, its centre within 40 m of the origin. Returns false if the world refused
/// a triangle (reported by the caller).
bool buildClosedMesh(ftest::Random& r, ClosedMesh& mesh) {
    mesh.box = r.below(2) == 0;
    mesh.rotation = randomRotation(r);
    mesh.center = ftest::toD(ftest::toR(DVec3(r.uniform(-40, 40), r.uniform(-40, 40), r.uniform(-40, 40))));
    std::vector<std::array<DVec3, 3>> local;
    if (mesh.box) {
        mesh.halfExtents = DVec3(logUniform(r, 0.2, 5.0), logUniform(r, 0.2, 5.0), logUniform(r, 0.2, 5.0));
        DVec3 corners[8];
        for (int i = 0; i < 8; ++i) {
            corners[i] = DVec3((i & 1) ? mesh.halfExtents.x : -mesh.halfExtents.x,
                               (i & 2) ? mesh.halfExtents.y : -mesh.halfExtents.y,
                               (i & 4) ? mesh.halfExtents.z : -mesh.halfExtents.z);
        }
        // Each face as a cycle of corners (bit 0: +x, bit 1: +y, bit 2: +z), split in two.
        constexpr int kQuads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                      {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
        for (const auto& q : kQuads) {
            local.push_back({corners[q[0]], corners[q[1]], corners[q[2]]});
            local.push_back({corners[q[0]], corners[q[2]], corners[q[3]]});
        }
    } else {
        const double radius = logUniform(r, 0.3, 5.0);
        mesh.halfExtents = DVec3(radius);
        for (const auto& t : unitIcosphere()) local.push_back({t[0] * radius, t[1] * radius, t[2] * radius});
    }
    mesh.reach = 0.0;
    mesh.inradius = std::numeric_limits<double>::infinity();
    for (const auto& t : local) {
        DVec3 w[3];
        for (int k = 0; k < 3; ++k) {
            // The world's float vertex, and the reference's double copy of that same float.
            w[k] = ftest::toD(ftest::toR(mesh.center + ftest::dRotate(mesh.rotation, t[k])));
            mesh.reach = std::max({mesh.reach, std::fabs(w[k].x), std::fabs(w[k].y), std::fabs(w[k].z)});
        }
        if (mesh.world.add(foresight::Triangle{ftest::toR(w[0]), ftest::toR(w[1]), ftest::toR(w[2])}) != Status::Ok)
            return false;
        DVec3 n = glm::normalize(glm::cross(w[1] - w[0], w[2] - w[0]));
        if (glm::dot(n, w[0] - mesh.center) < 0) n = -n;
        mesh.faces.push_back({n, w[0]});
        mesh.inradius = std::min(mesh.inradius, glm::dot(n, w[0] - mesh.center));
    }
    return true;
}

/// A random point at least `clearance` inside the mesh (uniform in the box shrunk by it, or in
/// the icosphere's inscribed ball shrunk by it).
DVec3 pointInside(ftest::Random& r, const ClosedMesh& mesh, double clearance) {
    if (mesh.box) {
        const DVec3 room = mesh.halfExtents - DVec3(clearance);
        const DVec3 local(r.uniform(-room.x, room.x), r.uniform(-room.y, room.y), r.uniform(-room.z, room.z));
        return mesh.center + ftest::dRotate(mesh.rotation, local);
    }
    return mesh.center + randomUnit(r) * (std::cbrt(r.uniform(0, 1)) * (mesh.inradius - clearance));
}

/// Gravity: standard -Y (half the cases), or any direction at 2 .. 20 m/s^2.
Vec3 randomGravity(ftest::Random& r) {
    if (r.below(2) == 0) return Vec3(0.0f, -foresight::kDefaultGravity, 0.0f);
    return ftest::toF(randomUnit(r) * r.uniform(2.0, 20.0));
}

/// The engine profiles whose contacts are speculative (the sphere closes the gap and no more).
/// Godot 3 (GodotPhysics) penetrates first, by up to a step's motion, as the engine itself
/// does: a fast sphere there leaves a thin mesh in the real engine too, so it is not tested.
constexpr PhysicsEngine kSpeculativeEngines[] = {PhysicsEngine::Jolt, PhysicsEngine::PhysX, PhysicsEngine::Rapier,
                                                 PhysicsEngine::Bullet};

/// A projectile thrown inside a random closed mesh.
struct MeshThrow {
    ClosedMesh mesh;
    DVec3 start{0.0};
    Vec3 velocity{0.0f};
    float time = 1.0f;
    ProjectileSettings settings;

    std::string describe() const {
        std::ostringstream s;
        s.precision(9);
        s << "method " << static_cast<int>(settings.method);
        if (settings.method == ProjectileMethod::Engine) s << " engine " << static_cast<int>(settings.engine.engine);
        s << " radius " << settings.radius << "; " << mesh.describe() << "; start " << str(start) << " velocity "
          << str(ftest::toD(velocity)) << " time " << time << " step " << settings.step << " e " << settings.restitution
          << " mu " << settings.friction << " gravity " << str(ftest::toD(settings.gravity));
        return s.str();
    }
};

/// Prints a trajectory (when a single case runs, FORESIGHT_PROPERTY_CASE, to study it).
void printTrajectory(const MeshThrow& t, const std::vector<TrajectoryPoint>& points, const ProjectileResult& result) {
    if (config().only < 0) return;
    const std::size_t n = std::min(result.trajectorySize, points.size());
    for (std::size_t k = 0; k < n; ++k) {
        const DVec3 p = ftest::toD(points[k].position);
        std::printf("  %4zu t %.9g event %d p %s v %s n %s outside %.3g\n", k, static_cast<double>(points[k].time),
                    static_cast<int>(points[k].event), str(p).c_str(), str(ftest::toD(points[k].velocity)).c_str(),
                    str(ftest::toD(points[k].normal)).c_str(), t.mesh.outside(p));
    }
}

/// Builds a random throw. `allowEngine`: also ProjectileMethod::Engine (spheres only: an engine
/// body is a sphere).
bool randomMeshThrow(ftest::Random& r, bool allowEngine, MeshThrow& t) {
    if (!buildClosedMesh(r, t.mesh)) return false;
    const int method = r.below(allowEngine ? 3 : 2);
    t.settings = ProjectileSettings();
    t.settings.method = method == 0   ? ProjectileMethod::Exact
                        : method == 1 ? ProjectileMethod::Stepped
                                      : ProjectileMethod::Engine;
    const bool sphere = t.settings.method == ProjectileMethod::Engine || r.below(2) == 0;
    t.settings.radius = sphere ? static_cast<float>(r.uniform(0.01, 0.4) * t.mesh.inradius) : 0.0f;
    t.settings.restitution = static_cast<float>(r.uniform(0, 1));
    t.settings.friction = static_cast<float>(r.uniform(0, 1));
    t.settings.step = static_cast<float>(r.uniform(0.005, 0.05));
    t.settings.gravity = randomGravity(r);
    double maxSpeed = 300.0;  // a drop to a bullet-fast 300 m/s (many mesh sizes per step)
    t.time = static_cast<float>(r.uniform(0.2, 1.5));
    if (t.settings.method == ProjectileMethod::Engine) {
        t.settings.engine = foresight::engineProfile(kSpeculativeEngines[r.below(4)]);
        // An engine's discrete step finds a contact only within its contact distance of the
        // step's start: a sphere that moves further than that plus its radius in one step
        // passes a thin wall in the real engine too (no continuous collision), and the method
        // reproduces it. So these throws stay in the regime where the engine holds the
        // sphere: no step moves it more than half its radius plus the contact distance. The
        // speed never exceeds the start speed plus |g| t (restitution <= 1).
        t.settings.radius = static_cast<float>(r.uniform(0.2, 0.45) * t.mesh.inradius);
        const double reach =
            0.5 * (static_cast<double>(t.settings.radius) + static_cast<double>(t.settings.engine.contactDistance));
        maxSpeed = 0.5 * reach / static_cast<double>(t.settings.engine.timestep);
        const double g = glm::length(ftest::toD(t.settings.gravity));
        t.time = static_cast<float>(std::min(static_cast<double>(t.time), maxSpeed / g));
    }
    const double clearance = static_cast<double>(t.settings.radius) + 0.05 * t.mesh.inradius;
    t.start = ftest::toD(ftest::toR(pointInside(r, t.mesh, clearance)));
    t.velocity = ftest::toF(randomUnit(r) * logUniform(r, 0.1 * std::min(1.0, maxSpeed), maxSpeed));
    return true;
}

// =============================================================================================
// 1. No tunnelling through closed meshes.

// Known failures at the default seed: none in the long run (200 000 cases per property). A run
// of 10^6 cases per property finds 15, all the Exact method with a point (radius 0) in a box
// after 27 to 256 bounces: rattling into a corner or along an inside edge at a few mm/s, or
// meeting an edge at a grazing angle, the point ends within float rounding of a third face's
// plane, on its far side, and the next chord leaves through that face (0.05 mm to 1.7 m out).
// Not fixed yet. Their history, for whoever breaks this again: 323 failures in 200 000 before
// keepInFront, the grazing probe and the crease slide of the Exact method and the Bullet
// profile's slide cast; then 17 (Exact: a point and a ball rattling in a box's corner or along
// its edge, fixed by the crease handling of locateImpact and crossesRecentSurface; Engine: balls
// that sank into a facet beside the one they were pressed into, 6 Bullet, 7 PhysX and 2 Rapier,
// fixed by asking the world for the surfaces the sphere penetrates, CollisionWorld::findNear;
// the Engine method has none in 10^6). The article's Stepped loop leaves the mesh in 10 cases of
// 200 000 (38 of 10^6): counted, not failures (see the test).
const KnownFailures kKnownTunnelling = {209875, 256179, 270187, 326206, 513587, 543718, 608684, 610912,
                                        641628, 728160, 762573, 801124, 840045, 943538, 954793};
// The Engine method's past failures (see above), run in every run.
const PastFailures kPastTunnelling = {2524,  16395, 22081,  31200,  34592,  36289,  48581, 52535,
                                      68478, 80584, 107985, 119585, 163166, 167429, 193978};

TEST(Property, NoTunnelling) {
    std::vector<TrajectoryPoint> points(8192);
    double worst = -std::numeric_limits<double>::infinity();
    std::int64_t articleEscapes = 0;
    runCases(
        "NoTunnelling", 1,
        [&](std::int64_t, ftest::Random& r) -> std::string {
            MeshThrow t;
            if (!randomMeshThrow(r, true, t)) return "a mesh triangle was refused: " + t.mesh.describe();
            ProjectileResult result;
            const Status status = foresight::predictProjectile(ftest::toR(t.start), t.velocity, t.time, t.settings,
                                                               &t.mesh.world, points, result);
            if (status != Status::Ok) return "status " + std::to_string(static_cast<int>(status)) + ": " + t.describe();
            printTrajectory(t, points, result);
            // A centre may sit up to the world's surface tolerance behind a surface and still be on
            // it (StaticWorldSettings: 1e-5 m plus 4 ulps of the coordinates), and each output
            // coordinate is a float rounded by half an ulp (sqrt(3)/2 ulp as a distance): the
            // tolerance is 1e-5 m + 6 ulps at the mesh's reach.
            const double ulp = floatUlp(t.mesh.reach + 1.0);
            const double tolerance = 1e-5 + 6.0 * ulp;
            const std::size_t n = std::min(result.trajectorySize, points.size());
            for (std::size_t k = 0; k <= n; ++k) {
                const DVec3 p = ftest::toD(k < n ? points[k].position : result.position);
                const double out = t.mesh.outside(p);
                if (!(out <= tolerance) && t.settings.method == ProjectileMethod::Stepped) {
                    // The article's loop casts on from the hit point itself: in a corner that point
                    // may lie on the far side of the next face, and the loop goes through it. The
                    // Stepped method reproduces the article, errors included (Exact is the fix):
                    // counted, not a failure.
                    ++articleEscapes;
                    return {};
                }
                if (!(out <= tolerance)) {
                    std::ostringstream s;
                    s.precision(9);
                    s << (k < n ? "point " + std::to_string(k) : std::string("end")) << " at t "
                      << (k < n ? points[k].time : result.time) << " is " << out << " m outside (tolerance "
                      << tolerance << "), bounces " << result.bounces << "; " << t.describe() << "; at " << str(p);
                    return s.str();
                }
                worst = std::max(worst, out / tolerance);
            }
            return {};
        },
        kKnownTunnelling, kPastTunnelling);
    // How close the passing cases come to the tolerance (surfaces are touched: near 0 or above).
    std::printf(
        "[ property ] NoTunnelling: largest distance outside / tolerance %.3g; the article's Stepped loop "
        "left the mesh in %lld cases (its own error, reproduced)\n",
        worst, static_cast<long long>(articleEscapes));
}

// =============================================================================================
// 2. Energy never increases (Exact and Stepped). ProjectileMethod::Engine is left out: an
// engine's position correction pushes a penetrating body out without charging for it (the
// engines do so, and the method reproduces them), which is not an energy law.

double energy(const DVec3& p, const DVec3& v, const DVec3& g) { return 0.5 * glm::dot(v, v) - glm::dot(g, p); }

TEST(Property, EnergyNeverIncreases) {
    std::vector<TrajectoryPoint> points(8192);
    double worst = -std::numeric_limits<double>::infinity();
    runCases("EnergyNeverIncreases", 2, [&](std::int64_t, ftest::Random& r) -> std::string {
        MeshThrow t;
        if (!randomMeshThrow(r, false, t)) return "a mesh triangle was refused: " + t.mesh.describe();
        ProjectileResult result;
        const Status status = foresight::predictProjectile(ftest::toR(t.start), t.velocity, t.time, t.settings,
                                                           &t.mesh.world, points, result);
        if (status != Status::Ok) return "status " + std::to_string(static_cast<int>(status)) + ": " + t.describe();
        const DVec3 g = decimalGravity(t.settings.gravity);
        const DVec3 v0 = ftest::toD(t.velocity);
        // The start is exact (float inputs). A recorded point is the double state rounded to
        // floats: its position by half an ulp per axis (|dp| <= sqrt(3)/2 ulp at the mesh's
        // reach), which moves g.p by up to |g| |dp|; its velocity by 2^-24 relative, which moves
        // |v|^2/2 by up to |v|^2 2^-24. A body resting or sliding on a face may also sit up to
        // the surface tolerance (1e-5 m plus 4 ulps, StaticWorldSettings) behind it, against
        // gravity at worst. Allowing 2 ulps for the rounding and 4 for the tolerance, and
        // doubling the velocity term (speeds never exceed the start's: energy does not grow):
        const double ulp = floatUlp(t.mesh.reach + 1.0);
        const double tolerance = glm::length(g) * (1e-5 + 6.0 * ulp) + 2.0 * glm::dot(v0, v0) * 0x1.0p-24 + 1e-12;
        const double e0 = energy(t.start, v0, g);
        const std::size_t n = std::min(result.trajectorySize, points.size());
        for (std::size_t k = 0; k <= n; ++k) {
            const DVec3 p = ftest::toD(k < n ? points[k].position : result.position);
            const DVec3 v = ftest::toD(k < n ? points[k].velocity : result.velocity);
            const double gain = energy(p, v, g) - e0;
            if (k > 0) worst = std::max(worst, gain / tolerance);
            if (!(gain <= tolerance)) {
                std::ostringstream s;
                s.precision(9);
                s << (k < n ? "point " + std::to_string(k) : std::string("end")) << " at t "
                  << (k < n ? points[k].time : result.time) << " has energy " << gain << " J/kg above the start " << e0
                  << " (tolerance " << tolerance << ") at " << str(p) << " v " << str(v) << "; bounces "
                  << result.bounces << "; " << t.describe();
                return s.str();
            }
        }
        return {};
    });
    std::printf("[ property ] EnergyNeverIncreases: largest energy gain / tolerance %.3g\n", worst);
}

// =============================================================================================
// 3. Determinism at scale: order, fresh worlds and threads.

/// A random world of every shape kind about the origin: a floor plane, spheres, rotated boxes
/// (some rounded), triangles, some with their own materials.
void buildRandomWorld(ftest::Random& r, StaticWorld& world) {
    const Vec3 up = ftest::toF(glm::normalize(DVec3(r.uniform(-0.3, 0.3), 1.0, r.uniform(-0.3, 0.3))));
    EXPECT_EQ(world.add(foresight::Plane{up, static_cast<Real>(r.uniform(-2, 0))}), Status::Ok);
    const int shapes = 2 + r.below(6);
    for (int i = 0; i < shapes; ++i) {
        const DVec3 c(r.uniform(-8, 8), r.uniform(0, 4), r.uniform(-8, 8));
        foresight::SurfaceMaterial material;
        if (r.below(3) == 0) material = {static_cast<float>(r.uniform(0, 1)), static_cast<float>(r.uniform(0, 1))};
        switch (r.below(3)) {
            case 0:
                EXPECT_EQ(world.add(foresight::Sphere{ftest::toR(c), static_cast<float>(r.uniform(0.2, 2))}, material),
                          Status::Ok);
                break;
            case 1: {
                const Vec3 h(static_cast<float>(r.uniform(0.2, 2)), static_cast<float>(r.uniform(0.2, 2)),
                             static_cast<float>(r.uniform(0.2, 2)));
                foresight::OrientedBox box{ftest::toR(c), h, ftest::toF(randomRotation(r))};
                if (r.below(2) == 0)
                    box.rounding = 0.5f * std::min({h.x, h.y, h.z}) * static_cast<float>(r.uniform(0, 1));
                EXPECT_EQ(world.add(box, material), Status::Ok);
                break;
            }
            default: {
                const foresight::Triangle t{ftest::toR(c + randomUnit(r) * 3.0), ftest::toR(c + randomUnit(r) * 3.0),
                                            ftest::toR(c + randomUnit(r) * 3.0)};
                if (foresight::validateTriangle(t) == Status::Ok) {
                    EXPECT_EQ(world.add(t, material), Status::Ok);
                }
                break;
            }
        }
    }
}

/// One random prediction: every method, every engine profile, points and spheres.
struct Throw {
    foresight::RVec3 start{0};
    Vec3 velocity{0.0f};
    float time = 1.0f;
    ProjectileSettings settings;
};

Throw randomThrow(ftest::Random& r) {
    Throw t;
    const int method = r.below(3);
    t.settings.method = method == 0   ? ProjectileMethod::Exact
                        : method == 1 ? ProjectileMethod::Stepped
                                      : ProjectileMethod::Engine;
    if (t.settings.method == ProjectileMethod::Engine) {
        t.settings.engine = foresight::engineProfile(static_cast<PhysicsEngine>(1 + r.below(7)));
    }
    t.settings.radius = r.below(3) == 0 ? 0.0f : static_cast<float>(r.uniform(0.02, 0.5));
    t.settings.restitution = static_cast<float>(r.uniform(0, 1));
    t.settings.friction = static_cast<float>(r.uniform(0, 1));
    t.settings.step = static_cast<float>(r.uniform(0.005, 0.05));
    t.settings.gravity = randomGravity(r);
    t.start = ftest::toR(DVec3(r.uniform(-6, 6), r.uniform(0.5, 6), r.uniform(-6, 6)));
    t.velocity = ftest::toF(randomUnit(r) * logUniform(r, 0.1, 60.0));
    t.time = static_cast<float>(r.uniform(0.1, 2.5));
    return t;
}

/// FNV-1a of everything a prediction returns: status, result and every trajectory point's raw
/// bytes (the same fields determinism_test.cpp hashes).
std::uint64_t hashThrow(const Throw& t, const StaticWorld& world, std::vector<TrajectoryPoint>& points) {
    ftest::Hasher h;
    ProjectileResult result;
    const Status status = foresight::predictProjectile(t.start, t.velocity, t.time, t.settings, &world, points, result);
    h.add(static_cast<std::uint64_t>(status));
    h.add(result);
    for (std::size_t k = 0; k < std::min(result.trajectorySize, points.size()); ++k) {
        h.add(points[k].time);
        h.add(static_cast<std::uint64_t>(points[k].event));
        h.add(points[k].position);
        h.add(points[k].velocity);
        h.add(points[k].normal);
    }
    return h.value();
}

TEST(Property, Determinism) {
    std::vector<TrajectoryPoint> points(4096);
    std::vector<TrajectoryPoint> otherPoints(4096);
    ftest::Hasher all;
    runCases("Determinism", 3, [&](std::int64_t index, ftest::Random& r) -> std::string {
        const std::uint64_t worldSeed = r.next();
        const Throw a = randomThrow(r);
        const Throw b = randomThrow(r);
        // Each alone in a fresh world (built from the same seed).
        std::uint64_t freshA = 0, freshB = 0;
        {
            StaticWorld world;
            ftest::Random wr(worldSeed);
            buildRandomWorld(wr, world);
            freshA = hashThrow(a, world, points);
        }
        {
            StaticWorld world;
            ftest::Random wr(worldSeed);
            buildRandomWorld(wr, world);
            freshB = hashThrow(b, world, points);
        }
        // A then B, and B then A, in one shared world; then both at once on two threads (every
        // 16th case: a thread start costs more than a prediction).
        StaticWorld shared;
        ftest::Random wr(worldSeed);
        buildRandomWorld(wr, shared);
        const std::uint64_t ab[2] = {hashThrow(a, shared, points), hashThrow(b, shared, points)};
        const std::uint64_t ba1 = hashThrow(b, shared, points);
        const std::uint64_t ba0 = hashThrow(a, shared, points);
        std::uint64_t threadA = freshA, threadB = freshB;
        if (index % 16 == 0) {
            std::thread worker([&] { threadB = hashThrow(b, shared, otherPoints); });
            threadA = hashThrow(a, shared, points);
            worker.join();
        }
        all.add(freshA);
        all.add(freshB);
        std::ostringstream s;
        if (ab[0] != freshA || ba0 != freshA || threadA != freshA)
            s << "A: fresh " << freshA << ", first of AB " << ab[0] << ", second of BA " << ba0 << ", thread "
              << threadA;
        if (ab[1] != freshB || ba1 != freshB || threadB != freshB)
            s << " B: fresh " << freshB << ", second of AB " << ab[1] << ", first of BA " << ba1 << ", thread "
              << threadB;
        if (!s.str().empty()) {
            s << " (A method " << static_cast<int>(a.settings.method) << ", B method "
              << static_cast<int>(b.settings.method) << ")";
        }
        return s.str();
    });
    // For information, as determinism_test.cpp prints its scenario hash: it may differ between
    // compilers and platforms, so it is compared with nothing stored.
    std::printf("[ property ] Determinism: hash of every case's trajectories %016" PRIx64 "\n", all.value());
    ::testing::Test::RecordProperty("property_hash", std::to_string(all.value()));
}

// =============================================================================================
// 4. Every aim solution flies into its target; no crossing root of the constraint is missed.

DVec3 targetAt(const AimTarget& target, double t) {
    return ftest::toD(target.position) + ftest::toD(target.velocity) * t +
           ftest::toD(target.acceleration) * (0.5 * t * t);
}

/// The direction against gravity the constraints measure heights and vertical speeds along
/// (+Y with zero gravity, aim.h).
DVec3 upOf(const AimShot& shot) {
    const DVec3 g = decimalGravity(shot.gravity);
    return glm::length(g) > 0.0 ? -glm::normalize(g) : DVec3(0, 1, 0);
}

const char* constraintName(AimConstraint c) {
    switch (c) {
        case AimConstraint::Speed:
            return "Speed";
        case AimConstraint::HorizontalSpeed:
            return "HorizontalSpeed";
        case AimConstraint::ApexAboveStart:
            return "ApexAboveStart";
        case AimConstraint::ApexAboveTarget:
            return "ApexAboveTarget";
    }
    return "?";
}

std::string describeAim(const AimShot& shot, const AimTarget& target) {
    std::ostringstream s;
    s.precision(9);
    s << constraintName(shot.constraint) << " from " << str(ftest::toD(shot.from)) << " speed " << shot.speed
      << " apex " << shot.apexHeight << " gravity " << str(ftest::toD(shot.gravity)) << " maxTime " << shot.maxTime
      << "; target " << str(ftest::toD(target.position)) << " v " << str(ftest::toD(target.velocity)) << " a "
      << str(ftest::toD(target.acceleration));
    return s.str();
}

/// The function whose roots on (0, maxTime] are the constraint's solutions, and whether a root
/// at t is admissible, clear of the boundaries of the admissible set (where the scan cannot tell
/// a root from a near miss). d(t) = target(t) - from - g t^2 / 2; up against gravity.
/// - HorizontalSpeed: |d(t) across up| - s t.
/// - ApexAboveStart: the vertical speed is sqrt(2 |g| h): d(t).up - sqrt(2 |g| h) t, meeting at
///   or after the apex (|g| t >= the vertical speed).
/// - ApexAboveTarget: the apex is h above the hit: (d.up / t)^2 = 2 |g| (h + (target - from).up)
///   with d.up >= 0 and |g| t^2 >= d.up (at or after the apex): d.up - t sqrt(2 |g| H).
struct AimScan {
    const AimShot& shot;
    const AimTarget& target;
    DVec3 up, g, from;
    double G;

    AimScan(const AimShot& s, const AimTarget& t)
        : shot(s), target(t), up(upOf(s)), g(decimalGravity(s.gravity)), from(ftest::toD(s.from)), G(glm::length(g)) {}

    DVec3 d(double t) const { return targetAt(target, t) - from - 0.5 * g * t * t; }
    double height(double t) const {
        return static_cast<double>(shot.apexHeight) + glm::dot(targetAt(target, t) - from, up);
    }
    double f(double t) const {
        const DVec3 dt = d(t);
        const double vertical = glm::dot(dt, up);
        switch (shot.constraint) {
            case AimConstraint::HorizontalSpeed:
                return glm::length(dt - vertical * up) - static_cast<double>(shot.speed) * t;
            case AimConstraint::ApexAboveStart:
                return vertical - std::sqrt(2.0 * G * static_cast<double>(shot.apexHeight)) * t;
            case AimConstraint::ApexAboveTarget:
                return vertical - t * std::sqrt(2.0 * G * std::max(0.0, height(t)));
            case AimConstraint::Speed:
                break;
        }
        return glm::length(dt) - static_cast<double>(shot.speed) * t;
    }
    /// A scale of f's terms at t (for relative margins).
    double scale(double t) const {
        return glm::length(d(t)) + (static_cast<double>(std::fabs(shot.speed)) + G * t) * t + 1.0;
    }
    bool admissible(double t) const {
        const double margin = 1e-6 * scale(t);
        const double vertical = glm::dot(d(t), up);
        switch (shot.constraint) {
            case AimConstraint::ApexAboveStart:
                return G * t * t - vertical > margin;
            case AimConstraint::ApexAboveTarget:
                return height(t) > 1e-6 * (std::fabs(height(t)) + 1.0) && vertical > margin &&
                       G * t * t - vertical > margin;
            default:
                return true;
        }
    }
};

void randomAim(ftest::Random& r, AimShot& shot, AimTarget& target) {
    shot = AimShot();
    target = AimTarget();
    shot.constraint = static_cast<AimConstraint>(r.below(4));
    const bool apex =
        shot.constraint == AimConstraint::ApexAboveStart || shot.constraint == AimConstraint::ApexAboveTarget;
    // Gravity: standard, any direction, or (straight-line shots, not the apex constraints) none.
    shot.gravity = !apex && r.below(8) == 0 ? Vec3(0.0f) : randomGravity(r);
    shot.from = ftest::toR(DVec3(r.uniform(-50, 50), r.uniform(-50, 50), r.uniform(-50, 50)));
    target.position =
        ftest::toR(ftest::toD(shot.from) + DVec3(r.uniform(-60, 60), r.uniform(-20, 40), r.uniform(-60, 60)));
    target.velocity = ftest::toF(DVec3(r.uniform(-15, 15), r.uniform(-8, 8), r.uniform(-15, 15)));
    if (r.below(4) != 0) target.acceleration = ftest::toF(DVec3(r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-5, 5)));
    shot.speed = static_cast<float>(r.uniform(1, 60));
    shot.apexHeight = static_cast<float>(r.uniform(-2, 40));
    shot.maxTime = static_cast<float>(r.uniform(2, 12));
}

TEST(Property, AimSolutionsHit) {
    std::int64_t solutions = 0, scanned = 0;
    runCases("AimSolutionsHit", 4, [&](std::int64_t, ftest::Random& r) -> std::string {
        AimShot shot;
        AimTarget target;
        randomAim(r, shot, target);
        std::array<FiringSolution, foresight::kMaxFiringSolutions> storage{};
        std::size_t count = 0;
        const Status status = foresight::aimProjectile(shot, target, storage, count);
        std::ostringstream s;
        s.precision(9);
        if (status != Status::Ok) {
            s << "status " << static_cast<int>(status) << "; " << describeAim(shot, target);
            return s.str();
        }
        solutions += static_cast<std::int64_t>(count);
        const AimScan scan(shot, target);
        const double G = scan.G;
        float previous = 0.0f;
        for (std::size_t i = 0; i < count; ++i) {
            const FiringSolution& sol = storage[i];
            const double t = ftest::decimal(sol.time);
            const DVec3 v = ftest::toD(sol.velocity);
            if (!(sol.time > previous && sol.time <= shot.maxTime))
                s << "time " << sol.time << " not in (previous, maxTime]; ";
            previous = sol.time;
            // Flown by the projectile model the aim assumes: predictProjectile, Exact, no world.
            ProjectileSettings settings;
            settings.gravity = shot.gravity;
            ProjectileResult flown;
            const Status fly =
                foresight::predictProjectile(shot.from, sol.velocity, sol.time, settings, nullptr, {}, flown);
            // 1e-3 m is aim.h's contract (aim_test.cpp holds it too). Float velocity and time
            // round to 6e-8 relative, about 2e-5 m over these distances (under 400 m) and float
            // positions to 4e-6 m at 100 m: a fiftieth of the tolerance.
            const double miss = glm::length(ftest::toD(flown.position) - targetAt(target, t));
            if (fly != Status::Ok || !(miss <= 1e-3))
                s << "solution " << i << " at t " << sol.time << " misses by " << miss << "; ";
            if (!(glm::length(ftest::toD(sol.hit) - targetAt(target, t)) <= 1e-3))
                s << "solution " << i << " reports its hit " << str(ftest::toD(sol.hit)) << " off the target; ";
            // The constraint, from the float velocity: its components round by 6e-8 of |v|; a
            // few of those and of the double-to-float time give 1e-5 of |v| (at least 1 m/s).
            const double vertical = glm::dot(v, scan.up);
            const double vTol = 1e-5 * std::max(1.0, glm::length(v));
            double expected = 0.0, got = 0.0;
            switch (shot.constraint) {
                case AimConstraint::Speed:
                    got = glm::length(v), expected = static_cast<double>(shot.speed);
                    break;
                case AimConstraint::HorizontalSpeed:
                    got = glm::length(v - vertical * scan.up), expected = static_cast<double>(shot.speed);
                    break;
                case AimConstraint::ApexAboveStart:
                case AimConstraint::ApexAboveTarget: {
                    // The apex's height above the start, v.up^2 / 2|g|, against h (ApexAboveStart)
                    // or h above the target at the hit (ApexAboveTarget). Heights, not vertical
                    // speeds: near a zero apex the speed is sqrt(2 |g| H), infinitely sensitive to H.
                    // The vertical speed's rounding (vTol) moves the height by v.up vTol / |g|; the
                    // float hit time (6e-8 relative) moves the target's height by its vertical speed
                    // times that, allowed as 1e-6 of t |v_target(t)|; 1e-6 m for the double sums.
                    got = vertical * vertical / (2.0 * G);
                    const bool start = shot.constraint == AimConstraint::ApexAboveStart;
                    expected = start ? static_cast<double>(shot.apexHeight) : scan.height(t);
                    const double targetSpeed =
                        glm::length(ftest::toD(target.velocity) + ftest::toD(target.acceleration) * t);
                    const double hTol = std::fabs(vertical) * vTol / G + (start ? 0.0 : 1e-6 * t * targetSpeed) +
                                        1e-6 * (1.0 + std::fabs(expected));
                    if (!(std::fabs(got - expected) <= hTol))
                        s << "solution " << i << " has its apex " << got << " m up, not " << expected << "; ";
                    got = expected;  // checked
                    break;
                }
            }
            if (!(std::fabs(got - expected) <= vTol))
                s << "solution " << i << " breaks its constraint: " << got << " vs " << expected << "; ";
            // The apex constraints meet the target at or after the apex (descending): the
            // vertical speed is spent by then, within the same rounding.
            const bool apex =
                shot.constraint == AimConstraint::ApexAboveStart || shot.constraint == AimConstraint::ApexAboveTarget;
            if (apex && !(vertical - G * t <= vTol)) s << "solution " << i << " still rises at the hit; ";
            if (!(std::isfinite(sol.elevation) && std::fabs(sol.elevation) <= 1.5707964f))
                s << "solution " << i << " elevation " << sol.elevation << "; ";
        }
        // The scan (aim_test.cpp scans Speed): sign changes of f on a 2000-sample grid, each
        // bisected to double; every admissible one must be a solution. The solver's time is a
        // float (6e-8 relative) and near-double roots lose more: 1e-5 relative, as aim_test.cpp.
        if (shot.constraint != AimConstraint::Speed &&
            !((shot.constraint == AimConstraint::ApexAboveStart || shot.constraint == AimConstraint::ApexAboveTarget) &&
              shot.apexHeight < 0.0f)) {
            constexpr int kSamples = 2000;
            const double tMax = static_cast<double>(shot.maxTime);
            double t0 = tMax * 1e-6, f0 = scan.f(t0);
            for (int k = 1; k <= kSamples; ++k) {
                const double t1 = tMax * k / kSamples, f1 = scan.f(t1);
                if ((f0 < 0) != (f1 < 0)) {
                    double lo = t0, hi = t1, flo = f0;
                    for (int i = 0; i < 80; ++i) {
                        const double mid = 0.5 * (lo + hi), fm = scan.f(mid);
                        if ((fm < 0) == (flo < 0))
                            lo = mid, flo = fm;
                        else
                            hi = mid;
                    }
                    const double root = 0.5 * (lo + hi);
                    ++scanned;
                    bool found = false;
                    for (std::size_t i = 0; i < count; ++i)
                        found = found ||
                                std::fabs(static_cast<double>(storage[i].time) - root) <= 1e-5 * std::max(1.0, root);
                    // A root at the window's end may fall on either side of maxTime.
                    if (!found && scan.admissible(root) && root < tMax * (1 - 1e-6)) {
                        s << "the scan's root t " << root << " (f " << scan.f(root) << ") is not a solution; solver:";
                        for (std::size_t i = 0; i < count; ++i) s << " " << storage[i].time;
                        s << "; ";
                    }
                }
                t0 = t1, f0 = f1;
            }
        }
        if (!s.str().empty()) s << describeAim(shot, target);
        return s.str();
    });
    std::printf("[ property ] AimSolutionsHit: %lld solutions flown, %lld scan roots\n",
                static_cast<long long>(solutions), static_cast<long long>(scanned));
    if (config().only < 0) {
        EXPECT_GT(solutions, config().cases / 2);  // the problems do have solutions
    }
}

// =============================================================================================
// 5. Dead reckoning: two half steps equal one step.
//
// dead_reckoning.h: each of the nine models is the flow of an autonomous differential equation
// whose whole state (position, velocity in the input's axes, orientation) is the output, so
// extrapolating t1 then t2 is extrapolating t1 + t2 for all nine; the closed forms (R1, R2 for
// the rotating body models) compose exactly in theory. None is left out: the header promises
// composition for every model, and nothing here needs a model that does not compose.

TEST(Property, DeadReckoningHalfSteps) {
    double worst = 0.0;
    runCases("DeadReckoningHalfSteps", 5, [&](std::int64_t, ftest::Random& r) -> std::string {
        DeadReckoningState s;
        s.algorithm = static_cast<DeadReckoningAlgorithm>(1 + r.below(foresight::kDeadReckoningAlgorithmCount));
        s.position = ftest::toR(DVec3(r.uniform(-1000, 1000), r.uniform(-1000, 1000), r.uniform(-1000, 1000)));
        s.velocity = ftest::toF(randomUnit(r) * r.uniform(0, 80));
        s.acceleration = ftest::toF(randomUnit(r) * r.uniform(0, 15));
        s.orientation = ftest::toF(randomRotation(r));
        // Angular speeds from none through the series' range (|w| t near 1e-4) to many turns.
        const int spin = r.below(4);
        s.angularVelocity = spin == 0 ? Vec3(0.0f) : ftest::toF(randomUnit(r) * logUniform(r, 1e-6, 4.0));
        const float time = static_cast<float>(r.uniform(0, 6));
        DeadReckoningResult whole, half, twice;
        if (foresight::predictDeadReckoning(s, time, whole) != Status::Ok ||
            foresight::predictDeadReckoning(s, 0.5f * time, half) != Status::Ok)
            return "refused";
        DeadReckoningState next = s;
        next.position = half.position;
        next.velocity = half.velocity;
        next.orientation = half.orientation;
        if (foresight::predictDeadReckoning(next, 0.5f * time, twice) != Status::Ok) return "refused the half step";
        // The intermediate state is floats: its position rounds by half an ulp per axis
        // (sqrt(3)/2 ulp), and both results by as much again; its velocity by 2^-24 of |v|, which
        // over t/2 moves the end by that much of the second half's path; its orientation by
        // about 2^-24 per component, a turn of up to 2.4e-7 rad of the second half's
        // displacement. Double those relative terms (the velocity grows as v + a t, and R1 and
        // R2 carry the turn of the body models), and 3 ulps for the positions:
        const double path =
            (static_cast<double>(glm::length(s.velocity)) + static_cast<double>(glm::length(s.acceleration)) * time) *
            time;
        const double reach = std::max({std::fabs(ftest::toD(whole.position).x), std::fabs(ftest::toD(whole.position).y),
                                       std::fabs(ftest::toD(whole.position).z), std::fabs(ftest::toD(half.position).x),
                                       std::fabs(ftest::toD(half.position).y), std::fabs(ftest::toD(half.position).z)});
        const double positionTol = 3.0 * floatUlp(reach) + 2.0 * (0x1.0p-24 + 2.4e-7) * path;
        // Velocity: v + a t in its axes (world or body, no turn in either): three roundings of
        // 2^-24 of its size; the body models' axes turn with the rounded orientation (2.4e-7).
        const double speed =
            static_cast<double>(glm::length(s.velocity)) + static_cast<double>(glm::length(s.acceleration)) * time;
        const double velocityTol = (3.0 * 0x1.0p-24 + 2.4e-7) * speed + 1e-12;
        // Orientation: three float roundings of a unit quaternion (6e-8 per component) and the
        // products: 1e-6, as dead_reckoning_test.cpp.
        std::ostringstream out;
        out.precision(9);
        worst = std::max(worst, glm::length(ftest::toD(twice.position) - ftest::toD(whole.position)) / positionTol);
        const auto p = ftest::vecNear(twice.position, whole.position, positionTol);
        const auto v = ftest::vecNear(twice.velocity, whole.velocity, velocityTol);
        const auto q = ftest::quatNear(twice.orientation, whole.orientation, 1e-6);
        if (!p) out << "position " << p.message() << "; ";
        if (!v) out << "velocity " << v.message() << "; ";
        if (!q) out << "orientation " << q.message() << "; ";
        if (!out.str().empty()) {
            out << foresight::deadReckoningAlgorithmName(s.algorithm) << " t " << time << " p "
                << str(ftest::toD(s.position)) << " v " << str(ftest::toD(s.velocity)) << " a "
                << str(ftest::toD(s.acceleration)) << " q " << ftest::describe(ftest::toD(s.orientation)) << " w "
                << str(ftest::toD(s.angularVelocity));
        }
        return out.str();
    });
    std::printf("[ property ] DeadReckoningHalfSteps: largest position difference / tolerance %.3g\n", worst);
}

}  // namespace
