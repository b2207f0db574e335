#include <foresight/static_world.h>

#include <foresight/orientation.h>

#include "internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace {

using Candidate = ClosestCandidate;
using Ray = PreparedRay;

// First entry of a ray that starts outside a sphere (centre c, radius r).
void sphereEntry(const Ray& ray, const DVec3& center, double radius, Candidate& best) {
    const DVec3 m = ray.origin - center;
    const double b = glm::dot(m, ray.direction);
    if (b >= 0.0) return;  // moving away from the centre: cannot enter
    const double c = glm::dot(m, m) - radius * radius;
    const double disc = b * b - c;
    if (disc < 0.0) return;
    // Stable root: the entry is c / (-b + sqrt(disc)) (equal to -b - sqrt(disc)).
    const double t = std::max(0.0, c / (-b + std::sqrt(disc)));
    if (t > ray.length || t >= best.distance) return;
    best.offer(t, glm::normalize(m + ray.direction * t));
}

// First entry of a ray that starts outside a capsule (segment a-b, radius r): the cylinder's
// side, then the two end spheres.
void capsuleEntry(const Ray& ray, const DVec3& a, const DVec3& b, double radius, Candidate& best) {
    const DVec3 ba = b - a;
    const DVec3 oa = ray.origin - a;
    const double baba = glm::dot(ba, ba);
    const double bard = glm::dot(ba, ray.direction);
    const double baoa = glm::dot(ba, oa);
    const double rdoa = glm::dot(ray.direction, oa);
    const double oaoa = glm::dot(oa, oa);
    const double qa = baba - bard * bard;
    if (qa > 1e-12 * baba) {  // not parallel to the axis: the side can be hit
        const double qb = baba * rdoa - baoa * bard;
        const double qc = baba * oaoa - baoa * baoa - radius * radius * baba;
        const double h = qb * qb - qa * qc;
        if (h >= 0.0) {
            const double t = std::max(0.0, (-qb - std::sqrt(h)) / qa);
            const double y = baoa + t * bard;  // axial coordinate times |ba|
            if (y > 0.0 && y < baba && t <= ray.length && t < best.distance) {
                const DVec3 n = oa + ray.direction * t - ba * (y / baba);
                const double nl = glm::length(n);
                if (nl > 0.0 && glm::dot(n, ray.direction) < 0.0) best.offer(t, n / nl);
            }
        }
    }
    sphereEntry(ray, a, radius, best);
    sphereEntry(ray, b, radius, best);
}

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
DVec3 closestOnTriangle(const DVec3& p, const DVec3& a, const DVec3& b, const DVec3& c) {
    const DVec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const DVec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    const DVec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

// Whether point p (on the plane of abc) lies inside the triangle, edges included with a small
// relative margin so that a segment through a shared edge hits one of the two triangles.
bool insideTriangle(const DVec3& p, const DVec3& a, const DVec3& b, const DVec3& c, const DVec3& n) {
    const double margin = -1e-9 * glm::dot(n, glm::cross(b - a, c - a));
    return glm::dot(n, glm::cross(b - a, p - a)) >= margin && glm::dot(n, glm::cross(c - b, p - b)) >= margin &&
           glm::dot(n, glm::cross(a - c, p - c)) >= margin;
}

// The rule shared by every solid: a start within the tolerance of the surface hits at 0 when it
// moves in; a start deeper inside hits nothing; a start outside is left to the entry test.
// Returns true when the entry test should run.
bool surfaceRule(const Ray& ray, double signedDistance, const DVec3& outward, Candidate& best) {
    if (signedDistance > ray.tolerance) return true;
    if (signedDistance >= -ray.tolerance && glm::dot(outward, ray.direction) < 0.0) best.offer(0.0, outward);
    return false;
}

void castPlane(const Ray& ray, double radius, const Plane& plane, Candidate& best) {
    const DVec3 n = toD(plane.normal);
    const double s0 = glm::dot(n, ray.origin) - static_cast<double>(plane.distance) - radius;
    const double dn = glm::dot(n, ray.direction);
    if (!surfaceRule(ray, s0, n, best)) return;
    if (dn >= 0.0) return;
    const double t = s0 / -dn;
    if (t <= ray.length) best.offer(t, n);
}

void castSphere(const Ray& ray, double radius, const Sphere& sphere, Candidate& best) {
    const DVec3 center = toD(sphere.center);
    const double r = static_cast<double>(sphere.radius) + radius;
    const DVec3 m = ray.origin - center;
    const double distance = glm::length(m);
    const DVec3 outward = distance > 0.0 ? m / distance : DVec3(0, 1, 0);
    if (!surfaceRule(ray, distance - r, outward, best)) return;
    sphereEntry(ray, center, r, best);
}

void castBox(const Ray& ray, double radius, const OrientedBox& box, Candidate& best) {
    // Work in the box's local frame: an axis-aligned box [-h, h], rounded by the cast radius.
    // A rounded box is the box shrunk by its rounding, met by a sphere that much larger.
    const DQuat q = toD(box.orientation);
    const DQuat qi = glm::conjugate(q);
    const double rounding = static_cast<double>(box.rounding);
    const DVec3 h = toD(box.halfExtents) - DVec3(rounding);
    radius += rounding;
    Ray local = ray;
    local.origin = qi * (ray.origin - toD(box.center));
    local.direction = qi * ray.direction;
    const DVec3& o = local.origin;

    // Signed distance to the rounded box and its gradient.
    DVec3 outward;
    const double signedDistance = boxSignedDistance(o, h, radius, outward);
    Candidate localBest;
    localBest.distance = best.distance;
    if (surfaceRule(local, signedDistance, outward, localBest)) {
        // Slab test against the box grown by the radius.
        const DVec3 e = h + DVec3(radius);
        double tEnter = 0.0, tExit = local.length;
        int enterAxis = -1;
        for (int i = 0; i < 3; ++i) {
            const double di = local.direction[i];
            if (std::abs(di) < 1e-300) {
                if (std::abs(o[i]) > e[i]) return;
                continue;
            }
            double t0 = (-e[i] - o[i]) / di, t1 = (e[i] - o[i]) / di;
            if (t0 > t1) std::swap(t0, t1);
            if (t0 > tEnter) {
                tEnter = t0;
                enterAxis = i;
            }
            tExit = std::min(tExit, t1);
            if (tEnter > tExit) return;
        }
        // enterAxis < 0: the origin is inside the grown box, in a corner or edge region that
        // lies outside the rounded box (a start inside the rounded box ended above).
        if (enterAxis < 0 && radius <= 0.0) return;
        int outsideAxes = enterAxis < 0 ? 2 : 0;
        const DVec3 p = o + local.direction * tEnter;
        for (int i = 0; i < 3 && enterAxis >= 0; ++i)
            if (i != enterAxis && std::abs(p[i]) > h[i]) ++outsideAxes;
        if (radius <= 0.0 || outsideAxes == 0) {
            DVec3 n(0.0);
            n[enterAxis] = local.direction[enterAxis] > 0.0 ? -1.0 : 1.0;
            localBest.offer(tEnter, n);
        } else {
            // Entered the grown box near an edge or corner: the rounded box's surface there is
            // one of the twelve edge capsules (whose end spheres are the corners).
            for (int axis = 0; axis < 3; ++axis) {
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                for (int su = -1; su <= 1; su += 2)
                    for (int sv = -1; sv <= 1; sv += 2) {
                        DVec3 a(0.0), b(0.0);
                        a[axis] = -h[axis];
                        b[axis] = h[axis];
                        a[u] = b[u] = su * h[u];
                        a[v] = b[v] = sv * h[v];
                        capsuleEntry(local, a, b, radius, localBest);
                    }
            }
        }
    }
    if (localBest.distance < best.distance) best.offer(localBest.distance, q * localBest.normal);
}

// The bounds of the spheres of radius `reach` along the ray's segment, grown by far more than
// the rounding of the tests: a shape whose bounds stay out of them is out of that reach.
struct SweepBounds {
    DVec3 lo, hi;
    bool apart(const DVec3& low, const DVec3& high) const {
        return low.x > hi.x || low.y > hi.y || low.z > hi.z || lo.x > high.x || lo.y > high.y || lo.z > high.z;
    }
};
SweepBounds sweepBounds(const Ray& ray, double reach) {
    const DVec3 end = ray.origin + ray.direction * ray.length;
    const double magnitude = std::max({std::abs(ray.origin.x), std::abs(ray.origin.y), std::abs(ray.origin.z),
                                       std::abs(end.x), std::abs(end.y), std::abs(end.z)});
    const double grow = reach + 1e-6 * (reach + ray.length + magnitude);
    return SweepBounds{glm::min(ray.origin, end) - grow, glm::max(ray.origin, end) + grow};
}

void castTriangle(const Ray& ray, double radius, const Triangle& tri, Candidate& best) {
    const DVec3 a = toD(tri.a), b = toD(tri.b), c = toD(tri.c);
    const DVec3 n = glm::normalize(glm::cross(b - a, c - a));
    const double s0 = glm::dot(n, ray.origin - a);
    if (radius <= 0.0) {
        // Two-sided and infinitely thin: no tolerance, the side is the sign of the start's
        // distance; a start exactly on the plane cannot tell its side and ignores the triangle.
        const double dn = glm::dot(n, ray.direction);
        if (s0 * dn >= 0.0) return;  // on the plane, parallel, or moving away
        const double t = s0 / -dn;
        if (t > ray.length || t >= best.distance) return;
        const DVec3 p = ray.origin + ray.direction * t;
        if (!insideTriangle(p, a, b, c, n)) return;
        best.offer(t, s0 > 0.0 ? n : -n);
        return;
    }
    // A swept sphere against a triangle: the triangle thickened by the radius, a convex solid. It
    // lies in the slab within the radius of the triangle's plane, so a sphere that starts outside
    // that slab (by more than the surface tolerance, and 1 um for rounding: the closest point's
    // distance is then beyond the tolerance too) enters the slab first and the solid no earlier:
    // a sphere heading away from the plane, or reaching the slab beyond the cast or the best hit
    // so far, cannot hit; one that reaches it inside the triangle's face hits there.
    const DVec3 side = s0 >= 0.0 ? n : -n;
    const double dn = glm::dot(side, ray.direction);
    const double outside = std::abs(s0) - radius;
    const bool outsideSlab = outside > ray.tolerance + 1e-6;
    if (outsideSlab) {
        if (dn >= 0.0 || outside / -dn > ray.length || outside / -dn >= best.distance) return;
    } else {
        const DVec3 closest = closestOnTriangle(ray.origin, a, b, c);
        const DVec3 away = ray.origin - closest;
        const double distance = glm::length(away);
        const DVec3 outward = distance > 0.0 ? away / distance : side;
        if (!surfaceRule(ray, distance - radius, outward, best)) return;
    }
    if (dn < 0.0) {
        // The face, offset by the radius towards the origin.
        const double t = outside / -dn;
        if (t >= 0.0 && t <= ray.length && t < best.distance) {
            const DVec3 p = ray.origin + ray.direction * t - side * radius;
            if (insideTriangle(p, a, b, c, n)) {
                best.offer(t, side);
                if (outsideSlab) return;
            }
        }
    }
    // The edges (capsules with their corner spheres). An edge whose bounding box stays out of
    // the swept sphere's (grown by far more than the rounding of the tests) cannot be entered:
    // capsuleEntry offers only points within the radius of the edge, along the segment.
    const SweepBounds sweep = sweepBounds(ray, radius);
    const auto reaches = [&](const DVec3& u, const DVec3& v) { return !sweep.apart(glm::min(u, v), glm::max(u, v)); };
    if (reaches(a, b)) capsuleEntry(ray, a, b, radius, best);
    if (reaches(b, c)) capsuleEntry(ray, b, c, radius, best);
    if (reaches(c, a)) capsuleEntry(ray, c, a, radius, best);
}

}  // namespace

