#pragma once
// Bullet's closest points between a box and a sphere, in Bullet's own float arithmetic. Internal
// to the library.
//
// Bullet (native 3.24, and the 2.8x inside ammo.js and Godot 3) meets a sphere and a box with its
// general convex test: btConvexConvexAlgorithm hands the two shapes to btGjkPairDetector, whose
// GJK loop (with btVoronoiSimplexSolver) finds the closest points of the box shrunk by its margin
// and the sphere's centre, then adds the margins back. In float, over a box whose corners are
// metres away from the contact (a floor box 30 m wide), the simplex's barycentric arithmetic
// rounds the closest point by micrometres: the contact normal comes out tilted by up to 1e-4 rad
// and the contact point off the sphere's axis, and both change completely with the last bit of
// the sphere's position. Only the same operations in the same order give the same contact; this
// is that computation, step for step. Where GJK cannot decide (the sphere's centre inside the box
// shrunk by its margin, or within Bullet's penetration tolerance of it), Bullet asks its
// penetration depth solver: EPA on the two shapes with their margins, whose point on the sphere
// lies off the normal through the centre. With `epa` that is reproduced too. Checked bit for bit
// against the linked btGjkPairDetector (3.24) in the Bullet tests, in both cases.

#include "internal.h"

#include <array>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

/// A float 3-vector with btVector3's arithmetic (the same operations in the same order).
struct BulletVec {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};

/// A box as Bullet holds it: its world transform (row-major rotation, as btMatrix3x3 from the
/// quaternion, and origin), its half extents without the margin (btBoxShape's implicit shape
/// dimensions) and its margin [m].
struct BulletBox {
    std::array<BulletVec, 3> basis{};  ///< rows of the rotation matrix
    BulletVec origin;
    BulletVec halfExtents;  ///< without the margin
    float margin = 0.0f;
};

/// btMatrix3x3::setRotation of the quaternion (x, y, z, w), in float as Bullet computes it.
std::array<BulletVec, 3> bulletBasis(float x, float y, float z, float w);

/// A btBoxShape's half extents without its margin and its margin, for full half extents `h` and a
/// margin `margin` set after construction, or the constructor's default margin (0.04 m, lowered
/// to a tenth of the smallest half extent: setSafeMargin) when `margin` is negative. Bullet 3.24.
void bulletBoxShape(const BulletVec& h, float margin, BulletBox& box);

/// btConvexConvexAlgorithm's largest squared distance of interest for box A and a sphere of
/// `radius` [m^2]: (margin A + margin B + the manifold's contact breaking threshold)^2, that
/// threshold being btCollisionDispatcher's relative one (the smaller shape's angular motion disc
/// times gContactBreakingThreshold, 0.02).
float bulletContactDistanceSquared(const BulletBox& box, float radius);

/// The contact btGjkPairDetector reports for box A and a sphere B (centre `center`, radius
/// `radius`), given the largest squared distance of interest (btConvexConvexAlgorithm's:
/// (margin A + margin B + contact breaking threshold)^2).
struct BulletGjkContact {
    bool handled = false;   ///< false: a case this does not reproduce (EPA, degenerate): no answer
    bool found = false;     ///< a contact within the distance of interest (output.addContactPoint)
    BulletVec normalOnB;    ///< unit normal on the sphere, pointing from the sphere towards the box
    BulletVec pointOnB;     ///< the contact point on the sphere's surface [m]
    float distance = 0.0f;  ///< negative when penetrating [m]
};
/// Bullet 2.88 and later (Godot 3's 2.89 and 3.24 have the same code here).
/// With `tooClose`, a centre outside the box shrunk by its margin but nearer than Bullet's
/// penetration tolerance (1 mm) is answered too, with GJK's own result: Bullet hands such a pair
/// to EPA as well but keeps GJK's result unless EPA's is deeper, which it is only by rounding (in
/// about one case of ten; the test measures it).
/// With `epa`, every case is answered as Bullet does: where GJK cannot (the centre inside the box
/// shrunk by its margin, within the penetration tolerance of it, a simplex that filled up),
/// btGjkEpaPenetrationDepthSolver's answer (btGjkEpaSolver2: EPA on the shapes with their margins,
/// or its own GJK without them) as btGjkPairDetector combines it with GJK's. Bit for bit against
/// the linked Bullet 3.24 in the Bullet tests, these cases included.
BulletGjkContact bulletBoxSphereGjk(const BulletBox& box, const BulletVec& center, float radius,
                                    float maximumDistanceSquared, bool tooClose = false, bool epa = false);

}  // namespace detail
FORESIGHT_NAMESPACE_END
