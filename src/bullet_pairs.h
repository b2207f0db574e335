#pragma once
// Bullet's broadphase and dispatcher bookkeeping for one moving sphere: which shapes it holds a
// collision pair with, and so a contact manifold (empty or not), in the order of the
// dispatcher's manifold array. The solver meets the manifolds in that order after
// btSimulationIslandManager's unstable sort, so that order decides which of two contacts pushes
// first (ProjectileMethod::Engine, the Bullet profiles; docs/engines.md).

#include "internal.h"

#include <foresight/static_world.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

/// The pairs and manifolds of one sphere in a btDiscreteDynamicsWorld with Bullet's defaults
/// (btDbvtBroadphase, btHashedOverlappingPairCache, btCollisionDispatcher), followed step by step:
/// - The sphere's broadphase leaf is its bounding box where the step starts and where its damped
///   velocity alone would take it (btCollisionWorld::updateSingleAabb with continuous collision
///   on, Bullet's default), grown by the contact breaking threshold (0.02 m). The leaf moves only
///   when that box leaves it, and is then that box grown by the tree's margin (0.05 m); a static
///   shape's leaf is its bounding box grown by both (0.07 m).
/// - A leaf that moves pairs with every shape leaf it overlaps; a new pair goes to the end of the
///   pair array. Then btDbvtBroadphase::collide checks at most max(1 + the leaves it overlapped,
///   a tenth of the pairs) pairs, round robin from where the last check stopped, and removes the
///   ones whose leaves no longer overlap (the last pair takes the removed one's place).
/// - The dispatcher makes a new pair's manifold when it first meets the pair, at the end of its
///   array; a removed pair's manifold leaves it, the last manifold taking its place. Godot 3's
///   predictive contact has a manifold of its own, made before the narrow phase and released at
///   the next step's start.
/// Where several pairs appear at once their order follows the tree's traversal, which depends on
/// node addresses (btDbvt's rotations compare them); they are taken in world order. Checked
/// against the linked Bullet 3.24 (tests/bullet_pairs_test.cpp): the same array at every step of
/// every throw where no two pairs appeared at once; where they did (the boxes right round the
/// throw's start), the same array throughout in 31 of 49 throws (27 in reverse world order).
class BulletPairs {
public:
    static constexpr std::size_t kMaxShapes = 64;      // shapes met in one run
    static constexpr std::size_t kMaxCandidates = 32;  // shapes near the sphere at once
    static constexpr std::size_t kMaxPairs = 24;
    static constexpr std::uint8_t kPredictive = 255;  // the predictive contact's manifold

    /// What a step changes (EngineRun's snapshots hold it).
    struct State {
        DVec3 lo{0.0}, hi{0.0};  // the sphere's leaf [m]
        std::array<std::uint8_t, kMaxPairs> pairs{};
        std::array<bool, kMaxPairs> made{};  // the pair's manifold exists
        std::array<std::uint8_t, kMaxPairs + 1> manifolds{};
        std::uint8_t pairCount = 0, manifoldCount = 0;
        std::uint32_t next = 0;  // where the round-robin check goes on (btDbvtBroadphase::m_cid)
        bool valid = false;
    };

    /// Starts a run: a sphere of `radius` [m] spawned at `centre` in `world`, whose shapes exist
    /// already. False (and invalid from then on) when the world cannot list its shapes.
    bool start(const CollisionWorld& world, const DVec3& centre, double radius) {
        mWorld = &world;
        mRadius = radius;
        mShapeCount = 0;
        mCandidateCount = 0;
        mCoverRadius = -1.0;
        mState = State{};
        mState.valid = true;
        mState.lo = centre - radius;
        mState.hi = centre + radius;
        if (!cover()) return false;
        // btDbvtBroadphase::createProxy pairs the new leaf with every leaf it overlaps.
        for (std::size_t i = 0; i < mCandidateCount; ++i)
            if (meets(mShapes[mCandidates[i]].lo, mShapes[mCandidates[i]].hi) && !addPair(mCandidates[i])) break;
        return mState.valid;
    }

