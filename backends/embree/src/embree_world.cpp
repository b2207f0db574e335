#include <foresight/embree_world.h>

#include <embree3/rtcore.h>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <type_traits>
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
    if (static_cast<double>(f) < x) {
        // The next float up: for a positive finite float, the next bit pattern (no libm call on
        // the casts' path); std::nextafter otherwise. Both give the same value.
        if (f > 0.0f && f < std::numeric_limits<float>::max())
            f = std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) + 1u);
        else
            f = std::nextafter(f, std::numeric_limits<float>::infinity());
    }
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

namespace {

// What the radius-0 fast path reads to confirm Embree's float hit on triangle t exactly: the
// triangle and its unit normal as ClosestHitCaster's triangle test computes it (in double,
// glm::normalize(glm::cross(b - a, c - a)) over the vertices converted to double: the same
// operations on the same values, so the same bits). In float builds this is 36 + 4 + 24 = 64
// bytes, one cache line (the records are allocated at 64 bytes), where reading the triangle
// (36 bytes at a stride of 36) and recomputing the normal touched two lines half of the time
// and paid a square root and a division per hit.
struct alignas(sizeof(Real) == 4 ? 64 : 32) Confirmation {
    Triangle triangle;
    glm::dvec3 normal{0.0};
};
static_assert(sizeof(Real) != 4 || sizeof(Confirmation) == 64, "one cache line per triangle in float builds");
static_assert(std::is_trivially_copyable_v<Confirmation> && std::is_trivially_destructible_v<Confirmation>);

// The confirmation records, one per mesh triangle in primitive order. Large arrays are aligned
// to 2 MiB and, on Linux, offered to the kernel for transparent huge pages (madvise), as Embree
// does for its BVH: the fast path reads one record per hit at random, and with 4 KiB pages a
// million records (64 MB, 16 384 pages) would add a TLB miss (a page walk) to each of those
// reads.
class ConfirmationBuffer {
public:
    ConfirmationBuffer() = default;
    ConfirmationBuffer(const ConfirmationBuffer&) = delete;
    ConfirmationBuffer& operator=(const ConfirmationBuffer&) = delete;
    ~ConfirmationBuffer() { release(); }

    // Room for `count` records (contents unspecified); false when out of memory.
    bool allocate(std::size_t count) {
        release();
        constexpr std::size_t kHugePage = std::size_t(2) << 20;
        const std::size_t bytes = count * sizeof(Confirmation);
        const std::size_t alignment = bytes >= kHugePage ? kHugePage : alignof(Confirmation);
        const std::size_t rounded = (bytes + alignment - 1) / alignment * alignment;
        void* memory = std::aligned_alloc(alignment, rounded);
        if (!memory) return false;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (alignment == kHugePage) (void)madvise(memory, rounded, MADV_HUGEPAGE);  // a hint: failure is harmless
#endif
        mData = static_cast<Confirmation*>(memory);
        mCount = count;
        return true;
    }
    void release() {
        std::free(mData);
        mData = nullptr;
        mCount = 0;
    }
    Confirmation* data() { return mData; }
    const Confirmation* data() const { return mData; }
    std::size_t size() const { return mCount; }

private:
    Confirmation* mData = nullptr;
    std::size_t mCount = 0;
};

}  // namespace

struct EmbreeWorld::Impl {
    std::vector<Triangle> triangles;   // as added (validated), in order
    ConfirmationBuffer confirmations;  // triangles[t] and its normal, built by commit()
    // What Embree traces: the meshes' own vertices rounded to float once (3 per vertex, shared
    // by the triangles that share them in the mesh) and 3 indices per kept triangle (triangle
    // t is triangles[t]).
    std::vector<float> floatVertices;
    std::vector<unsigned> vertexIndices;
    // Per triangle, its edges shared with exactly one other triangle on the edge's other side
    // (PlaneRegionTester's sharedEdges), built by commit(); empty before.
    std::vector<std::uint8_t> sharedEdges;
    double largest = 0.0;  // largest coordinate magnitude of the mesh [Units: m]
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    // The region queries' tree (firstTouch, mayTouch, gatherShapes): Embree's BVH builder over
    // the triangles' float bounding boxes, with nodes of our own (RegionNode, RegionLeaf) that a
    // capsule walks directly. Embree's own tree answers only rays and point queries (spheres),
    // and a sphere holding a long capsule holds most of a level.
    RTCBVH regionBvh = nullptr;
    const void* regionRoot = nullptr;
    bool committed = false;

