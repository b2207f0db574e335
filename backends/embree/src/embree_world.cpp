#include <foresight/embree_world.h>

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <new>
#include <vector>

FORESIGHT_NAMESPACE_BEGIN

namespace {

using DVec3 = glm::dvec3;

DVec3 toD(const RVec3& v) { return DVec3(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)); }

// Largest float not above x / smallest not below x.
float floatDown(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float floatUp(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

struct Box {
    DVec3 lo{0.0}, hi{0.0};
};

// What Embree's callbacks see of the mesh.
struct GeometryData {
    const Box* bounds = nullptr;
    double pad = 0.0;  // the float bounds are the exact ones grown by this [Units: m]
};

}  // namespace

struct EmbreeWorld::Impl {
    std::vector<Triangle> triangles;  // as added (validated), in order
    std::vector<Box> bounds;          // exact bounds of each triangle (double)
    GeometryData geometry;            // for the callbacks (stable address: Impl is on the heap)
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    bool committed = false;

    ~Impl() { release(); }
    void release() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
        scene = nullptr;
        device = nullptr;
        committed = false;
    }
};

namespace {

void boundsCallback(const RTCBoundsFunctionArguments* args) {
    const auto* data = static_cast<const GeometryData*>(args->geometryUserPtr);
    const Box& b = data->bounds[args->primID];
    const double pad = data->pad;
    RTCBounds* out = args->bounds_o;
    out->lower_x = floatDown(b.lo.x - pad);
    out->lower_y = floatDown(b.lo.y - pad);
    out->lower_z = floatDown(b.lo.z - pad);
    out->upper_x = floatUp(b.hi.x + pad);
    out->upper_y = floatUp(b.hi.y + pad);
    out->upper_z = floatUp(b.hi.z + pad);
}

// What one cast's point query needs.
struct QueryState {
    const Triangle* triangles = nullptr;
    const Box* bounds = nullptr;
    SegmentCast cast;
    float surfaceTolerance = 0.0f;
    DVec3 origin{0.0};
    DVec3 displacement{0.0};
    DVec3 inverse{0.0};  // 1 / displacement per axis (inf for 0)
    double length = 0.0;
    double padding = 0.0;
    // The candidates whose own closest fraction equals the smallest one seen so far. Fractions
    // are distances divided by the length, so two different distances may share a fraction:
    // these all go through one caster at the end, in the order they were added, as in
    // StaticWorld (the smallest distance wins, the first added among equal distances).
    double bestFraction = std::numeric_limits<double>::infinity();
    std::array<unsigned, 128> ties{};
    std::size_t tieCount = 0;
    bool tiesOverflowed = false;  // then every triangle with that fraction is retested in order
};

// Whether the segment origin + s * displacement, s in [0, sMax], meets box `b` grown by `pad`.
bool segmentMeetsBox(const QueryState& q, const Box& b, double sMax) {
    double s0 = 0.0, s1 = sMax;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = b.lo[axis] - q.padding, hi = b.hi[axis] + q.padding;
        const double o = q.origin[axis];
        if (q.displacement[axis] == 0.0) {
            if (o < lo || o > hi) return false;
            continue;
        }
        double t0 = (lo - o) * q.inverse[axis], t1 = (hi - o) * q.inverse[axis];
        if (t0 > t1) std::swap(t0, t1);
        // A hair of slack for the division's rounding.
        t0 -= 1e-12;
        t1 += 1e-12;
        s0 = std::max(s0, t0);
        s1 = std::min(s1, t1);
        if (s0 > s1) return false;
    }
    return true;
}

float queryRadius(const QueryState& q, double distance) {
    const double r = (distance + q.padding) * (1.0 + 1e-6);
    return floatUp(r);
}

// Tests one candidate: the closest triangle wins; among equal fractions, the first added.
bool offerTriangle(QueryState& q, unsigned index) {
    const double sMax = std::min(1.0, q.bestFraction);
    if (!segmentMeetsBox(q, q.bounds[index], sMax)) return false;
    ClosestHitCaster caster(q.cast, q.surfaceTolerance);
    caster.test(q.triangles[index]);
    const double f = caster.closestFraction();
    if (!(f <= 1.0)) return false;
    if (f > q.bestFraction) return false;
    const bool shrink = f < q.bestFraction;
    if (shrink) {
        q.bestFraction = f;
        q.tieCount = 0;
        q.tiesOverflowed = false;
    }
    if (q.tieCount < q.ties.size()) q.ties[q.tieCount++] = index;
    else q.tiesOverflowed = true;
    return shrink;
}

bool pointQueryCallback(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<QueryState*>(args->userPtr);
    if (!offerTriangle(*q, args->primID)) return false;
    const float radius = queryRadius(*q, q->bestFraction * q->length);
    if (radius < args->query->radius) {
        args->query->radius = radius;
        return true;
    }
    return false;
}