// Negative values are "none"; NaN and infinities are refused.
Status validateMaterial(const SurfaceMaterial& m) {
    if (!isFinite(m.restitution) || !isFinite(m.friction)) return Status::NonFiniteInput;
    if (m.restitution > 1.0f) return Status::InvalidRestitution;
    return Status::Ok;
}

Status validatePlane(const Plane& plane) {
    if (!isFinite(plane.normal) || !isFinite(static_cast<double>(plane.distance))) return Status::NonFiniteInput;
    if (!(glm::length(toD(plane.normal)) > 0.0)) return Status::ZeroVector;
    return Status::Ok;
}

Status validateSphere(const Sphere& sphere) {
    if (!isFinite(sphere.center) || !isFinite(sphere.radius)) return Status::NonFiniteInput;
    if (!(sphere.radius > 0.0f)) return Status::InvalidRadius;
    return Status::Ok;
}

Status validateBox(const OrientedBox& box) {
    if (!isFinite(box.center) || !isFinite(box.halfExtents)) return Status::NonFiniteInput;
    Quat q;
    if (Status s = normalizeQuaternion(box.orientation, q); s != Status::Ok) return s;
    if (!(box.halfExtents.x > 0.0f && box.halfExtents.y > 0.0f && box.halfExtents.z > 0.0f))
        return Status::DegenerateShape;
    if (!std::isfinite(box.rounding)) return Status::NonFiniteInput;
    if (!(box.rounding >= 0.0f) || box.rounding > std::min({box.halfExtents.x, box.halfExtents.y, box.halfExtents.z}))
        return Status::InvalidRadius;
    return Status::Ok;
}

