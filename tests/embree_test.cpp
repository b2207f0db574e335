// EmbreeWorld (backends/embree): same hits as StaticWorld on the same shapes, projectiles stay
// inside a closed mesh room, file loaders and their errors, concurrent casts.
#include <foresight/embree_world.h>
#include <foresight/foresight.h>

#include <gtest/gtest.h>

#include "counting_allocator.h"  // replaces operator new/delete in this binary (counts them)

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using foresight::CastHit;
using foresight::EmbreeWorld;
using foresight::PlaneRegion;
using foresight::RVec3;
using foresight::SegmentCast;
using foresight::StaticWorld;
using foresight::Status;
using foresight::Triangle;
using foresight::Vec3;
using DVec3 = glm::dvec3;
namespace fs = std::filesystem;

RVec3 r3(double x, double y, double z) {
    using R = foresight::Real;
    return RVec3(static_cast<R>(x), static_cast<R>(y), static_cast<R>(z));
}
DVec3 d3(const RVec3& v) { return DVec3(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)); }

// An indexed mesh.
struct Mesh {
    std::vector<RVec3> vertices;
    std::vector<std::uint32_t> indices;
};

// An axis-aligned box as 12 triangles; `inward` flips nothing (triangles are two-sided) but the
// room is the same shape seen from inside.
void addBoxMesh(Mesh& mesh, const DVec3& lo, const DVec3& hi) {
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (int i = 0; i < 8; ++i)
        mesh.vertices.push_back(r3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z));
    // Faces as quads (corner bits), split in two.
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        for (const int k : {q[0], q[1], q[2], q[0], q[2], q[3]})
            mesh.indices.push_back(base + static_cast<std::uint32_t>(k));
    }
}

// The room (10 x 4 x 8, closed), a few boxes inside it, a ramp; plus primitives.
Mesh sceneMesh() {
    Mesh mesh;
    addBoxMesh(mesh, DVec3(-5, 0, -4), DVec3(5, 4, 4));
    addBoxMesh(mesh, DVec3(-3, 0, -2), DVec3(-2, 1, -1));
    addBoxMesh(mesh, DVec3(1, 0, 1), DVec3(2.5, 2, 1.5));
    addBoxMesh(mesh, DVec3(-1, 1.5, 2), DVec3(0, 2.5, 3));  // floating
    addBoxMesh(mesh, DVec3(3, 0, -3), DVec3(3.2, 3, -1));   // a thin wall
    // A ramp (two triangles) and a degenerate triangle (skipped).
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back(r3(-4, 0, 1));
    mesh.vertices.push_back(r3(-2, 1, 1));
    mesh.vertices.push_back(r3(-2, 1, 3));
    mesh.vertices.push_back(r3(-4, 0, 3));
    for (const std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u, 0u, 0u, 1u}) mesh.indices.push_back(base + k);
    return mesh;
}

void addPrimitives(auto& world) {
    ASSERT_EQ(world.add(foresight::Sphere{r3(0, 1, -2), 0.5f}), Status::Ok);
    foresight::OrientedBox box;
    box.center = r3(2, 0.5, -2);
    box.halfExtents = Vec3(0.3f, 0.5f, 0.4f);
    box.orientation = glm::angleAxis(0.6f, glm::normalize(Vec3(0.2f, 1.0f, 0.1f)));
    ASSERT_EQ(world.add(box), Status::Ok);
    ASSERT_EQ(world.add(foresight::Plane{Vec3(0, 1, 0), -1}), Status::Ok);  // below the room
    ASSERT_EQ(world.add(Triangle{r3(-1, 3, -1), r3(1, 3, -1), r3(0, 3.5, 0.5)}), Status::Ok);
}

struct Worlds {
    StaticWorld reference;
    EmbreeWorld embree;
    std::vector<Triangle> meshTriangles;  // valid ones, in order
};

// Both worlds with the same shapes: primitives, then the mesh triangles in order.
void buildWorlds(Worlds& w) {
    addPrimitives(w.reference);
    addPrimitives(w.embree);
    const Mesh mesh = sceneMesh();
    foresight::MeshReport report;
    ASSERT_EQ(w.embree.addMesh(mesh.vertices, mesh.indices, &report), Status::Ok) << report.error;
    EXPECT_EQ(report.degenerateTriangles, 1u);
    EXPECT_EQ(report.firstDegenerateTriangle, mesh.indices.size() / 3 - 1);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Triangle tri{mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                           mesh.vertices[mesh.indices[t + 2]]};
        if (foresight::validateTriangle(tri) == Status::Ok) {
            w.meshTriangles.push_back(tri);
            ASSERT_EQ(w.reference.add(tri), Status::Ok);
        }
    }
    EXPECT_EQ(report.triangles, w.meshTriangles.size());
    EXPECT_EQ(w.embree.meshTriangleCount(), w.meshTriangles.size());
    std::string error;
    ASSERT_TRUE(w.embree.commit(&error)) << error;
}

// Random segments, many of them special: starting on a surface, grazing an edge or a vertex,
// parallel to a face, zero length.
std::vector<SegmentCast> randomCasts(const std::vector<Triangle>& triangles, int count, float radius,
                                     std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto inRoom = [&] { return DVec3(-5.5 + 11 * u(rng), -0.5 + 5 * u(rng), -4.5 + 9 * u(rng)); };
    auto direction = [&] {
        DVec3 d;
        do d = DVec3(2 * u(rng) - 1, 2 * u(rng) - 1, 2 * u(rng) - 1);
        while (glm::length(d) < 0.1 || glm::length(d) > 1.0);
        return glm::normalize(d);
    };
    auto pickTriangle = [&]() -> const Triangle& {
        return triangles[static_cast<std::size_t>(u(rng) * static_cast<double>(triangles.size())) % triangles.size()];
    };
    std::vector<SegmentCast> casts;
    casts.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        SegmentCast cast;
        cast.radius = radius;
        DVec3 origin = inRoom();
        DVec3 displacement = direction() * (0.01 + 6 * u(rng));
        switch (i % 8) {
            case 0:
            case 1:
            case 2:
                break;  // plain
            case 3: {   // starts exactly on a triangle (or offset by the radius), moves in or out
                const Triangle& t = pickTriangle();
                const double a = u(rng), b = u(rng) * (1 - a);
                const DVec3 A = d3(t.a), B = d3(t.b), C = d3(t.c);
                const DVec3 n = glm::normalize(glm::cross(B - A, C - A));
                origin = A + (B - A) * a + (C - A) * b + n * (static_cast<double>(radius) * (u(rng) < 0.5 ? 1 : -1));
                break;
            }
            case 4: {  // aims exactly at an edge point (or a vertex) of a triangle
                const Triangle& t = pickTriangle();
                const DVec3 A = d3(t.a), B = d3(t.b);
                const double s = u(rng) < 0.3 ? 0.0 : u(rng);
                const DVec3 target = A + (B - A) * s;
                displacement = (target - origin) * (1.0 + u(rng));
                break;
            }
            case 5: {  // parallel to a face, in its plane or a radius away
                const Triangle& t = pickTriangle();
                const DVec3 A = d3(t.a), B = d3(t.b), C = d3(t.c);
                const DVec3 n = glm::normalize(glm::cross(B - A, C - A));
                origin = A + (B - A) * (u(rng) * 1.4 - 0.2) + (C - A) * (u(rng) * 0.5) +
                         n * (u(rng) < 0.5 ? 0.0 : static_cast<double>(radius));
                DVec3 d = direction();
                d -= n * glm::dot(d, n);
                if (glm::length(d) < 1e-3) d = glm::normalize(B - A);
                displacement = glm::normalize(d) * (0.1 + 4 * u(rng));
                break;
            }
            case 6:  // zero length
                if (u(rng) < 0.5)
                    displacement = DVec3(0.0);
                else
                    displacement = direction() * 1e-7;
                break;
            case 7: {  // from a vertex of one triangle to a vertex of another
                origin = d3(pickTriangle().a);
                displacement = d3(pickTriangle().c) - origin;
                break;
            }
        }
        cast.origin = r3(origin.x, origin.y, origin.z);
        cast.displacement = Vec3(displacement);
        casts.push_back(cast);
    }
    return casts;
}

struct Outcome {
    bool hit = false;
    CastHit value;
};

void expectSame(const Outcome& expected, const Outcome& actual, const SegmentCast& cast, int index) {
    ASSERT_EQ(expected.hit, actual.hit) << "cast " << index << " from (" << cast.origin.x << ", " << cast.origin.y
                                        << ", " << cast.origin.z << ") by (" << cast.displacement.x << ", "
                                        << cast.displacement.y << ", " << cast.displacement.z << ") r " << cast.radius;
    if (!expected.hit) return;
    EXPECT_NEAR(expected.value.fraction, actual.value.fraction, 1e-6) << "cast " << index;
    EXPECT_LE(glm::length(d3(expected.value.position) - d3(actual.value.position)), 1e-4) << "cast " << index;
    EXPECT_LE(glm::length(DVec3(expected.value.normal - actual.value.normal)), 1e-5)
        << "cast " << index << " from (" << cast.origin.x << ", " << cast.origin.y << ", " << cast.origin.z << ") by ("
        << cast.displacement.x << ", " << cast.displacement.y << ", " << cast.displacement.z << ") r " << cast.radius
        << " fraction " << expected.value.fraction << " normal (" << expected.value.normal.x << ", "
        << expected.value.normal.y << ", " << expected.value.normal.z << ") vs (" << actual.value.normal.x << ", "
        << actual.value.normal.y << ", " << actual.value.normal.z << ")";
}

class embree_world : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        worlds = new Worlds;
        buildWorlds(*worlds);
    }
    static void TearDownTestSuite() {
        delete worlds;
        worlds = nullptr;
    }
    static Worlds* worlds;
};
Worlds* embree_world::worlds = nullptr;

// EmbreeWorld's documented reach of a graze for a ray cast (embree_world.h): rho divided by
// the sine of the angle between the segment and the triangle's plane (below 1e-3: 1e-3).
double grazeReach(const std::vector<Triangle>& triangles, const SegmentCast& cast, const Triangle& t) {
    double largest = 0.0;
    for (const Triangle& m : triangles)
        for (const RVec3& v : {m.a, m.b, m.c})
            largest = std::max({largest, std::abs(double(v.x)), std::abs(double(v.y)), std::abs(double(v.z))});
    const DVec3 o = d3(cast.origin), d(cast.displacement);
    const double length = glm::length(d);
    const double rho =
        1e-6 + std::ldexp(std::max({largest, std::abs(o.x), std::abs(o.y), std::abs(o.z)}) + length, -20);
    const DVec3 n = glm::normalize(glm::cross(d3(t.b) - d3(t.a), d3(t.c) - d3(t.a)));
    return rho / std::max(std::abs(glm::dot(n, d)) / length, 1e-3);
}

// The in-plane distance from `p` to the nearest edge line of `t`.
double edgeDistance(const Triangle& t, const DVec3& p) {
    const DVec3 a = d3(t.a), b = d3(t.b), c = d3(t.c);
    const DVec3 n = glm::normalize(glm::cross(b - a, c - a));
    auto line = [&](const DVec3& u, const DVec3& v) {
        return std::abs(glm::dot(n, glm::cross(v - u, p - u))) / glm::length(v - u);
    };
    return std::min({line(a, b), line(b, c), line(c, a)});
}

// The mesh triangles whose own exact test gives exactly `hit`.
std::vector<Triangle> trianglesGiving(const std::vector<Triangle>& triangles, const SegmentCast& cast,
                                      const CastHit& hit) {
    std::vector<Triangle> out;
    for (const Triangle& t : triangles) {
        foresight::ClosestHitCaster caster(cast);
        caster.test(t);
        CastHit h;
        if (caster.result(h) && h.fraction == hit.fraction && h.normal == hit.normal) out.push_back(t);
    }
    return out;
}