    ~Impl() { release(); }
    void release() {
        confirmations.release();
        sharedEdges.clear();
        if (regionBvh) rtcReleaseBVH(regionBvh);
        regionBvh = nullptr;
        regionRoot = nullptr;
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
    const void* regionRoot = nullptr;  // the region tree (runChecks walks it), or null: Embree's point query
};

// Offers offerTriangle every triangle of the region tree's leaves whose boxes lie within
// `radius` of `centre` (with regionCapsule's margin); false when the walk ran out of stack.
bool offerNear(const void* regionRoot, const DVec3& centre, double radius, QueryState& q);

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
        // The region tree's leaves around the point (a walk of a few boxes, where Embree's point
        // query costs about four times as much); Embree's where there is no tree.
        if (q.regionRoot && offerNear(q.regionRoot, centre, q.checkRadii[k], q)) continue;
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
    // 2^-20 as a product (exact, as std::ldexp would be, without the libm call).
    return 1e-6 + (std::max(largest, originMagnitude) + length) * 0x1p-20;
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

enum class FastRay { Hit, Doubt };

// A radius-0 cast prepared for the fast path: the values that ClosestHitCaster's constructor
// and castSegment compute from the cast, computed the same way (so that confirm() below
// reproduces their bits).
struct FastCast {
    DVec3 origin{0.0};        // the cast's origin in double
    DVec3 displacement{0.0};  // the cast's displacement in double
    double length = 0.0;      // glm::length(displacement) [m]
    double rho = 0.0;         // floatReach of the cast [m]
    double shift = 0.0;       // rho / length: the traced ray starts this fraction early
};

// Whether `cast` takes the fast path (radius 0, a valid segment within Embree's float range,
// `built`: a committed scene), and its prepared values; `largest` is Impl::largest.
bool prepareFast(const SegmentCast& cast, bool built, double largest, FastCast& f) {
    // A mesh reaching beyond kEmbreeReach would start the ray that far back (rho): no fast path.
    if (!(cast.radius <= 0.0f) || !built || !(largest < kEmbreeReach)) return false;
    f.origin = toD(cast.origin);
    f.displacement = toD(cast.displacement);
    f.length = glm::length(f.displacement);
    // ClosestHitCaster::valid(): such a cast hits nothing; castSegment says so.
    if (!(f.length > 0.0) || !std::isfinite(f.length) || !std::isfinite(f.origin.x + f.origin.y + f.origin.z))
        return false;
    const double originMagnitude = std::max({std::abs(f.origin.x), std::abs(f.origin.y), std::abs(f.origin.z)});
    if (!(originMagnitude + f.length < kEmbreeReach)) return false;
    f.rho = floatReach(largest, originMagnitude, f.length);
    f.shift = f.rho / f.length;
    return true;
}

// StaticWorld's insideTriangle (src/static_world.cpp): the same expressions, so the same answer.
bool insideTriangle(const DVec3& p, const DVec3& a, const DVec3& b, const DVec3& c, const DVec3& n) {
    const double margin = -1e-9 * glm::dot(n, glm::cross(b - a, c - a));
    return glm::dot(n, glm::cross(b - a, p - a)) >= margin && glm::dot(n, glm::cross(c - b, p - b)) >= margin &&
           glm::dot(n, glm::cross(a - c, p - c)) >= margin;
}

// The exact hit of one confirmed triangle: its distance along the cast's direction [m] and its
// normal facing the cast's origin (ClosestHitCaster's best after testing that triangle alone).
struct FastHit {
    double distance = 0.0;  // [m] along the direction
    double fraction = 0.0;  // distance / length, in [0, 1]
    DVec3 point{0.0};       // origin + displacement * fraction [m]
    DVec3 normal{0.0};
};

// The fast path's verdict on Embree's float closest hit, the triangle of `record`. Hit: the
// exact test (ClosestHitCaster's, for this triangle alone) hits within the segment farther than
// grazeReach from the triangle's edges, and `hit` is that test's result; it is the mesh's
// result: a triangle the exact test hits closer, away from its own edges, is hit by the float
// test too, which would have reported it first unless both hits lie within the float error of
// each other along the ray (the near-tie exception in embree_world.h). Doubt: anything else
// (the exact test misses, hits beyond the end or near an edge; about 0.3% of casts): the caller
// takes the slow path (castRay).
//
// The verdict and the hit are those of the former implementation (ClosestHitCaster::test on the
// triangle, then a nearness test of its hit), computed with fewer operations:
// - the normal comes from the record (the same bits as castTriangle's normalize);
// - the exact test's inside-the-triangle check (insideTriangle at p = origin + direction t) is
//   skipped when the nearness test already shows p inside: there, for each edge uv, side =
//   N . ((v - u) x (p' - u)) at p' = origin + displacement (t / length), with N = (b - a) x
//   (c - a), is positive and passes side^2 max((N . d)^2, 1e-6 |N|^2 L^2) >= rho^2 |N|^4 L^2
//   |uv|^2 (as computed). Since max(...) <= |N|^2 L^2, the computed side is at least
//   rho |N| |uv| (1 - 1e-14), so p' lies at least rho (1 - 1e-14) >= 0.99e-6 m inside the line
//   of uv, up to the rounding of that computation. Each rounding error here (p' - u, the cross
//   and dot products, p against p': p = o + (d / L) t and p' = o + d (t / L) differ by a few
//   ulps of |o| + L) is at most about 16 ulps of the largest coordinate involved, that is
//   2^-48 (largest + |o| + L) in distance, while rho >= 2^-20 (largest + |o| + L) + 1e-6 m:
//   2^28 times larger. So p lies inside each edge line by more than 0.9 rho > 0, where
//   insideTriangle's computed tests (same rounding bound, and a margin <= 0) all pass: skipping
//   it changes nothing. When a side is not positive, insideTriangle runs as before.
FastRay confirm(const Confirmation& record, const FastCast& f, FastHit& hit) {
    const DVec3 a = toD(record.triangle.a), b = toD(record.triangle.b), c = toD(record.triangle.c);
    const DVec3& n = record.normal;
    // ClosestHitCaster's unit direction; computed here, while the record is being read.
    const DVec3 direction = f.displacement / f.length;
    // castTriangle (src/static_world.cpp), radius 0, nothing hit yet.
    const double s0 = glm::dot(n, f.origin - a);
    const double dn = glm::dot(n, direction);
    if (s0 * dn >= 0.0) return FastRay::Doubt;  // on the plane, parallel, or moving away
    const double t = s0 / -dn;
    if (t > f.length) return FastRay::Doubt;
    const double fraction = t / f.length;  // ClosestHitCaster::closestFraction()
    if (!(fraction <= 1.0)) return FastRay::Doubt;
    // Within grazeReach of an edge line, without square roots: the hit p' is within
    // reach = rho / max(sine, 1e-3) of the line of edge uv when (N . (uv x p'u))^2
    // max((N . d)^2, 1e-6 |N|^2 L^2) < rho^2 |N|^4 L^2 |uv|^2 (sine = |N . d| / (|N| L)).
    const DVec3 p = f.origin + f.displacement * fraction;
    const DVec3 normal = glm::cross(b - a, c - a);
    const double nn = glm::dot(normal, normal), nd = glm::dot(normal, f.displacement), ll = f.length * f.length;
    const double grazing = std::max(nd * nd, 1e-6 * nn * ll);
    const double bound = f.rho * f.rho * nn * nn * ll;
    bool positive = true;
    auto near = [&](const DVec3& u, const DVec3& v) {
        const DVec3 e = v - u;
        const double side = glm::dot(normal, glm::cross(e, p - u));
        positive = positive && side > 0.0;
        return side * side * grazing < bound * glm::dot(e, e);
    };
    if (near(a, b) || near(b, c) || near(c, a)) return FastRay::Doubt;
    if (!positive && !insideTriangle(f.origin + direction * t, a, b, c, n)) return FastRay::Doubt;
    hit.distance = t;
    hit.fraction = fraction;
    hit.point = p;
    hit.normal = s0 > 0.0 ? n : -n;
    return FastRay::Hit;
}

// ClosestHitCaster::result for a caster whose closest hit is `h` from a mesh triangle (no
// material): the same values (its fraction, distance / length, is already in [0, 1], so its
// clamp changes nothing, and its position is origin + displacement * fraction).
void writeHit(const FastHit& h, CastHit& hit) {
    hit.fraction = static_cast<float>(h.fraction);
    hit.position = RVec3(h.point);
    hit.normal = Vec3(h.normal);
    hit.restitution = SurfaceMaterial{}.restitution;
    hit.friction = SurfaceMaterial{}.friction;
}

// The primitives, in StaticWorld's order.
void testPrimitives(const StaticWorld& primitives, ClosestHitCaster& caster) {
    for (std::size_t i = 0; i < primitives.planes().size(); ++i)
        caster.test(primitives.planes()[i], primitives.planeMaterials()[i]);
    for (std::size_t i = 0; i < primitives.spheres().size(); ++i)
        caster.test(primitives.spheres()[i], primitives.sphereMaterials()[i]);
    for (std::size_t i = 0; i < primitives.boxes().size(); ++i)
        caster.test(primitives.boxes()[i], primitives.boxMaterials()[i]);
    for (std::size_t i = 0; i < primitives.triangles().size(); ++i)
        caster.test(primitives.triangles()[i], primitives.triangleMaterials()[i]);
}

// castSegment's answer from the fast path, given Embree's float closest hit (`primID`, or
// RTC_INVALID_GEOMETRY_ID for none). Returns false when in doubt (the slow path answers);
// otherwise `found` and `hit` are the answer (hit is written only when found). No float hit
// means no mesh hit: a triangle the exact test hits away from its edges and the segment's ends
// is hit by the float test (the other cases are the graze exception in embree_world.h).
bool finishFast(const StaticWorld& primitives, float surfaceTolerance, const Confirmation* confirmations,
                const SegmentCast& cast, const FastCast& f, unsigned primID, CastHit& hit, bool& found) {
    FastHit h;
    const bool mesh = primID != RTC_INVALID_GEOMETRY_ID;
    if (mesh && confirm(confirmations[primID], f, h) == FastRay::Doubt) return false;
    if (primitives.planes().empty() && primitives.spheres().empty() && primitives.boxes().empty() &&
        primitives.triangles().empty()) {
        found = mesh;
        if (mesh) writeHit(h, hit);
        return true;
    }
    ClosestHitCaster caster(cast, surfaceTolerance);
    testPrimitives(primitives, caster);
    if (mesh && h.fraction < caster.closestFraction()) {
        // Strictly closer than the primitives: its own test is the result (the same as testing
        // it after them); otherwise the primitives win or tie, in their order.
        writeHit(h, hit);
        found = true;
        return true;
    }
    if (mesh) caster.test(confirmations[primID].triangle);
    found = caster.result(hit);
    return true;
}

// Starts reading the cache line at `address` (a hint; nothing where the compiler has no prefetch).
void prefetch(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

// Embree's closest hit of a traced ray: its primitive, or RTC_INVALID_GEOMETRY_ID for none.
unsigned closestPrimitive(const RTCRayHit& rayhit) {
    return rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID ? RTC_INVALID_GEOMETRY_ID : rayhit.hit.primID;
}

// PlaneRegionTester's sharedEdges for every triangle (3 vertex indices each, into `vertexCount`
// vertices): bit k is set when exactly one other triangle has edge k over the same two vertices
// and, seen along this triangle's normal, its third vertex lies on the edge's other side (the
// cosine of the fold at the edge above 1e-3: folded back over the edge, or near a right angle,
// the edge stays unmarked). Whether the two lie in a region's plane is each one's own test when
// it is offered; when both do, the region's normal (within 4.5e-7 rad of theirs) sees the same
// sides, so result() would have paired the edge. Found through each vertex's triangles (linear
// in the mesh). Empty when out of memory: isOnlyPlane then keeps every edge, as without it.
std::vector<std::uint8_t> sharedEdgeMasks(const std::vector<Triangle>& triangles, const std::vector<unsigned>& indices,
                                          std::size_t vertexCount) {
    std::vector<std::uint8_t> masks;
    try {
        const std::size_t count = triangles.size();
        masks.assign(count, 0);
        // The triangles around each vertex (compressed rows).
        std::vector<unsigned> start(vertexCount + 1, 0), around(3 * count);
        for (const unsigned v : indices) ++start[v + 1];
        for (std::size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
        std::vector<unsigned> next(start.begin(), start.end() - 1);
        for (std::size_t t = 0; t < count; ++t)
            for (int k = 0; k < 3; ++k) around[next[indices[3 * t + k]]++] = static_cast<unsigned>(t);
        const auto corner = [&](std::size_t t, int k) {
            const Triangle& tri = triangles[t];
            return toD(k == 0 ? tri.a : k == 1 ? tri.b : tri.c);
        };
        for (std::size_t t = 0; t < count; ++t) {
            for (int k = 0; k < 3; ++k) {
                const unsigned u = indices[3 * t + k], v = indices[3 * t + (k + 1) % 3];
                // Every other triangle over both u and v.
                unsigned partner = 0, partners = 0;
                for (unsigned i = start[u]; i < start[u + 1]; ++i) {
                    const unsigned o = around[i];
                    if (o == t) continue;
                    const unsigned* oi = &indices[3 * static_cast<std::size_t>(o)];  // u is one of them
                    if (oi[0] == v || oi[1] == v || oi[2] == v) {
                        partner = o;
                        ++partners;
                    }
                }
                if (partners != 1) continue;
                const unsigned* oi = &indices[3 * static_cast<std::size_t>(partner)];
                const int third = oi[0] != u && oi[0] != v ? 0 : oi[1] != u && oi[1] != v ? 1 : 2;
                const DVec3 a = corner(t, k), b = corner(t, (k + 1) % 3), w = corner(t, (k + 2) % 3);
                const DVec3 wo = corner(partner, third);
                const DVec3 n = glm::cross(b - a, w - a);
                const DVec3 across = glm::cross(b - a, wo - a);
                // Opposite sides: the partner's normal along n points the other way; clearly so.
                const double side = glm::dot(n, across);
                if (side < 0.0 && -side > 1e-3 * glm::length(n) * glm::length(across))
                    masks[t] |= std::uint8_t(1u << k);
            }
        }
    } catch (const std::bad_alloc&) {
        masks.clear();
    }
    return masks;
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
    if (const Status status = checkMesh(vertices, indices, r); status != Status::Ok) return status;
    if (!mImpl) mImpl = std::make_unique<Impl>();
    std::vector<Triangle> added;
    std::vector<unsigned> addedIndices;  // into vertices, 3 per added triangle
    added.reserve(r.triangles);
    addedIndices.reserve(3 * r.triangles);
    for (std::size_t t = 0; t < indices.size() / 3; ++t) {
        const Triangle triangle{vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]};
        if (!usableInCheckedMesh(triangle, t, r)) continue;  // counted by checkMesh
        added.push_back(triangle);
        addedIndices.insert(addedIndices.end(), indices.begin() + static_cast<std::ptrdiff_t>(3 * t),
                            indices.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
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
    mImpl->committed = false;
    return Status::Ok;
}

namespace {

// The region tree's nodes, allocated by Embree's builder (owned by Impl::regionBvh). Both start
// with a count: 0 for an inner node, the number of triangles for a leaf. An inner node keeps its
// up to four children's boxes by axis (structure of arrays), for one pass over all four.
constexpr unsigned kRegionWidth = 4;
struct alignas(16) RegionNode {
    std::uint32_t leafCount = 0;  // 0: an inner node
    std::uint32_t childCount = 0;
    const void* child[kRegionWidth] = {};
    float lo[3][kRegionWidth] = {};  // lo[axis][child]: each child's box holds its triangles
    float hi[3][kRegionWidth] = {};
    // Whether all of a child's triangles lie in one plane with every edge shared (markFlat):
    // their unit normals within flatSpread of +-flatNormal; isOnlyPlane's tester may then pass
    // the child as a whole (PlaneRegionTester::passesFlatGroup). Read by isOnlyPlane only.
    bool flat[kRegionWidth] = {};
    double flatSpread[kRegionWidth] = {};
    double flatNormal[kRegionWidth][3] = {};
};
struct RegionLeaf {
    std::uint32_t leafCount = 0;  // > 0: how many of `triangles` are used
    std::uint32_t triangles[1];   // primitive indices (the leaf is allocated with room for all)
};
constexpr unsigned kRegionLeafSize = 8;
constexpr unsigned kRegionDepth = 64;  // Embree's builder refuses deeper trees
static_assert(std::is_standard_layout_v<RegionNode> && std::is_standard_layout_v<RegionLeaf>);

std::uint32_t regionCount(const void* node) { return *static_cast<const std::uint32_t*>(node); }

void* createRegionNode(RTCThreadLocalAllocator allocator, unsigned childCount, void*) {
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(RegionNode), alignof(RegionNode));
    auto* node = ::new (memory) RegionNode;
    node->childCount = std::min(childCount, kRegionWidth);
    return node;
}

void setRegionChildren(void* node, void** children, unsigned childCount, void*) {
    auto* n = static_cast<RegionNode*>(node);
    for (unsigned i = 0; i < childCount && i < kRegionWidth; ++i) n->child[i] = children[i];
}

void setRegionBounds(void* node, const RTCBounds** bounds, unsigned childCount, void*) {
    auto* n = static_cast<RegionNode*>(node);
    for (unsigned i = 0; i < childCount && i < kRegionWidth; ++i) {
        n->lo[0][i] = bounds[i]->lower_x;
        n->lo[1][i] = bounds[i]->lower_y;
        n->lo[2][i] = bounds[i]->lower_z;
        n->hi[0][i] = bounds[i]->upper_x;
        n->hi[1][i] = bounds[i]->upper_y;
        n->hi[2][i] = bounds[i]->upper_z;
    }
}

void* createRegionLeaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* primitives, std::size_t count,
                       void*) {
    const std::size_t bytes = sizeof(RegionLeaf) + (count > 0 ? count - 1 : 0) * sizeof(std::uint32_t);
    auto* leaf = ::new (rtcThreadLocalAlloc(allocator, bytes, alignof(RegionLeaf))) RegionLeaf;
    leaf->leafCount = static_cast<std::uint32_t>(count);
    for (std::size_t i = 0; i < count; ++i) leaf->triangles[i] = primitives[i].primID;
    return leaf;
}

// The float box holding a triangle's vertices (rounded outwards where they are not floats).
RTCBuildPrimitive regionPrimitive(const Triangle& t, unsigned index) {
    const Box b = triangleBox(t);
    const auto down = [](double x) {
        float f = static_cast<float>(x);
        return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
    };
    RTCBuildPrimitive p;
    p.lower_x = down(b.lo.x);
    p.lower_y = down(b.lo.y);
    p.lower_z = down(b.lo.z);
    p.upper_x = floatUp(b.hi.x);
    p.upper_y = floatUp(b.hi.y);
    p.upper_z = floatUp(b.hi.z);
    p.geomID = 0;
    p.primID = index;
    return p;
}

// Builds the region tree over `impl`'s triangles; false when Embree failed.
bool buildRegionTree(RTCDevice device, const std::vector<Triangle>& triangles, RTCBVH& bvh, const void*& root) {
    std::vector<RTCBuildPrimitive> primitives(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        primitives[t] = regionPrimitive(triangles[t], static_cast<unsigned>(t));
    bvh = rtcNewBVH(device);
    if (!bvh) return false;
    RTCBuildArguments arguments = rtcDefaultBuildArguments();
    arguments.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
    arguments.maxBranchingFactor = kRegionWidth;
    arguments.maxDepth = kRegionDepth;
    arguments.maxLeafSize = kRegionLeafSize;
    arguments.bvh = bvh;
    arguments.primitives = primitives.data();
    arguments.primitiveCount = primitives.size();
    arguments.primitiveArrayCapacity = primitives.size();
    arguments.createNode = createRegionNode;
    arguments.setNodeChildren = setRegionChildren;
    arguments.setNodeBounds = setRegionBounds;
    arguments.createLeaf = createRegionLeaf;
    root = rtcBuildBVH(&arguments);
    return root != nullptr && rtcGetDeviceError(device) == RTC_ERROR_NONE;
}

// A subtree's flatness (markFlat): every triangle's unit normal (PlaneRegionTester::test's
// cross product over its length) within `spread` of +-normal, per component, and every edge
// shared (sharedEdges 7).
struct Flatness {
    bool flat = false;
    bool empty = true;  // no triangle merged yet: `normal` not set
    DVec3 normal{0.0};
    double spread = 0.0;
};

// Fills the flat fields of `node`'s subtree and returns its flatness. A spread above 1e-14 is
// not flat (passesFlatGroup's limit); `depth` guards the recursion (the builder keeps trees
// within kRegionDepth).
Flatness markFlat(const void* node, const std::vector<Triangle>& triangles, const std::vector<std::uint8_t>& shared,
                  unsigned depth) {
    constexpr double kSpread = 1e-14;
    Flatness result;
    const auto merge = [&](const DVec3& normal, double spread) {
        if (!result.flat) return;
        if (result.empty) {
            result.empty = false;
            result.normal = normal;
            result.spread = spread;
            return;
        }
        const DVec3 d = glm::dot(normal, result.normal) >= 0.0 ? normal - result.normal : normal + result.normal;
        const double apart = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        result.spread = std::max(result.spread, apart + spread);
        if (!(result.spread <= kSpread)) result.flat = false;
    };
    result.flat = true;
    if (depth > kRegionDepth) return Flatness{};
    if (regionCount(node) > 0) {
        const auto& leaf = *static_cast<const RegionLeaf*>(node);
        for (std::uint32_t i = 0; i < leaf.leafCount && result.flat; ++i) {
            const unsigned t = leaf.triangles[i];
            const Triangle& tri = triangles[t];
            const DVec3 a = toD(tri.a), b = toD(tri.b), c = toD(tri.c);
            const DVec3 n = glm::cross(b - a, c - a);
            const double area2 = glm::length(n);
            if (shared[t] != 7u || !(area2 > 0.0) || !std::isfinite(area2)) return Flatness{};
            merge(n / area2, 0.0);
        }
        return result.flat ? result : Flatness{};
    }
    auto& inner = *const_cast<RegionNode*>(static_cast<const RegionNode*>(node));
    for (unsigned k = 0; k < inner.childCount && k < kRegionWidth; ++k) {
        const Flatness child = markFlat(inner.child[k], triangles, shared, depth + 1);
        inner.flat[k] = child.flat;
        inner.flatSpread[k] = child.spread;
        for (int axis = 0; axis < 3; ++axis) inner.flatNormal[k][axis] = child.normal[axis];
        if (!child.flat)
            result.flat = false;
        else
            merge(child.normal, child.spread);
    }
    return result.flat ? result : Flatness{};
}

}  // namespace

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
    // A mesh reaching beyond kEmbreeReach gets no tree: Embree's builder bins the boxes in float
    // and fails there (a vertex near the float range's end made it abort on an assertion).
    if (!(impl.largest < kEmbreeReach) ||
        !buildRegionTree(impl.device, impl.triangles, impl.regionBvh, impl.regionRoot)) {
        // Not fatal: the region queries then test every triangle, as before commit().
        if (impl.regionBvh) rtcReleaseBVH(impl.regionBvh);
        impl.regionBvh = nullptr;
        impl.regionRoot = nullptr;
    }
    if (!impl.confirmations.allocate(count)) return fail("cannot allocate the confirmation records");
    for (std::size_t t = 0; t < count; ++t) {
        const Triangle& triangle = impl.triangles[t];
        const DVec3 a = toD(triangle.a), b = toD(triangle.b), c = toD(triangle.c);
        // castTriangle's normal (src/static_world.cpp), the same expression.
        ::new (static_cast<void*>(impl.confirmations.data() + t))
            Confirmation{triangle, glm::normalize(glm::cross(b - a, c - a))};
    }
    if (mSettings.meshAdjacency) impl.sharedEdges = sharedEdgeMasks(impl.triangles, impl.vertexIndices, vertexCount);
    if (impl.regionRoot && impl.sharedEdges.size() == count)
        markFlat(impl.regionRoot, impl.triangles, impl.sharedEdges, 0);
    impl.committed = true;
    return true;
}

bool EmbreeWorld::castSegment(const SegmentCast& cast, CastHit& hit) const {
    const Impl* impl = mImpl.get();
    FastCast f;
    if (impl && !impl->triangles.empty() && prepareFast(cast, impl->committed && impl->scene, impl->largest, f)) {
        // Radius 0, the fast path: one plain rtcIntersect1 (no filter) along the segment, started
        // rho before it and ended rho after it, then the exact confirmation of its closest hit.
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rayhit;
        prepareRay(rayhit, f.origin, f.displacement, f.shift, floatUp(1.0 + 2.0 * f.shift));
        rtcIntersect1(impl->scene, &context, &rayhit);
        bool found = false;
        if (finishFast(mPrimitives, mSettings.surfaceTolerance, impl->confirmations.data(), cast, f,
                       closestPrimitive(rayhit), hit, found))
            return found;
    }
    return castSlow(cast, hit);
}

std::size_t EmbreeWorld::castSegments(std::span<const SegmentCast> casts, std::span<CastHit> hits,
                                      std::span<std::uint8_t> found) const {
    const std::size_t n = std::min({casts.size(), hits.size(), found.size()});
    const Impl* impl = mImpl.get();
    const bool built = impl && !impl->triangles.empty() && impl->committed && impl->scene;
    const double largest = impl ? impl->largest : 0.0;
    const Confirmation* confirmations = impl ? impl->confirmations.data() : nullptr;
    // Per group of kGroup casts: first every fast one (castSegment's fast path) is traced, and the
    // confirmation record of its float hit is prefetched as soon as its ray returns, so that the
    // memory reads of the group overlap the traversals that follow instead of each stalling its
    // own cast; then every cast is answered in order: the fast ones by finishFast, the others and
    // the doubtful ones by castSlow. The same rays, the same Embree call and the same code as
    // castSegment: the same answers, bit for bit. (16-ray packets, rtcIntersect16, measured no
    // faster on the benchmark's incoherent segments nor on a fan of rays from one point, and
    // Embree's packet traversal may choose differently between two triangles whose float hits
    // tie exactly: single rays keep the answers identical by construction.)
    constexpr std::size_t kGroup = 16;
    std::array<FastCast, kGroup> prepared;
    std::array<unsigned, kGroup> closest;
    std::array<bool, kGroup> fast;
    std::size_t count = 0;
    for (std::size_t first = 0; first < n; first += kGroup) {
        const std::size_t size = std::min(kGroup, n - first);
        for (std::size_t k = 0; k < size; ++k) {
            fast[k] = built && prepareFast(casts[first + k], true, largest, prepared[k]);
            if (!fast[k]) continue;
            const FastCast& f = prepared[k];
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            RTCRayHit rayhit;
            prepareRay(rayhit, f.origin, f.displacement, f.shift, floatUp(1.0 + 2.0 * f.shift));
            rtcIntersect1(impl->scene, &context, &rayhit);
            closest[k] = closestPrimitive(rayhit);
            if (closest[k] != RTC_INVALID_GEOMETRY_ID) prefetch(confirmations + closest[k]);
        }
        for (std::size_t k = 0; k < size; ++k) {
            const std::size_t i = first + k;
            bool hit = false;
            if (!fast[k] || !finishFast(mPrimitives, mSettings.surfaceTolerance, confirmations, casts[i], prepared[k],
                                        closest[k], hits[i], hit))
                hit = castSlow(casts[i], hits[i]);
            found[i] = hit ? 1 : 0;
            count += hit ? 1 : 0;
        }
    }
    return count;
}

bool EmbreeWorld::castSlow(const SegmentCast& cast, CastHit& hit) const {
    ClosestHitCaster caster(cast, mSettings.surfaceTolerance);
    if (!caster.valid()) return false;
    const ClosestHitCaster pristine = caster;
    testPrimitives(mPrimitives, caster);

    const Impl* impl = mImpl.get();
    if (impl && !impl->triangles.empty()) {
        const DVec3 origin = toD(cast.origin), displacement(cast.displacement);
        const double length = glm::length(displacement);
        const double originMagnitude = std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z)});
        // Embree's float rays are valid only well inside float range (it asserts beyond about
        // 1.8e18): a segment reaching past 1e15 m, or any segment in a mesh that does (its ray
        // would start rho back, floatReach), is tested against every triangle instead.
        const bool built =
            impl->committed && impl->scene && originMagnitude + length < kEmbreeReach && impl->largest < kEmbreeReach;
        QueryState q;
        q.triangles = impl->triangles.data();
        q.regionRoot = impl->committed ? impl->regionRoot : nullptr;
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
            castRay(impl->scene, floatReach(impl->largest, originMagnitude, length), q);
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

namespace {

struct NearQueryState {
    const Triangle* triangles = nullptr;
    NearTester* tester = nullptr;
};

bool nearCallback(RTCPointQueryFunctionArguments* args) {
    auto* q = static_cast<NearQueryState*>(args->userPtr);
    q->tester->test(q->triangles[args->primID]);
    return false;  // the query's sphere stays as it is: every triangle in it is wanted
}

}  // namespace

bool EmbreeWorld::findNear(const NearQuery& query, NearCollector& collector) const {
    const Impl* impl = mImpl.get();
    const bool mesh = impl && !impl->triangles.empty();
    const bool traverse = mesh && impl->committed && impl->scene;
    // The query's sphere as a capsule of no length: the centre rounded to float, the radius grown
    // by that rounding and a margin, so that every triangle within the radius is visited.
    SegmentCast sphere;
    sphere.origin = query.center;
    sphere.radius = query.radius;
    RTCPointQuery pointQuery;
    if (traverse && !capsuleQuery(sphere, pointQuery)) return false;  // beyond Embree's float range
    mPrimitives.findNear(query, collector);
    if (!mesh) return true;
    NearTester tester(query, collector, mSettings.surfaceTolerance);
    if (!tester.valid()) return true;
    if (!traverse) {
        for (const Triangle& t : impl->triangles) tester.test(t);
        return true;
    }
    NearQueryState q;
    q.triangles = impl->triangles.data();
    q.tester = &tester;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(impl->scene, &pointQuery, &context, nearCallback, &q);
    return true;
}

namespace {

// A capsule prepared for the region tree's boxes, in float: a box is entered when the segment
// meets it grown by the capsule's radius and a margin that holds every rounding of this float
// test (1e-5 of the coordinates' magnitude, far above float's 6e-8; a margin only costs speed).
// The triangles of the boxes entered then go through CapsuleTester's exact double tests.
struct RegionCapsule {
    float origin[3] = {};
    float inverse[3] = {};  // 1 / displacement per axis, its magnitude at most 1e30
    float grow = 0.0f;      // the radius and the margin [Units: m]
    bool valid = false;
};

RegionCapsule regionCapsule(const SegmentCast& capsule) {
    RegionCapsule c;
    const DVec3 a = toD(capsule.origin), d(capsule.displacement);
    const double magnitude = std::max(
        {std::abs(a.x), std::abs(a.y), std::abs(a.z), std::abs(a.x + d.x), std::abs(a.y + d.y), std::abs(a.z + d.z)});
    const double radius = std::max(0.0, static_cast<double>(capsule.radius));
    const double grow = radius + 1e-4 + 1e-5 * (1.0 + magnitude + radius);
    if (!(magnitude < 1e30) || !(grow < 1e30)) return c;  // not finite, or beyond float: walk everything
    for (int axis = 0; axis < 3; ++axis) {
        c.origin[axis] = static_cast<float>(a[axis]);
        // A displacement of zero (or below 1e-30) as 1e-30: the slabs then say whether the
        // origin lies inside, without infinities or NaN.
        const double component = std::abs(d[axis]) < 1e-30 ? std::copysign(1e-30, d[axis]) : d[axis];
        c.inverse[axis] = static_cast<float>(1.0 / component);
    }
    c.grow = floatUp(grow);
    c.valid = true;
    return c;
}

// Which of `node`'s children the capsule enters (bit k for child k), and from which fraction
// of the segment at the earliest (1e-5 earlier than the float test says: its rounding).
unsigned enterChildren(const RegionNode& node, const RegionCapsule& c, float (&entry)[kRegionWidth]) {
#if defined(__SSE2__)
    // The four children at once (the same operations as the loop below, lane by lane).
    static_assert(kRegionWidth == 4);
    const __m128 grow = _mm_set1_ps(c.grow);
    __m128 first = _mm_setzero_ps(), last = _mm_set1_ps(1.0f);
    for (int axis = 0; axis < 3; ++axis) {
        const __m128 o = _mm_set1_ps(c.origin[axis]), inv = _mm_set1_ps(c.inverse[axis]);
        const __m128 t0 = _mm_mul_ps(_mm_sub_ps(_mm_sub_ps(_mm_loadu_ps(node.lo[axis]), grow), o), inv);
        const __m128 t1 = _mm_mul_ps(_mm_sub_ps(_mm_add_ps(_mm_loadu_ps(node.hi[axis]), grow), o), inv);
        first = _mm_max_ps(first, _mm_min_ps(t0, t1));
        last = _mm_min_ps(last, _mm_max_ps(t0, t1));
    }
    const __m128 margin = _mm_set1_ps(1e-5f);
    _mm_storeu_ps(entry, _mm_max_ps(_mm_setzero_ps(), _mm_sub_ps(first, margin)));
    const unsigned inside = static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(first, _mm_add_ps(last, margin))));
    return inside & ((1u << node.childCount) - 1u);
#else
    float first[kRegionWidth], last[kRegionWidth];
    for (unsigned k = 0; k < kRegionWidth; ++k) {
        first[k] = 0.0f;
        last[k] = 1.0f;
    }
    for (int axis = 0; axis < 3; ++axis) {
        const float o = c.origin[axis], inv = c.inverse[axis], g = c.grow;
        for (unsigned k = 0; k < kRegionWidth; ++k) {
            const float t0 = (node.lo[axis][k] - g - o) * inv, t1 = (node.hi[axis][k] + g - o) * inv;
            first[k] = std::max(first[k], std::min(t0, t1));
            last[k] = std::min(last[k], std::max(t0, t1));
        }
    }
    unsigned mask = 0;
    for (unsigned k = 0; k < kRegionWidth; ++k) {
        entry[k] = std::max(0.0f, first[k] - 1e-5f);
        if (k < node.childCount && first[k] <= last[k] + 1e-5f) mask |= 1u << k;
    }
    return mask;
#endif
}