Status validateTriangle(const Triangle& triangle) {
    if (!isFinite(triangle.a) || !isFinite(triangle.b) || !isFinite(triangle.c)) return Status::NonFiniteInput;
    const DVec3 a = toD(triangle.a), b = toD(triangle.b), c = toD(triangle.c);
    const double twiceArea = glm::length(glm::cross(b - a, c - a));
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    // Zero area, or a sliver whose height is under 1e-6 of its longest edge (unstable normal).
    if (!(twiceArea > 2e-12) || !(twiceArea > 1e-6 * longest * longest)) return Status::DegenerateShape;
    return Status::Ok;
}

Status checkMesh(std::span<const RVec3> vertices, std::span<const std::uint32_t> indices, MeshReport& report) {
    report = MeshReport{};
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (!isFinite(vertices[i])) {
            report.error = "vertex " + std::to_string(i) + " is not finite";
            return Status::NonFiniteInput;
        }
    }
    if (indices.size() % 3 != 0) {
        report.error = "the index count (" + std::to_string(indices.size()) + ") is not a multiple of 3";
        return Status::DegenerateShape;
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= vertices.size()) {
            report.error = "index " + std::to_string(i) + " refers to vertex " + std::to_string(indices[i]) +
                           ", out of range (" + std::to_string(vertices.size()) + " vertices)";
            return Status::DegenerateShape;
        }
    }
    for (std::size_t t = 0; t < indices.size() / 3; ++t) {
        const Triangle triangle{vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]};
        if (validateTriangle(triangle) == Status::Ok)
            ++report.triangles;
        else if (report.degenerateTriangles++ == 0)
            report.firstDegenerateTriangle = t;
    }
    if (report.triangles == 0) {
        report.error =
            report.degenerateTriangles > 0
                ? "no usable triangles (" + std::to_string(report.degenerateTriangles) + " degenerate ones skipped)"
                : std::string("no triangles");
        return Status::DegenerateShape;
    }
    return Status::Ok;
}

Status StaticWorld::addMesh(std::span<const RVec3> vertices, std::span<const std::uint32_t> indices,
                            MeshReport* report) {
    MeshReport local;
    MeshReport& r = report ? *report : local;
    const Status status = checkMesh(vertices, indices, r);
    if (status != Status::Ok) return status;
    mTriangles.reserve(mTriangles.size() + r.triangles);
    mTriangleMaterials.reserve(mTriangleMaterials.size() + r.triangles);
    for (std::size_t t = 0; t < indices.size() / 3; ++t) {
        const Triangle triangle{vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]};
        if (!usableInCheckedMesh(triangle, t, r)) continue;
        mTriangles.push_back(triangle);
        mTriangleMaterials.push_back(SurfaceMaterial{});
    }
    return Status::Ok;
}

Status StaticWorld::add(const Plane& plane) { return add(plane, SurfaceMaterial{}); }
Status StaticWorld::add(const Sphere& sphere) { return add(sphere, SurfaceMaterial{}); }
Status StaticWorld::add(const OrientedBox& box) { return add(box, SurfaceMaterial{}); }
Status StaticWorld::add(const Triangle& triangle) { return add(triangle, SurfaceMaterial{}); }

Status StaticWorld::add(const Plane& plane, const SurfaceMaterial& material) {
    if (Status s = validatePlane(plane); s != Status::Ok) return s;
    if (Status s = validateMaterial(material); s != Status::Ok) return s;
    const double length = glm::length(toD(plane.normal));
    Plane p;
    p.normal = toF(toD(plane.normal) / length);
    p.distance = static_cast<Real>(static_cast<double>(plane.distance) / length);
    mPlanes.push_back(p);
    mPlaneMaterials.push_back(material);
    return Status::Ok;
}

Status StaticWorld::add(const Sphere& sphere, const SurfaceMaterial& material) {
    if (Status s = validateSphere(sphere); s != Status::Ok) return s;
    if (Status s = validateMaterial(material); s != Status::Ok) return s;
    mSpheres.push_back(sphere);
    mSphereMaterials.push_back(material);
    return Status::Ok;
}

Status StaticWorld::add(const OrientedBox& box, const SurfaceMaterial& material) {
    if (Status s = validateBox(box); s != Status::Ok) return s;
    if (Status s = validateMaterial(material); s != Status::Ok) return s;
    OrientedBox b = box;
    normalizeQuaternion(box.orientation, b.orientation);
    mBoxes.push_back(b);
    mBoxMaterials.push_back(material);
    return Status::Ok;
}

Status StaticWorld::add(const Triangle& triangle, const SurfaceMaterial& material) {
    if (Status s = validateTriangle(triangle); s != Status::Ok) return s;
    if (Status s = validateMaterial(material); s != Status::Ok) return s;
    mTriangles.push_back(triangle);
    mTriangleMaterials.push_back(material);
    return Status::Ok;
}

void StaticWorld::clear() {
    mPlanes.clear();
    mSpheres.clear();
    mBoxes.clear();
    mTriangles.clear();
    mPlaneMaterials.clear();
    mSphereMaterials.clear();
    mBoxMaterials.clear();
    mTriangleMaterials.clear();
}

std::size_t StaticWorld::shapeCount() const {
    return mPlanes.size() + mSpheres.size() + mBoxes.size() + mTriangles.size();
}

ClosestHitCaster::ClosestHitCaster(const SegmentCast& cast, float surfaceTolerance) {
    const DVec3 origin = toD(cast.origin);
    mDisplacement = toD(cast.displacement);
    const double length = glm::length(mDisplacement);
    if (!(length > 0.0) || !std::isfinite(length) || !isFinite(origin)) return;  // hits nothing
    mRay.origin = origin;
    mRay.direction = mDisplacement / length;
    mRay.length = length;
    // The configured tolerance, plus 4 ulps of the coordinates' own precision.
    mRay.tolerance = static_cast<double>(std::max(0.0f, surfaceTolerance)) + realUlps(origin, 4.0);
    mRay.radius = std::max(0.0, static_cast<double>(cast.radius));
}

// Each test keeps the material of the shape that moved the closest hit.
void ClosestHitCaster::test(const Plane& plane, const SurfaceMaterial& material) {
    if (!valid()) return;
    const double before = mBest.distance;
    castPlane(mRay, mRay.radius, plane, mBest);
    if (mBest.distance < before) mBest.material = material;
}
void ClosestHitCaster::test(const Sphere& sphere, const SurfaceMaterial& material) {
    if (!valid()) return;
    const double before = mBest.distance;
    castSphere(mRay, mRay.radius, sphere, mBest);
    if (mBest.distance < before) mBest.material = material;
}
void ClosestHitCaster::test(const OrientedBox& box, const SurfaceMaterial& material) {
    if (!valid()) return;
    const double before = mBest.distance;
    castBox(mRay, mRay.radius, box, mBest);
    if (mBest.distance < before) mBest.material = material;
}
void ClosestHitCaster::test(const Triangle& triangle, const SurfaceMaterial& material) {
    if (!valid()) return;
    const double before = mBest.distance;
    castTriangle(mRay, mRay.radius, triangle, mBest);
    if (mBest.distance < before) mBest.material = material;
}