// Radius 0: EmbreeWorld may differ from StaticWorld only by missing a triangle that StaticWorld
// hits within the documented graze reach of its edges (Embree's float test can miss it there);
// it then reports a farther exact hit of another triangle, or none. Returns whether `actual`
// is such a case (and checks it); counted by the caller.
bool isDocumentedGraze(const Worlds& w, const Outcome& expected, const Outcome& actual, const SegmentCast& cast) {
    if (!expected.hit) return false;  // a hit where StaticWorld has none is never allowed
    if (actual.hit && actual.value.fraction < expected.value.fraction) return false;
    if (actual.hit && actual.value.fraction == expected.value.fraction && actual.value.normal == expected.value.normal)
        return false;
    bool grazed = false;
    const DVec3 p = d3(cast.origin) + DVec3(cast.displacement) * double(expected.value.fraction);
    for (const Triangle& t : trianglesGiving(w.meshTriangles, cast, expected.value))
        // 1e-6 relative: the hit point is rebuilt from the float fraction.
        grazed = grazed || edgeDistance(t, p) <=
                               grazeReach(w.meshTriangles, cast, t) + 1e-6 * glm::length(DVec3(cast.displacement));
    if (!grazed) return false;
    // What EmbreeWorld reports instead is an exact hit of a mesh triangle or the primitives'.
    if (!actual.hit || !trianglesGiving(w.meshTriangles, cast, actual.value).empty()) return true;
    StaticWorld primitives;
    addPrimitives(primitives);
    CastHit h;
    return primitives.castSegment(cast, h) && h.fraction == actual.value.fraction && h.normal == actual.value.normal;
}

void compareOnRandomCasts(const Worlds& w, float radius, std::uint32_t seed) {
    const auto casts = randomCasts(w.meshTriangles, 10000, radius, seed);
    int hits = 0, atStart = 0, grazes = 0;
    for (std::size_t i = 0; i < casts.size(); ++i) {
        Outcome expected, actual;
        expected.hit = w.reference.castSegment(casts[i], expected.value);
        actual.hit = w.embree.castSegment(casts[i], actual.value);
        hits += expected.hit ? 1 : 0;
        atStart += expected.hit && expected.value.fraction == 0.0f ? 1 : 0;
        if (radius == 0.0f && isDocumentedGraze(w, expected, actual, casts[i])) {
            ++grazes;
            continue;
        }
        expectSame(expected, actual, casts[i], static_cast<int>(i));
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(hits, 3000);  // the scene is closed: most casts hit something
    if (radius > 0.0f) {
        EXPECT_GT(atStart, 100);  // starts on a surface, moving in
    }
    // Grazes come from the casts aimed exactly at edges and vertices (cases 4 and 7, a quarter
    // of them); most of those agree all the same.
    EXPECT_LT(grazes, 250) << "grazes " << grazes;
    std::printf("[          ] %d of %zu casts graze an edge (documented difference)\n", grazes, casts.size());
}

TEST_F(embree_world, SameHitsAsStaticWorldForRays) { compareOnRandomCasts(*worlds, 0.0f, 1); }

TEST_F(embree_world, SameHitsAsStaticWorldForSpheres) { compareOnRandomCasts(*worlds, 0.1f, 2); }

TEST_F(embree_world, SameHitsBeforeCommit) {
    // Uncommitted: brute force over the mesh, still the same hits.
    Worlds local;
    addPrimitives(local.reference);
    addPrimitives(local.embree);
    Mesh mesh;
    addBoxMesh(mesh, DVec3(-1, -1, -1), DVec3(1, 1, 1));
    ASSERT_EQ(local.embree.addMesh(mesh.vertices, mesh.indices), Status::Ok);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const Triangle tri{mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                           mesh.vertices[mesh.indices[t + 2]]};
        local.meshTriangles.push_back(tri);
        ASSERT_EQ(local.reference.add(tri), Status::Ok);
    }
    for (const auto& cast : randomCasts(local.meshTriangles, 500, 0.05f, 3)) {
        Outcome expected, actual;
        expected.hit = local.reference.castSegment(cast, expected.value);
        actual.hit = local.embree.castSegment(cast, actual.value);
        expectSame(expected, actual, cast, 0);
    }
}

// A closed mesh sharing its vertices: an octahedron subdivided three times and pushed onto a
// sphere (512 triangles), off the origin.
Mesh closedSphereMesh(const DVec3& centre, double radius) {
    Mesh mesh;
    std::vector<DVec3> points{DVec3(1, 0, 0),  DVec3(-1, 0, 0), DVec3(0, 1, 0),
                              DVec3(0, -1, 0), DVec3(0, 0, 1),  DVec3(0, 0, -1)};
    std::vector<std::array<std::uint32_t, 3>> faces{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int level = 0; level < 3; ++level) {
        std::vector<std::array<std::uint32_t, 3>> finer;
        std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            for (const auto& m : midpoints)
                if (m.first == key) return m.second;
            points.push_back(glm::normalize(points[a] + points[b]));
            midpoints.emplace_back(key, static_cast<std::uint32_t>(points.size() - 1));
            return midpoints.back().second;
        };
        for (const auto& f : faces) {
            const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({ab, f[1], bc});
            finer.push_back({ca, bc, f[2]});
            finer.push_back({ab, bc, ca});
        }
        faces = finer;
    }
    for (const DVec3& q : points) {
        const DVec3 v = centre + q * radius;
        mesh.vertices.push_back(r3(v.x, v.y, v.z));
    }
    for (const auto& f : faces) mesh.indices.insert(mesh.indices.end(), f.begin(), f.end());
    return mesh;
}

TEST_F(embree_world, RaysThroughSharedEdgesAndVerticesOfAClosedMeshHit) {
    // Radius 0 through the float fast path: rays aimed exactly at shared vertices and at points
    // of shared edges (Embree's float test may put them on either side, or on neither triangle
    // by rounding) must never slip through a closed mesh, from outside or from inside.
    // Sketch: from far outside at each vertex / edge point (4 directions each); from the centre
    // outwards at the same points; the box room's corners and edges likewise.
    Mesh mesh = closedSphereMesh(DVec3(12.25, -3.5, 40.125), 2.0);
    ASSERT_EQ(mesh.indices.size(), 3u * 512u);
    addBoxMesh(mesh, DVec3(-5, 0, -4), DVec3(5, 4, 4));
    EmbreeWorld world;
    ASSERT_EQ(world.addMesh(mesh.vertices, mesh.indices), Status::Ok);
    ASSERT_TRUE(world.commit());
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto check = [&](const DVec3& from, const DVec3& target, const char* what) {
        const SegmentCast cast{r3(from.x, from.y, from.z), Vec3((target - from) * 1.5)};
        CastHit hit;
        EXPECT_TRUE(world.castSegment(cast, hit))
            << what << " aimed from (" << from.x << ", " << from.y << ", " << from.z << ") at (" << target.x << ", "
            << target.y << ", " << target.z << ")";
    };
    const std::size_t sphereIndices = 3 * 512;  // the sphere's come first, then the box's
    int aims = 0;
    for (const bool sphere : {true, false}) {
        const DVec3 centre = sphere ? DVec3(12.25, -3.5, 40.125) : DVec3(0.1, 2.05, -0.2);
        for (std::size_t t = sphere ? 0 : sphereIndices; t < (sphere ? sphereIndices : mesh.indices.size()); t += 3) {
            for (int k = 0; k < 3; ++k) {
                const DVec3 a = d3(mesh.vertices[mesh.indices[t + static_cast<std::size_t>(k)]]);
                const DVec3 b = d3(mesh.vertices[mesh.indices[t + static_cast<std::size_t>((k + 1) % 3)]]);
                for (const double s : {0.0, 0.5, u(rng)}) {
                    const DVec3 target = a + (b - a) * s;
                    const DVec3 out = glm::normalize(target - centre);
                    for (int d = 0; d < 4; ++d) {
                        // From outside, within 60 degrees of the outward direction.
                        DVec3 side(2 * u(rng) - 1, 2 * u(rng) - 1, 2 * u(rng) - 1);
                        side -= out * glm::dot(side, out);
                        const DVec3 from = target + (out + side * 0.8) * (3.0 + 5.0 * u(rng));
                        if (sphere) check(from, target, s == 0.0 ? "vertex" : "edge point");
                        ++aims;
                    }
                    check(centre, target, s == 0.0 ? "vertex (from inside)" : "edge point (from inside)");
                    ++aims;
                    if (::testing::Test::HasFailure()) return;
                }
            }
        }
    }
    EXPECT_GT(aims, 20000);
}

TEST_F(embree_world, SphereDoesNotPassThroughANarrowGap) {
    // Two walls 0.15 m apart with a 0.15 m slit; a 0.1 m sphere cannot pass, a point can.
    EmbreeWorld world;
    Mesh mesh;
    addBoxMesh(mesh, DVec3(-2, 0, 0), DVec3(-0.075, 2, 0.1));
    addBoxMesh(mesh, DVec3(0.075, 0, 0), DVec3(2, 2, 0.1));
    ASSERT_EQ(world.addMesh(mesh.vertices, mesh.indices), Status::Ok);
    ASSERT_TRUE(world.commit());
    CastHit hit;
    EXPECT_FALSE(world.castSegment(SegmentCast{r3(0, 1, -1), Vec3(0, 0, 2), 0.0f}, hit));
    ASSERT_TRUE(world.castSegment(SegmentCast{r3(0, 1, -1), Vec3(0, 0, 2), 0.1f}, hit));
    EXPECT_NEAR(hit.position.z, -0.1 + 0.0 - std::sqrt(0.1 * 0.1 - 0.075 * 0.075) + 0.1, 1e-4);
    EXPECT_TRUE(world.castSegment(SegmentCast{r3(0, 1, -1), Vec3(0, 0, 2), 0.076f}, hit));
    EXPECT_FALSE(world.castSegment(SegmentCast{r3(0, 1, -1), Vec3(0, 0, 2), 0.074f}, hit));
}

TEST_F(embree_world, ProjectilesStayInsideTheClosedRoom) {
    // The room alone (only the room's walls), throws from inside in every direction.
    EmbreeWorld room;
    Mesh mesh;
    addBoxMesh(mesh, DVec3(-5, 0, -4), DVec3(5, 4, 4));
    ASSERT_EQ(room.addMesh(mesh.vertices, mesh.indices), Status::Ok);
    ASSERT_TRUE(room.commit());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    foresight::ProjectileSettings settings;
    std::vector<foresight::TrajectoryPoint> points(foresight::trajectoryCapacity(3.0f, settings, 256));
    const double slack = 1e-4;
    for (int i = 0; i < 2000; ++i) {
        settings.restitution = static_cast<float>(u(rng));
        settings.friction = static_cast<float>(0.5 * u(rng));
        settings.radius = i % 2 == 0 ? 0.0f : static_cast<float>(0.2 * u(rng));
        const double r = static_cast<double>(settings.radius);
        const RVec3 start = r3(-5 + r + 0.01 + (10 - 2 * r - 0.02) * u(rng), r + 0.01 + (4 - 2 * r - 0.02) * u(rng),
                               -4 + r + 0.01 + (8 - 2 * r - 0.02) * u(rng));
        const Vec3 velocity(static_cast<float>(40 * u(rng) - 20), static_cast<float>(40 * u(rng) - 20),
                            static_cast<float>(40 * u(rng) - 20));
        foresight::ProjectileResult out;
        const Status status = foresight::predictProjectile(start, velocity, 3.0f, settings, &room, points, out);
        ASSERT_TRUE(status == Status::Ok || status == Status::TooManyEvents) << foresight::statusMessage(status);
        const std::size_t n = std::min(out.trajectorySize, points.size());
        for (std::size_t k = 0; k < n; ++k) {
            const DVec3 p = d3(points[k].position);
            ASSERT_TRUE(p.x >= -5 + r - slack && p.x <= 5 - r + slack && p.y >= r - slack && p.y <= 4 - r + slack &&
                        p.z >= -4 + r - slack && p.z <= 4 - r + slack)
                << "throw " << i << " point " << k << " at (" << p.x << ", " << p.y << ", " << p.z << ") radius " << r;
        }
    }
}