// rtcIntersect1 (radius 0): every primitive whose padded box the segment's ray crosses.
struct RayContext {
    RTCIntersectContext context;  // first member: Embree passes its address back
    QueryState* query;
};

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    QueryState& q = *reinterpret_cast<const RayContext*>(args->context)->query;
    if (!offerTriangle(q, args->primID)) return;
    // Cull what lies beyond the closest hit (plus a margin, so that ties are still visited).
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, 1);
    const float far = floatUp(q.bestFraction * (1.0 + 1e-6) + 1e-9);
    if (far < RTCRayN_tfar(ray, 1, 0)) RTCRayN_tfar(ray, 1, 0) = far;
}

}  // namespace

EmbreeWorld::EmbreeWorld() : EmbreeWorld(EmbreeWorldSettings{}) {}

EmbreeWorld::EmbreeWorld(const EmbreeWorldSettings& settings)
    : mSettings(settings), mPrimitives(StaticWorldSettings{settings.surfaceTolerance}), mImpl(std::make_unique<Impl>()) {}

EmbreeWorld::~EmbreeWorld() = default;
EmbreeWorld::EmbreeWorld(EmbreeWorld&&) noexcept = default;
EmbreeWorld& EmbreeWorld::operator=(EmbreeWorld&&) noexcept = default;

Status EmbreeWorld::add(const Plane& plane) { return mPrimitives.add(plane); }
Status EmbreeWorld::add(const Sphere& sphere) { return mPrimitives.add(sphere); }
Status EmbreeWorld::add(const OrientedBox& box) { return mPrimitives.add(box); }
Status EmbreeWorld::add(const Triangle& triangle) { return mPrimitives.add(triangle); }

std::size_t EmbreeWorld::meshTriangleCount() const { return mImpl ? mImpl->triangles.size() : 0; }

std::span<const Triangle> EmbreeWorld::meshTriangles() const {
    if (!mImpl) return {};
    return mImpl->triangles;
}

Status EmbreeWorld::addMesh(std::span<const RVec3> vertices, std::span<const std::uint32_t> indices,
                            MeshReport* report) {
    MeshReport local;
    MeshReport& r = report ? *report : local;
    r = MeshReport{};
    if (!mImpl) mImpl = std::make_unique<Impl>();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const DVec3 v = toD(vertices[i]);
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
            r.error = "vertex " + std::to_string(i) + " is not finite";
            return Status::NonFiniteInput;
        }
    }
    if (indices.size() % 3 != 0) {
        r.error = "the index count (" + std::to_string(indices.size()) + ") is not a multiple of 3";
        return Status::DegenerateShape;
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= vertices.size()) {
            r.error = "index " + std::to_string(i) + " refers to vertex " + std::to_string(indices[i]) +
                      ", out of range (" + std::to_string(vertices.size()) + " vertices)";
            return Status::DegenerateShape;
        }
    }
    std::vector<Triangle> added;
    added.reserve(indices.size() / 3);
    for (std::size_t t = 0; t < indices.size() / 3; ++t) {
        const Triangle triangle{vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]};
        const Status status = validateTriangle(triangle);
        if (status == Status::Ok) {
            added.push_back(triangle);
        } else {
            if (r.degenerateTriangles++ == 0) r.firstDegenerateTriangle = t;
        }
    }
    if (added.empty()) {
        r.error = r.degenerateTriangles > 0
                      ? "no usable triangles (" + std::to_string(r.degenerateTriangles) + " degenerate ones skipped)"
                      : std::string("no triangles");
        return Status::DegenerateShape;
    }
    if (mImpl->triangles.size() + added.size() > std::numeric_limits<unsigned>::max() - 1u) {
        r.error = "too many triangles";
        return Status::DegenerateShape;
    }
    for (const Triangle& triangle : added) {
        const DVec3 a = toD(triangle.a), b = toD(triangle.b), c = toD(triangle.c);
        mImpl->bounds.push_back(Box{glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))});
        mImpl->triangles.push_back(triangle);
    }
    r.triangles = added.size();
    mImpl->committed = false;
    return Status::Ok;
}

bool EmbreeWorld::commit(std::string* error) {
    if (!mImpl) mImpl = std::make_unique<Impl>();
    Impl& impl = *mImpl;
    impl.release();
    auto fail = [&](const char* what) {
        if (error) *error = std::string("Embree: ") + what;
        impl.release();
        return false;
    };
    if (impl.triangles.empty()) {
        impl.committed = true;  // nothing to build
        return true;
    }
    impl.device = rtcNewDevice(nullptr);
    if (!impl.device) return fail("cannot create a device");
    impl.scene = rtcNewScene(impl.device);
    if (!impl.scene) return fail("cannot create a scene");
    rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl.scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_USER);
    if (!geometry) return fail("cannot create a geometry");
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(impl.triangles.size()));
    // Bounds padding: covers the shape tests' edge margin (1e-9 of an edge), and the rounding of
    // a ray's origin to float when that origin is no farther out than twice the mesh
    // (2^-24 of a coordinate); see castSegment.
    double largest = 0.0;
    for (const Box& b : impl.bounds)
        largest = std::max({largest, std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.lo.z), std::abs(b.hi.x),
                            std::abs(b.hi.y), std::abs(b.hi.z)});
    impl.geometry.bounds = impl.bounds.data();
    impl.geometry.pad = 1e-6 + std::ldexp(largest, -21);
    rtcSetGeometryUserData(geometry, &impl.geometry);
    rtcSetGeometryBoundsFunction(geometry, boundsCallback, nullptr);
    rtcSetGeometryIntersectFunction(geometry, intersectCallback);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(impl.scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(impl.scene);
    if (rtcGetDeviceError(impl.device) != RTC_ERROR_NONE) return fail("building the BVH failed");
    impl.committed = true;
    return true;
}