    /// One step from `start`, where the damped velocity alone would take the centre to
    /// `predicted` [m]; `predictive`: this step has a predictive contact.
    void step(const DVec3& start, const DVec3& predicted, bool predictive) {
        if (!mState.valid) return;
        removeManifold(kPredictive);
        if (predictive) pushManifold(kPredictive);
        const double reach = mRadius + kContactBreaking;
        const DVec3 lo = glm::min(start, predicted) - reach, hi = glm::max(start, predicted) + reach;
        bool moved = true;
        if (!overlap(mState.lo, mState.hi, lo, hi)) {  // btDbvt's teleport: no margin
            mState.lo = lo;
            mState.hi = hi;
        } else if (!(glm::all(glm::lessThanEqual(mState.lo, lo)) && glm::all(glm::lessThanEqual(hi, mState.hi)))) {
            mState.lo = lo - kTreeMargin;
            mState.hi = hi + kTreeMargin;
        } else {
            moved = false;
        }
        if (moved) {
            if (!cover()) return;
            std::uint32_t met = 1;  // btDbvtBroadphase::m_newpairs
            for (std::size_t i = 0; i < mCandidateCount; ++i) {
                const Shape& s = mShapes[mCandidates[i]];
                if (!meets(s.lo, s.hi)) continue;
                ++met;
                if (!addPair(mCandidates[i])) return;
            }
            cleanUp(met);
        }
        for (std::size_t i = 0; i < mState.pairCount; ++i)
            if (!mState.made[i]) {
                pushManifold(mState.pairs[i]);
                mState.made[i] = true;
            }
    }

    bool valid() const { return mState.valid; }
    const State& state() const { return mState; }
    void restore(const State& s) { mState = s; }

    /// The manifolds in the order the solver meets them (btSimulationIslandManager sorts the
    /// array by island with btAlignedObjectArray::quickSort, and all of them have the sphere's
    /// island): shape numbers (shapeOn) and kPredictive. Returns their count.
    std::size_t solveOrder(std::array<std::uint8_t, kMaxPairs + 1>& order) const {
        const std::size_t n = mState.manifoldCount;
        std::copy_n(mState.manifolds.begin(), n, order.begin());
        if (n > 1) equalKeyQuickSort(order.data(), 0, static_cast<int>(n) - 1);
        return n;
    }

    /// The shape with a manifold that holds `point` [m] on its surface (within the rounding of
    /// the boxes' edges), or -1.
    int shapeOn(const DVec3& point) const { return nearest(mState.pairs.data(), mState.pairCount, point); }

    /// The box of shape number `id` (solveOrder, shapeOn), or null (a plane, a sphere).
    const OrientedBox* boxOf(std::uint8_t id) const {
        return id < mShapeCount && mShapes[id].kind == Kind::Box ? &mShapes[id].box : nullptr;
    }

    /// The gathered box whose surface lies nearest `point` [m] (within 0.05 m), or null.
    const OrientedBox* boxNear(const DVec3& point) const {
        const int i = nearest(mCandidates.data(), mCandidateCount, point);
        return i >= 0 ? boxOf(static_cast<std::uint8_t>(i)) : nullptr;
    }

private:
    static constexpr double kContactBreaking = 0.02;  // gContactBreakingThreshold [m]
    static constexpr double kTreeMargin = 0.05;       // gDbvtMargin [m]
    // How far beyond a shape its bounding box may reach and still be found by gathering the
    // shapes within that distance of the leaf [m]: boxes whose rotated bounding box reaches
    // farther from the box than this (about 4 m across, turned 45 degrees) may be missed.
    static constexpr double kSlack = 2.0;
    static constexpr double kTravel = 2.0;  // how far the leaf may move before gathering again [m]

