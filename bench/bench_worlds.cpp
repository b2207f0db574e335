/// bench_worlds.cpp: the collision worlds' speed. A benchmark, not a test:
/// compare ratios measured in one run (scripts/bench.sh --worlds prints them).
///
/// 1. Segment casts on a mesh of about one million triangles (makeBigMesh):
///      BM_Cast/Embree          foresight::EmbreeWorld::castSegment, radius 0
///      BM_Cast/EmbreeBatch     foresight::EmbreeWorld::castSegments, all 4096 segments in one
///                              call (groups of 16 whose confirmation reads overlap); checked
///                              before timing to give castSegment's answers bit for bit
///      BM_Cast/BulletRayTest   btCollisionWorld::rayTest + ClosestRayResultCallback on one
///                              static btBvhTriangleMeshShape (quantized BVH): "Bullet's ray tests"
///      BM_Cast/BulletWorld     foresight::BulletWorld::castSegment over that same Bullet world
///      For information (why EmbreeWorld is where it is), plain rtcIntersect1 on the same mesh:
///      BM_Cast/EmbreeNative    native triangles (RTC_GEOMETRY_TYPE_TRIANGLE, Embree's own float
///                              test), EmbreeWorld's scene flags (robust, high build quality)
///      BM_Cast/EmbreeNativeDefault   the same with Embree's default flags
///      BM_Cast/EmbreeUserFloat user geometry as EmbreeWorld builds it (one primitive per triangle,
///                              the same padded bounds and flags) whose callback is a plain float
///                              ray-triangle test: Embree's user-geometry traversal without
///                              EmbreeWorld's exact double tests (counter: candidates per cast)
///      BM_Sweep/Embree, BM_Sweep/BulletConvexSweep, BM_Sweep/BulletWorld
///                              for information: swept spheres of radius 0.1 m along the same
///                              segments raised by 0.2 m (so that none starts on the ground;
///                              a few start within 0.1 m of a wall, where Bullet reports a hit at
///                              0 and EmbreeWorld, moving away, none)
///    Targets: BM_Cast/Embree within 1.2x the time per cast of BM_Cast/EmbreeNative (what the
///    exact confirmation may cost over a bare float cast), and BM_Cast/EmbreeBatch at least 5x
///    the casts per second of BM_Cast/BulletRayTest (BM_Cast/Embree too, the older target).
///    Measured figures, the command and a note on this shared machine's noise: docs/results.md.
///    Every world gets the same 4096 segments; before timing, the ray worlds must agree on every
///    segment (hit or miss, and the hit's distance along the segment within 1e-4 m: Bullet's
///    float ray-triangle test is off by up to about 9e-5 m at 350 m from the origin), or the
///    program stops with a message. A hit within 1e-4 m of a segment's end that the other world
///    misses would count as a graze of the end, not a disagreement (there are none).
/// 2. Projectile predictions on the demo level (tools/demo_level/demo_level.h; 3 s at 50 Hz, the default
///    ProjectileSettings, Exact and Stepped): BM_DemoLevel/<world>/<method> through EmbreeWorld,
///    BulletWorld (its own btCollisionWorld holding the level as one btBvhTriangleMeshShape),
///    a StaticWorld holding the same triangles (brute force, for contrast) and a CallbackWorld
///    that forwards castSegment to the EmbreeWorld and answers nothing else (a game's own ray
///    cast: the predictors cannot clear many steps with one query there).
///    Targets, time ratios in one run: Exact at most 0.5x Stepped through EmbreeWorld and
///    StaticWorld, at most 1.0x through the callback world. Built only when the target
///    foresight_demo_level (tools/) exists.
/// 3. Engine-matched throws on the demo level against stepping a real engine: what a game does
///    when it clones its physics scene to preview a throw. 64 throws of a 0.1 m sphere for 3 s
///    at 60 Hz (restitution 0.5, friction 0.3), the native Bullet profile with its triangle-mesh
///    rules (EngineProfile::triangleMesh):
///      BM_EngineThrow/Predict/Embree   ProjectileMethod::Engine (engineProfile(Bullet)) through
///                                      EmbreeWorld
///      BM_EngineThrow/Predict/Bullet   the same through BulletWorld (Bullet's own BVH answers the
///                                      casts)
///      BM_EngineThrow/BulletStep       a btDiscreteDynamicsWorld that already holds the level (one
///                                      static btBvhTriangleMeshShape, margin 0) gets a btRigidBody
///                                      sphere with the throw's state and is stepped 180 times
///                                      (stepSimulation(1/60, 0)); the body is removed afterwards.
///                                      The world is built once, outside the timing: the cheapest
///                                      way to step the real engine.
///    Target: BM_EngineThrow/Predict/Embree at least 20x the throws per second of
///    BM_EngineThrow/BulletStep. Before timing, both sides run every throw once and the agreement
///    of the end positions is reported on stderr (for information: near the floor tiles' internal
///    edges Bullet adds contacts from the neighbouring triangles with tilted normals, which no
///    cast against the surface sees). A second line measures that on the level with its floor as
///    two triangles: how far Bullet's own ends move with the triangulation alone, and the
///    prediction against that world. With FORESIGHT_BENCH_ENGINE_DIVERGENCE=1 set, each throw
///    that ends more than 2 cm from Bullet's also prints the step where it first left Bullet's.
///
/// 4. The same targets timed in turns within one benchmark each (timeInTurns: every part once per
///    iteration, the order rotated, so that the parts share the load; the counters are the ratios
///    of their total times, and repetitions give their median and spread):
///      BM_Turns/Cast                 castSegment/native, rayTest/castSegment, rayTest/castSegments
///      BM_Turns/DemoLevel/<world>    exact/stepped through Embree, Static and Callback worlds
///      BM_Turns/EngineThrow          bulletStep/predict
///    Each part starts after another that read other data (cold caches for a million-triangle
///    mesh), where the separate benchmarks above keep their own data warm.
///
/// items_per_second is casts (or predictions) per second. Everything runs on one thread: Embree
/// and Bullet answer each query on the calling thread. The BVH builds happen once, before the
/// first benchmark that needs them, and are reported on stderr ("foresight_bench_worlds: ...")
/// with wall and CPU time (Embree builds with every core; Bullet with one) and the growth of
/// the resident memory (approximate: the allocator may reuse freed pages).

#include "bench_throws.h"
#include "bench_turns.h"

#include <foresight/bullet_world.h>
#include <foresight/embree_world.h>
#include <foresight/foresight.h>

#if FORESIGHT_BENCH_DEMO_LEVEL
#include "demo_level.h"
#endif

#include <benchmark/benchmark.h>
#include <btBulletCollisionCommon.h>
#include <btBulletDynamicsCommon.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace foresight;
using foresight_bench::kPi;
using foresight_bench::Part;
using foresight_bench::Random;
using foresight_bench::timeInTurns;
using foresight_bench::TimeRatio;

// ---------------------------------------------------------------------------------------------
// Measuring the builds

/// Resident memory of the process [bytes] (Linux; 0 elsewhere).
double residentBytes() {
    std::ifstream statm("/proc/self/statm");
    double pages = 0, resident = 0;
    if (!(statm >> pages >> resident)) return 0;
    return resident * 4096.0;
}

/// Wall and process CPU time (all threads) of one build step.
class BuildTimer {
public:
    BuildTimer() : mWall(std::chrono::steady_clock::now()), mCpu(std::clock()), mResident(residentBytes()) {}
    /// "1.23 s wall, 2.34 s CPU, +56 MB resident"
    std::string report() const {
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - mWall).count();
        const double cpu = static_cast<double>(std::clock() - mCpu) / CLOCKS_PER_SEC;
        const double megabytes = (residentBytes() - mResident) / (1024.0 * 1024.0);
        char text[96];
        std::snprintf(text, sizeof text, "%.3f s wall, %.3f s CPU, %+.0f MB resident", wall, cpu, megabytes);
        return text;
    }

private:
    std::chrono::steady_clock::time_point mWall;
    std::clock_t mCpu;
    double mResident;
};

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "foresight_bench_worlds: %s\n", message.c_str());
    std::exit(EXIT_FAILURE);
}

