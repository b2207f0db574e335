// Bullet's box-sphere closest points in float (bullet_gjk.h): btGjkPairDetector's GJK loop and
// btVoronoiSimplexSolver of Bullet Physics 3.24, written again for one box and one sphere with
// every float operation in Bullet's order, so that the results are Bullet's to the bit. An
// altered version of Bullet's source (restructured, reduced to this case), under its licence:
//
//   Bullet Continuous Collision Detection and Physics Library
//   Copyright (c) 2003-2006 Erwin Coumans  https://bulletphysics.org
//
//   This software is provided 'as-is', without any express or implied warranty.
//   In no event will the authors be held liable for any damages arising from the use of this software.
//   Permission is granted to anyone to use this software for any purpose,
//   including commercial applications, and to alter it and redistribute it freely,
//   subject to the following restrictions:
//
//   1. The origin of this software must not be misrepresented; you must not claim that you wrote the original software. If you use this software in a product, an acknowledgment in the product documentation would be appreciated but is not required.
//   2. Altered source versions must be plainly marked as such, and must not be misrepresented as being the original software.
//   3. This notice may not be removed or altered from any source distribution.
//
//   Elsevier CDROM license agreements grants nonexclusive license to use the software
//   for any purpose, commercial or non-commercial as long as the following credit is included
//   identifying the original source of the software:
//
//   Parts of the source are "from the book Real-Time Collision Detection by
//   Christer Ericson, published by Morgan Kaufmann Publishers,
//   (c) 2005 Elsevier Inc."

