// foresight::bullet against the built-in world: the same scene as a StaticWorld and as a Bullet
// world (BulletScene), the same casts through both, the same first hits; a projectile through
// BulletWorld in a closed room. StaticWorld's casts are exact (analytic, double), so it is the
// reference here; the deviations are Bullet's (btScalar = float, GJK, sweep margins).
//
// This binary replaces global operator new (and Bullet's btAlignedAlloc) to count allocations.

#include "test_util.h"

#include <foresight/bullet_world.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <vector>

namespace {
std::atomic<long> gAllocations{0};

void* countedAllocate(std::size_t size) {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size == 0 ? 1 : size);
}
[[gnu::noinline]] void countedRelease(void* p) noexcept { std::free(p); }

// Bullet allocates through btAlignedAlloc, which calls these (16-byte alignment).
void* bulletAllocate(std::size_t size, int alignment) {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    const auto align = static_cast<std::size_t>(std::max(alignment, 16));
    return std::aligned_alloc(align, (std::max<std::size_t>(size, 1) + align - 1) / align * align);
}
void bulletRelease(void* p) { std::free(p); }
void* bulletAllocateUnaligned(std::size_t size) { return bulletAllocate(size, 16); }
}  // namespace

void* operator new(std::size_t size) {
    if (void* p = countedAllocate(size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    if (void* p = countedAllocate(size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { countedRelease(p); }
void operator delete[](void* p) noexcept { countedRelease(p); }
void operator delete(void* p, std::size_t) noexcept { countedRelease(p); }
void operator delete[](void* p, std::size_t) noexcept { countedRelease(p); }

namespace {

using foresight::BulletScene;
using foresight::BulletWorld;
using foresight::CastHit;
using foresight::OrientedBox;
using foresight::Plane;
using foresight::ProjectileResult;
using foresight::ProjectileSettings;
using foresight::RVec3;
using foresight::SegmentCast;
using foresight::Sphere;
using foresight::StaticWorld;
using foresight::Status;
using foresight::TrajectoryPoint;
using foresight::Triangle;
using foresight::Vec3;
using ftest::DVec3;
using ftest::toD;
using ftest::toF;
using ftest::toR;

// Small deterministic generator (no <random> distributions: CONTRIBUTING.md).
class Random {
public:
    explicit Random(std::uint64_t seed) : mState(seed) {}
    std::uint64_t next() {
        mState ^= mState << 13;
        mState ^= mState >> 7;
        mState ^= mState << 17;
        return mState;
    }
    double uniform(double lo, double hi) {
        return lo + (hi - lo) * static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0);
    }
    DVec3 inBox(const DVec3& lo, const DVec3& hi) {
        return DVec3(uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z));
    }
    DVec3 direction() {
        for (;;) {
            const DVec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    }

private:
    std::uint64_t mState;
};

// Both worlds built from the same shapes, with the same validation.
struct TwinWorld {
    StaticWorld reference;
    BulletScene scene;
    std::vector<Triangle> mesh;

    void add(const auto& shape) {
        ASSERT_EQ(reference.add(shape), Status::Ok);
        ASSERT_EQ(scene.add(shape), Status::Ok);
    }
    void finishMesh() {
        for (const Triangle& t : mesh) ASSERT_EQ(reference.add(t), Status::Ok);
        ASSERT_EQ(scene.addMesh(mesh), Status::Ok);
    }
};

foresight::Quat rotation(double angle, DVec3 axis) {
    return glm::angleAxis(static_cast<float>(angle), toF(glm::normalize(axis)));
}

// A walled yard: floor, a tilted plane, spheres, rotated boxes and a triangle mesh (a ridge of
// a tent: two slanted quads, and a small pyramid), all inside [-10, 10]^2 x [0, 8].
void buildYard(TwinWorld& w) {
    w.add(Plane{Vec3(0, 1, 0), 0});
    w.add(Plane{glm::normalize(Vec3(-1, 0.3f, 0)), -9.0f});  // a leaning wall at x ~ 9
    w.add(Sphere{RVec3(-4, 1.5f, 3), 1.5f});
    w.add(Sphere{RVec3(5, 3, -5), 1.0f});
    w.add(OrientedBox{RVec3(2, 1, 4), Vec3(1.5f, 1, 0.75f), rotation(0.6, DVec3(0, 1, 0))});
    w.add(OrientedBox{RVec3(-5, 2, -4), Vec3(0.5f, 2, 2), rotation(0.4, DVec3(1, 1, 0))});
    const RVec3 a(-2, 0.5f, -8), b(3, 0.5f, -8), c(3, 3, -6), d(-2, 3, -6), e(3, 0.5f, -4), f(-2, 0.5f, -4);
    w.mesh = {Triangle{a, b, c}, Triangle{a, c, d}, Triangle{d, c, e}, Triangle{d, e, f}};
    const RVec3 p0(6, 0, 5), p1(8, 0, 5), p2(7, 0, 7), top(7, 2, 5.7f);
    w.mesh.push_back(Triangle{p0, p1, top});
    w.mesh.push_back(Triangle{p1, p2, top});
    w.mesh.push_back(Triangle{p2, p0, top});
    w.finishMesh();
}

// Signed distance of `p` to the solids of the yard's StaticWorld (planes, spheres, boxes), used
// to keep random starts outside them: the contract for starts inside a solid is "no hit" but
// Bullet's answer there is its own (see bullet_world.h).
double solidDistance(const StaticWorld& world, const DVec3& p) {
    double d = 1e30;
    for (const Plane& plane : world.planes())
        d = std::min(d, glm::dot(toD(plane.normal), p) - static_cast<double>(plane.distance));
    for (const Sphere& s : world.spheres())
        d = std::min(d, glm::length(p - toD(s.center)) - static_cast<double>(s.radius));
    for (const OrientedBox& b : world.boxes()) {
        const ftest::DQuat q = ftest::toD(b.orientation);
        const DVec3 local = glm::conjugate(q) * (p - toD(b.center));
        const DVec3 qd = glm::abs(local) - toD(b.halfExtents);
        d = std::min(d, glm::length(glm::max(qd, DVec3(0.0))) + std::min(std::max({qd.x, qd.y, qd.z}), 0.0));
    }
    return d;
}

// Distance from `p` to the nearest triangle of the mesh (for sphere starts).
double meshDistance(const std::vector<Triangle>& mesh, const DVec3& p) {
    double best = 1e30;
    for (const Triangle& t : mesh) {
        // Sampled closest point is enough here (a margin check, not a reference value).
        const DVec3 a = toD(t.a), b = toD(t.b), c = toD(t.c);
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; i + j <= 20; ++j) {
                const DVec3 q = a + (b - a) * (i / 20.0) + (c - a) * (j / 20.0);
                best = std::min(best, glm::length(p - q));
            }
    }
    return best;
}

struct Deviation {
    long casts = 0, hits = 0, mismatched = 0;
    double fraction = 0, position = 0, normal = 0, surfaceGap = 0;
    void print(const char* label) const {
        std::printf("[ %s ] %ld casts, %ld hits, %ld hit/miss mismatches; max |d fraction * length| %.3g m, "
                    "max position %.3g m, max normal %.3g, max gap %.3g m\n",
                    label, casts, hits, mismatched, fraction, position, normal, surfaceGap);
    }
};

// Casts `cast` through both worlds and records the differences.
void compare(const StaticWorld& reference, const BulletWorld& bullet, const SegmentCast& cast,
             Deviation& dev, double positionTolerance, double normalTolerance, long maxMismatches) {
    CastHit expected, actual;
    const bool hitExpected = reference.castSegment(cast, expected);
    const bool hitActual = bullet.castSegment(cast, actual);
    ++dev.casts;
    if (hitExpected != hitActual) {
        ++dev.mismatched;
        if (dev.mismatched <= maxMismatches) return;
        ADD_FAILURE() << "hit " << hitExpected << " vs bullet " << hitActual << " from "
                      << ftest::describe(toD(cast.origin)) << " by " << ftest::describe(toD(cast.displacement))
                      << " radius " << cast.radius
                      << (hitExpected ? " expected at " + std::to_string(expected.fraction) : std::string())
                      << (hitActual ? " bullet at " + std::to_string(actual.fraction) : std::string());
        return;
    }
    if (!hitExpected) return;
    ++dev.hits;
    const double length = glm::length(toD(cast.displacement));
    const double df = std::abs(static_cast<double>(expected.fraction) - static_cast<double>(actual.fraction)) * length;
    const double dp = glm::length(toD(expected.position) - toD(actual.position));
    const double dn = glm::length(toD(expected.normal) - toD(actual.normal));
    dev.fraction = std::max(dev.fraction, df);
    dev.position = std::max(dev.position, dp);
    dev.normal = std::max(dev.normal, dn);
    // The gap along the reference normal between the two hit positions: what a sweep's
    // conservative advancement leaves (it stops short of the contact along the normal).
    dev.surfaceGap = std::max(dev.surfaceGap,
                              std::abs(glm::dot(toD(expected.position) - toD(actual.position), toD(expected.normal))));
    EXPECT_LE(dp, positionTolerance) << "from " << ftest::describe(toD(cast.origin)) << " by "
                                     << ftest::describe(toD(cast.displacement)) << " radius " << cast.radius
                                     << " fractions " << expected.fraction << " / " << actual.fraction;
    EXPECT_LE(dn, normalTolerance) << "normals " << ftest::describe(toD(expected.normal)) << " vs "
                                   << ftest::describe(toD(actual.normal));
    EXPECT_LT(glm::dot(toD(actual.normal), toD(cast.displacement)), 0.0);
}

const DVec3 kYardLo(-9.5, 0.0, -9.5), kYardHi(8.5, 8.0, 9.5);

// 10 000 random segments, radius 0: hits agree within 1e-4 m and normals within 1e-3.
TEST(BulletWorld, RaysMatchStaticWorld) {
    TwinWorld w;
    buildYard(w);
    const BulletWorld bullet(w.scene.world());
    Random random(12345);
    Deviation dev;
    int made = 0;
    while (made < 10000) {
        const DVec3 origin = random.inBox(kYardLo, kYardHi);
        // Outside the solids by 1 mm: a start inside a solid is Bullet's to answer.
        if (solidDistance(w.reference, origin) < 1e-3) continue;
        const DVec3 displacement = random.direction() * random.uniform(0.05, 12.0);
        ++made;
        // Bullet computes in float: 1e-4 m is ~50 float ulps at 10 m (its ray-triangle and
        // ray-plane tests subtract coordinates of that size); normals: float and the GJK ray
        // cast on spheres.
        compare(w.reference, bullet, SegmentCast{toR(origin), toF(displacement), 0.0f}, dev, 1e-4, 1e-3, 0);
    }
    dev.print("rays");
    EXPECT_GT(dev.hits, 3000);
}
