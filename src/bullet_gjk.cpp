// Bullet's box-sphere closest points in float (bullet_gjk.h): btGjkPairDetector's GJK loop and
// btVoronoiSimplexSolver of Bullet Physics 3.24, and the btGjkEpaSolver2 (GJK and EPA) its
// penetration depth solver runs, written again for one box and one sphere with every float
// operation in Bullet's order, so that the results are Bullet's to the bit. An altered version
// of Bullet's source (restructured, reduced to this case), under its licence:
//
//   Bullet Continuous Collision Detection and Physics Library
//   Copyright (c) 2003-2006 Erwin Coumans  https://bulletphysics.org
//   GJK-EPA collision solver by Nathanael Presson, 2008
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

// --- btGjkEpa2 (Bullet's second GJK and its EPA), float build, for box A and sphere B ----------
// btGjkPairDetector asks btGjkEpaPenetrationDepthSolver where its own GJK cannot answer: the
// sphere's centre inside the box shrunk by its margin, within the penetration tolerance of it, or
// a simplex that filled up. That solver runs btGjkEpaSolver2::Penetration (GJK on the shapes
// with their margins, then EPA when it finds the origin inside) and, where that fails,
// btGjkEpaSolver2::Distance (GJK on the shapes without margins). Everything here is in the box's
// frame, as in Bullet (gjkepa2_impl::MinkowskiDiff).

constexpr float kGjkAccuracy = 0.0001f;       // GJK_ACCURACY (float build)
constexpr float kGjkMinDistance = 0.0001f;    // GJK_MIN_DISTANCE
constexpr float kGjkDuplicatedEps = 0.0001f;  // GJK_DUPLICATED_EPS
constexpr unsigned kGjkMaxIterations = 128;   // GJK_MAX_ITERATIONS
constexpr float kEpaAccuracy = 0.0001f;       // EPA_ACCURACY
constexpr float kEpaPlaneEps = 0.00001f;      // EPA_PLANE_EPS
constexpr unsigned kEpaMaxIterations = 255;   // EPA_MAX_ITERATIONS
// EPA_MAX_VERTICES of Bullet 2.89 and later; ammo.js's 2.83 has 64, which changed none of
// 200 000 random box-sphere contacts (EPA converges on them long before).
constexpr unsigned kEpaMaxVertices = 128;

// btVector3::normalize and operator/ (a product with the reciprocal).
BulletVec dividedBy(const BulletVec& v, float s) { return v * (1.0f / s); }
float length(const BulletVec& v) { return std::sqrt(length2(v)); }
BulletVec rowsTimes(const std::array<BulletVec, 3>& m, const BulletVec& v) {
    return {dot(m[0], v), dot(m[1], v), dot(m[2], v)};
}

struct BoxSphereDifference {  // MinkowskiDiff
    BulletVec half;           // the box's half extents without margin
    float boxMargin = 0.0f, radius = 0.0f;
    std::array<BulletVec, 3> toSphere{};  // m_toshape1 (the box's rotation: rows)
    std::array<BulletVec, 3> toBox{};     // m_toshape0's basis (its transpose: rows)
    BulletVec sphereInBox;                // m_toshape0's origin
    bool margins = true;

    // localGetSupportVertexNonVirtual: the direction normalised (or (-1, -1, -1) if too short),
    // the support without margin, plus the margin along it.
    static BulletVec unit(const BulletVec& d) {
        BulletVec n = d;
        if (length2(n) < kSimdEpsilon * kSimdEpsilon) n = BulletVec{-1.0f, -1.0f, -1.0f};
        return dividedBy(n, length(n));
    }
    BulletVec support0(const BulletVec& d) const {
        if (!margins) return boxSupport(half, d);
        const BulletVec n = unit(d);
        return boxSupport(half, n) + n * boxMargin;
    }
    BulletVec support1(const BulletVec& d) const {
        BulletVec local{0.0f, 0.0f, 0.0f};
        if (margins) local = BulletVec{0.0f, 0.0f, 0.0f} + unit(rowsTimes(toSphere, d)) * radius;
        return transform(toBox, sphereInBox, local);
    }
    BulletVec support(const BulletVec& d) const { return support0(d) - support1(-d); }
};

struct EpaVertex {  // sSV
    BulletVec d, w;
};
struct EpaSimplex {  // sSimplex
    EpaVertex* c[4] = {};
    float p[4] = {};
    unsigned rank = 0;
};