    enum class Kind : std::uint8_t { Plane, Sphere, Box };
    struct Shape {
        Kind kind = Kind::Box;
        OrientedBox box;
        Sphere sphere;
        Plane plane;
        DVec3 lo{0.0}, hi{0.0};   // its leaf [m]
        glm::dmat3 toLocal{1.0};  // a box: world to box axes
        bool same(const Shape& o) const {
            if (kind != o.kind) return false;
            if (kind == Kind::Plane) return plane.normal == o.plane.normal && plane.distance == o.plane.distance;
            if (kind == Kind::Sphere) return sphere.center == o.sphere.center && sphere.radius == o.sphere.radius;
            return box.center == o.box.center && box.halfExtents == o.box.halfExtents &&
                   box.orientation == o.box.orientation && box.rounding == o.box.rounding;
        }
        // How far `p` lies from the shape's surface [m].
        double distance(const DVec3& p) const {
            if (kind == Kind::Plane) {
                const DVec3 n = glm::normalize(DVec3(plane.normal));
                return std::abs(glm::dot(n, p) - static_cast<double>(plane.distance));
            }
            if (kind == Kind::Sphere)
                return std::abs(glm::length(p - DVec3(sphere.center)) - static_cast<double>(sphere.radius));
            DVec3 outward;
            return std::abs(boxSignedDistance(toLocal * (p - DVec3(box.center)), DVec3(box.halfExtents), 0.0, outward));
        }
    };

    // Collects the world's shapes near the leaf into the run's list.
    class Gatherer final : public ShapeCollector {
    public:
        explicit Gatherer(BulletPairs& owner) : mOwner(owner) {}
        void begin(float) override {}
        bool add(const Plane& plane, const SurfaceMaterial&) override {
            Shape s;
            s.kind = Kind::Plane;
            s.plane = plane;
            s.lo = DVec3(-kUnbounded);  // btStaticPlaneShape: an unbounded box
            s.hi = DVec3(kUnbounded);
            return mOwner.offer(s);
        }
        bool add(const Sphere& sphere, const SurfaceMaterial&) override {
            Shape s;
            s.kind = Kind::Sphere;
            s.sphere = sphere;
            const double r = static_cast<double>(sphere.radius) + kContactBreaking + kTreeMargin;
            s.lo = DVec3(sphere.center) - r;
            s.hi = DVec3(sphere.center) + r;
            return mOwner.offer(s);
        }
        bool add(const OrientedBox& box, const SurfaceMaterial&) override {
            Shape s;
            s.kind = Kind::Box;
            s.box = box;
            const glm::dmat3 m = glm::mat3_cast(glm::normalize(DQuat(box.orientation)));
            s.toLocal = glm::transpose(m);
            const DVec3 h(box.halfExtents);
            DVec3 extent(kContactBreaking + kTreeMargin);
            for (int axis = 0; axis < 3; ++axis) extent += glm::abs(m[axis]) * h[axis];
            s.lo = DVec3(box.center) - extent;
            s.hi = DVec3(box.center) + extent;
            return mOwner.offer(s);
        }
        // A triangle mesh is one shape to Bullet, a single pair: not followed.
        bool add(const Triangle&, const SurfaceMaterial&) override { return false; }

    private:
        BulletPairs& mOwner;
    };
    static constexpr double kUnbounded = 1e30;

    bool meets(const DVec3& lo, const DVec3& hi) const { return overlap(lo, hi, mState.lo, mState.hi); }
    static bool overlap(const DVec3& alo, const DVec3& ahi, const DVec3& blo, const DVec3& bhi) {
        return glm::all(glm::lessThanEqual(alo, bhi)) && glm::all(glm::lessThanEqual(blo, ahi));
    }

    // Of the shapes numbered `ids`, the one whose surface lies nearest `point` (within 0.05 m),
    // or -1.
    int nearest(const std::uint8_t* ids, std::size_t count, const DVec3& point) const {
        int best = -1;
        double bestDistance = 0.05;
        for (std::size_t i = 0; i < count; ++i) {
            const double d = mShapes[ids[i]].distance(point);
            if (d < bestDistance) {
                bestDistance = d;
                best = ids[i];
            }
        }
        return best;
    }