bool EmbreeWorld::castSegment(const SegmentCast& cast, CastHit& hit) const {
    ClosestHitCaster caster(cast, mSettings.surfaceTolerance);
    if (!caster.valid()) return false;
    // The primitives first, in StaticWorld's order.
    for (const Plane& p : mPrimitives.planes()) caster.test(p);
    for (const Sphere& s : mPrimitives.spheres()) caster.test(s);
    for (const OrientedBox& b : mPrimitives.boxes()) caster.test(b);
    for (const Triangle& t : mPrimitives.triangles()) caster.test(t);

    const Impl* impl = mImpl.get();
    if (impl && !impl->triangles.empty()) {
        QueryState q;
        q.triangles = impl->triangles.data();
        q.bounds = impl->bounds.data();
        q.cast = cast;
        q.surfaceTolerance = mSettings.surfaceTolerance;
        q.origin = toD(cast.origin);
        q.displacement = DVec3(cast.displacement);
        q.length = glm::length(q.displacement);
        for (int axis = 0; axis < 3; ++axis)
            q.inverse[axis] = q.displacement[axis] != 0.0 ? 1.0 / q.displacement[axis] : 0.0;
        const double magnitude = std::max({std::abs(q.origin.x), std::abs(q.origin.y), std::abs(q.origin.z)}) + q.length;
        q.padding = std::max(0.0, static_cast<double>(cast.radius)) +
                    static_cast<double>(std::max(0.0f, mSettings.surfaceTolerance)) + 1e-4 + 1e-6 * magnitude;
        // The float ray Embree traces: the displacement is float already (exact); the origin
        // rounds to float, within the bounds' padding unless it lies far outside the mesh.
        const DVec3 rayOrigin(static_cast<float>(q.origin.x), static_cast<float>(q.origin.y),
                              static_cast<float>(q.origin.z));
        const bool rayExact = glm::length(rayOrigin - q.origin) * 2.0 <= impl->geometry.pad;
        if (impl->committed && impl->scene && cast.radius <= 0.0f && rayExact) {
            RayContext context;
            rtcInitIntersectContext(&context.context);
            context.query = &q;
            RTCRayHit rayhit;
            rayhit.ray.org_x = static_cast<float>(rayOrigin.x);
            rayhit.ray.org_y = static_cast<float>(rayOrigin.y);
            rayhit.ray.org_z = static_cast<float>(rayOrigin.z);
            rayhit.ray.dir_x = cast.displacement.x;
            rayhit.ray.dir_y = cast.displacement.y;
            rayhit.ray.dir_z = cast.displacement.z;
            rayhit.ray.tnear = 0.0f;
            rayhit.ray.tfar = std::nextafter(1.0f, 2.0f);
            rayhit.ray.time = 0.0f;
            rayhit.ray.mask = 0xFFFFFFFFu;
            rayhit.ray.id = 0;
            rayhit.ray.flags = 0;
            rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
            rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(impl->scene, &context.context, &rayhit);
        } else if (impl->committed && impl->scene) {
            RTCPointQuery query;
            // The centre is rounded to float: grow the radius by that rounding.
            query.x = static_cast<float>(q.origin.x);
            query.y = static_cast<float>(q.origin.y);
            query.z = static_cast<float>(q.origin.z);
            query.time = 0.0f;
            const double rounding = glm::length(DVec3(query.x, query.y, query.z) - q.origin);
            q.padding += rounding;
            query.radius = queryRadius(q, q.length);
            RTCPointQueryContext context;
            rtcInitPointQueryContext(&context);
            rtcPointQuery(impl->scene, &query, &context, pointQueryCallback, &q);
        } else {
            for (unsigned i = 0; i < impl->triangles.size(); ++i) offerTriangle(q, i);
        }
        if (q.tiesOverflowed) {
            // Rare (more than 128 triangles at exactly the same fraction): all of them, in order.
            for (unsigned i = 0; i < impl->triangles.size(); ++i) {
                if (!segmentMeetsBox(q, impl->bounds[i], std::min(1.0, q.bestFraction))) continue;
                ClosestHitCaster single(cast, mSettings.surfaceTolerance);
                single.test(impl->triangles[i]);
                if (single.closestFraction() == q.bestFraction) caster.test(impl->triangles[i]);
            }
        } else {
            std::sort(q.ties.begin(), q.ties.begin() + static_cast<std::ptrdiff_t>(q.tieCount));
            for (std::size_t k = 0; k < q.tieCount; ++k) caster.test(impl->triangles[q.ties[k]]);
        }
    }
    return caster.result(hit);
}

FORESIGHT_NAMESPACE_END