float det(const BulletVec& a, const BulletVec& b, const BulletVec& c) {
    return a.y * b.z * c.x + a.z * b.x * c.y - a.x * b.z * c.y - a.y * b.x * c.z + a.x * b.y * c.z - a.z * b.y * c.x;
}

float projectOrigin(const BulletVec& a, const BulletVec& b, float* w, unsigned& m) {
    const BulletVec d = b - a;
    const float l = length2(d);
    if (l > 0.0f) {
        const float t = l > 0.0f ? -dot(a, d) / l : 0.0f;
        if (t >= 1.0f) {
            w[0] = 0.0f;
            w[1] = 1.0f;
            m = 2;
            return length2(b);
        }
        if (t <= 0.0f) {
            w[0] = 1.0f;
            w[1] = 0.0f;
            m = 1;
            return length2(a);
        }
        w[1] = t;
        w[0] = 1.0f - t;
        m = 3;
        return length2(a + d * t);
    }
    return -1.0f;
}

float projectOrigin(const BulletVec& a, const BulletVec& b, const BulletVec& c, float* w, unsigned& m) {
    static constexpr unsigned imd3[] = {1, 2, 0};
    const BulletVec* vt[] = {&a, &b, &c};
    const BulletVec dl[] = {a - b, b - c, c - a};
    const BulletVec n = cross(dl[0], dl[1]);
    const float l = length2(n);
    if (l > 0.0f) {
        float mindist = -1.0f;
        float subw[2] = {0.0f, 0.0f};
        unsigned subm = 0;
        for (unsigned i = 0; i < 3; ++i) {
            if (dot(*vt[i], cross(dl[i], n)) > 0.0f) {
                const unsigned j = imd3[i];
                const float subd = projectOrigin(*vt[i], *vt[j], subw, subm);
                if (mindist < 0.0f || subd < mindist) {
                    mindist = subd;
                    m = ((subm & 1) ? 1u << i : 0u) + ((subm & 2) ? 1u << j : 0u);
                    w[i] = subw[0];
                    w[j] = subw[1];
                    w[imd3[j]] = 0.0f;
                }
            }
        }
        if (mindist < 0.0f) {
            const float d = dot(a, n);
            const float s = std::sqrt(l);
            const BulletVec p = n * (d / l);
            mindist = length2(p);
            m = 7;
            w[0] = length(cross(dl[1], b - p)) / s;
            w[1] = length(cross(dl[2], c - p)) / s;
            w[2] = 1.0f - (w[0] + w[1]);
        }
        return mindist;
    }
    return -1.0f;
}

float projectOrigin(const BulletVec& a, const BulletVec& b, const BulletVec& c, const BulletVec& d, float* w,
                    unsigned& m) {
    static constexpr unsigned imd3[] = {1, 2, 0};
    const BulletVec* vt[] = {&a, &b, &c, &d};
    const BulletVec dl[] = {a - d, b - d, c - d};
    const float vl = det(dl[0], dl[1], dl[2]);
    const bool ng = (vl * dot(a, cross(b - c, a - b))) <= 0.0f;
    if (ng && std::abs(vl) > 0.0f) {
        float mindist = -1.0f;
        float subw[3] = {0.0f, 0.0f, 0.0f};
        unsigned subm = 0;
        for (unsigned i = 0; i < 3; ++i) {
            const unsigned j = imd3[i];
            const float s = vl * dot(d, cross(dl[i], dl[j]));
            if (s > 0.0f) {
                const float subd = projectOrigin(*vt[i], *vt[j], d, subw, subm);
                if (mindist < 0.0f || subd < mindist) {
                    mindist = subd;
                    m = ((subm & 1) ? 1u << i : 0u) + ((subm & 2) ? 1u << j : 0u) + ((subm & 4) ? 8u : 0u);
                    w[i] = subw[0];
                    w[j] = subw[1];
                    w[imd3[j]] = 0.0f;
                    w[3] = subw[2];
                }
            }
        }
        if (mindist < 0.0f) {
            mindist = 0.0f;
            m = 15;
            w[0] = det(c, b, d) / vl;
            w[1] = det(a, c, d) / vl;
            w[2] = det(b, a, d) / vl;
            w[3] = 1.0f - (w[0] + w[1] + w[2]);
        }
        return mindist;
    }
    return -1.0f;
}

enum class GjkStatus { Valid, Inside, Failed };