TEST_F(embree_world, ConcurrentCastsMatchSequential) {
    const auto casts = randomCasts(worlds->meshTriangles, 4000, 0.05f, 11);
    std::vector<Outcome> sequential(casts.size());
    for (std::size_t i = 0; i < casts.size(); ++i)
        sequential[i].hit = worlds->embree.castSegment(casts[i], sequential[i].value);
    std::vector<Outcome> parallel(casts.size());
    auto run = [&](std::size_t begin) {
        for (std::size_t i = begin; i < casts.size(); i += 2)
            parallel[i].hit = worlds->embree.castSegment(casts[i], parallel[i].value);
    };
    std::thread a(run, 0), b(run, 1);
    a.join();
    b.join();
    for (std::size_t i = 0; i < casts.size(); ++i) {
        ASSERT_EQ(sequential[i].hit, parallel[i].hit) << i;
        if (!sequential[i].hit) continue;
        EXPECT_EQ(sequential[i].value.fraction, parallel[i].value.fraction) << i;
        EXPECT_EQ(sequential[i].value.position, parallel[i].value.position) << i;
        EXPECT_EQ(sequential[i].value.normal, parallel[i].value.normal) << i;
    }
}

// Whether two casts' answers are the same, bit for bit (hit or miss; fraction, position, normal
// and material of a hit).
bool sameBits(bool hitA, const CastHit& a, bool hitB, const CastHit& b) {
    if (hitA != hitB) return false;
    if (!hitA) return true;
    return std::memcmp(&a.fraction, &b.fraction, sizeof a.fraction) == 0 &&
           std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
           std::memcmp(&a.normal, &b.normal, sizeof a.normal) == 0 &&
           std::memcmp(&a.restitution, &b.restitution, sizeof a.restitution) == 0 &&
           std::memcmp(&a.friction, &b.friction, sizeof a.friction) == 0;
}

// castSegments against castSegment, cast by cast: the same answers bit for bit, and the count.
void expectBatchMatchesSingle(const EmbreeWorld& world, const std::vector<SegmentCast>& casts) {
    std::vector<CastHit> hits(casts.size());
    std::vector<std::uint8_t> found(casts.size(), 7);
    const std::size_t count = world.castSegments(casts, hits, found);
    std::size_t expectedCount = 0;
    for (std::size_t i = 0; i < casts.size(); ++i) {
        CastHit single;
        const bool hit = world.castSegment(casts[i], single);
        expectedCount += hit ? 1 : 0;
        ASSERT_TRUE(found[i] == 0 || found[i] == 1) << i;
        ASSERT_TRUE(sameBits(hit, single, found[i] == 1, hits[i]))
            << "cast " << i << " from (" << casts[i].origin.x << ", " << casts[i].origin.y << ", " << casts[i].origin.z
            << ") by (" << casts[i].displacement.x << ", " << casts[i].displacement.y << ", " << casts[i].displacement.z
            << ") r " << casts[i].radius;
    }
    EXPECT_EQ(count, expectedCount);
}

TEST_F(embree_world, CastSegmentsGiveCastSegmentsAnswersBitForBit) {
    // The scene with primitives and the mesh; rays and spheres, plain and special (on a surface,
    // at edges and vertices, parallel, zero length, vertex to vertex: randomCasts' cases), in
    // batches of every length from 0 to 40 (groups of 16 and their remainders).
    for (const float radius : {0.0f, 0.05f}) {
        const auto casts = randomCasts(worlds->meshTriangles, 4000, radius, 21);
        expectBatchMatchesSingle(worlds->embree, casts);
        if (::testing::Test::HasFailure()) return;
        for (std::size_t length = 0; length <= 40; ++length)
            expectBatchMatchesSingle(worlds->embree,
                                     std::vector<SegmentCast>(casts.begin() + 100, casts.begin() + 100 + length));
    }
    // Rays and spheres mixed in one batch.
    auto mixed = randomCasts(worlds->meshTriangles, 2000, 0.0f, 22);
    for (std::size_t i = 0; i < mixed.size(); i += 3) mixed[i].radius = 0.1f;
    expectBatchMatchesSingle(worlds->embree, mixed);
}

TEST_F(embree_world, CastSegmentsStopAtTheShortestSpan) {
    // n = min of the three lengths; entries from n on are not touched.
    const auto casts = randomCasts(worlds->meshTriangles, 64, 0.0f, 23);
    std::vector<CastHit> hits(64);
    std::vector<std::uint8_t> found(40, 7);
    hits[50].fraction = 0.25f;
    const std::size_t count = worlds->embree.castSegments(casts, hits, found);
    std::size_t expected = 0;
    for (std::size_t i = 0; i < 40; ++i) {
        CastHit hit;
        expected += worlds->embree.castSegment(casts[i], hit) ? 1 : 0;
    }
    EXPECT_EQ(count, expected);
    EXPECT_EQ(hits[50].fraction, 0.25f);  // beyond n = 40: untouched
    std::vector<CastHit> none;
    EXPECT_EQ(worlds->embree.castSegments(casts, none, found), 0u);
}

TEST_F(embree_world, CastsDoNotAllocate) {
    // Rays (fast and slow paths) and spheres, one by one and in a batch, into caller storage.
    std::vector<SegmentCast> casts = randomCasts(worlds->meshTriangles, 400, 0.0f, 25);
    for (std::size_t i = 0; i < casts.size(); i += 4) casts[i].radius = 0.1f;
    std::vector<CastHit> hits(casts.size());
    std::vector<std::uint8_t> found(casts.size());
    // The replacement is in effect (otherwise the check below would pass vacuously); the
    // pointer escapes through a volatile, so the pair cannot be optimised away.
    const long probe = ftest::gAllocations.load();
    int* volatile sink = new int(1);
    delete sink;
    EXPECT_GT(ftest::gAllocations.load(), probe);
    const long before = ftest::gAllocations.load();
    std::size_t count = 0;
    for (const SegmentCast& cast : casts) count += worlds->embree.castSegment(cast, hits[0]) ? 1 : 0;
    count += worlds->embree.castSegments(casts, hits, found);
    EXPECT_EQ(ftest::gAllocations.load() - before, 0);
    EXPECT_GT(count, 0u);
}

TEST(embree_mesh, CastSegmentsBeforeCommitAndWithoutAMesh) {
    // Before commit() (brute force) and for a world of primitives only: castSegment's answers.
    Worlds w;
    addPrimitives(w.embree);
    const Mesh mesh = sceneMesh();
    ASSERT_EQ(w.embree.addMesh(mesh.vertices, mesh.indices), Status::Ok);
    std::vector<Triangle> triangles;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Triangle tri{mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                           mesh.vertices[mesh.indices[t + 2]]};
        if (foresight::validateTriangle(tri) == Status::Ok) triangles.push_back(tri);
    }
    const auto casts = randomCasts(triangles, 500, 0.0f, 24);
    expectBatchMatchesSingle(w.embree, casts);
    EmbreeWorld primitivesOnly;
    addPrimitives(primitivesOnly);
    ASSERT_TRUE(primitivesOnly.commit());
    expectBatchMatchesSingle(primitivesOnly, casts);
}

// Uniform doubles in [0, 1) from SplitMix64: the same sequence with every standard library
// (std::uniform_real_distribution's is not).
class UnitRandom {
public:
    explicit UnitRandom(std::uint64_t seed) : mState(seed) {}
    double operator()() {
        std::uint64_t z = (mState += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1p-53;
    }

private:
    std::uint64_t mState;
};

// A closed height field: a grid of `cells` x `cells` squares of `size` m (two triangles each,
// alternating diagonals) with hills, centred on (cx, cz).
Mesh hillsMesh(int cells, double size, double cx, double cz) {
    Mesh mesh;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const double x = cx + (i - 0.5 * cells) * size, z = cz + (j - 0.5 * cells) * size;
            mesh.vertices.push_back(
                r3(x, 1.5 * std::sin(0.37 * x) * std::cos(0.29 * z) + 0.2 * std::sin(2.3 * x + z), z));
        }
    const auto side = static_cast<std::uint32_t>(cells + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(cells); ++j)
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cells); ++i) {
            const std::uint32_t v00 = j * side + i, v10 = v00 + 1, v01 = v00 + side, v11 = v01 + 1;
            if ((i + j) % 2 == 0)
                mesh.indices.insert(mesh.indices.end(), {v00, v10, v11, v00, v11, v01});
            else
                mesh.indices.insert(mesh.indices.end(), {v00, v10, v01, v10, v11, v01});
        }
    return mesh;
}

// Radius 0, the third documented difference (embree_world.h): a segment that grazes a
// triangle's plane may miss a hit that lies within the graze reach (rho / sine) of its start or
// end; EmbreeWorld then reports a farther exact hit or none.
bool isDocumentedEndGraze(const Worlds& w, const Outcome& expected, const Outcome& actual, const SegmentCast& cast) {
    if (!expected.hit || (actual.hit && actual.value.fraction < expected.value.fraction)) return false;
    if (actual.hit && !trianglesGiving(w.meshTriangles, cast, actual.value).size()) return false;
    const double length = glm::length(DVec3(cast.displacement));
    const double f = double(expected.value.fraction);
    bool grazed = false;
    for (const Triangle& t : trianglesGiving(w.meshTriangles, cast, expected.value))
        // 1e-6 relative: the fraction is a float.
        grazed = grazed || std::min(f, 1.0 - f) * length <= grazeReach(w.meshTriangles, cast, t) + 1e-6 * length;
    return grazed;
}

