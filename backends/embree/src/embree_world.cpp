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
// How far from the origin segments are handed to Embree [m] (its rays assert beyond ~1.8e18).
constexpr double kEmbreeReach = 1e15;
}  // namespace

namespace {

using DVec3 = glm::dvec3;

DVec3 toD(const RVec3& v) {
    return DVec3(static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z));
}

// Smallest float not below x.
float floatUp(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

struct Box {
    DVec3 lo{0.0}, hi{0.0};
};

Box triangleBox(const Triangle& t) {
    const DVec3 a = toD(t.a), b = toD(t.b), c = toD(t.c);
    return Box{glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
}

}  // namespace

struct EmbreeWorld::Impl {
    std::vector<Triangle> triangles;  // as added (validated), in order
    // What Embree traces: the meshes' own vertices rounded to float once (3 per vertex, shared
    // by the triangles that share them in the mesh) and 3 indices per kept triangle (triangle
    // t is triangles[t]).
    std::vector<float> floatVertices;
    std::vector<unsigned> vertexIndices;
    double largest = 0.0;  // largest coordinate magnitude of the mesh [Units: m]
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

// What one cast's queries need.
struct QueryState {
    const Triangle* triangles = nullptr;
    ClosestHitCaster single{SegmentCast{}};  // the cast prepared once, copied per candidate
    DVec3 origin{0.0};
    DVec3 displacement{0.0};
    DVec3 inverse{0.0};  // 1 / displacement per axis (0 for 0)
    double length = 0.0;
    double padding = 0.0;
    // The candidates whose own closest fraction equals the smallest one seen so far. Fractions
    // are distances divided by the length, so two different distances may share a fraction:
    // these all go through one caster at the end, in the order they were added, as in
    // StaticWorld (the smallest distance wins, the first added among equal distances).
    double bestFraction = std::numeric_limits<double>::infinity();
    std::array<unsigned, 32> ties;  // the first tieCount are used (left uninitialised: per cast)
    std::size_t tieCount = 0;
    ClosestHitCaster best{SegmentCast{}};  // the exact test of ties[0] alone
    bool overflowed = false;               // too many ties or checks: the cast is redone by the exact search

    // Radius 0 (rtcIntersect1 on the float triangles):
    double rho = 0.0;    // how far from a triangle's edges float and exact may disagree [m]
    double shift = 0.0;  // the traced ray starts this fraction before the segment
    float limit = 0.0f;  // the traced ray's current tfar
    // Points (fractions of the segment) around which every triangle within a radius [m] is
    // tested exactly (left uninitialised: per cast).
    std::array<double, 4> checks;
    std::array<double, 4> checkRadii;
    std::size_t checkCount = 0;
};

// Whether the segment origin + s * displacement, s in [0, sMax], meets box `b` grown by the
// padding.
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

// Records a triangle's exact fraction `f` (a hit when <= 1): the closest wins; among equal
// fractions, all are kept for the final ordered retest. Returns whether the best improved.
bool record(QueryState& q, unsigned index, double f) {
    if (!(f <= 1.0) || f > q.bestFraction) return false;
    const bool shrink = f < q.bestFraction;
    if (shrink) {
        q.bestFraction = f;
        q.tieCount = 0;
    }
    bool known = false;
    for (std::size_t k = 0; k < q.tieCount; ++k) known = known || q.ties[k] == index;
    if (known) return shrink;
    if (q.tieCount < q.ties.size())
        q.ties[q.tieCount++] = index;
    else
        q.overflowed = true;
    return shrink;
}

// Tests one triangle exactly and records it.
bool testAndRecord(QueryState& q, unsigned index, double* fraction = nullptr) {
    ClosestHitCaster caster = q.single;
    caster.test(q.triangles[index]);
    const double f = caster.closestFraction();
    if (fraction) *fraction = f;
    const bool shrink = record(q, index, f);
    if (shrink) q.best = caster;
    return shrink;
}

double exactFraction(const QueryState& q, unsigned index) {
    ClosestHitCaster caster = q.single;
    caster.test(q.triangles[index]);
    return caster.closestFraction();
}

// Tests one candidate found by a point query (after a box check).
bool offerTriangle(QueryState& q, unsigned index) {
    const double sMax = std::min(1.0, q.bestFraction);
    if (!segmentMeetsBox(q, triangleBox(q.triangles[index]), sMax)) return false;
    return testAndRecord(q, index);
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

// A local check (radius 0): every triangle near a point, tested exactly; the radius stays.
bool localCheckCallback(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<QueryState*>(args->userPtr);
    offerTriangle(*q, args->primID);
    return false;
}

void addCheck(QueryState& q, double fraction, double radius) {
    if (q.checkCount < q.checks.size()) {
        q.checks[q.checkCount] = fraction;
        q.checkRadii[q.checkCount++] = radius;
    } else {
        q.overflowed = true;
    }
}

// rho divided by the sine of the angle between the segment and the triangle's plane (below
// 1e-3: 1e-3): how far along the plane float and exact may put the crossing apart. `n` is the
// triangle's (unnormalised) normal, `area2` its length.
double grazeReach(const QueryState& q, const DVec3& n, double area2) {
    const double sine = std::abs(glm::dot(n, q.displacement)) / (area2 * q.length);
    return q.rho / std::max(sine, 1e-3);
}

// Whether the exact hit p (on the triangle's plane, inside it) lies within grazeReach of the
// triangle's edges (float errors along the plane grow as the ray grazes it).
bool nearEdge(const QueryState& q, const Triangle& t, const DVec3& p) {
    const DVec3 a = toD(t.a), b = toD(t.b), c = toD(t.c);
    const DVec3 n = glm::cross(b - a, c - a);
    const double area2 = glm::length(n);  // twice the area
    const double reach = grazeReach(q, n, area2);
    // Distance to the line of edge uv: |n . ((v - u) x (p - u))| / (|n| |v - u|).
    return std::abs(glm::dot(n, glm::cross(b - a, p - a))) < reach * area2 * glm::length(b - a) ||
           std::abs(glm::dot(n, glm::cross(c - b, p - b))) < reach * area2 * glm::length(c - b) ||
           std::abs(glm::dot(n, glm::cross(a - c, p - c))) < reach * area2 * glm::length(a - c);
}

// A triangle Embree's float test hit (at fraction fFloat of the segment) whose exact test gave
// fraction f: where float and exact may disagree, a local check is queued. Returns whether one
// was. An exact hit within grazeReach of the triangle's edges: a neighbour across the edge may
// hit closer (a concave corner), or the float test of a neighbour may have missed; every
// triangle within 4 reaches of the hit is tested. An exact miss: the ray passes just outside
// the triangle, where a neighbour sharing the edge or vertex hits (watertightness); the check
// is centred where the segment's line crosses the triangle's plane (exact, within reach of the
// edge that float put it inside of).
bool checkDoubt(QueryState& q, unsigned index, double f, double fFloat) {
    const Triangle& t = q.triangles[index];
    const DVec3 a = toD(t.a), b = toD(t.b), c = toD(t.c);
    const DVec3 n = glm::cross(b - a, c - a);
    const double reach = grazeReach(q, n, glm::length(n));
    if (f <= 1.0) {
        if (!nearEdge(q, t, q.origin + q.displacement * f)) return false;
        addCheck(q, f, 4.0 * reach);
        return true;
    }
    const double dn = glm::dot(n, q.displacement);
    const double crossing = dn != 0.0 ? -glm::dot(n, q.origin - a) / dn : fFloat;
    addCheck(q, std::isfinite(crossing) ? std::clamp(crossing, 0.0, 1.0) : std::clamp(fFloat, 0.0, 1.0), 4.0 * reach);
    return true;
}

// The slow path of radius 0 (a context filter on rtcIntersect1): Embree reports each triangle
// its float test hits, in no set order; each is tested exactly and recorded, and doubtful ones
// get a local check (checkDoubt). The traced ray then ends a margin (2 rho) past the best exact
// hit, so that near-ties are still reported.
struct RayContext {
    RTCIntersectContext context;  // first member: Embree passes its address back
    QueryState* query;
};

void intersectFilter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    QueryState& q = *reinterpret_cast<const RayContext*>(args->context)->query;
    const unsigned index = RTCHitN_primID(args->hit, 1, 0);
    float& tfar = RTCRayN_tfar(args->ray, 1, 0);
    const double fFloat = static_cast<double>(tfar) - q.shift;
    double f = 0.0;
    testAndRecord(q, index, &f);
    checkDoubt(q, index, f, fFloat);
    // Accepted with tfar where the search must go on to (never beyond where it was).
    const double far = std::min(1.0, q.bestFraction) + q.shift + 2.0 * q.rho / q.length;
    q.limit = std::min(q.limit, floatUp(far));
    tfar = q.limit;
}

// The exact search (radius > 0, and radius 0 when in doubt): one point query, a sphere centred
// at the segment's start holding every triangle that can be hit, shrunk as hits are found.
void exactSearch(RTCScene scene, QueryState& q) {
    RTCPointQuery query;
    // The centre is rounded to float: grow the radius by that rounding.
    query.x = static_cast<float>(q.origin.x);
    query.y = static_cast<float>(q.origin.y);
    query.z = static_cast<float>(q.origin.z);
    query.time = 0.0f;
    const double rounding = glm::length(DVec3(query.x, query.y, query.z) - q.origin);
    const double padding = q.padding;
    q.padding += rounding;
    query.radius = queryRadius(q, q.length * std::min(1.0, q.bestFraction));
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(scene, &query, &context, pointQueryCallback, &q);
    q.padding = padding;
}

// Local checks: every triangle within each queued check's radius of its point, tested exactly.
void runChecks(RTCScene scene, QueryState& q) {
    for (std::size_t k = 0; k < q.checkCount && !q.overflowed; ++k) {
        const double f = q.checks[k];
        if (f > q.bestFraction + 2.0 * q.shift) continue;  // cannot beat the best any more
        const DVec3 centre = q.origin + q.displacement * f;
        RTCPointQuery query;
        query.x = static_cast<float>(centre.x);
        query.y = static_cast<float>(centre.y);
        query.z = static_cast<float>(centre.z);
        query.time = 0.0f;
        query.radius = floatUp(q.checkRadii[k] + glm::length(DVec3(query.x, query.y, query.z) - centre));
        RTCPointQueryContext pointContext;
        rtcInitPointQueryContext(&pointContext);
        rtcPointQuery(scene, &query, &pointContext, localCheckCallback, &q);
    }
}

// Where Embree's float test (float vertices, float ray) and the exact test may disagree, for a
// segment of the given length [m]: 2^-20 of the largest coordinate involved, eight times the
// float rounding of a coordinate (2^-24 each for the vertices, the ray's origin and Embree's
// translation of the vertices to the ray's origin), plus 1 um.
double floatReach(double largest, double originMagnitude, double length) {
    return 1e-6 + std::ldexp(std::max(largest, originMagnitude) + length, -20);
}

// The ray Embree traces for a segment (radius 0): it starts rho before the segment, so that a
// hit at the very start is reported even when the float test puts it a little behind, and ends
// rho after it; t is measured along the displacement from that start.
void prepareRay(RTCRayHit& rayhit, const DVec3& origin, const DVec3& displacement, double shift, float limit) {
    const DVec3 start = origin - displacement * shift;
    rayhit.ray.org_x = static_cast<float>(start.x);
    rayhit.ray.org_y = static_cast<float>(start.y);
    rayhit.ray.org_z = static_cast<float>(start.z);
    rayhit.ray.dir_x = static_cast<float>(displacement.x);
    rayhit.ray.dir_y = static_cast<float>(displacement.y);
    rayhit.ray.dir_z = static_cast<float>(displacement.z);
    rayhit.ray.tnear = 0.0f;
    rayhit.ray.tfar = limit;
    rayhit.ray.time = 0.0f;
    rayhit.ray.mask = 0xFFFFFFFFu;
    rayhit.ray.id = 0;
    rayhit.ray.flags = 0;
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

enum class FastRay { Miss, Hit, Doubt };

// Radius 0, the fast path: one plain rtcIntersect1 (no filter) for Embree's float closest hit,
// then the exact test of that one triangle (`exact`, a copy of the prepared cast). Hit: the
// exact test hits within the segment farther than grazeReach from the triangle's edges; it is
// the mesh's result: a triangle the exact test hits closer, away from its own edges, is hit by
// the float test too, which would have reported it first unless both hits lie within the float
// error of each other along the ray (the near-tie exception in embree_world.h). Miss: no float
// hit (a triangle the exact test hits away from its edges and the segment's ends is hit by the
// float test). Doubt: anything else (the exact test misses, hits beyond the end or near an
// edge; about 0.3% of casts): the caller takes the slow path (castRay).
FastRay fastRay(RTCScene scene, const Triangle* triangles, const DVec3& origin, const DVec3& displacement,
                double length, double rho, ClosestHitCaster& exact, unsigned& index) {
    const double shift = rho / length;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit;
    prepareRay(rayhit, origin, displacement, shift, floatUp(1.0 + 2.0 * shift));
    rtcIntersect1(scene, &context, &rayhit);
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return FastRay::Miss;
    index = rayhit.hit.primID;
    const Triangle& t = triangles[index];
    exact.test(t);
    const double f = exact.closestFraction();
    if (!(f <= 1.0)) return FastRay::Doubt;
    // nearEdge without square roots: the hit p is within reach = rho / max(sine, 1e-3) of the
    // line of edge uv when (n . (uv x up))^2 max((n . d)^2, 1e-6 |n|^2 L^2) <
    // rho^2 |n|^4 L^2 |uv|^2 (sine = |n . d| / (|n| L)).
    const DVec3 a = toD(t.a), b = toD(t.b), c = toD(t.c);
    const DVec3 p = origin + displacement * f;
    const DVec3 n = glm::cross(b - a, c - a);
    const double nn = glm::dot(n, n), nd = glm::dot(n, displacement), ll = length * length;
    const double grazing = std::max(nd * nd, 1e-6 * nn * ll);
    const double bound = rho * rho * nn * nn * ll;
    auto near = [&](const DVec3& u, const DVec3& v) {
        const DVec3 e = v - u;
        const double side = glm::dot(n, glm::cross(e, p - u));
        return side * side * grazing < bound * glm::dot(e, e);
    };
    return near(a, b) || near(b, c) || near(c, a) ? FastRay::Doubt : FastRay::Hit;
}

// Radius 0, the slow path: the ray traced again with the filter (every float hit tested
// exactly, doubtful ones checked locally), and the exhaustive exact search if its fixed-size
// lists overflow.
void castRay(RTCScene scene, double rho, QueryState& q) {
    q.rho = rho;
    q.shift = q.rho / q.length;
    q.limit = floatUp(1.0 + 2.0 * q.shift);
    RayContext context;
    rtcInitIntersectContext(&context.context);
    context.query = &q;
    context.context.filter = intersectFilter;
    RTCRayHit rayhit;
    prepareRay(rayhit, q.origin, q.displacement, q.shift, q.limit);
    rtcIntersect1(scene, &context.context, &rayhit);
    runChecks(scene, q);
    if (q.overflowed) {
        // Rare (many near-ties or doubtful points): the exact search from scratch.
        q.bestFraction = std::numeric_limits<double>::infinity();
        q.tieCount = 0;
        q.overflowed = false;
        exactSearch(scene, q);
    }
}

}  // namespace

EmbreeWorld::EmbreeWorld() : EmbreeWorld(EmbreeWorldSettings{}) {}

EmbreeWorld::EmbreeWorld(const EmbreeWorldSettings& settings)
    : mSettings(settings), mPrimitives(StaticWorldSettings{settings.surfaceTolerance}),
      mImpl(std::make_unique<Impl>()) {}

EmbreeWorld::~EmbreeWorld() = default;
EmbreeWorld::EmbreeWorld(EmbreeWorld&&) noexcept = default;
EmbreeWorld& EmbreeWorld::operator=(EmbreeWorld&&) noexcept = default;

Status EmbreeWorld::add(const Plane& plane) { return mPrimitives.add(plane); }
Status EmbreeWorld::add(const Sphere& sphere) { return mPrimitives.add(sphere); }
Status EmbreeWorld::add(const OrientedBox& box) { return mPrimitives.add(box); }
Status EmbreeWorld::add(const Triangle& triangle) { return mPrimitives.add(triangle); }
void EmbreeWorld::addPrimitives(const StaticWorld& world) {
    for (std::size_t i = 0; i < world.planes().size(); ++i)
        mPrimitives.add(world.planes()[i], world.planeMaterials()[i]);
    for (std::size_t i = 0; i < world.spheres().size(); ++i)
        mPrimitives.add(world.spheres()[i], world.sphereMaterials()[i]);
    for (std::size_t i = 0; i < world.boxes().size(); ++i) mPrimitives.add(world.boxes()[i], world.boxMaterials()[i]);
    for (std::size_t i = 0; i < world.triangles().size(); ++i)
        mPrimitives.add(world.triangles()[i], world.triangleMaterials()[i]);
}

Status EmbreeWorld::add(const Plane& plane, const SurfaceMaterial& m) { return mPrimitives.add(plane, m); }
Status EmbreeWorld::add(const Sphere& sphere, const SurfaceMaterial& m) { return mPrimitives.add(sphere, m); }
Status EmbreeWorld::add(const OrientedBox& box, const SurfaceMaterial& m) { return mPrimitives.add(box, m); }
Status EmbreeWorld::add(const Triangle& triangle, const SurfaceMaterial& m) { return mPrimitives.add(triangle, m); }

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
    std::vector<unsigned> addedIndices;  // into vertices, 3 per added triangle
    added.reserve(indices.size() / 3);
    addedIndices.reserve(indices.size());
    for (std::size_t t = 0; t < indices.size() / 3; ++t) {
        const Triangle triangle{vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]};
        const Status status = validateTriangle(triangle);
        if (status == Status::Ok) {
            added.push_back(triangle);
            addedIndices.insert(addedIndices.end(), indices.begin() + static_cast<std::ptrdiff_t>(3 * t),
                                indices.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
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
    const std::size_t vertexBase = mImpl->floatVertices.size() / 3;
    if (vertexBase + vertices.size() > std::numeric_limits<unsigned>::max() - 1u) {
        r.error = "too many vertices";
        return Status::DegenerateShape;
    }
    // The vertices once, rounded to float: triangles sharing a vertex in the mesh share it in
    // Embree too (and equal coordinates round equally), so shared edges stay watertight.
    mImpl->floatVertices.reserve(mImpl->floatVertices.size() + 3 * vertices.size());
    for (const RVec3& v : vertices) {
        mImpl->floatVertices.push_back(static_cast<float>(v.x));
        mImpl->floatVertices.push_back(static_cast<float>(v.y));
        mImpl->floatVertices.push_back(static_cast<float>(v.z));
    }
    mImpl->vertexIndices.reserve(mImpl->vertexIndices.size() + addedIndices.size());
    for (const std::uint32_t i : addedIndices) mImpl->vertexIndices.push_back(static_cast<unsigned>(vertexBase + i));
    for (const Triangle& triangle : added) {
        const Box b = triangleBox(triangle);
        mImpl->largest = std::max({mImpl->largest, std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.lo.z),
                                   std::abs(b.hi.x), std::abs(b.hi.y), std::abs(b.hi.z)});
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
    // Robust: Embree's watertight float test. The context filter is set only by the casts'
    // slow path (castRay); plain rtcIntersect1 calls leave it null and pay nothing for it.
    rtcSetSceneFlags(impl.scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(impl.scene, RTC_BUILD_QUALITY_HIGH);
    // Native triangles over the meshes' shared float vertices (primID = index in `triangles`).
    RTCGeometry geometry = rtcNewGeometry(impl.device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) return fail("cannot create a geometry");
    const std::size_t vertexCount = impl.floatVertices.size() / 3;
    const std::size_t count = impl.triangles.size();
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), vertexCount));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        return fail("cannot allocate the mesh buffers");
    }
    std::copy(impl.floatVertices.begin(), impl.floatVertices.end(), vertices);
    std::copy(impl.vertexIndices.begin(), impl.vertexIndices.end(), indices);
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
    const ClosestHitCaster pristine = caster;
    // The primitives first, in StaticWorld's order.
    for (std::size_t i = 0; i < mPrimitives.planes().size(); ++i)
        caster.test(mPrimitives.planes()[i], mPrimitives.planeMaterials()[i]);
    for (std::size_t i = 0; i < mPrimitives.spheres().size(); ++i)
        caster.test(mPrimitives.spheres()[i], mPrimitives.sphereMaterials()[i]);
    for (std::size_t i = 0; i < mPrimitives.boxes().size(); ++i)
        caster.test(mPrimitives.boxes()[i], mPrimitives.boxMaterials()[i]);
    for (std::size_t i = 0; i < mPrimitives.triangles().size(); ++i)
        caster.test(mPrimitives.triangles()[i], mPrimitives.triangleMaterials()[i]);

    const Impl* impl = mImpl.get();
    if (impl && !impl->triangles.empty()) {
        const DVec3 origin = toD(cast.origin), displacement(cast.displacement);
        const double length = glm::length(displacement);
        const double originMagnitude = std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z)});
        // Embree's float rays are valid only well inside float range (it asserts beyond about
        // 1.8e18): a segment reaching past 1e15 m is tested against every triangle instead.
        const bool built = impl->committed && impl->scene && originMagnitude + length < kEmbreeReach;
        double rho = 0.0;
        if (built && cast.radius <= 0.0f) {
            rho = floatReach(impl->largest, originMagnitude, length);
            ClosestHitCaster exact = pristine;
            unsigned index = 0;
            switch (fastRay(impl->scene, impl->triangles.data(), origin, displacement, length, rho, exact, index)) {
                case FastRay::Miss:
                    return caster.result(hit);
                case FastRay::Hit:
                    // Strictly closer than the primitives: its own test is the result (the same as
                    // testing it after them); otherwise the primitives win or tie, in their order.
                    if (exact.closestFraction() < caster.closestFraction())
                        caster = exact;
                    else
                        caster.test(impl->triangles[index]);
                    return caster.result(hit);
                case FastRay::Doubt:
                    break;
            }
        }
        QueryState q;
        q.triangles = impl->triangles.data();
        q.single = pristine;
        q.origin = origin;
        q.displacement = displacement;
        q.length = length;
        for (int axis = 0; axis < 3; ++axis)
            q.inverse[axis] = q.displacement[axis] != 0.0 ? 1.0 / q.displacement[axis] : 0.0;
        const double magnitude = originMagnitude + q.length;
        q.padding = std::max(0.0, static_cast<double>(cast.radius)) +
                    static_cast<double>(std::max(0.0f, mSettings.surfaceTolerance)) + 1e-4 + 1e-6 * magnitude;
        if (built && cast.radius <= 0.0f) {
            castRay(impl->scene, rho, q);
        } else if (built) {
            exactSearch(impl->scene, q);
        } else {
            for (unsigned i = 0; i < impl->triangles.size(); ++i) offerTriangle(q, i);
        }
        if (q.overflowed) {
            // Rare (more than 32 triangles at exactly the same fraction): all of them, in order.
            for (unsigned i = 0; i < impl->triangles.size(); ++i) {
                if (!segmentMeetsBox(q, triangleBox(impl->triangles[i]), std::min(1.0, q.bestFraction))) continue;
                if (exactFraction(q, i) == q.bestFraction) caster.test(impl->triangles[i]);
            }
        } else if (q.tieCount == 1 && q.bestFraction < caster.closestFraction()) {
            // One closest triangle, strictly closer than the primitives: its own test is the
            // result (the same as testing it after them).
            caster = q.best;
        } else {
            std::sort(q.ties.begin(), q.ties.begin() + static_cast<std::ptrdiff_t>(q.tieCount));
            for (std::size_t k = 0; k < q.tieCount; ++k) caster.test(impl->triangles[q.ties[k]]);
        }
    }
    return caster.result(hit);
}