struct EpaGjk {  // gjkepa2_impl::GJK
    BoxSphereDifference shape;
    BulletVec ray;
    EpaSimplex simplices[2];
    EpaVertex store[4];
    EpaVertex* free[4] = {};
    unsigned nfree = 0, current = 0;
    EpaSimplex* simplex = nullptr;
    GjkStatus status = GjkStatus::Failed;

    void getSupport(const BulletVec& d, EpaVertex& sv) const {
        sv.d = dividedBy(d, length(d));
        sv.w = shape.support(sv.d);
    }
    void removeVertex(EpaSimplex& s) { free[nfree++] = s.c[--s.rank]; }
    void appendVertex(EpaSimplex& s, const BulletVec& v) {
        s.p[s.rank] = 0.0f;
        s.c[s.rank] = free[--nfree];
        getSupport(v, *s.c[s.rank++]);
    }

    GjkStatus evaluate(const BulletVec& guess) {
        unsigned iterations = 0;
        float alpha = 0.0f;
        BulletVec lastw[4];
        unsigned clastw = 0;
        for (unsigned i = 0; i < 4; ++i) free[i] = &store[i];
        nfree = 4;
        current = 0;
        status = GjkStatus::Valid;
        simplices[0].rank = 0;
        ray = guess;
        const float sqrl = length2(ray);
        appendVertex(simplices[0], sqrl > 0.0f ? -ray : BulletVec{1.0f, 0.0f, 0.0f});
        simplices[0].p[0] = 1.0f;
        ray = simplices[0].c[0]->w;
        lastw[0] = lastw[1] = lastw[2] = lastw[3] = ray;
        do {
            const unsigned next = 1 - current;
            EpaSimplex& cs = simplices[current];
            EpaSimplex& ns = simplices[next];
            const float rl = length(ray);
            if (rl < kGjkMinDistance) {
                status = GjkStatus::Inside;
                break;
            }
            appendVertex(cs, -ray);
            const BulletVec w = cs.c[cs.rank - 1]->w;
            bool found = false;
            for (unsigned i = 0; i < 4; ++i) {
                if (length2(w - lastw[i]) < kGjkDuplicatedEps) {
                    found = true;
                    break;
                }
            }
            if (found) {
                removeVertex(simplices[current]);
                break;
            }
            lastw[clastw = (clastw + 1) & 3] = w;
            const float omega = dot(ray, w) / rl;
            alpha = std::max(omega, alpha);
            if (((rl - alpha) - (kGjkAccuracy * rl)) <= 0.0f) {
                removeVertex(simplices[current]);
                break;
            }
            float weights[4] = {};
            unsigned mask = 0;
            float sqdist = 0.0f;
            if (cs.rank == 2)
                sqdist = projectOrigin(cs.c[0]->w, cs.c[1]->w, weights, mask);
            else if (cs.rank == 3)
                sqdist = projectOrigin(cs.c[0]->w, cs.c[1]->w, cs.c[2]->w, weights, mask);
            else if (cs.rank == 4)
                sqdist = projectOrigin(cs.c[0]->w, cs.c[1]->w, cs.c[2]->w, cs.c[3]->w, weights, mask);
            if (sqdist >= 0.0f) {
                ns.rank = 0;
                ray = BulletVec{0.0f, 0.0f, 0.0f};
                current = next;
                for (unsigned i = 0, ni = cs.rank; i < ni; ++i) {
                    if (mask & (1u << i)) {
                        ns.c[ns.rank] = cs.c[i];
                        ns.p[ns.rank++] = weights[i];
                        ray = ray + cs.c[i]->w * weights[i];
                    } else {
                        free[nfree++] = cs.c[i];
                    }
                }
                if (mask == 15) status = GjkStatus::Inside;
            } else {
                removeVertex(simplices[current]);
                break;
            }
            if (++iterations >= kGjkMaxIterations) status = GjkStatus::Failed;
        } while (status == GjkStatus::Valid);
        simplex = &simplices[current];
        return status;
    }