TEST(embree_mesh, RaysNearEdgesVerticesAndGrazingGetTheExactAnswer) {
    // Where Embree's float hit is in doubt, the exact answer: rays on a closed height field
    // (every edge away from the border shared by two triangles) aimed at interior points at
    // distances 1e-9 to 1e-1 m from an edge line (inside and outside the triangle), at shared
    // vertices, and across the surface at grazing angles (sine 1e-4 to 0.1) and steeply, from
    // above and from below: EmbreeWorld's answer (the fast path's confirmation, its proof
    // that the hit is far enough inside, or the slow path) must be StaticWorld's, bit for bit,
    // or a documented graze (a ray that only touches the surface at an edge or vertex, within
    // rho / sine of it, or a grazing ray whose hit lies within rho / sine of its end: Embree's
    // float test may miss those; isDocumentedGraze and isDocumentedEndGraze check them).
    // Near the origin and 3 km away (larger float errors, larger rho). Also through castSegments.
    for (const double centre : {0.0, 3000.0}) {
        const Mesh mesh = hillsMesh(24, 0.5, centre, -centre);
        Worlds w;  // no primitives: the mesh alone, in both worlds
        EmbreeWorld& world = w.embree;
        StaticWorld& reference = w.reference;
        ASSERT_EQ(world.addMesh(mesh.vertices, mesh.indices), Status::Ok);
        ASSERT_TRUE(world.commit());
        std::vector<Triangle> interior;  // triangles with no vertex on the border
        const double half = 0.5 * 24 * 0.5 - 0.25;
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            const Triangle tri{mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                               mesh.vertices[mesh.indices[t + 2]]};
            ASSERT_EQ(reference.add(tri), Status::Ok);
            w.meshTriangles.push_back(tri);
            bool inside = true;
            for (const RVec3& v : {tri.a, tri.b, tri.c})
                inside = inside && std::abs(double(v.x) - centre) < half && std::abs(double(v.z) + centre) < half;
            if (inside) interior.push_back(tri);
        }
        ASSERT_GT(interior.size(), 800u);
        UnitRandom u(31);
        std::vector<SegmentCast> casts;
        for (int i = 0; i < 6000; ++i) {
            const Triangle& t = interior[static_cast<std::size_t>(u() * double(interior.size())) % interior.size()];
            const DVec3 a = d3(t.a), b = d3(t.b), c = d3(t.c);
            const DVec3 n = glm::normalize(glm::cross(b - a, c - a));
            const int edge = i % 3;
            const DVec3 u0 = edge == 0 ? a : edge == 1 ? b : c, u1 = edge == 0 ? b : edge == 1 ? c : a;
            const DVec3 opposite = edge == 0 ? c : edge == 1 ? a : b;
            const DVec3 inward = glm::normalize(glm::cross(n, u1 - u0)) *
                                 (glm::dot(glm::cross(n, u1 - u0), opposite - u0) > 0 ? 1.0 : -1.0);
            DVec3 target;
            switch ((i / 3) % 4) {
                case 0:  // near an edge line, inside or outside, 1e-9 to 1e-1 m
                case 1:
                    target = u0 + (u1 - u0) * (0.05 + 0.9 * u()) +
                             inward * ((u() < 0.5 ? 1.0 : -1.0) * std::pow(10.0, -9.0 + 8.0 * u()));
                    break;
                case 2:  // at a shared vertex, or within 1e-6 m of it
                    target = u0 + (u() < 0.5 ? DVec3(0.0) : DVec3(u() - 0.5, 0.0, u() - 0.5) * 2e-6);
                    break;
                default:  // anywhere in the triangle
                    target = a + (b - a) * (0.5 * u()) + (c - a) * (0.5 * u());
                    break;
            }
            // Steep, or grazing: the direction's sine against the triangle's plane, 1e-4 to 0.1.
            DVec3 along = glm::normalize(u1 - u0 + inward * (u() - 0.5));
            const double sine = u() < 0.4 ? 0.3 + 0.7 * u() : std::pow(10.0, -4.0 + 3.0 * u());
            const double side = u() < 0.5 ? 1.0 : -1.0;  // from above or below
            const DVec3 direction = glm::normalize(along * std::sqrt(1.0 - sine * sine) - n * (side * sine));
            const double before = 0.05 + 2.0 * u(), after = u() < 0.8 ? 0.5 : 1e-6;
            const DVec3 from = target - direction * before;
            casts.push_back(SegmentCast{r3(from.x, from.y, from.z), Vec3(direction * (before + after))});
        }
        int hits = 0, grazes = 0;
        for (std::size_t i = 0; i < casts.size(); ++i) {
            Outcome expected, actual;
            expected.hit = reference.castSegment(casts[i], expected.value);
            actual.hit = world.castSegment(casts[i], actual.value);
            hits += expected.hit ? 1 : 0;
            if (sameBits(expected.hit, expected.value, actual.hit, actual.value)) continue;
            ASSERT_TRUE(isDocumentedGraze(w, expected, actual, casts[i]) ||
                        isDocumentedEndGraze(w, expected, actual, casts[i]))
                << "centre " << centre << " cast " << i << ": expected " << expected.hit << " at "
                << expected.value.fraction << ", got " << actual.hit << " at " << actual.value.fraction;
            ++grazes;
        }
        EXPECT_GT(hits, 5000);  // nearly all aim at the surface from within 2 m
        // The casts are built to graze: a fifth end 1e-6 m past the surface, three fifths at a sine
        // below 0.1 (rho / sine up to 3 mm near the origin, 3 cm at 3 km). Measured: 47 and 125
        // in float builds, 92 and 235 in double builds (whose vertices Embree rounds to float).
        EXPECT_LT(grazes, 400) << "grazes " << grazes;
        std::printf("[          ] centre %g: %d of %zu casts graze an edge (documented difference)\n", centre, grazes,
                    casts.size());
        expectBatchMatchesSingle(world, casts);
    }
}

// ---------------------------------------------------------------------------------------------
// Loaders

class embree_loader : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDir = fs::temp_directory_path() / ("foresight_embree_test_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(mDir, ec);
    }
    fs::path write(const std::string& name, const std::string& bytes) {
        const fs::path path = mDir / name;
        fs::create_directories(path.parent_path());
        std::ofstream out(path, std::ios::binary);
        out << bytes;
        return path;
    }
    fs::path mDir;
};

const char* kQuadObj = "v -10 0 -10\nv 10 0 -10\nv 10 0 10\nv -10 0 10\nf 1 4 3 2\n";