double ClosestHitCaster::closestFraction() const {
    return valid() ? mBest.distance / mRay.length : std::numeric_limits<double>::infinity();
}

bool ClosestHitCaster::result(CastHit& hit) const {
    if (!valid() || !(mBest.distance <= mRay.length)) return false;
    const double fraction = std::clamp(mBest.distance / mRay.length, 0.0, 1.0);
    hit.fraction = static_cast<float>(fraction);
    hit.position = toR(mRay.origin + mDisplacement * fraction);
    hit.normal = toF(mBest.normal);
    hit.restitution = mBest.material.restitution;
    hit.friction = mBest.material.friction;
    return true;
}

#if defined(__GNUC__)
// The shape tests are also called from ClosestHitCaster::test; keep them inlined here, in the
// loop every prediction step runs.
#define FORESIGHT_FLATTEN __attribute__((flatten))
#else
#define FORESIGHT_FLATTEN
#endif

namespace {

// A capsule in double precision, with the margin that covers the float inputs' rounding and the
// casts' surface tolerance (a conservative answer may only err towards true); lo and hi are the
// segment's bounds grown by the radius (boundsMeet).
using Capsule = detail::PreparedCapsule;

void setBounds(Capsule& c) {
    c.lo = glm::min(c.a, c.b) - c.radius;
    c.hi = glm::max(c.a, c.b) + c.radius;
}

Capsule prepareCapsule(const SegmentCast& capsule) {
    Capsule c;
    c.a = glm::dvec3(capsule.origin);
    c.b = c.a + glm::dvec3(capsule.displacement);
    const double magnitude = std::max(
        {std::abs(c.a.x), std::abs(c.a.y), std::abs(c.a.z), std::abs(c.b.x), std::abs(c.b.y), std::abs(c.b.z)});
    c.radius = std::max(0.0, static_cast<double>(capsule.radius)) + 1e-4 + 1e-6 * magnitude;
    c.valid = std::isfinite(magnitude) && std::isfinite(c.radius);
    setBounds(c);
    return c;
}

// The capsule's segment in the box's own frame (centre at the origin, axes along the box's);
// false when the box's orientation is no rotation.
bool intoBoxFrame(Capsule& c, const OrientedBox& box) {
    const glm::dquat q(box.orientation);
    const double norm = glm::length(q);
    if (!(norm > 0.0)) return false;
    const glm::dquat inverse = glm::conjugate(q / norm);
    const glm::dvec3 centre(box.center);
    c.a = inverse * (c.a - centre);
    c.b = inverse * (c.b - centre);
    setBounds(c);
    return true;
}

// The heights of the capsule's ends above the plane; false when its normal has no length.
bool planeHeights(const Capsule& c, const Plane& plane, double& sa, double& sb) {
    const glm::dvec3 n(plane.normal);
    const double length = glm::length(n);
    if (!(length > 0.0)) return false;
    const double d = static_cast<double>(plane.distance);
    sa = (glm::dot(n, c.a) - d) / length;
    sb = (glm::dot(n, c.b) - d) / length;
    return true;
}

// Whether the boxes [lo, hi] and the capsule's bounds may overlap: false only when they are
// certainly apart (NaN anywhere: true).
bool boundsMeet(const Capsule& c, const glm::dvec3& lo, const glm::dvec3& hi) {
    return !(c.lo.x > hi.x || c.lo.y > hi.y || c.lo.z > hi.z || lo.x > c.hi.x || lo.y > c.hi.y || lo.z > c.hi.z);
}

}  // namespace

bool mayTouch(const SegmentCast& capsule, const Plane& plane) {
    const Capsule c = prepareCapsule(capsule);
    double sa = 0.0, sb = 0.0;
    if (!c.valid || !planeHeights(c, plane, sa, sb)) return true;
    return !((sa > c.radius && sb > c.radius) || (sa < -c.radius && sb < -c.radius));
}

