#pragma once
/// @file fuzz_mesh.h
/// What the mesh harnesses do with an EmbreeWorld after a loader: check the result, build the
/// BVH and cast through the mesh, as a scenario's predictions would.

#include "fuzz_common.h"

#include <foresight/embree_world.h>

#include <algorithm>
#include <cmath>

namespace foresight_fuzz {

inline void useLoaded(foresight::EmbreeWorld& world, const foresight::MeshLoadResult& loaded) {
    if (!loaded.ok) {
        FORESIGHT_FUZZ_CHECK(!loaded.error.empty());
        FORESIGHT_FUZZ_CHECK(world.meshTriangleCount() == 0);
        return;
    }
    FORESIGHT_FUZZ_CHECK(loaded.report.triangles == world.meshTriangleCount());
    FORESIGHT_FUZZ_CHECK(world.meshTriangleCount() > 0);
    double extent = 0;
    for (const auto& t : world.meshTriangles())
        for (const auto& v : {t.a, t.b, t.c})
            for (int k = 0; k < 3; ++k) {
                FORESIGHT_FUZZ_CHECK(std::isfinite(static_cast<double>(v[k])));
                extent = std::max(extent, std::abs(static_cast<double>(v[k])));
            }
    std::string error;
    if (!world.commit(&error)) return;
    // Any extent: EmbreeWorld answers segments beyond Embree's float range without it.
    // A sphere down through the first triangle's centroid, from above the whole mesh.
    const auto& t = world.meshTriangles().front();
    const foresight::RVec3 centre = (t.a + t.b + t.c) / static_cast<foresight::Real>(3);
    foresight::SegmentCast cast;
    cast.origin = foresight::RVec3(centre.x, static_cast<foresight::Real>(extent + 1), centre.z);
    cast.displacement = foresight::Vec3(0.0f, static_cast<float>(-2 * extent - 2), 0.0f);
    cast.radius = 0.1f;
    foresight::CastHit hit;
    if (world.castSegment(cast, hit)) {
        FORESIGHT_FUZZ_CHECK(std::isfinite(hit.fraction) && hit.fraction >= 0 && hit.fraction <= 1);
    }
    world.mayTouch(cast);
    // The closest-point query around the same centroid: finite reports, within the radius.
    struct Collector final : foresight::NearCollector {
        float radius = 0.0f;
        void add(const foresight::NearSurface& s) override {
            FORESIGHT_FUZZ_CHECK(std::isfinite(s.distance) && s.distance <= radius * 1.0001f + 1e-3f);
            FORESIGHT_FUZZ_CHECK(std::isfinite(s.normal.x) && std::isfinite(s.normal.y) && std::isfinite(s.normal.z));
        }
    } collector;
    foresight::NearQuery query;
    query.center = centre;
    query.radius = collector.radius = static_cast<float>(std::min(1e30, 0.1 * extent + 1.0));
    world.findNear(query, collector);
}

}  // namespace foresight_fuzz