namespace {

struct TouchQuery {
    const Triangle* triangles = nullptr;
    SegmentCast capsule;
    bool touched = false;
};

bool touchCallback(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<TouchQuery*>(args->userPtr);
    if (q->touched || !mayTouch(q->capsule, q->triangles[args->primID])) return false;
    q->touched = true;
    args->query->radius = 0.0f;  // found one: the traversal may stop
    return true;
}

}  // namespace

namespace {

struct PlaneQuery {
    const Triangle* triangles = nullptr;
    PlaneRegionTester* tester = nullptr;
};

bool planeCallback(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<PlaneQuery*>(args->userPtr);
    q->tester->test(q->triangles[args->primID]);
    if (!q->tester->failed()) return false;
    args->query->radius = 0.0f;  // ruled out: the traversal may stop
    return true;
}

// A point query holding the capsule: a sphere around its middle, grown by the centre's rounding
// to float and a margin. False when the capsule lies beyond Embree's float range.
bool capsuleQuery(const SegmentCast& capsule, RTCPointQuery& query) {
    const DVec3 a = toD(capsule.origin), d(capsule.displacement);
    const DVec3 centre = a + 0.5 * d;
    if (!std::isfinite(centre.x + centre.y + centre.z)) return false;
    const double extent = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)}) + glm::length(d);
    if (!(extent < kEmbreeReach)) return false;
    query.x = static_cast<float>(centre.x);
    query.y = static_cast<float>(centre.y);
    query.z = static_cast<float>(centre.z);
    query.time = 0.0f;
    const double rounding = glm::length(DVec3(query.x, query.y, query.z) - centre);
    const double magnitude = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    query.radius = floatUp((0.5 * glm::length(d) + std::max(0.0, static_cast<double>(capsule.radius)) + rounding +
                            1e-4 + 1e-6 * magnitude) *
                           (1.0 + 1e-6));
    return true;
}

}  // namespace