// A glTF buffer: 4 float vertices (a 2 x 2 quad at y = 0) then 6 uint16 indices.
std::string quadBuffer() {
    const float positions[12] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    const std::uint16_t indices[6] = {0, 3, 2, 0, 2, 1};
    std::string bytes(sizeof positions + sizeof indices, '\0');
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + sizeof positions, indices, sizeof indices);
    return bytes;
}

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                           (static_cast<unsigned char>(bytes[i + 1]) << 8) | static_cast<unsigned char>(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += table[(v >> (6 * k)) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

// The glTF JSON of two nodes using the quad mesh: one moved up by 2, one scaled by 3.
// `uri` empty: the GLB's own binary chunk. `indexCount` and `indexType` let tests break it.
std::string quadGltfJson(const std::string& uri, int bufferLength, int indexCount = 6, int indexType = 5123,
                         const char* extraPrimitive = "") {
    std::string buffer =
        "{\"byteLength\": " + std::to_string(bufferLength) + (uri.empty() ? "" : ", \"uri\": \"" + uri + "\"") + "}";
    return std::string(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
  "nodes": [{"mesh": 0, "translation": [0, 2, 0]}, {"mesh": 0, "scale": [3, 3, 3], "children": [2]},
            {"mesh": 0, "translation": [0, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4})") +
           extraPrimitive + R"(]}],
  "buffers": [)" +
           buffer + R"(],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                {"bufferView": 1, "componentType": )" +
           std::to_string(indexType) + R"(, "count": )" + std::to_string(indexCount) + R"(, "type": "SCALAR"}]})";
}

std::string glb(std::string json, const std::string& bin) {
    while (json.size() % 4 != 0) json += ' ';
    std::string padded = bin;
    while (padded.size() % 4 != 0) padded += '\0';
    std::string out;
    auto u32 = [&](std::uint32_t v) {
        char b[4];
        std::memcpy(b, &v, 4);
        out.append(b, 4);
    };
    out += "glTF";
    u32(2);
    u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + padded.size()));
    u32(static_cast<std::uint32_t>(json.size()));
    u32(0x4E4F534Au);
    out += json;
    u32(static_cast<std::uint32_t>(padded.size()));
    u32(0x004E4942u);
    out += padded;
    return out;
}

TEST_F(embree_loader, ObjLoadsItsTriangles) {
    EmbreeWorld world;
    const auto result = world.loadObj(write("quad.obj", kQuadObj));
    ASSERT_TRUE(result.ok) << result.error;
    EXPECT_EQ(result.report.triangles, 2u);
    ASSERT_TRUE(world.commit());
    CastHit hit;
    ASSERT_TRUE(world.castSegment(SegmentCast{r3(1, 2, 1), Vec3(0, -4, 0), 0.0f}, hit));
    EXPECT_NEAR(hit.fraction, 0.5f, 1e-6f);
    EXPECT_EQ(hit.normal, Vec3(0, 1, 0));
}

TEST_F(embree_loader, GltfAndGlbLoadWithNodeTransforms) {
    const std::string bin = quadBuffer();
    for (const bool binary : {false, true}) {
        EmbreeWorld world;
        const fs::path path =
            binary ? write("quad.glb", glb(quadGltfJson("", static_cast<int>(bin.size())), bin))
                   : write("quad.gltf", quadGltfJson("data:application/octet-stream;base64," + base64(bin),
                                                     static_cast<int>(bin.size())));
        const auto result = world.loadGltf(path);
        ASSERT_TRUE(result.ok) << result.error;
        EXPECT_EQ(result.report.triangles, 6u);  // three nodes, two triangles each
        ASSERT_TRUE(world.commit());
        CastHit hit;
        // Node 0: the quad at y = 2 (x, z in -1 .. 1).
        ASSERT_TRUE(world.castSegment(SegmentCast{r3(0.5, 10, 0.5), Vec3(0, -20, 0), 0.0f}, hit));
        EXPECT_NEAR(hit.position.y, 3.0, 1e-5);  // node 2: scale 3 of (translate 1) -> y = 3, above node 0's y = 2
        // Outside the small quads but inside the scaled one (x = 2): y = 0 (node 1) or 3 (node 2).
        ASSERT_TRUE(world.castSegment(SegmentCast{r3(2, 10, 0), Vec3(0, -20, 0), 0.0f}, hit));
        EXPECT_NEAR(hit.position.y, 3.0, 1e-5);
        ASSERT_TRUE(world.castSegment(SegmentCast{r3(2, 2.5, 0), Vec3(0, -20, 0), 0.0f}, hit));
        EXPECT_NEAR(hit.position.y, 0.0, 1e-5);
        ASSERT_TRUE(world.castSegment(SegmentCast{r3(0.5, 2.5, 0.5), Vec3(0, -20, 0), 0.0f}, hit));
        EXPECT_NEAR(hit.position.y, 2.0, 1e-5);
    }
}

TEST_F(embree_loader, ExternalGltfBuffer) {
    const std::string bin = quadBuffer();
    write("quad.bin", bin);
    EmbreeWorld world;
    const auto result = world.loadGltf(write("quad.gltf", quadGltfJson("quad.bin", static_cast<int>(bin.size()))));
    ASSERT_TRUE(result.ok) << result.error;
    EXPECT_EQ(result.report.triangles, 6u);
}

struct BadFile {
    const char* name;
    const char* file;
    std::string bytes;  // "" with missing: no file
    bool missing = false;
    const char* reason;
};

std::vector<BadFile> badFiles() {
    const std::string bin = quadBuffer();
    const int n = static_cast<int>(bin.size());
    std::string nanBin = bin;
    const float nan = std::nanf("");
    std::memcpy(nanBin.data() + 4, &nan, 4);
    std::string rangeBin = bin;
    const std::uint16_t nine = 9;
    std::memcpy(rangeBin.data() + 48 + 2, &nine, 2);
    const std::string full = glb(quadGltfJson("", n), bin);
    std::vector<BadFile> cases;
    cases.push_back({"MissingObj", "none.obj", "", true, "No such file"});
    cases.push_back({"MissingGltf", "none.glb", "", true, "No such file"});
    cases.push_back({"MalformedObj", "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 0\n", false, "malformed"});
    cases.push_back({"ObjIndexOutOfRange", "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 9\n", false, "out of range"});
    // tinyobjloader alone reads these as 0, 1 or a truncated index: checkObjText refuses them.
    for (const char* value : {"nan", "inf", "abc", "+", ".", "1e", "0x10", "1,5", "1..2", "1e400", "1e39"})
        cases.push_back({"ObjLenientNumber", "bad.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 0 ") + value + "\nf 1 2 3\n",
                         false, "is not a finite decimal number"});
    cases.push_back(
        {"ObjTwoCoordinates", "bad.obj", "v 0 0 0\nv 1 0 0\nv 1 0\nf 1 2 3\n", false, "a vertex has 2 numbers"});
    cases.push_back({"ObjFractionalIndex", "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3.7\n", false, "face corner"});
    cases.push_back(
        {"ObjWrappingIndex", "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 4294967299\n", false, "face corner"});
    cases.push_back(
        {"ObjNulByte", "bad.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n\0junk", 36), false, "NUL"});
    cases.push_back({"ObjNoFaces", "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\n", false, "no triangles"});
    cases.push_back({"ObjEmpty", "bad.obj", "", false, "no triangles"});
    cases.push_back(
        {"ObjOnlyDegenerate", "bad.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", false, "no usable triangles"});
    cases.push_back({"MalformedGltfJson", "bad.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [", false,
                     "malformed glTF"});
    cases.push_back({"GltfNotJson", "bad.gltf", "hello", false, "malformed glTF"});
    cases.push_back({"TruncatedGlb", "bad.glb", full.substr(0, full.size() - 10), false, "malformed GLB"});
    cases.push_back({"TruncatedGlbHeader", "bad.glb", full.substr(0, 10), false, "malformed GLB"});
    cases.push_back({"GlbNanVertex", "bad.glb", glb(quadGltfJson("", n), nanBin), false, "not finite"});
    cases.push_back({"GlbIndexOutOfRange", "bad.glb", glb(quadGltfJson("", n), rangeBin), false, "out of range"});
    cases.push_back({"GlbIndicesPastTheBuffer", "bad.glb", glb(quadGltfJson("", n, 60), bin), false, ""});
    cases.push_back({"GltfNoMeshes", "bad.gltf", R"({"asset": {"version": "2.0"}})", false, "no triangles"});
    // Offsets near 2^64 must not wrap the bounds check.
    const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
        return text;
    };
    const std::string json = quadGltfJson("", n);
    cases.push_back(
        {"GlbAccessorOffsetWraps", "bad.glb",
         glb(replaced(json, R"("bufferView": 1, )", R"("bufferView": 1, "byteOffset": 18446744073709551568, )"), bin),
         false, "reaches past"});
    cases.push_back({"GlbViewOffsetWraps", "bad.glb",
                     glb(replaced(json, R"("byteOffset": 48, "byteLength": 12)",
                                  R"("byteOffset": 18446744073709551568, "byteLength": 64)"),
                         bin),
                     false, ""});
    cases.push_back({"GlbStrideSmallerThanAnElement", "bad.glb",
                     glb(replaced(json, R"("byteOffset": 0, "byteLength": 48)",
                                  R"("byteOffset": 0, "byteLength": 48, "byteStride": 4)"),
                         bin),
                     false, "byteStride"});
    cases.push_back({"GlbSceneOutOfRange", "bad.glb", glb(replaced(json, R"("scene": 0)", R"("scene": 5)"), bin), false,
                     "scene 5 does not exist"});
    cases.push_back({"GlbNegativeIndices", "bad.glb", glb(replaced(json, R"("indices": 1)", R"("indices": -5)"), bin),
                     false, "does not exist"});
    cases.push_back({"GlbZeroRotation", "bad.glb",
                     glb(replaced(json, R"("translation": [0, 2, 0])", R"("rotation": [0, 0, 0, 0])"), bin), false,
                     "unit quaternion"});
    cases.push_back({"GlbNodeCycle", "bad.glb",
                     glb(replaced(json, R"("translation": [0, 1, 0])", R"("children": [1])"), bin), false, "node 1"});
    cases.push_back({"GlbRootWithParent", "bad.glb",
                     glb(replaced(json, R"([{"nodes": [0, 1]}])", R"([{"nodes": [0, 2]}])"), bin), false,
                     "not a root"});
    // 40 nodes each listing the next one twice: 2^40 visits if walked as given.
    std::string chain = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [)";
    for (int i = 0; i < 40; ++i)
        chain += "{\"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]}, ";
    chain += R"({"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "buffers": [{"byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}]})";
    cases.push_back({"GlbExponentialNodeGraph", "bad.glb", glb(chain, std::string(36, '\0')), false, "a child twice"});
    std::string version1 = full;
    version1[4] = 1;
    cases.push_back({"GlbVersion1", "bad.glb", version1, false, "GLB version 1"});
    // Buffer files: inside the glTF's folder, regular files only.
    cases.push_back({"GltfBufferOutsideItsFolder", "sub/bad.gltf", quadGltfJson("../outside.bin", n), false,
                     "outside the glTF's folder"});
    cases.push_back({"GltfBufferAbsolutePath", "bad.gltf", quadGltfJson("/etc/hostname", n), false, ""});
    cases.push_back({"GltfBufferDevice", "bad.gltf", quadGltfJson("/dev/zero", n), false, ""});
    cases.push_back({"GltfBufferDirectory", "bad.gltf", quadGltfJson(".", n), false, ""});
    return cases;
}

TEST_F(embree_loader, BadFilesGiveAnErrorNamingTheFile) {
    write("outside.bin", quadBuffer());  // a real file beside the folder of sub/bad.gltf
    for (const BadFile& c : badFiles()) {
        SCOPED_TRACE(c.name);
        const fs::path path = c.missing ? mDir / c.file : write(c.file, c.bytes);
        EmbreeWorld world;
        const std::string extension = path.extension().string();
        const auto result = extension == ".obj" ? world.loadObj(path) : world.loadGltf(path);
        EXPECT_FALSE(result.ok);
        EXPECT_NE(result.error.find(path.string()), std::string::npos) << result.error;
        EXPECT_NE(result.error.find(c.reason), std::string::npos) << result.error;
        EXPECT_EQ(result.error.find('\n'), std::string::npos) << result.error;
        EXPECT_EQ(world.meshTriangleCount(), 0u);
    }
}

TEST_F(embree_loader, OnlyRegularFilesAreRead) {
    for (const char* device : {"/dev/zero", "/dev/null", "/tmp"}) {
        SCOPED_TRACE(device);
        EmbreeWorld world;
        for (const auto& result : {world.loadObj(device), world.loadGltf(device)}) {
            EXPECT_FALSE(result.ok);
            EXPECT_NE(result.error.find("not a regular file"), std::string::npos) << result.error;
        }
    }
}

TEST_F(embree_loader, DegenerateTrianglesAreSkippedAndCounted) {
    EmbreeWorld world;
    const auto result = world.loadObj(write("floor.obj", std::string(kQuadObj) + "v 0 0 0\nf 1 5 5\nf 1 2 3\n"));
    ASSERT_TRUE(result.ok) << result.error;
    EXPECT_EQ(result.report.triangles, 3u);
    EXPECT_EQ(result.report.degenerateTriangles, 1u);
    EXPECT_EQ(result.report.firstDegenerateTriangle, 2u);
}

// Embree's float rays assert beyond about 1.8e18 m (a crash in release builds): segments that
// reach that far are tested against every triangle instead, with StaticWorld's answer.
TEST(embree_mesh, SegmentsFarBeyondFloatRaysStillGetTheExactAnswer) {
    const std::vector<RVec3> vertices = {r3(-10, 0, -10), r3(10, 0, -10), r3(10, 0, 10), r3(-10, 0, 10)};
    const std::vector<std::uint32_t> indices = {0, 3, 2, 0, 2, 1};
    EmbreeWorld world;
    ASSERT_EQ(world.addMesh(vertices, indices), Status::Ok);
    ASSERT_TRUE(world.commit());
    StaticWorld reference;
    ASSERT_EQ(reference.add(Triangle{vertices[0], vertices[3], vertices[2]}), Status::Ok);
    ASSERT_EQ(reference.add(Triangle{vertices[0], vertices[2], vertices[1]}), Status::Ok);
    const SegmentCast casts[] = {
        {r3(1, 2e18, 1), Vec3(0, -4e18f, 0), 0.0f},          // through the quad, from far above
        {r3(1, 2e18, 1), Vec3(0, -4e18f, 0), 0.5f},          // the same, swept
        {r3(2e18, 1, 0), Vec3(-4e18f, 0, 0), 0.0f},          // beside it
        {r3(1e17, 1e17, 0), Vec3(-1e19f, -1e19f, 0), 0.0f},  // 1e17 m/s for 100 s
    };
    for (const SegmentCast& cast : casts) {
        CastHit hit, expected;
        const bool hits = world.castSegment(cast, hit);
        ASSERT_EQ(hits, reference.castSegment(cast, expected));
        if (hits) {
            EXPECT_EQ(hit.fraction, expected.fraction);
            EXPECT_EQ(hit.normal, expected.normal);
            EXPECT_TRUE(world.mayTouch(cast));
        }
    }
}

// A triangle near the end of the float range (a fuzzed glTF file's vertex of 3.4e38 m): Embree's
// BVH builder cannot bin such boxes (it aborted on an assertion), so commit() builds no region
// tree; the region queries then test every triangle and still answer as StaticWorld does.
TEST(embree_mesh, TriangleAtTheEndOfTheFloatRangeCommitsWithoutARegionTree) {
    const double far = 3.39e38;  // about the file's float 0x7f7f7f7f
    const std::vector<RVec3> vertices = {r3(-5, 0, -5), r3(5, 0, -5),    r3(0, 0, 5),
                                         r3(0, far, 0), r3(far, far, 0), r3(0, far, far)};
    const std::vector<std::uint32_t> indices = {0, 2, 1, 3, 4, 5};
    EmbreeWorld world;
    if (world.addMesh(vertices, indices) != Status::Ok) GTEST_SKIP() << "this build refuses such vertices";
    std::string error;
    ASSERT_TRUE(world.commit(&error)) << error;
    StaticWorld reference;
    ASSERT_EQ(reference.add(Triangle{vertices[0], vertices[2], vertices[1]}), Status::Ok);
    ASSERT_EQ(reference.add(Triangle{vertices[3], vertices[4], vertices[5]}), Status::Ok);
    const SegmentCast capsules[] = {
        {r3(0, 2, 0), Vec3(0, -4, 0), 0.1f},    // through the floor triangle
        {r3(0, 2, 0), Vec3(3, 0, 0), 0.5f},     // above it, clear
        {r3(20, 1, 0), Vec3(-30, 0, 0), 0.0f},  // beside it, through its plane's edge region
    };
    for (const SegmentCast& capsule : capsules) {
        float fraction = -1.0f, expected = -1.0f;
        const bool touches = world.firstTouch(capsule, fraction);
        ASSERT_EQ(touches, reference.firstTouch(capsule, expected));
        if (touches) {
            EXPECT_EQ(fraction, expected);
        }
        EXPECT_EQ(world.mayTouch(capsule), reference.mayTouch(capsule));
        CastHit hit, expectedHit;
        ASSERT_EQ(world.castSegment(capsule, hit), reference.castSegment(capsule, expectedHit));
    }
}

// firstTouch walks a tree of the mesh triangles' boxes (Embree's BVH builder) and tests the
// triangles of the boxes the capsule's slabs enter as StaticWorld tests every triangle; a box it
// skips holds only triangles that test refuses, or that touch no earlier than a touch already
// found. So the answer is StaticWorld's, bit for bit; and its promise is checked against the
// casts: no swept sphere inside the capsule cut at the fraction hits anything. mayTouch skips
// the same boxes, so it raises no alarm that StaticWorld's does not.
TEST(embree_mesh, FirstTouchAnswersAsStaticWorldAndKeepsItsPromise) {
    Worlds w;
    buildWorlds(w);
    std::mt19937 rng(414);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int touched = 0, cut = 0, clear = 0;
    for (int i = 0; i < 20000; ++i) {
        SegmentCast capsule;
        capsule.origin = r3(-7 + 14 * u(rng), -2 + 8 * u(rng), -6 + 12 * u(rng));
        const double length = i % 4 == 0 ? 0.0 : 12 * u(rng) * u(rng);
        const DVec3 direction = glm::normalize(DVec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        capsule.displacement = Vec3(direction * length);
        capsule.radius = static_cast<float>(i % 3 == 0 ? 0.0 : 0.6 * u(rng));
        float fraction = -1.0f, expected = -1.0f;
        const bool touches = w.embree.firstTouch(capsule, fraction);
        const bool referenceTouches = w.reference.firstTouch(capsule, expected);
        ASSERT_EQ(touches, referenceTouches) << i;
        const bool alarm = w.embree.mayTouch(capsule);
        if (touches) {
            EXPECT_TRUE(alarm) << "a touch that mayTouch rules out, " << i;
        }
        if (alarm) {
            EXPECT_TRUE(w.reference.mayTouch(capsule)) << "an alarm StaticWorld does not raise, " << i;
        }
        if (touches) {
            ASSERT_EQ(fraction, expected) << i;
            ++touched;
            cut += fraction > 0.0f ? 1 : 0;
        } else {
            ++clear;
            fraction = 1.0f;
        }
        const DVec3 a = d3(capsule.origin), d = DVec3(capsule.displacement) * static_cast<double>(fraction);
        for (int k = 0; k < 4 && fraction > 0.0f; ++k) {
            const double r = capsule.radius * 0.9 * u(rng);
            const DVec3 side = glm::normalize(DVec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5)) *
                               (0.9 * (static_cast<double>(capsule.radius) - r) * u(rng));
            // 0.999: the cut's own end is where the first surface may touch.
            const DVec3 from = a + d * (0.999 * u(rng)) + side, to = a + d * (0.999 * u(rng)) + side;
            const SegmentCast inside{r3(from.x, from.y, from.z), Vec3(to - from), static_cast<float>(r)};
            CastHit hit;
            EXPECT_FALSE(w.embree.castSegment(inside, hit)) << "capsule " << i << " cast " << k;
        }
    }
    EXPECT_GT(touched, 1000);
    EXPECT_GT(cut, 1000);
    EXPECT_GT(clear, 100);
}

// firstTouchInFront may leave out the shapes wholly behind a plane (none of their points more than
// the tolerance in front): its answer is firstTouch's in a world without them. That world is
// built here from the shapes' own points (a triangle's vertices, a box's eight corners, a
// sphere's top along the normal, an infinite plane only when parallel), and EmbreeWorld (whose
// tree skips boxes wholly behind) and StaticWorld must answer as it does, bit for bit. Planes
// level with the floor, the boxes' tops and the primitives, and tilted ones; capsules skimming
// the floor (which plain firstTouch meets at once) and anywhere.
TEST(embree_mesh, FirstTouchInFrontAnswersAsAWorldWithoutTheShapesBehind) {
    Worlds w;
    buildWorlds(w);
    std::mt19937 rng(4141);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double levels[] = {0.0, 1.0, 2.0, 4.0, -1.0, 0.5};
    int leftOut = 0, unlike = 0;
    for (int i = 0; i < 3000; ++i) {
        foresight::InFrontOf front;
        DVec3 n(0, 1, 0);
        if (i % 4 == 3) n = glm::normalize(DVec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        front.normal = Vec3(n);
        const double level = levels[i % 6] + (i % 5 == 0 ? 5e-6 : 0.0);
        front.point = r3(4 * u(rng) - 2, level, 4 * u(rng) - 2);
        front.tolerance = i % 7 == 0 ? 0.0f : 1e-5f;
        // The world without the shapes wholly behind, from their own points.
        const DVec3 unit = glm::normalize(DVec3(front.normal));
        const double top = glm::dot(unit, DVec3(front.point)) + static_cast<double>(front.tolerance);
        const auto behind = [&](std::initializer_list<DVec3> points) {
            for (const DVec3& p : points)
                if (glm::dot(unit, p) > top) return false;
            return true;
        };
        StaticWorld kept;
        std::size_t left = 0;
        const StaticWorld& all = w.reference;
        for (const foresight::Plane& plane : all.planes()) {
            const bool parallel = plane.normal == front.normal || plane.normal == -front.normal;
            const double height = (plane.normal == front.normal ? 1.0 : -1.0) * static_cast<double>(plane.distance) /
                                  glm::length(DVec3(plane.normal));
            if (parallel && height <= top)
                ++left;
            else
                ASSERT_EQ(kept.add(plane), Status::Ok);
        }
        for (const foresight::Sphere& sphere : all.spheres()) {
            if (behind({DVec3(sphere.center) + unit * static_cast<double>(sphere.radius)}))
                ++left;
            else
                ASSERT_EQ(kept.add(sphere), Status::Ok);
        }
        for (const foresight::OrientedBox& box : all.boxes()) {
            const glm::dmat3 axes = glm::mat3_cast(glm::dquat(box.orientation));
            bool allBehind = true;
            for (int c = 0; c < 8; ++c) {
                const DVec3 corner(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
                allBehind = allBehind && behind({DVec3(box.center) + axes * (corner * DVec3(box.halfExtents))});
            }
            if (allBehind)
                ++left;
            else
                ASSERT_EQ(kept.add(box), Status::Ok);
        }
        for (const Triangle& t : all.triangles()) {
            if (behind({DVec3(t.a), DVec3(t.b), DVec3(t.c)}))
                ++left;
            else
                ASSERT_EQ(kept.add(t), Status::Ok);
        }
        SegmentCast capsule;
        if (i % 2 == 0) {
            // Skimming the plane: from just above the level to anywhere.
            capsule.radius = static_cast<float>(0.4 * u(rng));
            const DVec3 start = DVec3(front.point) + unit * (static_cast<double>(capsule.radius) + 1e-3 * u(rng));
            capsule.origin = r3(start.x, start.y, start.z);
        } else {
            capsule.radius = static_cast<float>(i % 3 == 0 ? 0.0 : 0.6 * u(rng));
            capsule.origin = r3(-7 + 14 * u(rng), -2 + 8 * u(rng), -6 + 12 * u(rng));
        }
        const DVec3 direction = glm::normalize(DVec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        capsule.displacement = Vec3(direction * (8 * u(rng)));
        float expected = -1.0f, embree = -1.0f, reference = -1.0f, plain = -1.0f;
        const bool touches = kept.firstTouch(capsule, expected);
        ASSERT_EQ(w.embree.firstTouchInFront(capsule, front, embree), touches) << i;
        ASSERT_EQ(w.reference.firstTouchInFront(capsule, front, reference), touches) << i;
        if (touches) {
            ASSERT_EQ(embree, expected) << i;
            ASSERT_EQ(reference, expected) << i;
        }
        const bool plainTouches = w.reference.firstTouch(capsule, plain);
        leftOut += left > 0 ? 1 : 0;
        unlike += plainTouches != touches || (touches && plain != expected) ? 1 : 0;
    }
    // Both sides are exercised: queries with shapes left out, and answers that leaving them out
    // changed.
    EXPECT_GT(leftOut, 2000);
    EXPECT_GT(unlike, 500);
}

// findNear walks Embree's BVH for the mesh's triangles; StaticWorld tests every triangle. Both
// use NearTester on the same triangles, so the lists are the same (as sets, bit for bit), before
// and after commit.
// isOnlyPlane through EmbreeWorld leaves out the mesh edges that commit() found shared by
// exactly two triangles, one on either side (EmbreeWorldSettings::meshAdjacency,
// PlaneRegionTester's sharedEdges): it must answer as the same world without that, which pairs
// every edge itself (the settings' two exceptions, too many edges or an edge's two copies
// rounded apart, could only give the plane where that refused it; neither occurs here); both
// must give the plane wherever StaticWorld does (EmbreeWorld's tree leaves out
// triangles that StaticWorld's conservative test may still offer), and where they give it, casts
// inside the region must meet what the plane alone meets. A floor of 1 m tiles over shared
// vertices (diagonals alternating) with a hole, a tile cut in three by a vertex on its
// neighbour's edge (a T-junction), a coincident duplicate of a tile over vertices of its own, a
// tile repeated over the same vertices, a triangle over a border edge on its tile's side, a sliver, a ridge folded up from the floor along a row
// of shared vertices, a wall standing on shared floor vertices, and a tilted patch of tiles;
// random capsules lying along the floor's plane and the tilted one, some narrow, some long.
// `mesh` in an EmbreeWorld with its adjacency, one without (EmbreeWorldSettings::meshAdjacency)
// and a StaticWorld holding the same triangles: isOnlyPlane's three answers.
void holdMesh(const Mesh& mesh, EmbreeWorld& embree, EmbreeWorld& unpaired, StaticWorld& reference) {
    for (EmbreeWorld* world : {&embree, &unpaired}) {
        foresight::MeshReport report;
        ASSERT_EQ(world->addMesh(mesh.vertices, mesh.indices, &report), Status::Ok) << report.error;
        std::string error;
        ASSERT_TRUE(world->commit(&error)) << error;
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        ASSERT_EQ(reference.add(Triangle{mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                                         mesh.vertices[mesh.indices[t + 2]]}),
                  Status::Ok);
}

TEST(embree_mesh, IsOnlyPlaneAnswersWithTheMeshAdjacencyAsWithoutIt) {
    Mesh mesh;
    constexpr int kTiles = 12;  // x and z from -6 to 6
    const auto at = [](int i, int j) { return static_cast<std::uint32_t>(i * (kTiles + 1) + j); };
    for (int i = 0; i <= kTiles; ++i)
        for (int j = 0; j <= kTiles; ++j) mesh.vertices.push_back(r3(i - 6.0, 0.0, j - 6.0));
    const auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        for (const std::uint32_t k : {a, b, c}) mesh.indices.push_back(k);
    };
    const auto extra = [&](double x, double y, double z) {
        mesh.vertices.push_back(r3(x, y, z));
        return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    };
    for (int i = 0; i < kTiles; ++i) {
        for (int j = 0; j < kTiles; ++j) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (i == 3 && j == 3) continue;  // a hole
            if (i == 7 && j == 2) {
                // Cut in three by a vertex on the edge it shares with tile (8, 2): a T-junction.
                const std::uint32_t m = extra(i - 6.0 + 1.0, 0.0, j - 6.0 + 0.5);
                tri(a, b, m);
                tri(a, m, d);
                tri(d, m, c);
                continue;
            }
            if ((i + j) % 2 == 0) {
                tri(a, d, c);
                tri(a, c, b);
            } else {
                tri(a, d, b);
                tri(b, d, c);
            }
            if (i == 5 && j == 8) {
                // A coincident duplicate over vertices of its own.
                const std::uint32_t e = extra(i - 6.0, 0.0, j - 6.0), f = extra(i - 5.0, 0.0, j - 5.0),
                                    g = extra(i - 5.0, 0.0, j - 6.0);
                tri(e, f, g);
            }
            if (i == 9 && j == 9) tri(a, d, b);  // the same triangle twice, over the same vertices
        }
    }
    // On the floor's border z = -6, a second triangle over a border edge, on the same side as
    // the tile's (the edge has two triangles, and nothing beyond it).
    tri(at(2, 0), at(3, 0), extra(-3.5, 0.0, -5.5));
    // A sliver on the floor beyond x = 6 (its own vertices and one of the floor's border).
    tri(at(kTiles, 4), extra(6.0 + 1e-4, 0.0, -1.0), at(kTiles, 5));
    // A ridge folded up from the floor's row z = 6 (x from -6 to 0), and a wall standing on the
    // floor's row x = -6 (z from 0 to 6), both over the floor's vertices.
    for (int i = 0; i < 6; ++i) {
        const std::uint32_t p = extra(i - 6.0, 0.3, 6.6), q = extra(i - 5.0, 0.3, 6.6);
        tri(at(i, kTiles), p, q);
        tri(at(i, kTiles), q, at(i + 1, kTiles));
    }
    for (int j = 6; j < kTiles; ++j) {
        const std::uint32_t p = extra(-6.0, 1.0, j - 6.0), q = extra(-6.0, 1.0, j - 5.0);
        tri(at(0, j), at(0, j + 1), q);
        tri(at(0, j), q, p);
    }
    // A tilted patch (slope 0.25 along x) of 4 x 4 tiles beside, x from 7 to 11.
    const std::uint32_t tilted = static_cast<std::uint32_t>(mesh.vertices.size());
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) mesh.vertices.push_back(r3(7.0 + i, 0.25 * i, j - 2.0));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const std::uint32_t a = tilted + static_cast<std::uint32_t>(i * 5 + j), b = a + 5, c = a + 6, d = a + 1;
            tri(a, d, c);
            tri(a, c, b);
        }

    StaticWorld reference;
    EmbreeWorld embree, unpaired(foresight::EmbreeWorldSettings{.meshAdjacency = false});
    ASSERT_NO_FATAL_FAILURE(holdMesh(mesh, embree, unpaired, reference));

    std::mt19937 rng(2611);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const DVec3 slope = glm::normalize(DVec3(-0.25, 1.0, 0.0));
    int plane = 0, notPlane = 0, staticPlane = 0, gained = 0, checkedCasts = 0;
    for (int i = 0; i < 20000; ++i) {
        PlaneRegion region;
        const bool onTilt = i % 5 == 4;
        DVec3 start, normal;
        if (onTilt) {
            normal = slope;
            const double x = 7.0 + 4.0 * u(rng);
            start = DVec3(x, 0.25 * (x - 7.0), -2.0 + 4.0 * u(rng));
        } else {
            normal = DVec3(0, 1, 0);
            start = DVec3(-6.5 + 14.0 * u(rng), 0.0, -6.5 + 14.0 * u(rng));
        }
        const double radius = i % 3 == 0 ? 0.05 + 0.1 * u(rng) : 0.05 + 0.8 * u(rng);
        // Along the plane, starting a little off it (within the radius).
        const DVec3 along = glm::normalize(glm::cross(normal, DVec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5)));
        const double length = i % 4 == 0 ? 0.0 : 6.0 * u(rng) * u(rng);
        region.point = r3(start.x, start.y, start.z);
        region.normal = Vec3(normal);
        const DVec3 lifted = start + normal * (0.5 * radius * u(rng));
        region.capsule.origin = r3(lifted.x, lifted.y, lifted.z);
        region.capsule.displacement = Vec3(along * length);
        region.capsule.radius = static_cast<float>(radius);
        const bool only = embree.isOnlyPlane(region), before = unpaired.isOnlyPlane(region);
        const bool staticOnly = reference.isOnlyPlane(region);
        ASSERT_TRUE(only || !before) << "adjacency refused a region the pairing accepted, " << i;
        ASSERT_TRUE(before || !staticOnly) << "StaticWorld accepted a region EmbreeWorld refused, " << i;
        gained += only != before ? 1 : 0;
        staticPlane += staticOnly ? 1 : 0;
        (only ? plane : notPlane) += 1;
        if (!only) continue;
        // The promise: casts inside the capsule, starting clear of the plane, meet what the
        // plane alone meets (the tiles lie in it up to their vertices' rounding: 1e-5 m).
        const DVec3 point = d3(region.point);
        StaticWorld alone;
        ASSERT_EQ(alone.add(foresight::Plane{region.normal, static_cast<float>(glm::dot(normal, point))}), Status::Ok);
        const DVec3 a = d3(region.capsule.origin), d(region.capsule.displacement);
        for (int k = 0; k < 3; ++k) {
            const double r = 0.3 * radius * u(rng);
            const DVec3 side = glm::normalize(glm::cross(normal, DVec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5))) *
                               (0.5 * (radius - r) * u(rng));
            DVec3 from = a + d * u(rng) + side, to = a + d * u(rng) + side;
            // From above the plane by more than r (within the capsule) to below it.
            from += normal * (r + 0.2 * (radius - r) - glm::dot(normal, from - point));
            to -= normal * (0.3 * (radius - r) + glm::dot(normal, to - point));
            const SegmentCast cast{r3(from.x, from.y, from.z), Vec3(to - from), static_cast<float>(r)};
            CastHit hit, expected;
            const bool found = embree.castSegment(cast, hit), planeFound = alone.castSegment(cast, expected);
            ASSERT_EQ(found, planeFound) << "region " << i << " cast " << k;
            if (found) {
                EXPECT_NEAR(hit.fraction, expected.fraction, 1e-5) << "region " << i << " cast " << k;
                EXPECT_GT(glm::dot(d3(hit.normal), normal), 0.999999) << "region " << i << " cast " << k;
            }
            ++checkedCasts;
        }
    }
    std::printf(
        "[ isOnlyPlane ] the plane alone in %d of %d regions (%d only with the adjacency; StaticWorld: "
        "%d), %d casts inside them as against the plane\n",
        plane, plane + notPlane, gained, staticPlane, checkedCasts);
    EXPECT_GT(plane, 4000);
    EXPECT_GT(notPlane, 4000);
    // Neither exception occurs on this mesh: the adjacency changes no answer.
    EXPECT_EQ(gained, 0);
}