// No child left out (walkRegion's `prune`).
struct NoPrune {
    bool operator()(const RegionNode&, unsigned) const { return false; }
};

// A walk of the region tree, nearer children first; `leaf(leaf)` returns true to stop the walk,
// `skip(entry)` whether a node entered at `entry` may be skipped. An invalid capsule enters
// every box. False when the walk ran out of stack (a tree deeper than the builder was allowed to
// make it): the caller answers "maybe".
// With `behind`, the children whose boxes lie wholly behind its plane are left out too, and so
// are those for which `prune(node, k)` returns true (asked when their parent is walked, in the
// children's order).
template <class Skip, class Leaf, class Prune = NoPrune>
bool walkRegion(const void* root, const RegionCapsule& capsule, Skip&& skip, Leaf&& leaf,
                const BehindTester* behind = nullptr, Prune&& prune = Prune{}) {
    struct Entry {
        const void* node;
        float entry;
    };
    std::array<Entry, (kRegionWidth - 1) * kRegionDepth + 4> stack;
    std::size_t size = 0;
    stack[size++] = Entry{root, 0.0f};
    while (size > 0) {
        const Entry e = stack[--size];
        if (skip(e.entry)) continue;
        if (regionCount(e.node) > 0) {
            if (leaf(*static_cast<const RegionLeaf*>(e.node))) return true;
            continue;
        }
        const auto& node = *static_cast<const RegionNode*>(e.node);
        float entry[kRegionWidth];
        unsigned mask = capsule.valid ? enterChildren(node, capsule, entry) : (1u << node.childCount) - 1u;
        if (behind)
            for (unsigned k = 0; k < kRegionWidth; ++k)
                if ((mask & (1u << k)) && behind->behind(glm::dvec3(node.lo[0][k], node.lo[1][k], node.lo[2][k]),
                                                         glm::dvec3(node.hi[0][k], node.hi[1][k], node.hi[2][k])))
                    mask &= ~(1u << k);
        if constexpr (!std::is_same_v<std::decay_t<Prune>, NoPrune>)
            for (unsigned k = 0; k < kRegionWidth; ++k)
                if ((mask & (1u << k)) && prune(node, k)) mask &= ~(1u << k);
        if (!capsule.valid) std::fill(std::begin(entry), std::end(entry), 0.0f);
        if (size + kRegionWidth > stack.size()) return false;
        // The entered children, the farthest pushed first (insertion by entry): the nearest on top.
        const std::size_t base = size;
        for (unsigned k = 0; k < kRegionWidth; ++k) {
            if (!(mask & (1u << k))) continue;
            std::size_t at = size++;
            while (at > base && stack[at - 1].entry < entry[k]) {
                stack[at] = stack[at - 1];
                --at;
            }
            stack[at] = Entry{node.child[k], entry[k]};
        }
    }
    return true;
}