void note(const std::string& message) { std::fprintf(stderr, "foresight_bench_worlds: %s\n", message.c_str()); }

// ---------------------------------------------------------------------------------------------
// The meshes

/// An indexed triangle mesh (three indices per triangle). Coordinates are floats (exact in
/// RVec3 and in btScalar), so every world holds exactly the same triangles.
struct Mesh {
    std::vector<RVec3> vertices;
    std::vector<std::uint32_t> indices;
    std::size_t triangleCount() const { return indices.size() / 3; }
};

constexpr int kGridQuads = 706;                     // per side: 2 * 706^2 = 996,872 terrain triangles
constexpr int kBuildingCount = 400;                 // 10 triangles each: 4,000
constexpr float kGridHalfSize = 0.5f * kGridQuads;  // [m], 1 m quads centred on the origin

/// Rolling hills (up to about +-9 m) with a small ripple.
float terrainHeight(float x, float z) {
    return 6.0f * std::sin(0.021f * x) * std::cos(0.017f * z) +
           2.5f * std::sin(0.07f * x + 0.3f) * std::sin(0.05f * z) + 0.6f * std::sin(0.31f * x + 0.11f * z);
}

/// About one million triangles: a 706 x 706 terrain grid of 1 m quads with hills (996,872
/// triangles), plus 400 closed-topped "buildings" (rotated boxes 1-6 m wide and 2-10 m tall
/// sunk into the ground: 8 wall and 2 roof triangles each), so that the mesh is not only a
/// heightfield and horizontal casts meet vertical walls. 1,000,872 triangles in all.
Mesh makeBigMesh() {
    Mesh mesh;
    const int side = kGridQuads + 1;
    mesh.vertices.reserve(static_cast<std::size_t>(side) * side + 8 * kBuildingCount);
    mesh.indices.reserve(6 * static_cast<std::size_t>(kGridQuads) * kGridQuads + 30 * kBuildingCount);
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            const float x = static_cast<float>(i) - kGridHalfSize;
            const float z = static_cast<float>(j) - kGridHalfSize;
            mesh.vertices.emplace_back(x, terrainHeight(x, z), z);
        }
    }
    for (int j = 0; j < kGridQuads; ++j) {
        for (int i = 0; i < kGridQuads; ++i) {
            const auto v00 = static_cast<std::uint32_t>(j * side + i);
            const std::uint32_t v10 = v00 + 1, v01 = v00 + static_cast<std::uint32_t>(side), v11 = v01 + 1;
            mesh.indices.insert(mesh.indices.end(), {v00, v10, v11, v00, v11, v01});
        }
    }
    Random random(2024);
    for (int b = 0; b < kBuildingCount; ++b) {
        const float cx = random.uniform(-330, 330), cz = random.uniform(-330, 330);
        const float hx = random.uniform(0.5f, 3), hz = random.uniform(0.5f, 3);
        const float height = random.uniform(2, 10), yaw = random.uniform(0, 2 * kPi);
        const float c = std::cos(yaw), s = std::sin(yaw);
        const std::array<float, 4> ux{-hx, hx, hx, -hx}, uz{-hz, -hz, hz, hz};
        std::array<float, 4> x{}, z{};
        float base = terrainHeight(cx, cz);
        for (int k = 0; k < 4; ++k) {
            x[k] = cx + c * ux[k] + s * uz[k];
            z[k] = cz - s * ux[k] + c * uz[k];
            base = std::min(base, terrainHeight(x[k], z[k]));
        }
        base -= 1.0f;  // sunk into the hills: no gap under a wall
        const float top = terrainHeight(cx, cz) + height;
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (int k = 0; k < 4; ++k) mesh.vertices.emplace_back(x[k], base, z[k]);
        for (int k = 0; k < 4; ++k) mesh.vertices.emplace_back(x[k], top, z[k]);
        for (std::uint32_t k = 0; k < 4; ++k) {
            const std::uint32_t n = (k + 1) % 4;
            mesh.indices.insert(mesh.indices.end(),
                                {first + k, first + n, first + 4 + n, first + k, first + 4 + n, first + 4 + k});
        }
        mesh.indices.insert(mesh.indices.end(), {first + 4, first + 5, first + 6, first + 4, first + 6, first + 7});
    }
    return mesh;
}

// ---------------------------------------------------------------------------------------------
// The worlds

btVector3 toBt(const RVec3& v) {
    return btVector3(static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z));
}

/// A btCollisionWorld (btDbvtBroadphase) holding one static btBvhTriangleMeshShape (quantized
/// BVH, margin 0, as BulletScene builds it) over a btTriangleMesh of the mesh's vertices and
/// indices.
class BulletMeshWorld {
public:
    /// Builds the world; `report` (if not null) gets the timings of the mesh copy and the BVH.
    BulletMeshWorld(const Mesh& mesh, std::string* report) {
        BuildTimer copyTimer;
        mMesh.preallocateVertices(static_cast<int>(mesh.vertices.size()));
        mMesh.preallocateIndices(static_cast<int>(mesh.indices.size()));
        for (const RVec3& v : mesh.vertices) mMesh.findOrAddVertex(toBt(v), false);
        for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
            mMesh.addTriangleIndices(static_cast<int>(mesh.indices[i]), static_cast<int>(mesh.indices[i + 1]),
                                     static_cast<int>(mesh.indices[i + 2]));
        const std::string copied = copyTimer.report();
        BuildTimer bvhTimer;
        mShape = std::make_unique<btBvhTriangleMeshShape>(&mMesh, true);
        const std::string built = bvhTimer.report();
        mShape->setMargin(btScalar(0));
        mObject.setCollisionShape(mShape.get());
        mObject.setCollisionFlags(mObject.getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
        mWorld.addCollisionObject(&mObject);
        if (report) *report = "btTriangleMesh copy " + copied + "; btBvhTriangleMeshShape BVH " + built;
    }
    ~BulletMeshWorld() { mWorld.removeCollisionObject(&mObject); }
    BulletMeshWorld(const BulletMeshWorld&) = delete;
    BulletMeshWorld& operator=(const BulletMeshWorld&) = delete;

    const btCollisionWorld& world() const { return mWorld; }

private:
    btDefaultCollisionConfiguration mConfiguration;
    btCollisionDispatcher mDispatcher{&mConfiguration};
    btDbvtBroadphase mBroadphase;
    btCollisionWorld mWorld{&mDispatcher, &mBroadphase, &mConfiguration};
    btTriangleMesh mMesh{true, false};
    std::unique_ptr<btBvhTriangleMeshShape> mShape;
    btCollisionObject mObject;
};

/// How an Embree scene is built, for information next to EmbreeWorld: native triangles (Embree's
/// own float test) or user geometry with a plain float ray-triangle test in the callback (the
/// traversal EmbreeWorld pays for, without its exact double tests), each with EmbreeWorld's
/// scene flags (robust, high build quality) or Embree's defaults.
enum class EmbreeKind { NativeTriangles, UserTriangles };

/// One triangle of the user geometry (float, as Embree traces).
struct UserTriangle {
    glm::vec3 a, b, c;
};

/// What the user-geometry callbacks see.
struct UserGeometry {
    std::vector<UserTriangle> triangles;
    float pad = 0;  // bounds padding [m], EmbreeWorld's (1e-6 m + 2^-21 of the largest coordinate)
};

/// The ray context of the user geometry: Embree passes the first member's address back.
struct CountingContext {
    RTCIntersectContext context;
    std::uint64_t* candidates;
};

void userBounds(const RTCBoundsFunctionArguments* args) {
    const auto* g = static_cast<const UserGeometry*>(args->geometryUserPtr);
    const UserTriangle& t = g->triangles[args->primID];
    const glm::vec3 lo = glm::min(t.a, glm::min(t.b, t.c)) - g->pad, hi = glm::max(t.a, glm::max(t.b, t.c)) + g->pad;
    *args->bounds_o = RTCBounds{lo.x, lo.y, lo.z, 0.0f, hi.x, hi.y, hi.z, 0.0f};
}

/// Moller-Trumbore in float, two-sided.
void userIntersect(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    ++*reinterpret_cast<const CountingContext*>(args->context)->candidates;
    const auto* g = static_cast<const UserGeometry*>(args->geometryUserPtr);
    const UserTriangle& t = g->triangles[args->primID];
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);  // N == 1: the plain layout
    const glm::vec3 origin(rayhit->ray.org_x, rayhit->ray.org_y, rayhit->ray.org_z);
    const glm::vec3 direction(rayhit->ray.dir_x, rayhit->ray.dir_y, rayhit->ray.dir_z);
    const glm::vec3 e1 = t.b - t.a, e2 = t.c - t.a;
    const glm::vec3 p = glm::cross(direction, e2);
    const float determinant = glm::dot(e1, p);
    if (determinant == 0.0f) return;
    const float inverse = 1.0f / determinant;
    const glm::vec3 s = origin - t.a;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) return;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) return;
    const float distance = glm::dot(e2, q) * inverse;
    if (distance < rayhit->ray.tnear || distance > rayhit->ray.tfar) return;
    rayhit->ray.tfar = distance;
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.primID = args->primID;
}