// isOnlyPlane passes a node of the region tree whole where all its triangles lie in one plane
// with every edge shared (a flat floor's tiles) and the tester says each would pass
// (PlaneRegionTester::passesFlatGroup). A floor of 40 x 40 tiles at y = 0 with, lying on it, a
// rug of 20 x 20 tiles 1 cm up, a film of 6 x 6 tiles 2e-7 m up (within the plane's tolerance)
// and a plate of 6 x 6 tiles tilted by 1e-6 rad (beyond the normals' 4.5e-7 rad); regions on
// the floor's plane whose capsules reach the rug, the film or the plate or not. Every answer
// must be the answer of the same world without the adjacency (which offers every triangle) and
// at least as accepting as StaticWorld's. A tree that passed flat nodes before a triangle holds
// the cross-section's anchor fails it; passesFlatGroup's own checks (the box within the plane,
// the normal along it) have their test in engine_test.cpp (StaticWorldPlane): on this mesh no
// answer depends on them (checked by removing each).
TEST(embree_mesh, IsOnlyPlanePassesFlatNodesOnlyWhereEachTriangleWould) {
    Mesh mesh;
    // n x n tiles from (x0, z0), vertex (i, j) at height y(i, j), each tile two triangles.
    const auto grid = [&](int n, double x0, double z0, const auto& y) {
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) mesh.vertices.push_back(r3(x0 + i, y(i, j), z0 + j));
        const auto at = [&](int i, int j) { return first + static_cast<std::uint32_t>(i * (n + 1) + j); };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (const std::uint32_t k :
                     {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)})
                    mesh.indices.push_back(k);
    };
    grid(40, -20.0, -20.0, [](int, int) { return 0.0; });
    grid(20, -10.0, -10.0, [](int, int) { return 0.01; });              // the rug
    grid(6, 12.0, -18.0, [](int, int) { return 2e-7; });                // the film
    grid(6, -18.0, 12.0, [](int i, int) { return 0.001 + 1e-6 * i; });  // the plate

    StaticWorld reference;
    EmbreeWorld embree, unpaired(foresight::EmbreeWorldSettings{.meshAdjacency = false});
    ASSERT_NO_FATAL_FAILURE(holdMesh(mesh, embree, unpaired, reference));
    std::mt19937 rng(4242);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int plane = 0, notPlane = 0, nearPieces = 0, staticRefused = 0;
    for (int i = 0; i < 20000; ++i) {
        PlaneRegion region;
        const DVec3 start(-19.5 + 39.0 * u(rng), 0.0, -19.5 + 39.0 * u(rng));
        // Small radii, so that a capsule over a piece's middle meets nothing of its border.
        const double radius = 0.0005 + 0.03 * u(rng) * u(rng);
        const double heading = 2.0 * M_PI * u(rng), length = i % 4 == 0 ? 0.0 : 5.0 * u(rng) * u(rng);
        region.point = r3(start.x, 0.0, start.z);
        region.normal = Vec3(0.0f, 1.0f, 0.0f);
        region.capsule.origin = r3(start.x, 0.5 * radius * u(rng), start.z);
        region.capsule.displacement =
            Vec3(static_cast<float>(length * std::cos(heading)), 0.0f, static_cast<float>(length * std::sin(heading)));
        region.capsule.radius = static_cast<float>(radius);
        const bool only = embree.isOnlyPlane(region), every = unpaired.isOnlyPlane(region);
        const bool staticOnly = reference.isOnlyPlane(region);
        ASSERT_EQ(only, every) << "region " << i;
        // StaticWorld offers every triangle to its tester, whose bounds test may take one the tree
        // leaves out as out of reach (the plate's, off the plane): it may refuse more.
        ASSERT_TRUE(every || !staticOnly) << "StaticWorld accepted a region EmbreeWorld refused, " << i;
        staticRefused += every && !staticOnly ? 1 : 0;
        (only ? plane : notPlane) += 1;
        // Starts over the rug, the film or the plate.
        const bool overPiece = (start.x > -10.0 && start.x < 10.0 && start.z > -10.0 && start.z < 10.0) ||
                               (start.x > 12.0 && start.x < 18.0 && start.z > -18.0 && start.z < -12.0) ||
                               (start.x > -18.0 && start.x < -12.0 && start.z > 12.0 && start.z < 18.0);
        nearPieces += overPiece ? 1 : 0;
    }
    std::printf(
        "[ isOnlyPlane ] flat nodes: the plane alone in %d of %d regions (%d start over a piece; StaticWorld refused "
        "%d more)\n",
        plane, plane + notPlane, nearPieces, staticRefused);
    EXPECT_GT(plane, 10000);
    EXPECT_GT(notPlane, 2000);
}