    // GJK::EncloseOrigin: grows the simplex to a tetrahedron around the origin, trying each new
    // direction one way and then the other.
    bool encloseOrigin() {
        static constexpr BulletVec kAxes[] = {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
        switch (simplex->rank) {
            case 1:
                for (const BulletVec& axis : kAxes)
                    if (encloseAlong(axis)) return true;
                break;
            case 2: {
                const BulletVec d = simplex->c[1]->w - simplex->c[0]->w;
                for (const BulletVec& axis : kAxes) {
                    const BulletVec p = cross(d, axis);
                    if (length2(p) > 0.0f && encloseAlong(p)) return true;
                }
                break;
            }
            case 3: {
                const BulletVec n = cross(simplex->c[1]->w - simplex->c[0]->w, simplex->c[2]->w - simplex->c[0]->w);
                if (length2(n) > 0.0f && encloseAlong(n)) return true;
                break;
            }
            case 4:
                if (std::abs(det(simplex->c[0]->w - simplex->c[3]->w, simplex->c[1]->w - simplex->c[3]->w,
                                 simplex->c[2]->w - simplex->c[3]->w)) > 0.0f)
                    return true;
                break;
            default:
                break;
        }
        return false;
    }

    // encloseOrigin with the support along `d` added, then along -d.
    bool encloseAlong(const BulletVec& d) {
        for (const BulletVec& v : {d, -d}) {
            appendVertex(*simplex, v);
            if (encloseOrigin()) return true;
            removeVertex(*simplex);
        }
        return false;
    }
};

enum class EpaStatus {
    Valid,
    Touching,
    Degenerated,
    NonConvex,
    InvalidHull,
    OutOfFaces,
    OutOfVertices,
    AccuracyReached,
    FallBack,
    Failed
};

struct EpaFace {  // sFace
    BulletVec n;
    float d = 0.0f;
    EpaVertex* c[3] = {};
    EpaFace* f[3] = {};
    EpaFace* l[2] = {};
    unsigned char e[3] = {};
    unsigned char pass = 0;
};
struct EpaList {
    EpaFace* root = nullptr;
    unsigned count = 0;
};
struct EpaHorizon {
    EpaFace* cf = nullptr;
    EpaFace* ff = nullptr;
    unsigned nf = 0;
};

struct Epa {  // gjkepa2_impl::EPA
    EpaStatus status = EpaStatus::Failed;
    EpaSimplex result;
    BulletVec normal;
    float depth = 0.0f;
    EpaVertex vertexStore[kEpaMaxVertices];
    EpaFace faceStore[2 * kEpaMaxVertices];
    unsigned nextVertex = 0;
    EpaList hull, stock;

    Epa() {
        for (unsigned i = 0; i < 2 * kEpaMaxVertices; ++i) append(stock, &faceStore[2 * kEpaMaxVertices - i - 1]);
    }

    static void bind(EpaFace* fa, unsigned ea, EpaFace* fb, unsigned eb) {
        fa->e[ea] = static_cast<unsigned char>(eb);
        fa->f[ea] = fb;
        fb->e[eb] = static_cast<unsigned char>(ea);
        fb->f[eb] = fa;
    }
    static void append(EpaList& list, EpaFace* face) {
        face->l[0] = nullptr;
        face->l[1] = list.root;
        if (list.root) list.root->l[0] = face;
        list.root = face;
        ++list.count;
    }
    static void remove(EpaList& list, EpaFace* face) {
        if (face->l[1]) face->l[1]->l[0] = face->l[0];
        if (face->l[0]) face->l[0]->l[1] = face->l[1];
        if (face == list.root) list.root = face->l[1];
        --list.count;
    }