class EmbreeScene {
public:
    EmbreeScene(const Mesh& mesh, EmbreeKind kind, bool robust) {
        mDevice = rtcNewDevice(nullptr);
        mScene = rtcNewScene(mDevice);
        if (robust) {
            rtcSetSceneFlags(mScene, RTC_SCENE_FLAG_ROBUST);
            rtcSetSceneBuildQuality(mScene, RTC_BUILD_QUALITY_HIGH);
        }
        RTCGeometry geometry = nullptr;
        if (kind == EmbreeKind::NativeTriangles) {
            geometry = rtcNewGeometry(mDevice, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
                geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
            for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
                vertices[3 * i] = static_cast<float>(mesh.vertices[i].x);
                vertices[3 * i + 1] = static_cast<float>(mesh.vertices[i].y);
                vertices[3 * i + 2] = static_cast<float>(mesh.vertices[i].z);
            }
            auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
                geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), mesh.triangleCount()));
            std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
        } else {
            float largest = 0;
            for (const RVec3& v : mesh.vertices)
                largest = std::max({largest, std::abs(static_cast<float>(v.x)), std::abs(static_cast<float>(v.y)),
                                    std::abs(static_cast<float>(v.z))});
            mUser.pad = 1e-6f + std::ldexp(largest, -21);
            mUser.triangles.reserve(mesh.triangleCount());
            auto vertex = [&](std::size_t i) { return glm::vec3(mesh.vertices[mesh.indices[i]]); };
            for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
                mUser.triangles.push_back(UserTriangle{vertex(i), vertex(i + 1), vertex(i + 2)});
            geometry = rtcNewGeometry(mDevice, RTC_GEOMETRY_TYPE_USER);
            rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(mUser.triangles.size()));
            rtcSetGeometryUserData(geometry, &mUser);
            rtcSetGeometryBoundsFunction(geometry, userBounds, nullptr);
            rtcSetGeometryIntersectFunction(geometry, userIntersect);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(mScene, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(mScene);
        if (rtcGetDeviceError(mDevice) != RTC_ERROR_NONE) fail("Embree could not build a comparison scene");
    }
    ~EmbreeScene() {
        rtcReleaseScene(mScene);
        rtcReleaseDevice(mDevice);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    /// The segment as a ray with tfar 1; returns the hit's fraction, or a negative value.
    /// `candidates` counts the user geometry's callbacks.
    float castSegment(const RVec3& origin, const Vec3& displacement, std::uint64_t& candidates) const {
        CountingContext context;
        rtcInitIntersectContext(&context.context);
        context.candidates = &candidates;
        RTCRayHit rayhit;
        rayhit.ray.org_x = static_cast<float>(origin.x);
        rayhit.ray.org_y = static_cast<float>(origin.y);
        rayhit.ray.org_z = static_cast<float>(origin.z);
        rayhit.ray.dir_x = displacement.x;
        rayhit.ray.dir_y = displacement.y;
        rayhit.ray.dir_z = displacement.z;
        rayhit.ray.tnear = 0.0f;
        rayhit.ray.tfar = 1.0f;
        rayhit.ray.time = 0.0f;
        rayhit.ray.mask = 0xFFFFFFFFu;
        rayhit.ray.id = 0;
        rayhit.ray.flags = 0;
        rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(mScene, &context.context, &rayhit);
        return rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1.0f : rayhit.ray.tfar;
    }

private:
    UserGeometry mUser;  // user geometry only; its address is the callbacks' user data
    RTCDevice mDevice = nullptr;
    RTCScene mScene = nullptr;
};

// ---------------------------------------------------------------------------------------------
// The segments

struct Segment {
    RVec3 origin{0};
    Vec3 displacement{0};
    float length() const { return glm::length(displacement); }
};

constexpr int kSegmentCount = 4096;
constexpr float kSweepRadius = 0.1f;  // [m]
constexpr double kAgreement = 1e-4;   // [m] along the segment

/// Prediction-like segments over the big mesh: lengths 0.1 to 20 m (log-uniform: most are short,
/// as a projectile's steps are), origins inside the grid 0.05 m plus up to 0.8 of the length
/// above the ground; 65% downward or oblique (10 to 85 degrees down), 25% about horizontal
/// (within 3 degrees: hills and walls), 10% upward (5 to 60 degrees up, mostly misses). About
/// half of them hit.
std::vector<Segment> makeSegments() {
    Random random(99);
    std::vector<Segment> segments(kSegmentCount);
    for (Segment& s : segments) {
        const float x = random.uniform(-340, 340), z = random.uniform(-340, 340);
        const float length = 0.1f * std::pow(200.0f, random.uniform(0, 1));
        // Above the ground by up to 0.8 of the length: most downward segments reach it.
        s.origin = RVec3(x, terrainHeight(x, z) + 0.05f + length * random.uniform(0, 0.8f), z);
        const float kind = random.uniform(0, 1);
        const float degrees = kind < 0.65f   ? random.uniform(-85, -10)
                              : kind < 0.90f ? random.uniform(-3, 3)
                                             : random.uniform(5, 60);
        const float pitch = degrees * (kPi / 180), yaw = random.uniform(0, 2 * kPi);
        s.displacement =
            length * Vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    }
    return segments;
}

// One cast through each world: the hit's distance along the segment [m], or -1 for a miss.

double castEmbree(const EmbreeWorld& world, const Segment& s, float radius) {
    CastHit hit;
    return world.castSegment(SegmentCast{s.origin, s.displacement, radius}, hit)
               ? static_cast<double>(hit.fraction) * static_cast<double>(s.length())
               : -1.0;
}

double castBulletWorld(const BulletWorld& world, const Segment& s, float radius) {
    CastHit hit;
    return world.castSegment(SegmentCast{s.origin, s.displacement, radius}, hit)
               ? static_cast<double>(hit.fraction) * static_cast<double>(s.length())
               : -1.0;
}

double castBulletRay(const btCollisionWorld& world, const Segment& s) {
    const btVector3 from = toBt(s.origin), to = toBt(s.origin + RVec3(s.displacement));
    btCollisionWorld::ClosestRayResultCallback callback(from, to);
    world.rayTest(from, to, callback);
    return callback.hasHit() ? static_cast<double>(callback.m_closestHitFraction) * static_cast<double>(s.length())
                             : -1.0;
}

double castBulletSweep(const btCollisionWorld& world, const Segment& s) {
    const btSphereShape sphere(kSweepRadius);
    btTransform from, to;
    from.setIdentity();
    to.setIdentity();
    from.setOrigin(toBt(s.origin));
    to.setOrigin(toBt(s.origin + RVec3(s.displacement)));
    btCollisionWorld::ClosestConvexResultCallback callback(from.getOrigin(), to.getOrigin());
    world.convexSweepTest(&sphere, from, to, callback, btScalar(0));
    return callback.hasHit() ? static_cast<double>(callback.m_closestHitFraction) * static_cast<double>(s.length())
                             : -1.0;
}