TEST(embree_mesh, FindNearReportsWhatStaticWorldReports) {
    struct NearList final : foresight::NearCollector {
        std::vector<std::array<double, 5>> found;
        void add(const foresight::NearSurface& s) override {
            found.push_back({static_cast<double>(s.distance), static_cast<double>(s.point.x),
                             static_cast<double>(s.point.y), static_cast<double>(s.point.z),
                             static_cast<double>(s.normal.y)});
        }
        void sort() { std::sort(found.begin(), found.end()); }
    };
    Worlds w;
    buildWorlds(w);
    EmbreeWorld uncommitted;
    addPrimitives(uncommitted);
    const Mesh mesh = sceneMesh();
    ASSERT_EQ(uncommitted.addMesh(mesh.vertices, mesh.indices), Status::Ok);
    std::mt19937 rng(733);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::size_t reported = 0;
    for (int i = 0; i < 5000; ++i) {
        foresight::NearQuery query;
        query.center = r3(-7 + 14 * u(rng), -2 + 8 * u(rng), -6 + 12 * u(rng));
        query.radius = static_cast<float>(i % 10 == 0 ? 0.0 : 2.0 * u(rng));
        NearList expected, embree, before;
        ASSERT_TRUE(w.reference.findNear(query, expected));
        ASSERT_TRUE(w.embree.findNear(query, embree));
        ASSERT_TRUE(uncommitted.findNear(query, before));
        expected.sort();
        embree.sort();
        before.sort();
        ASSERT_EQ(embree.found, expected.found) << "query " << i;
        ASSERT_EQ(before.found, expected.found) << "query " << i;
        reported += expected.found.size();
    }
    EXPECT_GT(reported, 3000u);
    // Beyond Embree's float range it cannot answer (and reports nothing).
    foresight::NearQuery far;
    far.center = r3(1e30, 0, 0);
    far.radius = 1.0f;
    NearList none;
    EXPECT_FALSE(w.embree.findNear(far, none));
    EXPECT_TRUE(none.found.empty());
}