bool offerNear(const void* regionRoot, const DVec3& centre, double radius, QueryState& q) {
    SegmentCast point;
    point.origin = RVec3(centre);
    point.displacement = Vec3(0.0f);
    // The point's rounding to Real, then float up: every box within `radius` of `centre` is entered.
    point.radius = floatUp(radius + glm::length(toD(point.origin) - centre));
    return walkRegion(
        regionRoot, regionCapsule(point), [](float) { return false; },
        [&](const RegionLeaf& leaf) {
            for (std::uint32_t i = 0; i < leaf.leafCount; ++i) offerTriangle(q, leaf.triangles[i]);
            return false;
        });
}

}  // namespace

bool EmbreeWorld::mayTouch(const SegmentCast& capsule) const {
    if (mPrimitives.mayTouch(capsule)) return true;
    const Impl* impl = mImpl.get();
    if (!impl || impl->triangles.empty()) return false;
    const CapsuleTester tester(capsule);
    if (!tester.valid()) return true;
    const Triangle* triangles = impl->triangles.data();
    if (!impl->committed || !impl->regionRoot) {
        for (const Triangle& t : impl->triangles)
            if (tester.mayTouch(t)) return true;
        return false;
    }
    bool touched = false;
    const bool walked = walkRegion(
        impl->regionRoot, regionCapsule(capsule), [](float) { return false; },
        [&](const RegionLeaf& leaf) {
            for (std::uint32_t i = 0; i < leaf.leafCount; ++i)
                if (tester.mayTouch(triangles[leaf.triangles[i]])) return touched = true;
            return false;
        });
    return touched || !walked;
}