bool mayTouch(const SegmentCast& capsule, const Sphere& sphere) {
    const Capsule c = prepareCapsule(capsule);
    if (!c.valid) return true;
    const glm::dvec3 centre(sphere.center), ab = c.b - c.a;
    const double lengthSquared = glm::dot(ab, ab);
    const double t = lengthSquared > 0.0 ? std::clamp(glm::dot(centre - c.a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    const double reach = c.radius + static_cast<double>(sphere.radius) * (1.0 + 1e-6);
    const glm::dvec3 offset = c.a + ab * t - centre;
    return !(glm::dot(offset, offset) > reach * reach);
}

bool mayTouch(const SegmentCast& capsule, const OrientedBox& box) {
    Capsule c = prepareCapsule(capsule);
    if (!c.valid || !intoBoxFrame(c, box)) return true;
    const glm::dvec3 half = glm::dvec3(box.halfExtents) * (1.0 + 1e-6);
    return boundsMeet(c, -half, half);
}

namespace {

// mayTouch(const SegmentCast&, const Triangle&) of a prepared (valid) capsule.
bool mayTouchTriangle(const Capsule& c, const Triangle& triangle) {
    const glm::dvec3 p(triangle.a), q(triangle.b), r(triangle.c);
    if (!boundsMeet(c, glm::min(p, glm::min(q, r)), glm::max(p, glm::max(q, r)))) return false;
    const glm::dvec3 n = glm::cross(q - p, r - p);
    const double area2 = glm::length(n);
    if (!(area2 > 0.0)) return true;
    const double sa = glm::dot(n, c.a - p) / area2, sb = glm::dot(n, c.b - p) / area2;
    return !((sa > c.radius && sb > c.radius) || (sa < -c.radius && sb < -c.radius));
}

}  // namespace

bool mayTouch(const SegmentCast& capsule, const Triangle& triangle) {
    const Capsule c = prepareCapsule(capsule);
    return !c.valid || mayTouchTriangle(c, triangle);
}

namespace {

// The parameters t in [lo, hi] of a segment's points a + t (b - a), narrowed by slabs.
struct Span {
    double lo = 0.0, hi = 1.0;
    bool unknown = false;  // a non-finite input: the answer is "touches at once"
};

// Narrows `span` to where s0 + t (s1 - s0) lies within [low, high].
void clip(Span& span, double s0, double s1, double low, double high) {
    if (!std::isfinite(s0) || !std::isfinite(s1) || !std::isfinite(low) || !std::isfinite(high)) {
        span.unknown = true;
        return;
    }
    const double ds = s1 - s0;
    if (ds == 0.0) {
        if (s0 < low || s0 > high) span.hi = -1.0;
        return;
    }
    double t0 = (low - s0) / ds, t1 = (high - s0) / ds;
    if (t0 > t1) std::swap(t0, t1);
    span.lo = std::max(span.lo, t0);
    span.hi = std::min(span.hi, t1);
}

// The answer of a first-touch test: the span's start, rounded down to float.
bool touchAt(const Span& span, float& fraction) {
    fraction = 0.0f;
    if (span.unknown) return true;
    if (!(span.lo <= span.hi)) return false;
    float f = static_cast<float>(span.lo);
    if (static_cast<double>(f) > span.lo) f = std::nextafter(f, 0.0f);
    fraction = std::clamp(f, 0.0f, 1.0f);
    return true;
}

}  // namespace

bool firstTouch(const SegmentCast& capsule, const Plane& plane, float& fraction) {
    fraction = 0.0f;
    const Capsule c = prepareCapsule(capsule);
    double sa = 0.0, sb = 0.0;
    if (!c.valid || !planeHeights(c, plane, sa, sb)) return true;
    Span span;
    clip(span, sa, sb, -c.radius, c.radius);
    return touchAt(span, fraction);
}

bool firstTouch(const SegmentCast& capsule, const Sphere& sphere, float& fraction) {
    fraction = 0.0f;
    const Capsule c = prepareCapsule(capsule);
    if (!c.valid) return true;
    // |a + t (b - a) - centre| <= reach: A t^2 + 2 B t + C <= 0.
    const glm::dvec3 centre(sphere.center), ab = c.b - c.a, offset = c.a - centre;
    const double reach = c.radius + static_cast<double>(sphere.radius) * (1.0 + 1e-6);
    const double A = glm::dot(ab, ab), B = glm::dot(ab, offset), C = glm::dot(offset, offset) - reach * reach;
    if (!std::isfinite(A + B + C)) return true;
    if (C <= 0.0) return true;  // touching at the start
    const double discriminant = B * B - A * C;
    if (!(A > 0.0) || discriminant < 0.0) return false;
    const double root = std::sqrt(discriminant);
    Span span;
    span.lo = std::max(0.0, (-B - root) / A);
    span.hi = std::min(1.0, (-B + root) / A);
    return touchAt(span, fraction);
}

bool firstTouch(const SegmentCast& capsule, const OrientedBox& box, float& fraction) {
    fraction = 0.0f;
    Capsule c = prepareCapsule(capsule);
    if (!c.valid || !intoBoxFrame(c, box)) return true;
    const glm::dvec3 half = glm::dvec3(box.halfExtents) * (1.0 + 1e-6) + c.radius;
    Span span;
    for (int axis = 0; axis < 3; ++axis) clip(span, c.a[axis], c.b[axis], -half[axis], half[axis]);
    return touchAt(span, fraction);
}

namespace {

// firstTouch(const SegmentCast&, const Triangle&, float&) of a prepared (valid) capsule.
bool touchTriangle(const Capsule& c, const Triangle& triangle, float& fraction) {
    fraction = 0.0f;
    const glm::dvec3 p(triangle.a), q(triangle.b), r(triangle.c);
    const glm::dvec3 tlo = glm::min(p, glm::min(q, r)), thi = glm::max(p, glm::max(q, r));
    // Bounds apart: the slabs below would leave no span (most triangles of a world are far from
    // a capsule; this spares their divisions).
    if (!boundsMeet(c, tlo, thi)) return false;
    const glm::dvec3 lo = tlo - c.radius, hi = thi + c.radius;
    Span span;
    for (int axis = 0; axis < 3; ++axis) clip(span, c.a[axis], c.b[axis], lo[axis], hi[axis]);
    const glm::dvec3 n = glm::cross(q - p, r - p);
    const double area2 = glm::length(n);
    if (area2 > 0.0) clip(span, glm::dot(n, c.a - p) / area2, glm::dot(n, c.b - p) / area2, -c.radius, c.radius);
    return touchAt(span, fraction);
}

}  // namespace

bool firstTouch(const SegmentCast& capsule, const Triangle& triangle, float& fraction) {
    fraction = 0.0f;
    const Capsule c = prepareCapsule(capsule);
    if (!c.valid) return true;
    return touchTriangle(c, triangle, fraction);
}

BehindTester::BehindTester(const InFrontOf& front) {
    const DVec3 n(front.normal), point = toD(front.point);
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length) || !detail::isFinite(point) || !std::isfinite(front.tolerance))
        return;
    mNormal = n / length;
    mFloatNormal = front.normal;
    mLevel = glm::dot(mNormal, point) + std::max(0.0, static_cast<double>(front.tolerance));
    mValid = std::isfinite(mLevel);
}

bool BehindTester::behind(const Plane& plane) const {
    // Parallel in float (StaticWorld keeps normalised normals): the whole plane is one height.
    const Vec3 m = plane.normal;
    double height = 0.0;
    if (m == mFloatNormal)
        height = static_cast<double>(plane.distance);
    else if (m == -mFloatNormal)
        height = -static_cast<double>(plane.distance);
    else
        return false;
    return mValid && height / glm::length(DVec3(m)) <= mLevel;
}

bool BehindTester::behind(const Sphere& sphere) const {
    return mValid && glm::dot(mNormal, toD(sphere.center)) + static_cast<double>(sphere.radius) <= mLevel;
}

bool BehindTester::behind(const OrientedBox& box) const {
    if (!mValid) return false;
    const glm::dmat3 axes = glm::mat3_cast(glm::dquat(box.orientation));
    const DVec3 half(box.halfExtents);
    double reach = 0.0;
    for (int i = 0; i < 3; ++i) reach += std::abs(glm::dot(mNormal, axes[i])) * half[i];
    return glm::dot(mNormal, toD(box.center)) + reach <= mLevel;
}

bool BehindTester::behind(const Triangle& triangle) const {
    return mValid && glm::dot(mNormal, toD(triangle.a)) <= mLevel && glm::dot(mNormal, toD(triangle.b)) <= mLevel &&
           glm::dot(mNormal, toD(triangle.c)) <= mLevel;
}

bool BehindTester::behind(const glm::dvec3& lo, const glm::dvec3& hi) const {
    if (!mValid) return false;
    const DVec3 corner(mNormal.x > 0.0 ? hi.x : lo.x, mNormal.y > 0.0 ? hi.y : lo.y, mNormal.z > 0.0 ? hi.z : lo.z);
    return glm::dot(mNormal, corner) <= mLevel;
}

CapsuleTester::CapsuleTester(const SegmentCast& capsule) : mCapsule(prepareCapsule(capsule)) {}

bool CapsuleTester::mayTouch(const Triangle& triangle) const {
    return !mCapsule.valid || mayTouchTriangle(mCapsule, triangle);
}

bool CapsuleTester::firstTouch(const Triangle& triangle, float& fraction) const {
    fraction = 0.0f;
    return !mCapsule.valid || touchTriangle(mCapsule, triangle, fraction);
}