TEST(embree_mesh, AddMeshRefusesBadInput) {
    EmbreeWorld world;
    const std::vector<RVec3> vertices{r3(0, 0, 0), r3(1, 0, 0), r3(0, 0, 1)};
    foresight::MeshReport report;
    EXPECT_EQ(world.addMesh(vertices, std::vector<std::uint32_t>{0, 1, 3}, &report), Status::DegenerateShape);
    EXPECT_NE(report.error.find("out of range"), std::string::npos);
    EXPECT_EQ(world.addMesh(vertices, std::vector<std::uint32_t>{0, 1}, &report), Status::DegenerateShape);
    const std::vector<RVec3> bad{r3(0, 0, 0), r3(1, 0, 0), RVec3(std::numeric_limits<foresight::Real>::quiet_NaN())};
    EXPECT_EQ(world.addMesh(bad, std::vector<std::uint32_t>{0, 1, 2}, &report), Status::NonFiniteInput);
    EXPECT_EQ(world.addMesh(vertices, std::vector<std::uint32_t>{}, &report), Status::DegenerateShape);
    EXPECT_EQ(world.meshTriangleCount(), 0u);
    EXPECT_EQ(world.addMesh(vertices, std::vector<std::uint32_t>{0, 1, 2}, &report), Status::Ok);
    EXPECT_EQ(world.meshTriangleCount(), 1u);
    CastHit hit;
    EXPECT_FALSE(world.castSegment(SegmentCast{r3(0.2, 1, 0.2), Vec3(0, 0, 0), 0.0f}, hit));  // zero length
    ASSERT_TRUE(world.commit());
    EXPECT_TRUE(world.castSegment(SegmentCast{r3(0.2, 1, 0.2), Vec3(0, -2, 0), 0.0f}, hit));
}

// A ShapeCollector that builds a StaticWorld of what it is given (with the world's tolerance).
struct GatheredWorld final : foresight::ShapeCollector {
    StaticWorld world;
    std::size_t shapes = 0;
    void begin(float surfaceTolerance) override {
        world = StaticWorld(foresight::StaticWorldSettings{surfaceTolerance});
    }
    bool add(const foresight::Plane& p, const foresight::SurfaceMaterial& m) override { return keep(world.add(p, m)); }
    bool add(const foresight::Sphere& p, const foresight::SurfaceMaterial& m) override { return keep(world.add(p, m)); }
    bool add(const foresight::OrientedBox& p, const foresight::SurfaceMaterial& m) override {
        return keep(world.add(p, m));
    }
    bool add(const Triangle& p, const foresight::SurfaceMaterial& m) override { return keep(world.add(p, m)); }
    bool keep(Status s) {
        EXPECT_EQ(s, Status::Ok);
        ++shapes;
        return s == Status::Ok;
    }
};

// Every field of two cast answers, bit for bit.
bool sameAnswer(bool hitA, const CastHit& a, bool hitB, const CastHit& b) {
    if (hitA != hitB) return false;
    if (!hitA) return true;
    return std::memcmp(&a.fraction, &b.fraction, sizeof a.fraction) == 0 &&
           std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
           std::memcmp(&a.normal, &b.normal, sizeof a.normal) == 0 && a.restitution == b.restitution &&
           a.friction == b.friction;
}

struct SortedNear final : foresight::NearCollector {
    std::vector<std::array<float, 9>> found;
    void add(const foresight::NearSurface& s) override {
        found.push_back({static_cast<float>(s.point.x), static_cast<float>(s.point.y), static_cast<float>(s.point.z),
                         s.normal.x, s.normal.y, s.normal.z, s.distance, s.restitution, s.friction});
        std::sort(found.begin(), found.end());
    }
};

// CollisionWorld::gatherShapes' promise, for StaticWorld and EmbreeWorld: a StaticWorld of the
// gathered shapes answers every swept-sphere cast and closest-point query inside the region bit
// for bit as the world (the scene's random casts: starts on surfaces, grazes of edges and
// vertices, casts along faces; regions from just around the cast to 1.5 m beyond it).
TEST_F(embree_world, GatheredShapesAnswerAsTheWorld) {
    const Worlds& w = *worlds;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const float radius : {0.05f, 0.2f}) {
        const auto casts = randomCasts(w.meshTriangles, 3000, radius, 11);
        for (const foresight::CollisionWorld* world : {static_cast<const foresight::CollisionWorld*>(&w.reference),
                                                       static_cast<const foresight::CollisionWorld*>(&w.embree)}) {
            int hits = 0, gathered = 0, near = 0;
            for (std::size_t i = 0; i < casts.size(); ++i) {
                const SegmentCast& cast = casts[i];
                SegmentCast region = cast;
                region.radius = cast.radius + static_cast<float>(u(rng) < 0.3 ? 1e-3 : 1.5 * u(rng));
                GatheredWorld local;
                if (!world->gatherShapes(region, local)) continue;
                ++gathered;
                CastHit a, b;
                const bool hitA = world->castSegment(cast, a), hitB = local.world.castSegment(cast, b);
                ASSERT_TRUE(sameAnswer(hitA, a, hitB, b))
                    << "cast " << i << " region radius " << region.radius << ": " << hitA << " " << hitB << " fraction "
                    << a.fraction << " vs " << b.fraction << " (" << local.shapes << " shapes gathered)";
                hits += hitA ? 1 : 0;
                // The closest points around the start.
                foresight::NearQuery query;
                query.center = cast.origin;
                query.radius = region.radius - cast.radius * static_cast<float>(u(rng));
                SegmentCast sphere;
                sphere.origin = cast.origin;
                sphere.radius = query.radius;
                GatheredWorld around;
                ASSERT_TRUE(world->gatherShapes(sphere, around));
                SortedNear fromWorld, fromLocal;
                ASSERT_TRUE(world->findNear(query, fromWorld));
                ASSERT_TRUE(around.world.findNear(query, fromLocal));
                ASSERT_EQ(fromWorld.found, fromLocal.found) << "query " << i;
                near += static_cast<int>(fromWorld.found.size());
            }
            EXPECT_EQ(gathered, static_cast<int>(casts.size()));  // a small scene: always room
            EXPECT_GT(hits, 1000);
            EXPECT_GT(near, 1000);
        }
    }
}

// A collector with room for a few shapes: the world says it could not gather them all.
TEST_F(embree_world, GatheringFailsWhenTheCollectorIsFull) {
    struct Small final : foresight::ShapeCollector {
        int room = 3;
        void begin(float) override {}
        bool add(const foresight::Plane&, const foresight::SurfaceMaterial&) override { return room-- > 0; }
        bool add(const foresight::Sphere&, const foresight::SurfaceMaterial&) override { return room-- > 0; }
        bool add(const foresight::OrientedBox&, const foresight::SurfaceMaterial&) override { return room-- > 0; }
        bool add(const Triangle&, const foresight::SurfaceMaterial&) override { return room-- > 0; }
    };
    SegmentCast everything{r3(0, 2, 0), Vec3(0), 20.0f};
    Small a, b;
    EXPECT_FALSE(worlds->embree.gatherShapes(everything, a));
    EXPECT_FALSE(worlds->reference.gatherShapes(everything, b));
    GatheredWorld all;
    ASSERT_TRUE(worlds->embree.gatherShapes(everything, all));
    EXPECT_EQ(all.shapes, worlds->meshTriangles.size() + 4);  // the mesh and the four primitives
    // A world that cannot gather says so.
    const foresight::CallbackWorld callback([](void*, const SegmentCast&, CastHit&) { return false; }, nullptr);
    GatheredWorld none;
    EXPECT_FALSE(callback.gatherShapes(everything, none));
}

// Forwards every query to a world, gatherShapes only when `gathers` (and counts those).
class Forwarding final : public foresight::CollisionWorld {
public:
    Forwarding(const foresight::CollisionWorld& world, bool gather) : mWorld(world), mGathers(gather) {}
    bool castSegment(const SegmentCast& c, CastHit& h) const override { return mWorld.castSegment(c, h); }
    bool mayTouch(const SegmentCast& c) const override { return mWorld.mayTouch(c); }
    bool firstTouch(const SegmentCast& c, float& f) const override { return mWorld.firstTouch(c, f); }
    bool isOnlyPlane(const foresight::PlaneRegion& r) const override { return mWorld.isOnlyPlane(r); }
    float regionQueryCost(float r) const override { return mWorld.regionQueryCost(r); }
    bool findNear(const foresight::NearQuery& q, foresight::NearCollector& c) const override {
        return mWorld.findNear(q, c);
    }
    bool gatherShapes(const SegmentCast& r, foresight::ShapeCollector& c) const override {
        if (!mGathers) return false;
        ++gathers;
        return mWorld.gatherShapes(r, c);
    }
    mutable int gathers = 0;

private:
    const foresight::CollisionWorld& mWorld;
    bool mGathers;
};

// ProjectileMethod::Engine asks the shapes it gathered around a sphere in contact instead of the
// world: every engine's flight in the room (floor, walls, boxes, ramp, primitives) is the same,
// point for point and bit for bit, as when it asks the world every query.
// The Bullet profiles against convex shapes (Godot 3 with Bullet; Bullet 3.24 against boxes) also
// read the world's shapes, for Bullet's broadphase pairs (the solve order), its sweep's
// conservative advancement and the contact Bullet's own float arithmetic computes
// (bullet_gjk.h): a world that cannot list its shapes gets other answers there by design, so
// they are left out; Bullet 3.24 runs here against the room as one triangle mesh.
TEST_F(embree_world, EngineFlightIsTheSameWithGatheredShapes) {
    using foresight::PhysicsEngine;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const PhysicsEngine engine : {PhysicsEngine::Bullet, PhysicsEngine::Jolt, PhysicsEngine::PhysX,
                                       PhysicsEngine::Rapier, PhysicsEngine::Godot3}) {
        foresight::ProjectileSettings settings;
        settings.method = foresight::ProjectileMethod::Engine;
        settings.engine = foresight::engineProfile(engine);
        settings.engine.triangleMesh = engine == PhysicsEngine::Bullet;
        settings.step = settings.engine.timestep;
        for (const foresight::CollisionWorld* world :
             {static_cast<const foresight::CollisionWorld*>(&worlds->reference),
              static_cast<const foresight::CollisionWorld*>(&worlds->embree)}) {
            const Forwarding plain(*world, false), counted(*world, true);
            std::vector<foresight::TrajectoryPoint> a(400), b(400);
            for (int i = 0; i < 12; ++i) {
                settings.radius = static_cast<float>(0.05 + 0.2 * u(rng));
                settings.restitution = static_cast<float>(0.1 + 0.7 * u(rng));
                settings.friction = static_cast<float>(0.6 * u(rng));
                const RVec3 start = r3(-4 + 8 * u(rng), 0.5 + 3 * u(rng), -3 + 6 * u(rng));
                const Vec3 velocity(static_cast<float>(16 * u(rng) - 8), static_cast<float>(10 * u(rng) - 3),
                                    static_cast<float>(16 * u(rng) - 8));
                foresight::ProjectileResult ra, rb;
                ASSERT_EQ(foresight::predictProjectile(start, velocity, 3.0f, settings, &plain, a, ra), Status::Ok);
                ASSERT_EQ(foresight::predictProjectile(start, velocity, 3.0f, settings, &counted, b, rb), Status::Ok);
                ASSERT_EQ(ra.trajectorySize, rb.trajectorySize);
                for (std::size_t k = 0; k < ra.trajectorySize; ++k)
                    ASSERT_EQ(std::memcmp(&a[k], &b[k], sizeof a[k]), 0)
                        << "engine " << static_cast<int>(engine) << " throw " << i << " point " << k;
                EXPECT_EQ(ra.bounces, rb.bounces);
            }
            EXPECT_GT(counted.gathers, 12) << "engine " << static_cast<int>(engine);
        }
    }
}

}  // namespace