bool EmbreeWorld::firstTouch(const SegmentCast& capsule, float& fraction) const {
    return touchFirst(capsule, nullptr, nullptr, fraction);
}

bool EmbreeWorld::firstTouchInFront(const SegmentCast& capsule, const InFrontOf& front, float& fraction) const {
    const BehindTester behind(front);
    return behind.valid() ? touchFirst(capsule, &front, &behind, fraction)
                          : touchFirst(capsule, nullptr, nullptr, fraction);
}

bool EmbreeWorld::touchFirst(const SegmentCast& capsule, const InFrontOf* front, const BehindTester* behind,
                             float& fraction) const {
    fraction = 0.0f;
    bool touched = false;
    if (mPrimitives.shapeCount() > 0)
        touched = front ? mPrimitives.firstTouchInFront(capsule, *front, fraction)
                        : mPrimitives.firstTouch(capsule, fraction);
    const Impl* impl = mImpl.get();
    if (impl && !impl->triangles.empty() && !(touched && fraction == 0.0f)) {
        const CapsuleTester tester(capsule);
        const Triangle* triangles = impl->triangles.data();
        const auto offer = [&](const Triangle& t) {
            float f = 0.0f;
            if ((behind && behind->behind(t)) || !tester.firstTouch(t, f)) return false;
            fraction = touched ? std::min(fraction, f) : f;
            touched = true;
            return fraction == 0.0f;  // touching at the start: nothing can come earlier
        };
        if (!tester.valid()) {
            touched = true;
            fraction = 0.0f;
        } else if (!impl->committed || !impl->regionRoot) {
            for (const Triangle& t : impl->triangles)
                if (offer(t)) break;
        } else if (!walkRegion(
                       impl->regionRoot, regionCapsule(capsule),
                       [&](float entry) { return touched && entry >= fraction; },
                       [&](const RegionLeaf& leaf) {
                           for (std::uint32_t i = 0; i < leaf.leafCount; ++i)
                               if (offer(triangles[leaf.triangles[i]])) return true;
                           return false;
                       },
                       behind)) {
            touched = true;  // the walk ran out of stack: "maybe, at once"
            fraction = 0.0f;
        }
    }
    if (!touched) fraction = 0.0f;
    return touched;
}