bool EmbreeWorld::isOnlyPlane(const PlaneRegion& region) const {
    if (mSettings.surfaceTolerance != StaticWorldSettings{}.surfaceTolerance) return false;
    PlaneRegionTester tester(region);
    const StaticWorld& p = mPrimitives;
    for (std::size_t i = 0; i < p.planes().size() && !tester.failed(); ++i)
        tester.test(p.planes()[i], p.planeMaterials()[i]);
    for (std::size_t i = 0; i < p.spheres().size() && !tester.failed(); ++i)
        tester.test(p.spheres()[i], p.sphereMaterials()[i]);
    for (std::size_t i = 0; i < p.boxes().size() && !tester.failed(); ++i)
        tester.test(p.boxes()[i], p.boxMaterials()[i]);
    for (std::size_t i = 0; i < p.triangles().size() && !tester.failed(); ++i)
        tester.test(p.triangles()[i], p.triangleMaterials()[i]);
    const Impl* impl = mImpl.get();
    if (tester.failed() || !impl || impl->triangles.empty()) return tester.result();
    if (!impl->committed || !impl->scene) {
        for (std::size_t i = 0; i < impl->triangles.size() && !tester.failed(); ++i) tester.test(impl->triangles[i]);
        return tester.result();
    }
    RTCPointQuery query;
    if (!capsuleQuery(region.capsule, query)) return false;
    PlaneQuery q;
    q.triangles = impl->triangles.data();
    q.tester = &tester;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(impl->scene, &query, &context, planeCallback, &q);
    return tester.result();
}