    EpaStatus evaluate(EpaGjk& gjk, const BulletVec& guess) {
        EpaSimplex& simplex = *gjk.simplex;
        if (simplex.rank > 1 && gjk.encloseOrigin()) {
            while (hull.root) {
                EpaFace* f = hull.root;
                remove(hull, f);
                append(stock, f);
            }
            status = EpaStatus::Valid;
            nextVertex = 0;
            if (det(simplex.c[0]->w - simplex.c[3]->w, simplex.c[1]->w - simplex.c[3]->w,
                    simplex.c[2]->w - simplex.c[3]->w) < 0.0f) {
                std::swap(simplex.c[0], simplex.c[1]);
                std::swap(simplex.p[0], simplex.p[1]);
            }
            EpaFace* tetra[] = {newFace(simplex.c[0], simplex.c[1], simplex.c[2], true),
                                newFace(simplex.c[1], simplex.c[0], simplex.c[3], true),
                                newFace(simplex.c[2], simplex.c[1], simplex.c[3], true),
                                newFace(simplex.c[0], simplex.c[2], simplex.c[3], true)};
            if (hull.count == 4) {
                EpaFace* best = findBest();
                EpaFace outer = *best;
                unsigned pass = 0;
                bind(tetra[0], 0, tetra[1], 0);
                bind(tetra[0], 1, tetra[2], 0);
                bind(tetra[0], 2, tetra[3], 0);
                bind(tetra[1], 1, tetra[3], 2);
                bind(tetra[1], 2, tetra[2], 1);
                bind(tetra[2], 2, tetra[3], 1);
                status = EpaStatus::Valid;
                for (unsigned iterations = 0; iterations < kEpaMaxIterations; ++iterations) {
                    if (nextVertex < kEpaMaxVertices) {
                        EpaHorizon horizon;
                        EpaVertex* w = &vertexStore[nextVertex++];
                        bool valid = true;
                        best->pass = static_cast<unsigned char>(++pass);
                        gjk.getSupport(best->n, *w);
                        const float wdist = dot(best->n, w->w) - best->d;
                        if (wdist > kEpaAccuracy) {
                            for (unsigned j = 0; j < 3 && valid; ++j)
                                valid &= expand(pass, w, best->f[j], best->e[j], horizon);
                            if (valid && horizon.nf >= 3) {
                                bind(horizon.cf, 1, horizon.ff, 2);
                                remove(hull, best);
                                append(stock, best);
                                best = findBest();
                                outer = *best;
                            } else {
                                status = EpaStatus::InvalidHull;
                                break;
                            }
                        } else {
                            status = EpaStatus::AccuracyReached;
                            break;
                        }
                    } else {
                        status = EpaStatus::OutOfVertices;
                        break;
                    }
                }
                const BulletVec projection = outer.n * outer.d;
                normal = outer.n;
                depth = outer.d;
                result.rank = 3;
                result.c[0] = outer.c[0];
                result.c[1] = outer.c[1];
                result.c[2] = outer.c[2];
                result.p[0] = length(cross(outer.c[1]->w - projection, outer.c[2]->w - projection));
                result.p[1] = length(cross(outer.c[2]->w - projection, outer.c[0]->w - projection));
                result.p[2] = length(cross(outer.c[0]->w - projection, outer.c[1]->w - projection));
                const float sum = result.p[0] + result.p[1] + result.p[2];
                result.p[0] /= sum;
                result.p[1] /= sum;
                result.p[2] /= sum;
                return status;
            }
        }
        status = EpaStatus::FallBack;
        normal = -guess;
        const float nl = length(normal);
        normal = nl > 0.0f ? dividedBy(normal, nl) : BulletVec{1.0f, 0.0f, 0.0f};
        depth = 0.0f;
        result.rank = 1;
        result.c[0] = simplex.c[0];
        result.p[0] = 1.0f;
        return status;
    }

    static bool edgeDistance(const EpaFace* face, const EpaVertex* a, const EpaVertex* b, float& dist) {
        const BulletVec ba = b->w - a->w;
        const BulletVec nab = cross(ba, face->n);
        if (dot(a->w, nab) < 0.0f) {
            const float ba2 = length2(ba);
            const float adotba = dot(a->w, ba);
            const float bdotba = dot(b->w, ba);
            if (adotba > 0.0f) {
                dist = length(a->w);
            } else if (bdotba < 0.0f) {
                dist = length(b->w);
            } else {
                const float adotb = dot(a->w, b->w);
                dist = std::sqrt(std::max((length2(a->w) * length2(b->w) - adotb * adotb) / ba2, 0.0f));
            }
            return true;
        }
        return false;
    }

    EpaFace* newFace(EpaVertex* a, EpaVertex* b, EpaVertex* c, bool forced) {
        if (stock.root) {
            EpaFace* face = stock.root;
            remove(stock, face);
            append(hull, face);
            face->pass = 0;
            face->c[0] = a;
            face->c[1] = b;
            face->c[2] = c;
            face->n = cross(b->w - a->w, c->w - a->w);
            const float l = length(face->n);
            if (l > kEpaAccuracy) {
                if (!(edgeDistance(face, a, b, face->d) || edgeDistance(face, b, c, face->d) ||
                      edgeDistance(face, c, a, face->d)))
                    face->d = dot(a->w, face->n) / l;
                face->n = dividedBy(face->n, l);
                if (forced || face->d >= -kEpaPlaneEps) return face;
                status = EpaStatus::NonConvex;
            } else {
                status = EpaStatus::Degenerated;
            }
            remove(hull, face);
            append(stock, face);
            return nullptr;
        }
        status = stock.root ? EpaStatus::OutOfVertices : EpaStatus::OutOfFaces;
        return nullptr;
    }