    // The shape's number in the run's list, added if new (false when the list is full).
    bool offer(const Shape& s) {
        if (mCandidateCount == kMaxCandidates) return false;
        std::size_t i = 0;
        while (i < mShapeCount && !mShapes[i].same(s)) ++i;
        if (i == mShapeCount) {
            if (mShapeCount == kMaxShapes) return false;
            mShapes[mShapeCount++] = s;
        }
        mCandidates[mCandidateCount++] = static_cast<std::uint8_t>(i);
        return true;
    }

    // Makes sure the candidates hold every shape whose leaf may overlap the sphere's leaf.
    bool cover() {
        const DVec3 centre = 0.5 * (mState.lo + mState.hi);
        const double half = 0.5 * glm::length(mState.hi - mState.lo);
        if (glm::length(centre - mCoverCentre) + half + kSlack <= mCoverRadius) return true;
        mCoverCentre = centre;
        mCoverRadius = half + kSlack + kTravel;
        mCandidateCount = 0;
        SegmentCast region;
        region.origin = toR(centre);
        region.displacement = Vec3(0.0f);
        region.radius = static_cast<float>(mCoverRadius);
        Gatherer gatherer(*this);
        if (!mWorld->gatherShapes(region, gatherer)) mState.valid = false;
        return mState.valid;
    }

    bool addPair(std::uint8_t shape) {
        for (std::size_t i = 0; i < mState.pairCount; ++i)
            if (mState.pairs[i] == shape) return true;
        if (mState.pairCount == kMaxPairs) {
            mState.valid = false;
            return false;
        }
        mState.made[mState.pairCount] = false;
        mState.pairs[mState.pairCount++] = shape;
        return true;
    }

    // btDbvtBroadphase::collide's clean-up of the pair cache.
    void cleanUp(std::uint32_t met) {
        if (mState.pairCount == 0) return;
        auto size = static_cast<std::uint32_t>(mState.pairCount);
        std::uint32_t checks = std::min(size, std::max(met, size * 10 / 100));
        for (std::uint32_t i = 0; i < checks; ++i) {
            const std::uint32_t at = (mState.next + i) % size;
            const Shape& s = mShapes[mState.pairs[at]];
            if (meets(s.lo, s.hi)) continue;
            if (mState.made[at]) removeManifold(mState.pairs[at]);
            mState.pairs[at] = mState.pairs[size - 1];
            mState.made[at] = mState.made[size - 1];
            mState.pairCount = static_cast<std::uint8_t>(--size);
            --checks;
            --i;  // the pair moved into this place is checked next (wraps round at 0)
            if (size == 0) break;
        }
        mState.next = size > 0 ? (mState.next + checks) % size : 0;
    }

    void pushManifold(std::uint8_t id) {
        if (mState.manifoldCount == mState.manifolds.size()) {
            mState.valid = false;
            return;
        }
        mState.manifolds[mState.manifoldCount++] = id;
    }
    // btCollisionDispatcher::releaseManifold: the last manifold takes the released one's place.
    void removeManifold(std::uint8_t id) {
        for (std::size_t i = 0; i < mState.manifoldCount; ++i)
            if (mState.manifolds[i] == id) {
                mState.manifolds[i] = mState.manifolds[--mState.manifoldCount];
                return;
            }
    }

    // btAlignedObjectArray::quickSortInternal with every key equal: no element compares less,
    // so each partition only swaps its two ends inwards.
    static void equalKeyQuickSort(std::uint8_t* a, int lo, int hi) {
        int i = lo, j = hi;
        do {
            if (i <= j) {
                std::swap(a[i], a[j]);
                ++i;
                --j;
            }
        } while (i <= j);
        if (lo < j) equalKeyQuickSort(a, lo, j);
        if (i < hi) equalKeyQuickSort(a, i, hi);
    }

    const CollisionWorld* mWorld = nullptr;
    double mRadius = 0.0;
    std::array<Shape, kMaxShapes> mShapes{};
    std::size_t mShapeCount = 0;
    std::array<std::uint8_t, kMaxCandidates> mCandidates{};
    std::size_t mCandidateCount = 0;
    DVec3 mCoverCentre{0.0};
    double mCoverRadius = -1.0;
    State mState;
};

}  // namespace detail
FORESIGHT_NAMESPACE_END