bool EmbreeWorld::mayTouch(const SegmentCast& capsule) const {
    if (mPrimitives.mayTouch(capsule)) return true;
    const Impl* impl = mImpl.get();
    if (!impl || impl->triangles.empty()) return false;
    if (!impl->committed || !impl->scene) {
        for (const Triangle& t : impl->triangles)
            if (foresight::mayTouch(capsule, t)) return true;
        return false;
    }
    RTCPointQuery query;
    if (!capsuleQuery(capsule, query)) return true;  // beyond Embree's float range: "maybe"
    TouchQuery q;
    q.triangles = impl->triangles.data();
    q.capsule = capsule;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(impl->scene, &query, &context, touchCallback, &q);
    return q.touched;
}

namespace {

struct FirstTouchQuery {
    const Triangle* triangles = nullptr;
    SegmentCast capsule;
    bool touched = false;
    float fraction = 1.0f;
};

bool firstTouchCallback(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<FirstTouchQuery*>(args->userPtr);
    float f = 1.0f;
    if (!firstTouch(q->capsule, q->triangles[args->primID], f)) return false;
    q->touched = true;
    q->fraction = std::min(q->fraction, f);
    if (q->fraction > 0.0f) return false;
    args->query->radius = 0.0f;  // touching at the start: nothing can come earlier
    return true;
}

}  // namespace