    EpaFace* findBest() {
        EpaFace* minf = hull.root;
        float mind = minf->d * minf->d;
        for (EpaFace* f = minf->l[1]; f; f = f->l[1]) {
            const float sqd = f->d * f->d;
            if (sqd < mind) {
                minf = f;
                mind = sqd;
            }
        }
        return minf;
    }

    bool expand(unsigned pass, EpaVertex* w, EpaFace* f, unsigned e, EpaHorizon& horizon) {
        static constexpr unsigned i1m3[] = {1, 2, 0};
        static constexpr unsigned i2m3[] = {2, 0, 1};
        if (f->pass != pass) {
            const unsigned e1 = i1m3[e];
            if ((dot(f->n, w->w) - f->d) < -kEpaPlaneEps) {
                EpaFace* nf = newFace(f->c[e1], f->c[e], w, false);
                if (nf) {
                    bind(nf, 0, f, e);
                    if (horizon.cf)
                        bind(horizon.cf, 1, nf, 2);
                    else
                        horizon.ff = nf;
                    horizon.cf = nf;
                    ++horizon.nf;
                    return true;
                }
            } else {
                const unsigned e2 = i2m3[e];
                f->pass = static_cast<unsigned char>(pass);
                if (expand(pass, w, f->f[e1], f->e[e1], horizon) && expand(pass, w, f->f[e2], f->e[e2], horizon)) {
                    remove(hull, f);
                    append(stock, f);
                    return true;
                }
            }
        }
        return false;
    }
};

struct EpaResults {  // btGjkEpaSolver2::sResults (the parts used)
    BulletVec witness0, witness1, normal;
};

// btGjkEpaPenetrationDepthSolver::calcPenDepth for box A (basis rows `basis`, origin `originA`)
// and the sphere B at `originB`, in btGjkPairDetector's offset frame. Returns whether EPA found a
// penetration; `axis` is left at zero when neither solver answered.
bool penetrationDepth(const BulletBox& box, const BulletVec& originA, const BulletVec& originB, float radius,
                      BulletVec& axis, BulletVec& onA, BulletVec& onB) {
    BoxSphereDifference shape;
    shape.half = box.halfExtents;
    shape.boxMargin = box.margin;
    shape.radius = radius;
    shape.toSphere = box.basis;  // I^T R: R itself, to the bit
    for (int i = 0; i < 3; ++i) {
        const auto column = [&](const BulletVec& row) { return i == 0 ? row.x : i == 1 ? row.y : row.z; };
        shape.toBox[static_cast<std::size_t>(i)] =
            BulletVec{column(box.basis[0]), column(box.basis[1]), column(box.basis[2])};
    }
    shape.sphereInBox = timesBasis(originB - originA, box.basis);
    const auto safeNormalized = [](BulletVec v) {
        const float l2 = length2(v);
        return l2 >= kSimdEpsilon * kSimdEpsilon ? dividedBy(v, std::sqrt(l2)) : BulletVec{1.0f, 0.0f, 0.0f};
    };
    const BulletVec guesses[] = {safeNormalized(originB - originA),
                                 safeNormalized(originA - originB),
                                 {0, 0, 1},
                                 {0, 1, 0},
                                 {1, 0, 0},
                                 {1, 1, 0},
                                 {1, 1, 1},
                                 {0, 1, 1},
                                 {1, 0, 1}};
    for (const BulletVec& guess : guesses) {
        {  // Penetration (with margins)
            EpaGjk gjk;
            gjk.shape = shape;
            gjk.shape.margins = true;
            if (gjk.evaluate(-guess) == GjkStatus::Inside) {
                Epa epa;
                if (epa.evaluate(gjk, -guess) != EpaStatus::Failed) {
                    BulletVec w0{0.0f, 0.0f, 0.0f};
                    for (unsigned i = 0; i < epa.result.rank; ++i)
                        w0 = w0 + gjk.shape.support0(epa.result.c[i]->d) * epa.result.p[i];
                    onA = transform(box.basis, originA, w0);
                    onB = transform(box.basis, originA, w0 - epa.normal * epa.depth);
                    axis = -epa.normal;
                    return true;
                }
            }
        }
        {  // Distance (without margins)
            EpaGjk gjk;
            gjk.shape = shape;
            gjk.shape.margins = false;
            if (gjk.evaluate(guess) == GjkStatus::Valid) {
                BulletVec w0{0.0f, 0.0f, 0.0f}, w1{0.0f, 0.0f, 0.0f};
                for (unsigned i = 0; i < gjk.simplex->rank; ++i) {
                    const float p = gjk.simplex->p[i];
                    w0 = w0 + gjk.shape.support0(gjk.simplex->c[i]->d) * p;
                    w1 = w1 + gjk.shape.support1(-gjk.simplex->c[i]->d) * p;
                }
                onA = transform(box.basis, originA, w0);
                onB = transform(box.basis, originA, w1);
                BulletVec n = w0 - w1;
                const float distance = length(n);
                axis = dividedBy(n, distance > kGjkMinDistance ? distance : 1.0f);
                return false;
            }
        }
    }
    return false;
}

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
                                    float maximumDistanceSquared, bool tooClose, bool epa) {
    BulletGjkContact out;
    // btGjkPairDetector::getClosestPointsNonVirtual with A = the box, B = the sphere (its support
    // without margin is its centre, whatever its rotation).
    const BulletVec offset = (box.origin + center) * 0.5f;
    const BulletVec originA = box.origin - offset;
    const BulletVec originB = center - offset;
    const float marginA = box.margin, marginB = radius;
    const float margin = marginA + marginB;

    // The sphere's centre inside the box shrunk by its margin (the cores overlap): Bullet's
    // libccd test (status 0) then hands the pair to the penetration depth solver. With `epa` that
    // is followed (`inside`); without, neither that case nor the centre within twice the
    // penetration tolerance of it (GJK's degenerate exits) is answered.
    bool inside = false;
    {
        const BulletVec local = timesBasis(center - box.origin, box.basis);  // inverse rotation
        const float reach = 2.0f * kEpaPenetrationTolerance;
        if (std::abs(local.x) <= box.halfExtents.x + reach && std::abs(local.y) <= box.halfExtents.y + reach &&
            std::abs(local.z) <= box.halfExtents.z + reach) {
            const float dx = std::max(std::abs(local.x) - box.halfExtents.x, 0.0f);
            const float dy = std::max(std::abs(local.y) - box.halfExtents.y, 0.0f);
            const float dz = std::max(std::abs(local.z) - box.halfExtents.z, 0.0f);
            const float outside = dx * dx + dy * dy + dz * dz;
            if (epa)
                inside = outside == 0.0f;
            else if (tooClose ? outside == 0.0f : outside <= reach * reach)
                return out;  // not handled
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
    if (epa && (!valid || catchDegenerate || inside)) {
        // btGjkPairDetector's penetration case: the depth solver's answer replaces GJK's where GJK
        // had none or it is deeper (EPA), or nearer (the second GJK, without margins).
        BulletVec depthAxis{0.0f, 0.0f, 0.0f}, tmpA, tmpB;
        const bool penetrating = penetrationDepth(box, originA, originB, radius, depthAxis, tmpA, tmpB);
        if (length2(depthAxis) != 0.0f) {
            if (penetrating) {
                BulletVec n = tmpB - tmpA;
                float lenSqr = length2(n);
                if (lenSqr <= kSimdEpsilon * kSimdEpsilon) {
                    n = depthAxis;
                    lenSqr = length2(depthAxis);
                }
                if (lenSqr > kSimdEpsilon * kSimdEpsilon) {
                    n = dividedBy(n, std::sqrt(lenSqr));
                    const float distance2 = -length(tmpA - tmpB);
                    if (!valid || distance2 < distance) {
                        distance = distance2;
                        pointOnA = tmpA;
                        pointOnB = tmpB;
                        normalInB = n;
                        valid = true;
                    }
                }
            } else {
                const float distance2 = length(tmpA - tmpB) - margin;
                if (!valid || distance2 < distance) {
                    distance = distance2;
                    pointOnA = tmpA - depthAxis * marginA;
                    pointOnB = tmpB + depthAxis * marginB;
                    normalInB = dividedBy(depthAxis, length(depthAxis));
                    valid = true;
                }
            }
        }
        if (!valid) return out;
    } else if (!valid || (catchDegenerate && !tooClose)) {
        return out;
    }
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
