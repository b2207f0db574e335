/// hello_embree.cpp: a grenade predicted against a triangle mesh held in Embree's BVH
/// (foresight::embree, the `embree` component of the installed package).
///
///   find_package(foresight CONFIG REQUIRED COMPONENTS embree)
///   target_link_libraries(game PRIVATE foresight::embree)
///
/// A level would come from loadObj("level.obj") or loadGltf("level.glb"); here the mesh is
/// made in code: a 20 m x 20 m floor of 1 m tiles and a wall 6 m high, 0.5 m thick, at z = 6.

#include <foresight/embree_world.h>
#include <foresight/foresight.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using namespace foresight;

namespace {

// A box [lo, hi] as 12 triangles wound counter-clockwise seen from outside.
void addBox(std::vector<RVec3>& vertices, std::vector<std::uint32_t>& indices, RVec3 lo, RVec3 hi) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    for (int i = 0; i < 8; ++i)
        vertices.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    const std::uint32_t faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                        {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    for (const auto& face : faces)
        for (std::uint32_t corner : face) indices.push_back(base + corner);
}

}  // namespace

int main() {
    std::vector<RVec3> vertices;
    std::vector<std::uint32_t> indices;
    // The floor: 1 m tiles facing +Y.
    for (int x = -10; x < 10; ++x) {
        for (int z = -10; z < 10; ++z) {
            const auto base = static_cast<std::uint32_t>(vertices.size());
            vertices.emplace_back(x, 0, z);
            vertices.emplace_back(x + 1, 0, z);
            vertices.emplace_back(x + 1, 0, z + 1);
            vertices.emplace_back(x, 0, z + 1);
            for (std::uint32_t corner : {0u, 2u, 1u, 0u, 3u, 2u}) indices.push_back(base + corner);
        }
    }
    addBox(vertices, indices, RVec3(-5, 0, 6), RVec3(5, 6, 6.5));

    EmbreeWorld world;
    MeshReport report;
    if (world.addMesh(vertices, indices, &report) != Status::Ok) {
        std::fprintf(stderr, "mesh refused: %s\n", report.error.c_str());
        return 1;
    }
    std::string error;
    if (!world.commit(&error)) {
        std::fprintf(stderr, "Embree failed: %s\n", error.c_str());
        return 1;
    }

    // A grenade thrown at 12 m/s towards the wall, bouncing for its 3 s fuse.
    ProjectileSettings settings;  // Exact, restitution 0.5, step 0.02 s
    std::vector<TrajectoryPoint> points(trajectoryCapacity(3.0f, settings));
    ProjectileResult result;
    const Status status =
        predictProjectile(RVec3(0, 1.5f, 0), Vec3(0, 7.2f, 9.6f), 3.0f, settings, &world, points, result);
    if (status != Status::Ok) {
        std::fprintf(stderr, "prediction refused: %s\n", statusMessage(status));
        return 1;
    }
    std::printf("%zu mesh triangles; grenade after 3 s at (%.3f, %.3f, %.3f) after %u bounces%s\n",
                world.meshTriangleCount(), static_cast<double>(result.position.x),
                static_cast<double>(result.position.y) + 0.0, static_cast<double>(result.position.z), result.bounces,
                result.atRest ? ", at rest" : "");
    // It bounced off the wall (z < 6) and stays above the floor.
    return result.bounces > 0 && result.position.z < 6 && result.position.y >= 0 ? 0 : 1;
}