double castScene(const EmbreeScene& scene, const Segment& s, std::uint64_t& candidates) {
    const float fraction = scene.castSegment(s.origin, s.displacement, candidates);
    return fraction < 0 ? -1.0 : static_cast<double>(fraction) * static_cast<double>(s.length());
}

/// How two worlds answered the same segments.
struct Comparison {
    int hits = 0;                  // segments both worlds hit
    int misses = 0;                // segments both worlds missed
    int endGrazes = 0;             // hit/miss disagreements with the hit within `tolerance` of the end
    int disagreements = 0;         // other hit/miss disagreements, or distances beyond `tolerance`
    double largestDifference = 0;  // [m] among common hits
    std::string firstDisagreement;
};

/// Compares the distances `a` and `b` (-1: miss) of each segment. A hit within `tolerance` of the
/// segment's end that the other world misses is a graze of the end, not a disagreement (whether
/// the end touches the surface is decided by rounding).
Comparison compare(const std::vector<Segment>& segments, const std::vector<double>& a, const std::vector<double>& b,
                   double tolerance) {
    Comparison c;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const double length = static_cast<double>(segments[i].length());
        bool bad = false;
        if (a[i] < 0 && b[i] < 0) {
            ++c.misses;
        } else if (a[i] >= 0 && b[i] >= 0) {
            ++c.hits;
            const double difference = std::abs(a[i] - b[i]);
            c.largestDifference = std::max(c.largestDifference, difference);
            bad = difference > tolerance;
        } else if (std::max(a[i], b[i]) >= length - tolerance) {
            ++c.endGrazes;
        } else {
            bad = true;
        }
        if (bad && c.disagreements++ == 0) {
            const Segment& s = segments[i];
            char text[256];
            std::snprintf(text, sizeof text,
                          "segment %zu (origin %.7g %.7g %.7g, displacement %.7g %.7g %.7g, length %.7g m): "
                          "%.9g against %.9g m",
                          i, static_cast<double>(s.origin.x), static_cast<double>(s.origin.y),
                          static_cast<double>(s.origin.z), static_cast<double>(s.displacement.x),
                          static_cast<double>(s.displacement.y), static_cast<double>(s.displacement.z), length, a[i],
                          b[i]);
            c.firstDisagreement = text;
        }
    }
    return c;
}

std::string describe(const Comparison& c) {
    char text[160];
    std::snprintf(text, sizeof text, "%d hits, %d misses, %d end grazes, %d disagreements, largest difference %.3g m",
                  c.hits, c.misses, c.endGrazes, c.disagreements, c.largestDifference);
    return text;
}

/// The big mesh in every world, and the segments, built once (by the first benchmark that needs
/// them) and checked: the ray worlds must agree on every segment before anything is timed.
struct BigWorlds {
    Mesh mesh;
    std::vector<Segment> segments;
    std::vector<Segment> sweepSegments;  // the same, 0.2 m higher: no sphere starts in contact
    std::unique_ptr<EmbreeWorld> embree;
    std::unique_ptr<BulletMeshWorld> bullet;
    std::unique_ptr<BulletWorld> bulletAdapter;
    double hitShare = 0;             // segments that hit, out of all
    std::vector<SegmentCast> casts;  // the segments as EmbreeWorld::castSegments takes them (radius 0)
};

const BigWorlds& bigWorlds() {
    static const std::unique_ptr<BigWorlds> worlds = [] {
        auto w = std::make_unique<BigWorlds>();
        BuildTimer meshTimer;
        w->mesh = makeBigMesh();
        w->segments = makeSegments();
        w->sweepSegments = w->segments;
        for (Segment& s : w->sweepSegments) s.origin.y += 2 * kSweepRadius;
        note("big mesh: " + std::to_string(w->mesh.triangleCount()) + " triangles, " +
             std::to_string(w->mesh.vertices.size()) + " vertices (" + meshTimer.report() + ")");

        w->embree = std::make_unique<EmbreeWorld>();
        BuildTimer addTimer;
        MeshReport report;
        if (w->embree->addMesh(w->mesh.vertices, w->mesh.indices, &report) != Status::Ok)
            fail("EmbreeWorld::addMesh refused the big mesh: " + report.error);
        if (report.degenerateTriangles != 0) fail("the big mesh has degenerate triangles");
        const std::string added = addTimer.report();
        BuildTimer commitTimer;
        std::string error;
        if (!w->embree->commit(&error)) fail(error);
        note("EmbreeWorld: addMesh " + added + "; commit (BVH of native triangles) " + commitTimer.report());

        std::string bulletReport;
        w->bullet = std::make_unique<BulletMeshWorld>(w->mesh, &bulletReport);
        w->bulletAdapter = std::make_unique<BulletWorld>(w->bullet->world());
        note("Bullet: " + bulletReport);

        // Agreement of the ray worlds, segment by segment.
        const std::size_t n = w->segments.size();
        std::vector<double> embree(n), bulletRay(n), bulletWorld(n);
        int hits = 0;
        for (std::size_t i = 0; i < n; ++i) {
            embree[i] = castEmbree(*w->embree, w->segments[i], 0.0f);
            bulletRay[i] = castBulletRay(w->bullet->world(), w->segments[i]);
            bulletWorld[i] = castBulletWorld(*w->bulletAdapter, w->segments[i], 0.0f);
            hits += embree[i] >= 0 ? 1 : 0;
        }
        w->hitShare = static_cast<double>(hits) / static_cast<double>(n);
        const Comparison rays = compare(w->segments, embree, bulletRay, kAgreement);
        const Comparison adapter = compare(w->segments, embree, bulletWorld, kAgreement);
        note("rays, EmbreeWorld vs Bullet rayTest: " + describe(rays));
        note("rays, EmbreeWorld vs BulletWorld: " + describe(adapter));
        if (rays.disagreements > 0)
            fail("EmbreeWorld and Bullet's rayTest disagree (tolerance 1e-4 m); first: " + rays.firstDisagreement);
        if (adapter.disagreements > 0)
            fail("EmbreeWorld and BulletWorld disagree (tolerance 1e-4 m); first: " + adapter.firstDisagreement);

        // The batch must give castSegment's answers bit for bit.
        for (const Segment& s : w->segments) w->casts.push_back(SegmentCast{s.origin, s.displacement, 0.0f});
        std::vector<CastHit> batchHits(n);
        std::vector<std::uint8_t> batchFound(n);
        w->embree->castSegments(w->casts, batchHits, batchFound);
        for (std::size_t i = 0; i < n; ++i) {
            CastHit single;
            const bool found = w->embree->castSegment(w->casts[i], single);
            const CastHit& batch = batchHits[i];
            if (found != (batchFound[i] != 0) ||
                (found && (std::memcmp(&single.fraction, &batch.fraction, sizeof(float)) != 0 ||
                           std::memcmp(&single.position, &batch.position, sizeof(RVec3)) != 0 ||
                           std::memcmp(&single.normal, &batch.normal, sizeof(Vec3)) != 0)))
                fail("EmbreeWorld::castSegments differs from castSegment on segment " + std::to_string(i));
        }
        note("rays, EmbreeWorld::castSegments vs castSegment: the same " + std::to_string(n) + " answers, bit for bit");
        return w;
    }();
    return *worlds;
}

/// The comparison scenes of EmbreeKind (information), built when first used, with their
/// agreement with EmbreeWorld reported (never fatal: they test in float).
enum class ComparisonScene { NativeRobust, NativeDefault, UserRobust, Count };

