#include <foresight/bullet_world.h>

#include "bullet_convert.h"

#include <glm/geometric.hpp>

FORESIGHT_NAMESPACE_BEGIN

using bullet_detail::toBt;

BulletScene::BulletScene()
    : mConfiguration(std::make_unique<btDefaultCollisionConfiguration>()),
      mDispatcher(std::make_unique<btCollisionDispatcher>(mConfiguration.get())),
      mBroadphase(std::make_unique<btDbvtBroadphase>()),
      mSolver(std::make_unique<btSequentialImpulseConstraintSolver>()),
      mWorld(std::make_unique<btDiscreteDynamicsWorld>(mDispatcher.get(), mBroadphase.get(), mSolver.get(),
                                                       mConfiguration.get())) {
    // foresight's default gravity, 9.81 m/s^2 (Bullet's default is -10).
    mWorld->setGravity(btVector3(0, -static_cast<btScalar>(kDefaultGravity), 0));
}

BulletScene::~BulletScene() {
    // Objects leave the world before it (and the shapes they use) are destroyed.
    for (const std::unique_ptr<btCollisionObject>& object : mObjects) mWorld->removeCollisionObject(object.get());
}

void BulletScene::addObject(std::unique_ptr<btCollisionShape> shape, const btTransform& transform) {
    auto object = std::make_unique<btCollisionObject>();
    object->setCollisionShape(shape.get());
    object->setWorldTransform(transform);
    object->setCollisionFlags(object->getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
    // Neutral materials: Bullet multiplies the two bodies' restitution and friction (see the
    // class comment), so a simulated body's own values become the effective ones.
    object->setRestitution(btScalar(1));
    object->setFriction(btScalar(1));
    object->setRollingFriction(btScalar(0));
    object->setSpinningFriction(btScalar(0));
    // As a dynamics world files static objects: group StaticFilter, colliding with the rest.
    mWorld->addCollisionObject(object.get(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    mShapes.push_back(std::move(shape));
    mObjects.push_back(std::move(object));
}

Status BulletScene::add(const Plane& plane) {
    if (Status s = validatePlane(plane); s != Status::Ok) return s;
    // Normalised in double as StaticWorld does, then rounded to btScalar.
    const glm::dvec3 normal(static_cast<double>(plane.normal.x), static_cast<double>(plane.normal.y),
                            static_cast<double>(plane.normal.z));
    const double length = glm::length(normal);
    btTransform identity;
    identity.setIdentity();
    addObject(std::make_unique<btStaticPlaneShape>(toBt(normal / length),
                                                   static_cast<btScalar>(static_cast<double>(plane.distance) / length)),
              identity);
    return Status::Ok;
}

Status BulletScene::add(const Sphere& sphere) {
    if (Status s = validateSphere(sphere); s != Status::Ok) return s;
    btTransform transform;
    transform.setIdentity();
    transform.setOrigin(toBt(sphere.center));
    // A btSphereShape is all margin (the margin is the radius): exact.
    addObject(std::make_unique<btSphereShape>(static_cast<btScalar>(sphere.radius)), transform);
    return Status::Ok;
}

Status BulletScene::add(const OrientedBox& box) {
    if (Status s = validateBox(box); s != Status::Ok) return s;
    const Quat q = glm::normalize(box.orientation);
    btTransform transform;
    transform.setIdentity();
    transform.setOrigin(toBt(box.center));
    transform.setRotation(btQuaternion(static_cast<btScalar>(q.x), static_cast<btScalar>(q.y),
                                       static_cast<btScalar>(q.z), static_cast<btScalar>(q.w)));
    auto shape = std::make_unique<btBoxShape>(toBt(box.halfExtents));
    // btBoxShape keeps its outer size when the margin changes; margin 0 makes the edges and
    // corners sharp, like StaticWorld's box (the default 0.04 m rounds them).
    shape->setMargin(btScalar(0));
    addObject(std::move(shape), transform);
    return Status::Ok;
}

Status BulletScene::add(const Triangle& triangle) { return addMesh(std::span<const Triangle>(&triangle, 1)); }

Status BulletScene::addMesh(std::span<const Triangle> triangles) {
    for (const Triangle& t : triangles)
        if (Status s = validateTriangle(t); s != Status::Ok) return s;
    if (triangles.empty()) return Status::Ok;
    auto mesh = std::make_unique<btTriangleMesh>(true, false);
    for (const Triangle& t : triangles) mesh->addTriangle(toBt(t.a), toBt(t.b), toBt(t.c), false);
    auto shape = std::make_unique<btBvhTriangleMeshShape>(mesh.get(), true);
    shape->setMargin(btScalar(0));
    btTransform identity;
    identity.setIdentity();
    mMeshes.push_back(std::move(mesh));
    addObject(std::move(shape), identity);
    return Status::Ok;
}

Status BulletScene::add(const StaticWorld& world) {
    for (const Plane& p : world.planes())
        if (Status s = add(p); s != Status::Ok) return s;
    for (const Sphere& s : world.spheres())
        if (Status status = add(s); status != Status::Ok) return status;
    for (const OrientedBox& b : world.boxes())
        if (Status s = add(b); s != Status::Ok) return s;
    return addMesh(world.triangles());
}

FORESIGHT_NAMESPACE_END