namespace {

// The smallest distance between the segments [p0, p1] and [q0, q1] (Ericson, Real-Time
// Collision Detection, 5.1.9).
double segmentDistance(const DVec3& p0, const DVec3& p1, const DVec3& q0, const DVec3& q1) {
    const DVec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    double s = 0.0, t = 0.0;
    if (a <= 0.0 && e <= 0.0) return glm::length(r);
    if (a <= 0.0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, r);
        if (e <= 0.0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denom = a * e - b * b;
            s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return glm::length(p0 + d1 * s - (q0 + d2 * t));
}

bool lexicographicLess(const DVec3& a, const DVec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

}  // namespace

PlaneRegionTester::PlaneRegionTester(const PlaneRegion& region) {
    const Capsule c = prepareCapsule(region.capsule);
    const DVec3 normal(region.normal), point = toD(region.point);
    const double length = glm::length(normal);
    mMaterial.restitution = region.restitution;
    mMaterial.friction = region.friction;
    if (!c.valid || !(length > 0.0) || !std::isfinite(length) || !isFinite(point)) {
        mFailed = true;
        return;
    }
    mCapsule = region.capsule;
    mPrepared = c;
    mNormal = normal / length;
    mDistance = glm::dot(mNormal, point);
    // The plane of a mesh's floor holds its vertices up to their float rounding (half an ulp,
    // 6e-8 of the magnitude), and 1 um besides.
    const double magnitude = std::max({std::abs(point.x), std::abs(point.y), std::abs(point.z), std::abs(mPrepared.a.x),
                                       std::abs(mPrepared.a.y), std::abs(mPrepared.a.z)});
    mTolerance = 1e-6 + 1e-7 * magnitude;
    // The anchor must lie in the cross-section: the start within the radius of the plane.
    const double height = glm::dot(mNormal, mPrepared.a) - mDistance;
    if (!(std::abs(height) < mPrepared.radius)) mFailed = true;
    mAnchor = mPrepared.a - mNormal * height;
}

bool PlaneRegionTester::sameMaterial(const SurfaceMaterial& m) const {
    const auto same = [](float a, float b) { return (a < 0.0f && b < 0.0f) || a == b; };
    return same(m.restitution, mMaterial.restitution) && same(m.friction, mMaterial.friction);
}

void PlaneRegionTester::test(const Plane& plane, const SurfaceMaterial& material) {
    if (mFailed || !mayTouch(mCapsule, plane)) return;
    const DVec3 n(plane.normal);
    const double length = glm::length(n);
    if (!(length > 0.0) || glm::dot(n / length, mNormal) < 1.0 - 1e-12 ||
        std::abs(static_cast<double>(plane.distance) / length - mDistance) > mTolerance || !sameMaterial(material)) {
        mFailed = true;
        return;
    }
    mCovered = true;
}

void PlaneRegionTester::test(const Sphere& sphere, const SurfaceMaterial&) {
    if (!mFailed && mayTouch(mCapsule, sphere)) mFailed = true;
}

void PlaneRegionTester::test(const OrientedBox& box, const SurfaceMaterial& material) {
    if (mFailed || !mayTouch(mCapsule, box)) return;
    mFailed = true;  // unless one face holds the whole cross-section
    const glm::dquat q(box.orientation);
    const double norm = glm::length(q);
    if (!(norm > 0.0) || !sameMaterial(material)) return;
    const glm::dquat inverse = glm::conjugate(q / norm);
    const DVec3 centre = toD(box.center), half(box.halfExtents), n = inverse * mNormal;
    const DVec3 a = inverse * (mPrepared.a - centre), b = inverse * (mPrepared.b - centre);
    const double rounding = static_cast<double>(box.rounding);
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(n[axis]) < 1.0 - 1e-12) continue;
        const double sign = n[axis] > 0.0 ? 1.0 : -1.0;
        // The face's plane, and a box deeper than the region reaches behind it.
        if (std::abs(glm::dot(mNormal, centre) + sign * half[axis] - mDistance) > mTolerance) return;
        if (2.0 * half[axis] < mPrepared.radius) return;
        for (int other = 0; other < 3; ++other) {
            if (other == axis) continue;
            const double room = half[other] - rounding - mPrepared.radius;
            if (!(std::abs(a[other]) <= room && std::abs(b[other]) <= room)) return;
        }
        mFailed = false;
        mCovered = true;
        return;
    }
}

void PlaneRegionTester::test(const Triangle& triangle, const SurfaceMaterial& material, std::uint8_t sharedEdges) {
    // mayTouch(region.capsule, triangle) with the capsule prepared once (in the constructor).
    if (mFailed || !mayTouchTriangle(mPrepared, triangle)) return;
    const DVec3 a = toD(triangle.a), b = toD(triangle.b), c = toD(triangle.c);
    for (const DVec3& v : {a, b, c}) {
        if (std::abs(glm::dot(mNormal, v) - mDistance) > mTolerance) {
            mFailed = true;
            return;
        }
    }
    // Its hits' normals must be the plane's (a small triangle may tilt within the tolerance):
    // within 4.5e-7 rad, so that a body sliding for seconds on a mesh's tilted floor, its
    // tiles' normals that far apart by the rounding of their vertices, moves as on the plane
    // to g 4.5e-7 t^2 / 2 (4e-5 m after 4 s).
    const DVec3 n = glm::cross(b - a, c - a);
    const double area2 = glm::length(n);
    if (!(area2 > 0.0) || std::abs(glm::dot(n, mNormal)) / area2 < 1.0 - 1e-13 || !sameMaterial(material)) {
        mFailed = true;
        return;
    }
    if ((sharedEdges & 1u) == 0) addEdge(a, b, c);
    if ((sharedEdges & 2u) == 0) addEdge(b, c, a);
    if ((sharedEdges & 4u) == 0) addEdge(c, a, b);
    if (!mAnchored) {
        // The anchor inside the triangle (edges included), in the plane's own terms.
        const double ab = glm::dot(mNormal, glm::cross(b - a, mAnchor - a));
        const double bc = glm::dot(mNormal, glm::cross(c - b, mAnchor - b));
        const double ca = glm::dot(mNormal, glm::cross(a - c, mAnchor - c));
        mAnchored = (ab >= 0.0 && bc >= 0.0 && ca >= 0.0) || (ab <= 0.0 && bc <= 0.0 && ca <= 0.0);
    }
}