#include "bullet_gjk.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {
namespace {

// btVector3's operators (scalar build: each is the plain expression, left to right).
BulletVec operator+(const BulletVec& a, const BulletVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
BulletVec operator-(const BulletVec& a, const BulletVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
BulletVec operator-(const BulletVec& a) { return {-a.x, -a.y, -a.z}; }
BulletVec operator*(const BulletVec& a, float s) { return {a.x * s, a.y * s, a.z * s}; }
BulletVec operator*(float s, const BulletVec& a) { return a * s; }
float dot(const BulletVec& a, const BulletVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float length2(const BulletVec& a) { return dot(a, a); }
BulletVec cross(const BulletVec& a, const BulletVec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
bool operator==(const BulletVec& a, const BulletVec& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// v * M (btMatrix3x3's transpose product: tdotx, tdoty, tdotz).
BulletVec timesBasis(const BulletVec& v, const std::array<BulletVec, 3>& m) {
    return {m[0].x * v.x + m[1].x * v.y + m[2].x * v.z, m[0].y * v.x + m[1].y * v.y + m[2].y * v.z,
            m[0].z * v.x + m[1].z * v.y + m[2].z * v.z};
}
// btTransform::operator()(p): p.dot3(rows) + origin.
BulletVec transform(const std::array<BulletVec, 3>& basis, const BulletVec& origin, const BulletVec& p) {
    return BulletVec{dot(p, basis[0]), dot(p, basis[1]), dot(p, basis[2])} + origin;
}

// btBoxShape's support without margin (localGetSupportVertexWithoutMarginNonVirtual; btFsels).
BulletVec boxSupport(const BulletVec& h, const BulletVec& d) {
    return {d.x >= 0.0f ? h.x : -h.x, d.y >= 0.0f ? h.y : -h.y, d.z >= 0.0f ? h.z : -h.z};
}

constexpr float kRelError2 = 1.0e-6f;               // REL_ERROR2 (float build)
constexpr float kSimdEpsilon = FLT_EPSILON;         // SIMD_EPSILON
constexpr float kEqualVertexThreshold = 0.0001f;    // VORONOI_DEFAULT_EQUAL_VERTEX_THRESHOLD
constexpr float kEpaPenetrationTolerance = 0.001f;  // gGjkEpaPenetrationTolerance (float build)

struct Usage {
    bool a = false, b = false, c = false, d = false;
};

struct SubResult {  // btSubSimplexClosestResult
    BulletVec closest;
    Usage used;
    float bary[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    bool degenerate = false;
    void reset() {
        degenerate = false;
        setBary();
        used = Usage{};
    }
    bool valid() const { return bary[0] >= 0.0f && bary[1] >= 0.0f && bary[2] >= 0.0f && bary[3] >= 0.0f; }
    void setBary(float a = 0.0f, float b = 0.0f, float c = 0.0f, float d = 0.0f) {
        bary[0] = a;
        bary[1] = b;
        bary[2] = c;
        bary[3] = d;
    }
};

// Ericson's closest point on triangle abc to p, as btVoronoiSimplexSolver::closestPtPointTriangle.
void closestOnTriangle(const BulletVec& p, const BulletVec& a, const BulletVec& b, const BulletVec& c,
                       SubResult& result) {
    result.used = Usage{};
    const BulletVec ab = b - a;
    const BulletVec ac = c - a;
    const BulletVec ap = p - a;
    const float d1 = dot(ab, ap);
    const float d2 = dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) {
        result.closest = a;
        result.used.a = true;
        result.setBary(1, 0, 0);
        return;
    }
    const BulletVec bp = p - b;
    const float d3 = dot(ab, bp);
    const float d4 = dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) {
        result.closest = b;
        result.used.b = true;
        result.setBary(0, 1, 0);
        return;
    }
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
        const float v = d1 / (d1 - d3);
        result.closest = a + v * ab;
        result.used.a = true;
        result.used.b = true;
        result.setBary(1 - v, v, 0);
        return;
    }
    const BulletVec cp = p - c;
    const float d5 = dot(ab, cp);
    const float d6 = dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) {
        result.closest = c;
        result.used.c = true;
        result.setBary(0, 0, 1);
        return;
    }
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
        const float w = d2 / (d2 - d6);
        result.closest = a + w * ac;
        result.used.a = true;
        result.used.c = true;
        result.setBary(1 - w, 0, w);
        return;
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
        const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        result.closest = b + w * (c - b);
        result.used.b = true;
        result.used.c = true;
        result.setBary(0, 1 - w, w);
        return;
    }
    const float denom = 1.0f / (va + vb + vc);
    const float v = vb * denom;
    const float w = vc * denom;
    result.closest = a + ab * v + ac * w;
    result.used.a = true;
    result.used.b = true;
    result.used.c = true;
    result.setBary(1 - v - w, v, w);
}

// 1: p and d on opposite sides of plane abc; 0: the same side; -1: degenerate.
int outsideOfPlane(const BulletVec& p, const BulletVec& a, const BulletVec& b, const BulletVec& c, const BulletVec& d) {
    const BulletVec normal = cross(b - a, c - a);
    const float signp = dot(p - a, normal);
    const float signd = dot(d - a, normal);
    if (signd * signd < (1e-4f * 1e-4f)) return -1;  // CATCH_DEGENERATE_TETRAHEDRON
    return signp * signd < 0.0f ? 1 : 0;
}

bool closestOnTetrahedron(const BulletVec& p, const BulletVec& a, const BulletVec& b, const BulletVec& c,
                          const BulletVec& d, SubResult& final) {
    SubResult temp;
    final.closest = p;
    final.used = Usage{true, true, true, true};
    const int abc = outsideOfPlane(p, a, b, c, d);
    const int acd = outsideOfPlane(p, a, c, d, b);
    const int adb = outsideOfPlane(p, a, d, b, c);
    const int bdc = outsideOfPlane(p, b, d, c, a);
    if (abc < 0 || acd < 0 || adb < 0 || bdc < 0) {
        final.degenerate = true;
        return false;
    }
    if (!abc && !acd && !adb && !bdc) return false;
    float best = FLT_MAX;
    if (abc) {
        closestOnTriangle(p, a, b, c, temp);
        const BulletVec q = temp.closest;
        const float sq = dot(q - p, q - p);
        if (sq < best) {
            best = sq;
            final.closest = q;
            final.used = Usage{temp.used.a, temp.used.b, temp.used.c, false};
            final.setBary(temp.bary[0], temp.bary[1], temp.bary[2], 0);
        }
    }
    if (acd) {
        closestOnTriangle(p, a, c, d, temp);
        const BulletVec q = temp.closest;
        const float sq = dot(q - p, q - p);
        if (sq < best) {
            best = sq;
            final.closest = q;
            final.used = Usage{temp.used.a, false, temp.used.b, temp.used.c};
            final.setBary(temp.bary[0], 0, temp.bary[1], temp.bary[2]);
        }
    }
    if (adb) {
        closestOnTriangle(p, a, d, b, temp);
        const BulletVec q = temp.closest;
        const float sq = dot(q - p, q - p);
        if (sq < best) {
            best = sq;
            final.closest = q;
            final.used = Usage{temp.used.a, temp.used.c, false, temp.used.b};
            final.setBary(temp.bary[0], temp.bary[2], 0, temp.bary[1]);
        }
    }
    if (bdc) {
        closestOnTriangle(p, b, d, c, temp);
        const BulletVec q = temp.closest;
        const float sq = dot(q - p, q - p);
        if (sq < best) {
            final.closest = q;
            final.used = Usage{false, temp.used.a, temp.used.c, temp.used.b};
            final.setBary(0, temp.bary[0], temp.bary[2], temp.bary[1]);
        }
    }
    return true;
}

// btVoronoiSimplexSolver, the parts GJK uses.
class Simplex {
public:
    void reset() {
        mValidClosest = false;
        mCount = 0;
        mNeedsUpdate = true;
        mLastW = BulletVec{1e18f, 1e18f, 1e18f};  // BT_LARGE_FLOAT
        mBC.reset();
    }
    void add(const BulletVec& w, const BulletVec& p, const BulletVec& q) {
        mLastW = w;
        mNeedsUpdate = true;
        mW[mCount] = w;
        mP[mCount] = p;
        mQ[mCount] = q;
        ++mCount;
    }
    bool contains(const BulletVec& w) const {
        bool found = false;
        for (int i = 0; i < mCount; ++i) {
            const BulletVec d = mW[i] - w;
            if (length2(d) <= kEqualVertexThreshold) {
                found = true;
                break;
            }
        }
        if (w == mLastW) return true;
        return found;
    }
    bool closest(BulletVec& v) {
        const bool ok = update();
        v = mCachedV;
        return ok;
    }
    void points(BulletVec& p1, BulletVec& p2) {
        update();
        p1 = mCachedP1;
        p2 = mCachedP2;
    }
    bool full() const { return mCount == 4; }

private:
    void remove(int index) {
        --mCount;
        mW[index] = mW[mCount];
        mP[index] = mP[mCount];
        mQ[index] = mQ[mCount];
    }
    void reduce(const Usage& used) {
        if (mCount >= 4 && !used.d) remove(3);
        if (mCount >= 3 && !used.c) remove(2);
        if (mCount >= 2 && !used.b) remove(1);
        if (mCount >= 1 && !used.a) remove(0);
    }
    bool update() {
        if (!mNeedsUpdate) return mValidClosest;
        mBC.reset();
        mNeedsUpdate = false;
        switch (mCount) {
            case 0:
                mValidClosest = false;
                break;
            case 1:
                mCachedP1 = mP[0];
                mCachedP2 = mQ[0];
                mCachedV = mCachedP1 - mCachedP2;
                mBC.reset();
                mBC.setBary(1, 0, 0, 0);
                mValidClosest = mBC.valid();
                break;
            case 2: {
                const BulletVec from = mW[0];
                const BulletVec to = mW[1];
                const BulletVec origin{0.0f, 0.0f, 0.0f};
                BulletVec diff = origin - from;
                const BulletVec v = to - from;
                float t = dot(v, diff);
                if (t > 0) {
                    const float vv = dot(v, v);
                    if (t < vv) {
                        t /= vv;
                        diff = diff - t * v;
                        mBC.used.a = true;
                        mBC.used.b = true;
                    } else {
                        t = 1;
                        diff = diff - v;
                        mBC.used.b = true;
                    }
                } else {
                    t = 0;
                    mBC.used.a = true;
                }
                mBC.setBary(1 - t, t);
                mCachedP1 = mP[0] + t * (mP[1] - mP[0]);
                mCachedP2 = mQ[0] + t * (mQ[1] - mQ[0]);
                mCachedV = mCachedP1 - mCachedP2;
                reduce(mBC.used);
                mValidClosest = mBC.valid();
                break;
            }
            case 3: {
                const BulletVec origin{0.0f, 0.0f, 0.0f};
                closestOnTriangle(origin, mW[0], mW[1], mW[2], mBC);
                mCachedP1 = mP[0] * mBC.bary[0] + mP[1] * mBC.bary[1] + mP[2] * mBC.bary[2];
                mCachedP2 = mQ[0] * mBC.bary[0] + mQ[1] * mBC.bary[1] + mQ[2] * mBC.bary[2];
                mCachedV = mCachedP1 - mCachedP2;
                reduce(mBC.used);
                mValidClosest = mBC.valid();
                break;
            }
            case 4: {
                const BulletVec origin{0.0f, 0.0f, 0.0f};
                if (closestOnTetrahedron(origin, mW[0], mW[1], mW[2], mW[3], mBC)) {
                    mCachedP1 = mP[0] * mBC.bary[0] + mP[1] * mBC.bary[1] + mP[2] * mBC.bary[2] + mP[3] * mBC.bary[3];
                    mCachedP2 = mQ[0] * mBC.bary[0] + mQ[1] * mBC.bary[1] + mQ[2] * mBC.bary[2] + mQ[3] * mBC.bary[3];
                    mCachedV = mCachedP1 - mCachedP2;
                    reduce(mBC.used);
                } else {
                    if (mBC.degenerate) {
                        mValidClosest = false;
                    } else {
                        mValidClosest = true;
                        mCachedV = BulletVec{0.0f, 0.0f, 0.0f};
                    }
                    break;
                }
                mValidClosest = mBC.valid();
                break;
            }
            default:
                mValidClosest = false;
        }
        return mValidClosest;
    }

    int mCount = 0;
    std::array<BulletVec, 5> mW{}, mP{}, mQ{};
    BulletVec mCachedP1, mCachedP2, mCachedV, mLastW;
    bool mValidClosest = false;
    SubResult mBC;
    bool mNeedsUpdate = true;
};

}  // namespace

std::array<BulletVec, 3> bulletBasis(float x, float y, float z, float w) {
    const float d = x * x + y * y + z * z + w * w;
    const float s = 2.0f / d;
    const float xs = x * s, ys = y * s, zs = z * s;
    const float wx = w * xs, wy = w * ys, wz = w * zs;
    const float xx = x * xs, xy = x * ys, xz = x * zs;
    const float yy = y * ys, yz = y * zs, zz = z * zs;
    return {BulletVec{1.0f - (yy + zz), xy - wz, xz + wy}, BulletVec{xy + wz, 1.0f - (xx + zz), yz - wx},
            BulletVec{xz - wy, yz + wx, 1.0f - (xx + yy)}};
}

void bulletBoxShape(const BulletVec& h, float margin, BulletBox& box) {
    // The constructor: the default margin off the full half extents, then setSafeMargin.
    float current = 0.04f;  // CONVEX_DISTANCE_MARGIN
    BulletVec implicit = h - BulletVec{current, current, current};
    const auto setMargin = [&](float next) {  // btBoxShape::setMargin
        const BulletVec withMargin = implicit + BulletVec{current, current, current};
        current = next;
        implicit = withMargin - BulletVec{current, current, current};
    };
    const float smallest = h.x < h.y ? (h.x < h.z ? h.x : h.z) : (h.y < h.z ? h.y : h.z);  // minAxis
    const float safe = 0.1f * smallest;
    if (safe < current) setMargin(safe);
    if (margin >= 0.0f) setMargin(margin);
    box.halfExtents = implicit;
    box.margin = current;
}

float bulletContactDistanceSquared(const BulletBox& box, float radius) {
    // getAngularMotionDisc: the bounding sphere of the shape's AABB at the origin (half its
    // diagonal), times the threshold factor.
    const auto disc = [](float x, float y, float z) {
        const float lx = x + x, ly = y + y, lz = z + z;
        return std::sqrt(lx * lx + ly * ly + lz * lz) * 0.5f;
    };
    const float m = box.margin;
    const float sphere = disc(radius, radius, radius) * 0.02f;
    const float boxDisc = disc(box.halfExtents.x + m, box.halfExtents.y + m, box.halfExtents.z + m) * 0.02f;
    const float distance = m + radius + std::min(sphere, boxDisc);
    return distance * distance;
}

BulletGjkContact bulletBoxSphereGjk(const BulletBox& box, const BulletVec& center, float radius,
                                    float maximumDistanceSquared, bool tooClose) {
    BulletGjkContact out;
    // btGjkPairDetector::getClosestPointsNonVirtual with A = the box, B = the sphere (its support
    // without margin is its centre, whatever its rotation).
    const BulletVec offset = (box.origin + center) * 0.5f;
    const BulletVec originA = box.origin - offset;
    const BulletVec originB = center - offset;
    const float marginA = box.margin, marginB = radius;
    const float margin = marginA + marginB;

    // The sphere's centre inside the box shrunk by its margin (the cores overlap): Bullet's
    // libccd test then hands the pair to EPA. Not reproduced; near that (within twice the
    // penetration tolerance of GJK's degenerate exits) neither.
    {
        const BulletVec local = timesBasis(center - box.origin, box.basis);  // inverse rotation
        const float reach = 2.0f * kEpaPenetrationTolerance;
        if (std::abs(local.x) <= box.halfExtents.x + reach && std::abs(local.y) <= box.halfExtents.y + reach &&
            std::abs(local.z) <= box.halfExtents.z + reach) {
            const float dx = std::max(std::abs(local.x) - box.halfExtents.x, 0.0f);
            const float dy = std::max(std::abs(local.y) - box.halfExtents.y, 0.0f);
            const float dz = std::max(std::abs(local.z) - box.halfExtents.z, 0.0f);
            const float outside = dx * dx + dy * dy + dz * dz;
            if (tooClose ? outside == 0.0f : outside <= reach * reach) return out;  // not handled
        }
    }

    Simplex simplex;
    simplex.reset();
    BulletVec axis{0.0f, 1.0f, 0.0f};  // m_cachedSeparatingAxis
    float squaredDistance = 1e18f;     // BT_LARGE_FLOAT
    bool checkSimplex = false;
    int degenerate = 0;
    int iterations = 0;
    BulletVec pointOnA, pointOnB, normalInB;
    float distance = 0.0f;
    bool valid = false;
    BulletVec originalNormal{0.0f, 0.0f, 0.0f};
    for (;;) {
        const BulletVec axisInA = timesBasis(-axis, box.basis);
        const BulletVec pInA = boxSupport(box.halfExtents, axisInA);
        const BulletVec pWorld = transform(box.basis, originA, pInA);
        const BulletVec qWorld = originB;
        const BulletVec w = pWorld - qWorld;
        const float delta = dot(axis, w);
        if (delta > 0.0f && delta * delta > squaredDistance * maximumDistanceSquared) {
            degenerate = 10;
            checkSimplex = true;
            break;
        }
        if (simplex.contains(w)) {
            degenerate = 1;
            checkSimplex = true;
            break;
        }
        const float f0 = squaredDistance - delta;
        const float f1 = squaredDistance * kRelError2;
        if (f0 <= f1) {
            degenerate = f0 <= 0.0f ? 2 : 11;
            checkSimplex = true;
            break;
        }
        simplex.add(w, pWorld, qWorld);
        BulletVec next;
        if (!simplex.closest(next)) {
            degenerate = 3;
            checkSimplex = true;
            break;
        }
        if (length2(next) < kRelError2) {
            axis = next;
            degenerate = 6;
            checkSimplex = true;
            break;
        }
        const float previous = squaredDistance;
        squaredDistance = length2(next);
        if (previous - squaredDistance <= kSimdEpsilon * previous) {
            checkSimplex = true;
            degenerate = 12;
            break;
        }
        axis = next;
        if (iterations++ > 1000) return out;  // Bullet's iteration cap: not reproduced
        if (simplex.full()) {
            degenerate = 13;
            break;
        }
    }
    if (checkSimplex) {
        simplex.points(pointOnA, pointOnB);
        normalInB = axis;
        const float lenSqr = length2(axis);
        if (lenSqr < kRelError2) degenerate = 5;
        if (lenSqr > kSimdEpsilon * kSimdEpsilon) {
            const float rlen = 1.0f / std::sqrt(lenSqr);
            normalInB = normalInB * rlen;
            const float s = std::sqrt(squaredDistance);
            pointOnA = pointOnA - axis * (marginA / s);
            pointOnB = pointOnB + axis * (marginB / s);
            distance = (1.0f / rlen) - margin;
            valid = true;
            originalNormal = normalInB;
        }
    }
    // Where Bullet would go on to EPA (an invalid result, or a degenerate exit within the
    // penetration tolerance), the answer is not reproduced.
    const bool catchDegenerate = degenerate != 0 && (distance + margin) < kEpaPenetrationTolerance;
    if (!valid || (catchDegenerate && !tooClose)) return out;
    out.handled = true;
    if (!(distance < 0.0f || distance * distance < maximumDistanceSquared)) return out;

    // The check of the normal's direction (the EPA fix-up): supports along the normal both ways.
    float d2 = 0.0f;
    {
        const BulletVec pInA = boxSupport(box.halfExtents, timesBasis(-originalNormal, box.basis));
        const BulletVec w = transform(box.basis, originA, pInA) - originB;
        d2 = dot(originalNormal, w) - margin;
    }
    float d1 = 0.0f;
    {
        const BulletVec pInA = boxSupport(box.halfExtents, timesBasis(normalInB, box.basis));
        const BulletVec w = transform(box.basis, originA, pInA) - originB;
        d1 = dot(-normalInB, w) - margin;
    }
    float d0 = 0.0f;
    {
        const BulletVec pInA = boxSupport(box.halfExtents, timesBasis(-normalInB, box.basis));
        const BulletVec w = transform(box.basis, originA, pInA) - originB;
        d0 = dot(normalInB, w) - margin;
    }
    if (d1 > d0) normalInB = normalInB * -1.0f;
    if (length2(originalNormal) != 0.0f && d2 > d0 && d2 > d1 && d2 > distance) {
        normalInB = originalNormal;
        distance = d2;
    }
    out.found = true;
    out.normalOnB = normalInB;
    out.pointOnB = pointOnB + offset;
    out.distance = distance;
    return out;
}

}  // namespace detail
FORESIGHT_NAMESPACE_END