bool EmbreeWorld::gatherShapes(const SegmentCast& region, ShapeCollector& collector) const {
    // castSlow tests the primitives first, then the mesh triangles by index.
    if (!mPrimitives.gatherShapes(region, collector)) return false;
    const Impl* impl = mImpl.get();
    if (!impl || impl->triangles.empty()) return true;
    const SurfaceMaterial none;
    const CapsuleTester tester(region);
    if (!impl->committed || !impl->regionRoot || !tester.valid()) {
        for (const Triangle& t : impl->triangles)
            if (tester.mayTouch(t) && !collector.add(t, none)) return false;
        return true;
    }
    // Every triangle in a box the capsule's slabs enter, through mayTouch (as the loop above):
    // all that mayTouch(region, triangle) accepts except those certainly out of reach.
    std::array<unsigned, 512> found;  // the first count are used (left uninitialised: per query)
    std::size_t count = 0;
    bool overflowed = false;
    const Triangle* triangles = impl->triangles.data();
    const bool walked = walkRegion(
        impl->regionRoot, regionCapsule(region), [](float) { return false; },
        [&](const RegionLeaf& leaf) {
            for (std::uint32_t i = 0; i < leaf.leafCount; ++i) {
                const unsigned t = leaf.triangles[i];
                if (!tester.mayTouch(triangles[t])) continue;
                if (count == found.size()) return overflowed = true;
                found[count++] = t;
            }
            return false;
        });
    if (overflowed || !walked) return false;
    std::sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(count));
    for (std::size_t k = 0; k < count; ++k)
        if (!collector.add(triangles[found[k]], none)) return false;
    return true;
}

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
    if (!impl->committed || !impl->regionRoot) {
        for (std::size_t i = 0; i < impl->triangles.size() && !tester.failed(); ++i) tester.test(impl->triangles[i]);
        return tester.result();
    }
    // The triangles of the boxes the capsule enters: those of the others are certainly out of
    // its reach (they neither reach into the region nor have an edge crossing it). Their edges
    // shared by two triangles on either side (sharedEdgeMasks) are not kept: the partner is in
    // a box the capsule enters too.
    const Triangle* triangles = impl->triangles.data();
    const std::uint8_t* shared =
        impl->sharedEdges.size() == impl->triangles.size() ? impl->sharedEdges.data() : nullptr;
    // A child whose triangles all lie in one plane with every edge shared (markFlat) is passed
    // whole where the tester says each of them would pass (passesFlatGroup): a floor of tiles.
    const bool walked = walkRegion(
        impl->regionRoot, regionCapsule(region.capsule), [](float) { return false; },
        [&](const RegionLeaf& leaf) {
            for (std::uint32_t i = 0; i < leaf.leafCount && !tester.failed(); ++i)
                tester.test(triangles[leaf.triangles[i]], {}, shared ? shared[leaf.triangles[i]] : 0);
            return tester.failed();
        },
        nullptr,
        [&](const RegionNode& node, unsigned k) {
            return shared && node.flat[k] &&
                   tester.passesFlatGroup(DVec3(node.lo[0][k], node.lo[1][k], node.lo[2][k]),
                                          DVec3(node.hi[0][k], node.hi[1][k], node.hi[2][k]),
                                          DVec3(node.flatNormal[k][0], node.flatNormal[k][1], node.flatNormal[k][2]),
                                          node.flatSpread[k]);
        });
    return walked && tester.result();
}

FORESIGHT_NAMESPACE_END