const EmbreeScene& comparisonScene(ComparisonScene which) {
    static std::array<std::unique_ptr<EmbreeScene>, static_cast<std::size_t>(ComparisonScene::Count)> scenes;
    std::unique_ptr<EmbreeScene>& scene = scenes[static_cast<std::size_t>(which)];
    if (!scene) {
        const BigWorlds& w = bigWorlds();
        static constexpr std::array<const char*, 3> names{
            "native triangles, EmbreeWorld's flags (robust, high quality)", "native triangles, default flags",
            "user geometry with a float test, EmbreeWorld's flags and bounds padding"};
        const bool native = which != ComparisonScene::UserRobust;
        BuildTimer timer;
        scene = std::make_unique<EmbreeScene>(w.mesh, native ? EmbreeKind::NativeTriangles : EmbreeKind::UserTriangles,
                                              which != ComparisonScene::NativeDefault);
        const std::string built = timer.report();
        const std::size_t n = w.segments.size();
        std::vector<double> embree(n), other(n);
        std::uint64_t candidates = 0;
        for (std::size_t i = 0; i < n; ++i) {
            embree[i] = castEmbree(*w.embree, w.segments[i], 0.0f);
            other[i] = castScene(*scene, w.segments[i], candidates);
        }
        note(std::string("Embree ") + names[static_cast<std::size_t>(which)] + " (information): build " + built +
             "; against EmbreeWorld: " + describe(compare(w.segments, embree, other, kAgreement)));
    }
    return *scene;
}

/// Sphere sweeps (information only): compared once, reported, never fatal (Bullet's
/// conservative advancement stops up to about 1 mm short).
void checkSweepsOnce() {
    static const bool checked = [] {
        const BigWorlds& w = bigWorlds();
        const std::vector<Segment>& segments = w.sweepSegments;
        const std::size_t n = segments.size();
        std::vector<double> embree(n), bulletSweep(n), bulletWorld(n);
        for (std::size_t i = 0; i < n; ++i) {
            embree[i] = castEmbree(*w.embree, segments[i], kSweepRadius);
            bulletSweep[i] = castBulletSweep(w.bullet->world(), segments[i]);
            bulletWorld[i] = castBulletWorld(*w.bulletAdapter, segments[i], kSweepRadius);
        }
        const Comparison sweeps = compare(segments, embree, bulletSweep, 2e-3);
        note("spheres r=0.1, EmbreeWorld vs Bullet convexSweepTest (information, 2 mm): " + describe(sweeps) +
             (sweeps.disagreements > 0 ? "; first: " + sweeps.firstDisagreement : std::string()));
        note("spheres r=0.1, EmbreeWorld vs BulletWorld (information, 2 mm): " +
             describe(compare(segments, embree, bulletWorld, 2e-3)));
        return true;
    }();
    (void)checked;
}

// ---------------------------------------------------------------------------------------------
// Cast benchmarks

enum class CastWorld { Embree, BulletRayTest, BulletWorld, EmbreeNative, EmbreeNativeDefault, EmbreeUserFloat };

/// EmbreeWorld::castSegments over all the segments at once (16-ray packets); the same answers
/// as BM_Cast/Embree (checked bit for bit before timing).
void BM_CastBatch(benchmark::State& state) {
    const BigWorlds& w = bigWorlds();
    std::vector<CastHit> hits(w.casts.size());
    std::vector<std::uint8_t> found(w.casts.size());
    double sum = 0;
    for (auto _ : state) {
        w.embree->castSegments(w.casts, hits, found);
        for (std::size_t i = 0; i < w.casts.size(); ++i)
            sum +=
                found[i] ? static_cast<double>(hits[i].fraction) * static_cast<double>(w.segments[i].length()) : -1.0;
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(w.casts.size()));
    state.counters["hit_share"] = w.hitShare;
}

void BM_Cast(benchmark::State& state, CastWorld which) {
    const BigWorlds& w = bigWorlds();
    const EmbreeScene* scene = which == CastWorld::EmbreeNative ? &comparisonScene(ComparisonScene::NativeRobust)
                               : which == CastWorld::EmbreeNativeDefault
                                   ? &comparisonScene(ComparisonScene::NativeDefault)
                               : which == CastWorld::EmbreeUserFloat ? &comparisonScene(ComparisonScene::UserRobust)
                                                                     : nullptr;
    double sum = 0;
    std::uint64_t candidates = 0;
    for (auto _ : state) {
        for (const Segment& s : w.segments) {
            double d = 0;
            switch (which) {
                case CastWorld::Embree:
                    d = castEmbree(*w.embree, s, 0.0f);
                    break;
                case CastWorld::BulletRayTest:
                    d = castBulletRay(w.bullet->world(), s);
                    break;
                case CastWorld::BulletWorld:
                    d = castBulletWorld(*w.bulletAdapter, s, 0.0f);
                    break;
                case CastWorld::EmbreeNative:
                case CastWorld::EmbreeNativeDefault:
                case CastWorld::EmbreeUserFloat:
                    d = castScene(*scene, s, candidates);
                    break;
            }
            sum += d;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(w.segments.size()));
    state.counters["hit_share"] = w.hitShare;
    if (which == CastWorld::EmbreeUserFloat)
        state.counters["candidates/cast"] =
            static_cast<double>(candidates) / static_cast<double>(state.iterations() * w.segments.size());
}
BENCHMARK_CAPTURE(BM_Cast, Embree, CastWorld::Embree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CastBatch)->Name("BM_Cast/EmbreeBatch")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Cast, BulletRayTest, CastWorld::BulletRayTest)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Cast, BulletWorld, CastWorld::BulletWorld)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Cast, EmbreeNative, CastWorld::EmbreeNative)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Cast, EmbreeNativeDefault, CastWorld::EmbreeNativeDefault)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Cast, EmbreeUserFloat, CastWorld::EmbreeUserFloat)->Unit(benchmark::kMillisecond);

/// The segment-cast targets as ratios within one benchmark (timeInTurns): castSegment's time
/// over a bare native rtcIntersect1's (EmbreeNative's scene), and Bullet rayTest's time over
/// castSegment's and over castSegments'.
void BM_CastTurns(benchmark::State& state) {
    const BigWorlds& w = bigWorlds();
    const EmbreeScene& native = comparisonScene(ComparisonScene::NativeRobust);
    double sum = 0;
    std::uint64_t candidates = 0;
    std::vector<CastHit> hits(w.casts.size());
    std::vector<std::uint8_t> found(w.casts.size());
    const std::array<Part, 4> parts{{
        {"native",
         [&] {
             for (const Segment& s : w.segments) sum += castScene(native, s, candidates);
         }},
        {"castSegment",
         [&] {
             for (const Segment& s : w.segments) sum += castEmbree(*w.embree, s, 0.0f);
         }},
        {"castSegments",
         [&] {
             w.embree->castSegments(w.casts, hits, found);
             for (std::size_t i = 0; i < w.casts.size(); ++i) sum += found[i] ? hits[i].fraction : -1.0f;
         }},
        {"rayTest",
         [&] {
             for (const Segment& s : w.segments) sum += castBulletRay(w.bullet->world(), s);
         }},
    }};
    const std::array<TimeRatio, 3> ratios{
        {{"castSegment/native", 1, 0}, {"rayTest/castSegment", 3, 1}, {"rayTest/castSegments", 3, 2}}};
    timeInTurns(state, parts, ratios);
    benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_CastTurns)->Name("BM_Turns/Cast")->Unit(benchmark::kMillisecond);

enum class SweepWorld { Embree, BulletConvexSweep, BulletWorld };

void BM_Sweep(benchmark::State& state, SweepWorld which) {
    const BigWorlds& w = bigWorlds();
    checkSweepsOnce();
    double sum = 0;
    for (auto _ : state) {
        for (const Segment& s : w.sweepSegments) {
            double d = 0;
            switch (which) {
                case SweepWorld::Embree:
                    d = castEmbree(*w.embree, s, kSweepRadius);
                    break;
                case SweepWorld::BulletConvexSweep:
                    d = castBulletSweep(w.bullet->world(), s);
                    break;
                case SweepWorld::BulletWorld:
                    d = castBulletWorld(*w.bulletAdapter, s, kSweepRadius);
                    break;
            }
            sum += d;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(w.segments.size()));
}
BENCHMARK_CAPTURE(BM_Sweep, Embree, SweepWorld::Embree)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sweep, BulletConvexSweep, SweepWorld::BulletConvexSweep)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sweep, BulletWorld, SweepWorld::BulletWorld)->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------------------------------------
// Predictions on the demo level

#if FORESIGHT_BENCH_DEMO_LEVEL