bool EmbreeWorld::firstTouch(const SegmentCast& capsule, float& fraction) const {
    FirstTouchQuery q;
    q.touched = mPrimitives.firstTouch(capsule, q.fraction);
    if (!q.touched) q.fraction = 1.0f;
    const Impl* impl = mImpl.get();
    if (impl && !impl->triangles.empty() && q.fraction > 0.0f) {
        q.triangles = impl->triangles.data();
        q.capsule = capsule;
        RTCPointQuery query;
        if (!impl->committed || !impl->scene) {
            for (const Triangle& t : impl->triangles) {
                float f = 1.0f;
                if (!foresight::firstTouch(capsule, t, f)) continue;
                q.touched = true;
                q.fraction = std::min(q.fraction, f);
            }
        } else {
            // Piece by piece from the start (each point query's sphere holds one piece): a shape
            // whose first touch lies in a piece is within that piece's sphere, so the pieces
            // that start after the earliest touch found so far cannot hold an earlier one.
            const double length = glm::length(DVec3(capsule.displacement));
            const double radius = std::max(1e-3, 2.0 * static_cast<double>(capsule.radius));
            const int pieces = static_cast<int>(std::clamp(std::ceil(length / radius), 1.0, 8.0));
            for (int i = 0; i<pieces&& static_cast<double>(q.fraction)> static_cast<double>(i) / pieces; ++i) {
                SegmentCast piece = capsule;
                piece.origin = RVec3(toD(capsule.origin) + DVec3(capsule.displacement) * (double(i) / pieces));
                piece.displacement = capsule.displacement * (1.0f / static_cast<float>(pieces));
                if (!capsuleQuery(piece, query)) {
                    q.touched = true;  // beyond Embree's float range: "maybe, at once"
                    q.fraction = 0.0f;
                    break;
                }
                RTCPointQueryContext context;
                rtcInitPointQueryContext(&context);
                rtcPointQuery(impl->scene, &query, &context, firstTouchCallback, &q);
            }
        }
    }
    fraction = q.touched ? q.fraction : 0.0f;
    return q.touched;
}

FORESIGHT_NAMESPACE_END