bool PlaneRegionTester::passesFlatGroup(const DVec3& lo, const DVec3& hi, const DVec3& normal, double spread) const {
    if (mFailed || !mAnchored || !(spread >= 0.0 && spread <= 1e-14) || !sameMaterial(SurfaceMaterial{})) return false;
    // test()'s normal check, |dot(n, N)| / |n| >= 1 - 1e-13 for a triangle's n: its unit normal
    // lies within spread of +-normal in each component (so within 1.8 spread in length), and the
    // check's own rounding is a few ulps of 1; 5e-14 covers both.
    if (!(std::abs(glm::dot(normal, mNormal)) >= 1.0 - 5e-14)) return false;
    // test()'s vertex check, |dot(N, v) - d| <= tolerance: the expression is linear in v, so
    // over the box its extremes lie at two corners; a margin far above the rounding of either
    // evaluation (a few ulps of the magnitudes involved).
    DVec3 low, high;
    for (int axis = 0; axis < 3; ++axis) {
        low[axis] = mNormal[axis] >= 0.0 ? lo[axis] : hi[axis];
        high[axis] = mNormal[axis] >= 0.0 ? hi[axis] : lo[axis];
    }
    const double magnitude = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                                       std::abs(hi.z), std::abs(mDistance)});
    const double margin = 1e-13 * (1.0 + magnitude);
    const double below = glm::dot(mNormal, low) - mDistance, above = glm::dot(mNormal, high) - mDistance;
    return std::isfinite(below) && std::isfinite(above) && std::abs(below) <= mTolerance - margin &&
           std::abs(above) <= mTolerance - margin;
}

// Keeps edge uv when it comes within the region (it may cross the cross-section), with the side
// of it that w (the triangle's third vertex) lies on.
void PlaneRegionTester::addEdge(const DVec3& u, const DVec3& v, const DVec3& w) {
    if (mFailed) return;
    // An edge whose bounds are apart from the capsule's (the segment's, grown by the radius) is
    // farther than the radius: spared the distance's divisions and square root.
    if (!boundsMeet(mPrepared, glm::min(u, v), glm::max(u, v))) return;
    if (segmentDistance(u, v, mPrepared.a, mPrepared.b) > mPrepared.radius) return;
    if (mEdgeCount == kMaxEdges) {
        mFailed = true;
        return;
    }
    Edge& e = mEdges[static_cast<std::size_t>(mEdgeCount++)];
    const bool forward = lexicographicLess(u, v);
    e.from = forward ? u : v;
    e.to = forward ? v : u;
    const double side = glm::dot(mNormal, glm::cross(e.to - e.from, w - e.from));
    e.side = side > 0.0 ? 1 : side < 0.0 ? -1 : 0;
}

bool PlaneRegionTester::result() const {
    if (mFailed) return false;
    if (mCovered) return true;  // triangles on a covering plane or face change no answer
    if (!mAnchored && !mCovered) return false;
    // Every edge within the region must be shared by exactly two triangles, one on each side.
    const auto begin = mEdges.begin(), end = begin + mEdgeCount;
    std::sort(begin, end, [](const Edge& x, const Edge& y) {
        if (x.from != y.from) return lexicographicLess(x.from, y.from);
        if (x.to != y.to) return lexicographicLess(x.to, y.to);
        return x.side < y.side;
    });
    for (auto it = begin; it != end; it += 2) {
        const auto next = it + 1;
        if (next == end || next->from != it->from || next->to != it->to) return false;
        if (it->side != -1 || next->side != 1) return false;
        if (next + 1 != end && (next + 1)->from == it->from && (next + 1)->to == it->to) return false;
    }
    return true;
}

NearTester::NearTester(const NearQuery& query, NearCollector& collector, float surfaceTolerance)
    : mCollector(collector) {
    mCenter = toD(query.center);
    mRadius = static_cast<double>(query.radius);
    if (!isFinite(mCenter) || !(mRadius >= 0.0) || !std::isfinite(mRadius)) return;
    mTolerance = static_cast<double>(std::max(0.0f, surfaceTolerance)) + realUlps(mCenter, 4.0);
    mValid = true;
}

void NearTester::report(const DVec3& point, const DVec3& normal, double distance, const SurfaceMaterial& material) {
    NearSurface s;
    s.point = toR(point);
    s.normal = toF(normal);
    s.distance = static_cast<float>(distance);
    s.restitution = material.restitution;
    s.friction = material.friction;
    mCollector.add(s);
}

void NearTester::test(const Plane& plane, const SurfaceMaterial& material) {
    if (!mValid) return;
    const DVec3 n = toD(plane.normal);
    const double s = glm::dot(n, mCenter) - static_cast<double>(plane.distance);
    if (s > mRadius || s < -mTolerance) return;
    report(mCenter - n * s, n, s, material);
}

void NearTester::test(const Sphere& sphere, const SurfaceMaterial& material) {
    if (!mValid) return;
    const DVec3 center = toD(sphere.center);
    const DVec3 m = mCenter - center;
    const double length = glm::length(m);
    const double s = length - static_cast<double>(sphere.radius);
    if (s > mRadius || s < -mTolerance) return;
    const DVec3 n = length > 0.0 ? m / length : DVec3(0.0, 1.0, 0.0);
    report(center + n * static_cast<double>(sphere.radius), n, s, material);
}

void NearTester::test(const OrientedBox& box, const SurfaceMaterial& material) {
    if (!mValid) return;
    // The rounded box's signed distance and gradient in its frame, as castBox measures them.
    const DQuat q = toD(box.orientation);
    const double rounding = static_cast<double>(box.rounding);
    const DVec3 h = toD(box.halfExtents) - DVec3(rounding);
    const DVec3 o = glm::conjugate(q) * (mCenter - toD(box.center));
    DVec3 outward;
    const double s = boxSignedDistance(o, h, rounding, outward);
    if (s > mRadius || s < -mTolerance) return;
    const DVec3 n = q * outward;
    report(mCenter - n * s, n, s, material);
}

void NearTester::test(const Triangle& triangle, const SurfaceMaterial& material) {
    if (!mValid) return;
    const DVec3 a = toD(triangle.a), b = toD(triangle.b), c = toD(triangle.c);
    const DVec3 closest = closestOnTriangle(mCenter, a, b, c);
    const DVec3 away = mCenter - closest;
    const double length = glm::length(away);
    if (length > mRadius) return;
    DVec3 n;
    if (length > 0.0) {
        n = away / length;
    } else {
        const DVec3 face = glm::normalize(glm::cross(b - a, c - a));
        n = glm::dot(face, mCenter - a) >= 0.0 ? face : -face;
    }
    report(closest, n, length, material);
}

bool StaticWorld::findNear(const NearQuery& query, NearCollector& collector) const {
    NearTester tester(query, collector, mSettings.surfaceTolerance);
    for (std::size_t i = 0; i < mPlanes.size(); ++i) tester.test(mPlanes[i], mPlaneMaterials[i]);
    for (std::size_t i = 0; i < mSpheres.size(); ++i) tester.test(mSpheres[i], mSphereMaterials[i]);
    for (std::size_t i = 0; i < mBoxes.size(); ++i) tester.test(mBoxes[i], mBoxMaterials[i]);
    for (std::size_t i = 0; i < mTriangles.size(); ++i) tester.test(mTriangles[i], mTriangleMaterials[i]);
    return true;
}