constexpr int kLevelThrowCount = 64;
constexpr float kLevelFuse = 3.0f;  // [s]: 150 steps at the default 50 Hz

/// The demo level (tools/demo_level/demo_level.h) in every world, and the throws.
struct LevelWorlds {
    Mesh mesh;
    StaticWorld staticWorld;
    std::unique_ptr<EmbreeWorld> embree;
    std::unique_ptr<BulletMeshWorld> bullet;
    std::unique_ptr<BulletWorld> bulletAdapter;
    std::unique_ptr<CallbackWorld> callback;  // EmbreeWorld's castSegment alone
    std::array<foresight_bench::Throw, kLevelThrowCount> throws{};
    std::uint32_t floorTriangles = 0;  // the mesh's first triangles: the floor's 1 m tiles
};

/// Grenades from the open middle of the courtyard (|x| < 5, -5 < z < 8, 1.2 to 2 m up), 8 to
/// 20 m/s in every direction, 15 degrees down to 60 up: they hit the floor, walls, pillars,
/// crates, stairs and ramp, and some fly over the 4 m walls.
std::array<foresight_bench::Throw, kLevelThrowCount> makeLevelThrows() {
    Random random(31);
    std::array<foresight_bench::Throw, kLevelThrowCount> throws{};
    for (foresight_bench::Throw& t : throws) {
        t.position = RVec3(random.uniform(-5, 5), random.uniform(1.2f, 2), random.uniform(-5, 8));
        const float speed = random.uniform(8, 20), yaw = random.uniform(0, 2 * kPi);
        const float pitch = random.uniform(-15, 60) * (kPi / 180);
        t.velocity = speed * Vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    }
    return throws;
}

const LevelWorlds& levelWorlds() {
    static const std::unique_ptr<LevelWorlds> worlds = [] {
        auto w = std::make_unique<LevelWorlds>();
        const foresight_level::LevelMesh level = foresight_level::makeDemoLevel();
        // Every coordinate is a multiple of 1/256 m: exact in float.
        for (const glm::dvec3& v : level.vertices) w->mesh.vertices.emplace_back(v);
        w->mesh.indices = level.indices;
        if (level.parts.empty() || level.parts[0].name != "floor") fail("the demo level does not start with its floor");
        w->floorTriangles = level.parts[0].triangleCount;
        for (std::size_t i = 0; i < w->mesh.indices.size(); i += 3) {
            const Triangle t{w->mesh.vertices[w->mesh.indices[i]], w->mesh.vertices[w->mesh.indices[i + 1]],
                             w->mesh.vertices[w->mesh.indices[i + 2]]};
            if (w->staticWorld.add(t) != Status::Ok) fail("StaticWorld refused a demo level triangle");
        }
        w->embree = std::make_unique<EmbreeWorld>();
        MeshReport report;
        if (w->embree->addMesh(w->mesh.vertices, w->mesh.indices, &report) != Status::Ok)
            fail("EmbreeWorld::addMesh refused the demo level: " + report.error);
        std::string error;
        if (!w->embree->commit(&error)) fail(error);
        w->bullet = std::make_unique<BulletMeshWorld>(w->mesh, nullptr);
        w->bulletAdapter = std::make_unique<BulletWorld>(w->bullet->world());
        // A segment-only world, as a game's own ray cast behind a callback is: no mayTouch,
        // firstTouch or isOnlyPlane answers, so the predictors cast every chord.
        w->callback = std::make_unique<CallbackWorld>(
            [](void* embree, const SegmentCast& cast, CastHit& hit) {
                return static_cast<const EmbreeWorld*>(embree)->castSegment(cast, hit);
            },
            w->embree.get());
        w->throws = makeLevelThrows();
        note("demo level: " + std::to_string(w->mesh.triangleCount()) + " triangles, " +
             std::to_string(kLevelThrowCount) + " throws");
        return w;
    }();
    return *worlds;
}

enum class LevelWorld { Embree, Bullet, Static, Callback };

const CollisionWorld& levelWorld(const LevelWorlds& w, LevelWorld which) {
    switch (which) {
        case LevelWorld::Embree:
            return *w.embree;
        case LevelWorld::Bullet:
            return *w.bulletAdapter;
        case LevelWorld::Callback:
            return *w.callback;
        case LevelWorld::Static:
            break;
    }
    return w.staticWorld;
}

/// Where each throw ends and how often it bounced, through one world.
struct LevelOutcome {
    std::vector<RVec3> ends;
    std::uint64_t bounces = 0;
};

LevelOutcome predictLevel(const LevelWorlds& w, const CollisionWorld& world, const ProjectileSettings& settings,
                          std::vector<TrajectoryPoint>& trajectory) {
    LevelOutcome outcome;
    for (const foresight_bench::Throw& t : w.throws) {
        ProjectileResult result;
        if (predictProjectile(t.position, t.velocity, kLevelFuse, settings, &world, trajectory, result) != Status::Ok)
            fail("a demo level prediction failed");
        outcome.ends.push_back(result.position);
        outcome.bounces += result.bounces;
    }
    return outcome;
}

/// Once per method: how far the Embree and Bullet predictions end from StaticWorld's (Embree's
/// hits are StaticWorld's exactly; Bullet's are float), for information.
void compareLevelOnce(ProjectileMethod method) {
    static std::array<bool, 2> done{};
    bool& d = done[method == ProjectileMethod::Exact ? 0 : 1];
    if (d) return;
    d = true;
    const LevelWorlds& w = levelWorlds();
    ProjectileSettings settings;
    settings.method = method;
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(kLevelFuse, settings, 256));
    const LevelOutcome reference = predictLevel(w, w.staticWorld, settings, trajectory);
    std::string text = std::string("demo level, ") + (method == ProjectileMethod::Exact ? "Exact" : "Stepped") + ": " +
                       std::to_string(reference.bounces) + " bounces (StaticWorld)";
    for (const LevelWorld which : {LevelWorld::Embree, LevelWorld::Bullet}) {
        const LevelOutcome outcome = predictLevel(w, levelWorld(w, which), settings, trajectory);
        double largest = 0;
        int within = 0, below = 0, referenceBelow = 0;
        for (std::size_t i = 0; i < outcome.ends.size(); ++i) {
            const double distance = glm::length(glm::dvec3(outcome.ends[i]) - glm::dvec3(reference.ends[i]));
            largest = std::max(largest, distance);
            within += distance <= 1e-3 ? 1 : 0;
            // The floor is at y = 0 and reaches 2.5 m past the walls: below it, a throw fell
            // through a surface or flew out of the level.
            below += outcome.ends[i].y < -1 ? 1 : 0;
            referenceBelow += reference.ends[i].y < -1 ? 1 : 0;
        }
        char line[240];
        std::snprintf(line, sizeof line,
                      "; %s: %llu bounces, %d of %d end within 1 mm of StaticWorld's (largest %.3g m), "
                      "%d end below the floor (StaticWorld: %d)",
                      which == LevelWorld::Embree ? "EmbreeWorld" : "BulletWorld",
                      static_cast<unsigned long long>(outcome.bounces), within, kLevelThrowCount, largest, below,
                      referenceBelow);
        text += line;
    }
    note(text);
}

void BM_DemoLevel(benchmark::State& state, LevelWorld which, ProjectileMethod method) {
    const LevelWorlds& w = levelWorlds();
    compareLevelOnce(method);
    const CollisionWorld& world = levelWorld(w, which);
    ProjectileSettings settings;  // the defaults: 0.02 s step (50 Hz), restitution 0.5
    settings.method = method;
    timeThrows(state, w.throws, kLevelFuse, settings, world, true);
}
// Registered by name: BENCHMARK_CAPTURE's name token would carry the formatter's spaces.
void registerDemoLevelBenchmarks() {
    const std::pair<const char*, LevelWorld> worlds[] = {{"Embree", LevelWorld::Embree},
                                                         {"Bullet", LevelWorld::Bullet},
                                                         {"Static", LevelWorld::Static},
                                                         {"Callback", LevelWorld::Callback}};
    for (const auto& [name, which] : worlds)
        for (const ProjectileMethod method : {ProjectileMethod::Exact, ProjectileMethod::Stepped}) {
            const std::string label =
                std::string("BM_DemoLevel/") + name + "/" + (method == ProjectileMethod::Exact ? "Exact" : "Stepped");
            benchmark::RegisterBenchmark(label.c_str(), BM_DemoLevel, which, method)->Unit(benchmark::kMillisecond);
        }
}
const bool kDemoLevelRegistered = (registerDemoLevelBenchmarks(), true);

/// The exact / stepped target through one world as a ratio within one benchmark (timeInTurns):
/// the 64 throws with each method in turns.
void BM_DemoLevelTurns(benchmark::State& state, LevelWorld which) {
    const LevelWorlds& w = levelWorlds();
    const CollisionWorld& world = levelWorld(w, which);
    ProjectileSettings exact, stepped;
    exact.method = ProjectileMethod::Exact;
    stepped.method = ProjectileMethod::Stepped;
    std::vector<TrajectoryPoint> trajectory(
        std::max(trajectoryCapacity(kLevelFuse, exact, 256), trajectoryCapacity(kLevelFuse, stepped, 256)));
    double sum = 0;
    const auto throwAll = [&](const ProjectileSettings& settings) {
        for (const foresight_bench::Throw& t : w.throws) {
            ProjectileResult result;
            if (predictProjectile(t.position, t.velocity, kLevelFuse, settings, &world, trajectory, result) !=
                Status::Ok)
                fail("a demo level prediction failed");
            sum += static_cast<double>(result.position.x);
        }
    };
    const std::array<Part, 2> parts{{{"exact", [&] { throwAll(exact); }}, {"stepped", [&] { throwAll(stepped); }}}};
    const std::array<TimeRatio, 1> ratios{{{"exact/stepped", 0, 1}}};
    timeInTurns(state, parts, ratios);
    benchmark::DoNotOptimize(sum);
}
// clang-format off
BENCHMARK_CAPTURE(BM_DemoLevelTurns, Embree, LevelWorld::Embree)->Name("BM_Turns/DemoLevel/Embree")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DemoLevelTurns, Static, LevelWorld::Static)->Name("BM_Turns/DemoLevel/Static")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DemoLevelTurns, Callback, LevelWorld::Callback)->Name("BM_Turns/DemoLevel/Callback")
    ->Unit(benchmark::kMillisecond);
// clang-format on

// ---------------------------------------------------------------------------------------------
// Engine-matched throws against stepping the real engine

constexpr int kEngineHz = 60;
constexpr int kEngineSteps = 3 * kEngineHz;
constexpr float kEngineRadius = 0.1f, kEngineRestitution = 0.5f, kEngineFriction = 0.3f;

ProjectileSettings engineSettings() {
    ProjectileSettings settings;
    settings.method = ProjectileMethod::Engine;
    settings.engine = engineProfile(PhysicsEngine::Bullet);
    settings.engine.timestep = 1.0f / kEngineHz;
    settings.engine.triangleMesh = true;  // the level is one btBvhTriangleMeshShape
    settings.step = settings.engine.timestep;
    settings.radius = kEngineRadius;
    settings.restitution = kEngineRestitution;
    settings.friction = kEngineFriction;
    return settings;
}

/// A Bullet dynamics world holding the demo level as one static triangle mesh, stepped with one
/// sphere per throw as a game's cloned physics scene would be.
class BulletLevelDynamics {
public:
    explicit BulletLevelDynamics(const Mesh& mesh)
        : mDispatcher(&mConfiguration), mWorld(&mDispatcher, &mBroadphase, &mSolver, &mConfiguration),
          mSphere(kEngineRadius) {
        for (const RVec3& v : mesh.vertices)
            mMesh.findOrAddVertex(btVector3(btScalar(v.x), btScalar(v.y), btScalar(v.z)), false);
        for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
            mMesh.addTriangleIndices(static_cast<int>(mesh.indices[i]), static_cast<int>(mesh.indices[i + 1]),
                                     static_cast<int>(mesh.indices[i + 2]));
        mLevelShape = std::make_unique<btBvhTriangleMeshShape>(&mMesh, true);
        mLevelShape->setMargin(btScalar(0));
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, mLevelShape.get());
        info.m_restitution = 1;  // Bullet multiplies the two: the throw's value stays
        info.m_friction = 1;
        mLevel = std::make_unique<btRigidBody>(info);
        mWorld.addRigidBody(mLevel.get());
        mWorld.setGravity(btVector3(0, btScalar(-9.81), 0));
    }
    ~BulletLevelDynamics() { mWorld.removeRigidBody(mLevel.get()); }
    BulletLevelDynamics(const BulletLevelDynamics&) = delete;
    BulletLevelDynamics& operator=(const BulletLevelDynamics&) = delete;

    /// The sphere's centre after kEngineSteps steps; with `steps`, also its centre and velocity
    /// after each step.
    RVec3 simulate(const foresight_bench::Throw& t, std::vector<TrajectoryPoint>* steps = nullptr) {
        btVector3 inertia;
        mSphere.calculateLocalInertia(1, inertia);
        btTransform start;
        start.setIdentity();
        start.setOrigin(btVector3(btScalar(t.position.x), btScalar(t.position.y), btScalar(t.position.z)));
        btDefaultMotionState motion(start);
        btRigidBody::btRigidBodyConstructionInfo info(1, &motion, &mSphere, inertia);
        info.m_restitution = kEngineRestitution;
        info.m_friction = kEngineFriction;
        btRigidBody body(info);
        body.setLinearVelocity(btVector3(t.velocity.x, t.velocity.y, t.velocity.z));
        body.setActivationState(DISABLE_DEACTIVATION);
        mWorld.addRigidBody(&body);
        if (steps) steps->clear();
        for (int k = 0; k < kEngineSteps; ++k) {
            mWorld.stepSimulation(btScalar(1.0 / kEngineHz), 0);
            if (!steps) continue;
            const btVector3 p = body.getWorldTransform().getOrigin(), v = body.getLinearVelocity();
            TrajectoryPoint point;
            point.position = RVec3(p.x(), p.y(), p.z());
            point.velocity = Vec3(v.x(), v.y(), v.z());
            steps->push_back(point);
        }
        const btVector3 end = body.getWorldTransform().getOrigin();
        mWorld.removeRigidBody(&body);
        return RVec3(end.x(), end.y(), end.z());
    }

private:
    btDefaultCollisionConfiguration mConfiguration;
    btCollisionDispatcher mDispatcher;
    btDbvtBroadphase mBroadphase;
    btSequentialImpulseConstraintSolver mSolver;
    btDiscreteDynamicsWorld mWorld;
    btTriangleMesh mMesh;
    std::unique_ptr<btBvhTriangleMeshShape> mLevelShape;
    std::unique_ptr<btRigidBody> mLevel;
    btSphereShape mSphere;
};

BulletLevelDynamics& levelDynamics() {
    static const std::unique_ptr<BulletLevelDynamics> dynamics = [] {
        BuildTimer timer;
        auto d = std::make_unique<BulletLevelDynamics>(levelWorlds().mesh);
        note("demo level as a btDiscreteDynamicsWorld: " + timer.report());
        return d;
    }();
    return *dynamics;
}

/// "N of 64 end within 2 cm, median end distance M m" for end distances (sorted here).
std::string describeEnds(std::vector<double>& errors) {
    std::sort(errors.begin(), errors.end());
    const auto within = std::count_if(errors.begin(), errors.end(), [](double e) { return e <= 0.02; });
    char text[120];
    std::snprintf(text, sizeof text, "%td of %zu end within 2 cm, median end distance %.3g m", within, errors.size(),
                  errors[errors.size() / 2]);
    return text;
}

/// The demo level with its floor as two triangles instead of 1 m tiles: the same surfaces,
/// without the tiles' internal edges.
Mesh levelWithOneFloorQuad(const LevelWorlds& w) {
    Mesh mesh;
    mesh.vertices = w.mesh.vertices;
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const RVec3& v : {RVec3(-18, 0, -18), RVec3(-18, 0, 18), RVec3(18, 0, 18), RVec3(18, 0, -18)})
        mesh.vertices.push_back(v);
    for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    mesh.indices.insert(mesh.indices.end(), w.mesh.indices.begin() + 3 * std::ptrdiff_t{w.floorTriangles},
                        w.mesh.indices.end());
    return mesh;
}