bool StaticWorld::isOnlyPlane(const PlaneRegion& region) const {
    if (mSettings.surfaceTolerance != StaticWorldSettings{}.surfaceTolerance) return false;
    PlaneRegionTester tester(region);
    for (std::size_t i = 0; i < mPlanes.size() && !tester.failed(); ++i) tester.test(mPlanes[i], mPlaneMaterials[i]);
    for (std::size_t i = 0; i < mSpheres.size() && !tester.failed(); ++i) tester.test(mSpheres[i], mSphereMaterials[i]);
    for (std::size_t i = 0; i < mBoxes.size() && !tester.failed(); ++i) tester.test(mBoxes[i], mBoxMaterials[i]);
    for (std::size_t i = 0; i < mTriangles.size() && !tester.failed(); ++i)
        tester.test(mTriangles[i], mTriangleMaterials[i]);
    return tester.result();
}

bool StaticWorld::gatherShapes(const SegmentCast& region, ShapeCollector& collector) const {
    collector.begin(mSettings.surfaceTolerance);
    for (std::size_t i = 0; i < mPlanes.size(); ++i)
        if (foresight::mayTouch(region, mPlanes[i]) && !collector.add(mPlanes[i], mPlaneMaterials[i])) return false;
    for (std::size_t i = 0; i < mSpheres.size(); ++i)
        if (foresight::mayTouch(region, mSpheres[i]) && !collector.add(mSpheres[i], mSphereMaterials[i])) return false;
    for (std::size_t i = 0; i < mBoxes.size(); ++i)
        if (foresight::mayTouch(region, mBoxes[i]) && !collector.add(mBoxes[i], mBoxMaterials[i])) return false;
    const Capsule c = prepareCapsule(region);  // once for the triangles
    for (std::size_t i = 0; i < mTriangles.size(); ++i)
        if ((!c.valid || mayTouchTriangle(c, mTriangles[i])) && !collector.add(mTriangles[i], mTriangleMaterials[i]))
            return false;
    return true;
}

FORESIGHT_FLATTEN bool StaticWorld::mayTouch(const SegmentCast& capsule) const {
    for (const Plane& p : mPlanes)
        if (foresight::mayTouch(capsule, p)) return true;
    for (const Sphere& s : mSpheres)
        if (foresight::mayTouch(capsule, s)) return true;
    for (const OrientedBox& b : mBoxes)
        if (foresight::mayTouch(capsule, b)) return true;
    const Capsule c = prepareCapsule(capsule);  // once for the triangles
    for (const Triangle& t : mTriangles)
        if (!c.valid || mayTouchTriangle(c, t)) return true;
    return false;
}

namespace {

// StaticWorld::firstTouch, leaving out the shapes `behind` finds behind its plane (none when it
// is null).
bool firstTouchOf(std::span<const Plane> planes, std::span<const Sphere> spheres, std::span<const OrientedBox> boxes,
                  std::span<const Triangle> triangles, const SegmentCast& capsule, const BehindTester* behind,
                  float& fraction) {
    fraction = 1.0f;
    bool touched = false;
    const auto offer = [&](const auto& shape) {
        float f = 1.0f;
        if (behind && behind->behind(shape)) return;
        if (!foresight::firstTouch(capsule, shape, f)) return;
        touched = true;
        fraction = std::min(fraction, f);
    };
    for (const Plane& p : planes) offer(p);
    for (const Sphere& s : spheres) offer(s);
    for (const OrientedBox& b : boxes) offer(b);
    // The triangles with the capsule prepared once (each would prepare it again).
    const Capsule c = prepareCapsule(capsule);
    for (const Triangle& t : triangles) {
        if (behind && behind->behind(t)) continue;
        float f = 0.0f;  // an invalid capsule touches at once (as firstTouch(capsule, t, f) says)
        if (c.valid && !touchTriangle(c, t, f)) continue;
        touched = true;
        fraction = std::min(fraction, f);
    }
    if (!touched) fraction = 0.0f;
    return touched;
}

}  // namespace

FORESIGHT_FLATTEN bool StaticWorld::firstTouch(const SegmentCast& capsule, float& fraction) const {
    return firstTouchOf(mPlanes, mSpheres, mBoxes, mTriangles, capsule, nullptr, fraction);
}

FORESIGHT_FLATTEN bool StaticWorld::firstTouchInFront(const SegmentCast& capsule, const InFrontOf& front,
                                                      float& fraction) const {
    const BehindTester behind(front);
    return firstTouchOf(mPlanes, mSpheres, mBoxes, mTriangles, capsule, behind.valid() ? &behind : nullptr, fraction);
}

FORESIGHT_FLATTEN bool StaticWorld::castSegment(const SegmentCast& cast, CastHit& hit) const {
    ClosestHitCaster caster(cast, mSettings.surfaceTolerance);
    if (!caster.valid()) return false;
    // Local copies: the compiler keeps them in registers across the loops.
    const Ray ray = caster.mRay;
    Candidate best;
    // The shape that gave the closest hit, for its material (null: none of them).
    const SurfaceMaterial* material = nullptr;
    const auto keep = [&](double before, const SurfaceMaterial& m) {
        if (best.distance < before) material = &m;
    };
    for (std::size_t i = 0; i < mPlanes.size(); ++i) {
        const double before = best.distance;
        castPlane(ray, ray.radius, mPlanes[i], best);
        keep(before, mPlaneMaterials[i]);
    }
    for (std::size_t i = 0; i < mSpheres.size(); ++i) {
        const double before = best.distance;
        castSphere(ray, ray.radius, mSpheres[i], best);
        keep(before, mSphereMaterials[i]);
    }
    for (std::size_t i = 0; i < mBoxes.size(); ++i) {
        const double before = best.distance;
        castBox(ray, ray.radius, mBoxes[i], best);
        keep(before, mBoxMaterials[i]);
    }
    // A triangle can be hit only where the swept sphere comes within its radius and the surface
    // tolerance of it: one whose bounds stay out of the sweep's (grown by far more than the
    // rounding of the tests) is skipped without its tests.
    const SweepBounds sweep = sweepBounds(ray, ray.radius + ray.tolerance);
    for (std::size_t i = 0; i < mTriangles.size(); ++i) {
        const Triangle& t = mTriangles[i];
        const DVec3 a = toD(t.a), b = toD(t.b), c = toD(t.c);
        if (sweep.apart(glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)))) continue;
        const double before = best.distance;
        castTriangle(ray, ray.radius, t, best);
        keep(before, mTriangleMaterials[i]);
    }
    if (material) best.material = *material;
    caster.mBest = best;
    return caster.result(hit);
}

FORESIGHT_NAMESPACE_END