/// For a throw that ends more than 2 cm from Bullet's: the step where the prediction's centre
/// first leaves Bullet's by more than 0.1 mm, and the two steps before it (stderr).
void printDivergence(std::size_t throwIndex, std::span<const TrajectoryPoint> predicted,
                     std::span<const TrajectoryPoint> bullet) {
    // predicted[k] is after step k (predicted[0] the start); bullet[k - 1] is after step k.
    const std::size_t steps = std::min(predicted.size() - 1, bullet.size());
    std::size_t first = 1;
    while (first < steps &&
           glm::length(glm::dvec3(predicted[first].position) - glm::dvec3(bullet[first - 1].position)) <= 1e-4)
        ++first;
    std::fprintf(stderr, "throw %zu leaves Bullet at step %zu:\n", throwIndex, first);
    for (std::size_t k = first > 2 ? first - 2 : 1; k <= first && k <= steps; ++k) {
        const TrajectoryPoint &a = predicted[k], &b = bullet[k - 1];
        std::fprintf(stderr,
                     "  step %3zu predicted (%.5f %.5f %.5f) v (%.4f %.4f %.4f) contact normal (%.3f %.3f %.3f)\n"
                     "           Bullet    (%.5f %.5f %.5f) v (%.4f %.4f %.4f)\n",
                     k, static_cast<double>(a.position.x), static_cast<double>(a.position.y),
                     static_cast<double>(a.position.z), a.velocity.x, a.velocity.y, a.velocity.z, a.normal.x,
                     a.normal.y, a.normal.z, static_cast<double>(b.position.x), static_cast<double>(b.position.y),
                     static_cast<double>(b.position.z), b.velocity.x, b.velocity.y, b.velocity.z);
    }
}

/// Once: how far the engine-matched predictions end from the stepped Bullet world. Bullet
/// collides a triangle mesh triangle by triangle: near the floor tiles' internal edges (and
/// vertices) a penetrating sphere also gets contacts from the neighbouring triangles, with
/// normals tilted towards the edge, which a cast against the surface cannot see. The second
/// line measures that: the same level with the floor as two triangles, Bullet against itself
/// (how far the triangulation alone moves Bullet's ends) and the prediction against that world.
void compareEngineOnce() {
    static bool done = false;
    if (done) return;
    done = true;
    const LevelWorlds& w = levelWorlds();
    const ProjectileSettings settings = engineSettings();
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(kLevelFuse, settings, 256));
    auto predict = [&](const CollisionWorld& world, const foresight_bench::Throw& t) {
        ProjectileResult result;
        if (predictProjectile(t.position, t.velocity, kLevelFuse, settings, &world, trajectory, result) != Status::Ok)
            fail("an engine-matched demo level prediction failed");
        return result;
    };
    // FORESIGHT_BENCH_ENGINE_DIVERGENCE=1: where each throw that misses first leaves Bullet.
    const bool divergence = std::getenv("FORESIGHT_BENCH_ENGINE_DIVERGENCE") != nullptr;
    std::vector<TrajectoryPoint> bulletSteps;
    std::vector<double> errors;
    std::size_t contactSteps = 0;
    for (const foresight_bench::Throw& t : w.throws) {
        const ProjectileResult result = predict(*w.embree, t);
        for (std::size_t i = 0; i < result.trajectorySize; ++i)
            contactSteps += trajectory[i].event == TrajectoryEvent::Bounce ? 1 : 0;
        const RVec3 engine = levelDynamics().simulate(t, divergence ? &bulletSteps : nullptr);
        errors.push_back(glm::length(glm::dvec3(result.position) - glm::dvec3(engine)));
        if (divergence && errors.back() > 0.02)
            printDivergence(errors.size() - 1, std::span(trajectory.data(), result.trajectorySize), bulletSteps);
    }
    char line[300];
    std::snprintf(line, sizeof line,
                  "demo level, engine-matched (Bullet profile) against the stepped Bullet world: %s; %.0f %% of "
                  "the steps in contact",
                  describeEnds(errors).c_str(),
                  100.0 * static_cast<double>(contactSteps) / (kLevelThrowCount * kEngineSteps));
    note(line);

    const Mesh quad = levelWithOneFloorQuad(w);
    EmbreeWorld quadWorld;
    std::string error;
    if (quadWorld.addMesh(quad.vertices, quad.indices) != Status::Ok || !quadWorld.commit(&error))
        fail("EmbreeWorld refused the demo level with one floor quad " + error);
    BulletLevelDynamics quadDynamics(quad);
    std::vector<double> bulletSelf, predicted;
    for (const foresight_bench::Throw& t : w.throws) {
        const glm::dvec3 engine(quadDynamics.simulate(t));
        bulletSelf.push_back(glm::length(glm::dvec3(levelDynamics().simulate(t)) - engine));
        predicted.push_back(glm::length(glm::dvec3(predict(quadWorld, t).position) - engine));
    }
    note("demo level with the floor as two triangles instead of " + std::to_string(w.floorTriangles) +
         " (the same surfaces): the tiled level's Bullet ends against it: " + describeEnds(bulletSelf) +
         "; engine-matched against it: " + describeEnds(predicted));
}

void BM_EngineThrowPredict(benchmark::State& state, LevelWorld which) {
    const LevelWorlds& w = levelWorlds();
    compareEngineOnce();
    const CollisionWorld& world = levelWorld(w, which);
    const ProjectileSettings settings = engineSettings();
    timeThrows(state, w.throws, kLevelFuse, settings, world, false);
}

void BM_EngineThrowBulletStep(benchmark::State& state) {
    const LevelWorlds& w = levelWorlds();
    compareEngineOnce();
    BulletLevelDynamics& dynamics = levelDynamics();
    for (auto _ : state) {
        for (const foresight_bench::Throw& t : w.throws) {
            RVec3 end = dynamics.simulate(t);
            benchmark::DoNotOptimize(end);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * kLevelThrowCount);
}
// clang-format off
BENCHMARK_CAPTURE(BM_EngineThrowPredict, Embree, LevelWorld::Embree)->Name("BM_EngineThrow/Predict/Embree")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EngineThrowPredict, Bullet, LevelWorld::Bullet)->Name("BM_EngineThrow/Predict/Bullet")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EngineThrowBulletStep)->Name("BM_EngineThrow/BulletStep")->Unit(benchmark::kMillisecond);
// clang-format on

/// The engine-matched target as a ratio within one benchmark (timeInTurns): stepping the Bullet
/// world's 64 throws over predicting them through EmbreeWorld.
void BM_EngineThrowTurns(benchmark::State& state) {
    const LevelWorlds& w = levelWorlds();
    compareEngineOnce();
    BulletLevelDynamics& dynamics = levelDynamics();
    const ProjectileSettings settings = engineSettings();
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(kLevelFuse, settings, 256));
    double sum = 0;
    const std::array<Part, 2> parts{{
        {"predict",
         [&] {
             for (const foresight_bench::Throw& t : w.throws) {
                 ProjectileResult result;
                 if (predictProjectile(t.position, t.velocity, kLevelFuse, settings, w.embree.get(), trajectory,
                                       result) != Status::Ok)
                     fail("an engine-matched demo level prediction failed");
                 sum += static_cast<double>(result.position.x);
             }
         }},
        {"bulletStep",
         [&] {
             for (const foresight_bench::Throw& t : w.throws) sum += static_cast<double>(dynamics.simulate(t).x);
         }},
    }};
    const std::array<TimeRatio, 1> ratios{{{"bulletStep/predict", 1, 0}}};
    timeInTurns(state, parts, ratios);
    benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_EngineThrowTurns)->Name("BM_Turns/EngineThrow")->Unit(benchmark::kMillisecond);

#endif  // FORESIGHT_BENCH_DEMO_LEVEL

}  // namespace

BENCHMARK_MAIN();
