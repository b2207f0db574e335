/// hello_bullet.cpp: a game already on Bullet Physics predicts a grenade against its own world.
///
/// The game has a btDiscreteDynamicsWorld (a floor, a wall, a barrel, a crate that falls onto
/// the floor). One line makes it a foresight collision world:
///
///     foresight::BulletWorld world(dynamicsWorld);
///
/// and the grenade's bounces come from the game's own collision shapes. Build: see
/// CMakeLists.txt beside this file. Exits non-zero if a prediction fails or looks wrong.
///
/// Conventions (docs/ARCHITECTURE.md): metres, seconds, radians; +Y up, +Z forward; Bullet's
/// world is used as it is, so the game must use the same axes and units.

#include <foresight/bullet_world.h>
#include <foresight/foresight.h>

#include <btBulletDynamicsCommon.h>

#include <array>
#include <cstdio>
#include <memory>
#include <vector>

namespace {

// What any Bullet game already has: a dynamics world and its bodies.
struct Game {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btDefaultMotionState>> motionStates;
    std::vector<std::unique_ptr<btRigidBody>> bodies;

    Game() { world.setGravity(btVector3(0, -9.81f, 0)); }
    ~Game() {
        for (auto& body : bodies) world.removeRigidBody(body.get());
    }

    btRigidBody* addBody(std::unique_ptr<btCollisionShape> shape, const btVector3& position, btScalar mass) {
        btTransform transform;
        transform.setIdentity();
        transform.setOrigin(position);
        btVector3 inertia(0, 0, 0);
        if (mass > 0) shape->calculateLocalInertia(mass, inertia);
        motionStates.push_back(std::make_unique<btDefaultMotionState>(transform));
        btRigidBody::btRigidBodyConstructionInfo info(mass, motionStates.back().get(), shape.get(), inertia);
        bodies.push_back(std::make_unique<btRigidBody>(info));
        world.addRigidBody(bodies.back().get());
        shapes.push_back(std::move(shape));
        return bodies.back().get();
    }
};

void printVec(const char* label, foresight::RVec3 v) {
    std::printf("%s(%.3f, %.3f, %.3f)", label, static_cast<double>(v.x) + 0.0, static_cast<double>(v.y) + 0.0,
                static_cast<double>(v.z) + 0.0);
}

// Predicts one grenade and prints it; false if the prediction failed or left the arena.
bool throwGrenade(const foresight::CollisionWorld& world, float radius) {
    using namespace foresight;
    ProjectileSettings settings;  // Exact, restitution 0.5, gravity 9.81 m/s^2 along -Y
    settings.friction = 0.3f;
    settings.radius = radius;
    const RVec3 hand(0, 1.5f, 0);
    const Vec3 velocity(0, 4, 12);  // thrown forward at the wall 8 m ahead
    const float fuse = 3.0f;
    std::array<TrajectoryPoint, 512> points;  // caller-owned: no allocation per prediction
    ProjectileResult grenade;
    if (Status status = predictProjectile(hand, velocity, fuse, settings, &world, points, grenade);
        status != Status::Ok) {
        std::fprintf(stderr, "predictProjectile failed: %s\n", statusMessage(status));
        return false;
    }
    std::printf("grenade (radius %.2f m): %u bounces, ", static_cast<double>(radius), grenade.bounces);
    printVec("explodes at ", grenade.position);
    std::printf("%s\n", grenade.atRest ? ", at rest" : "");
    for (std::size_t i = 0; i < grenade.trajectorySize; ++i)
        if (points[i].event == TrajectoryEvent::Bounce) {
            std::printf("  bounce at t = %.3f s ", static_cast<double>(points[i].time));
            printVec("at ", points[i].position);
            std::printf(", normal (%.2f, %.2f, %.2f)\n", static_cast<double>(points[i].normal.x) + 0.0,
                        static_cast<double>(points[i].normal.y) + 0.0, static_cast<double>(points[i].normal.z) + 0.0);
        }
    // It must have bounced off the wall (z = 7.75 m, its front face) and stayed on this side.
    const double z = static_cast<double>(grenade.position.z);
    const double y = static_cast<double>(grenade.position.y);
    if (grenade.bounces == 0 || z > 7.75 - static_cast<double>(radius) + 1e-3 ||
        y < static_cast<double>(radius) - 1e-3) {
        std::fprintf(stderr, "unexpected grenade path\n");
        return false;
    }
    return true;
}

}  // namespace

int main() {
    Game game;
    // The level: a floor, a 3 m wall 8 m ahead (a btBoxShape with Bullet's default 4 cm
    // margin), a barrel (a cylinder: Bullet's own convex cast answers for it) and a crate that
    // the game has let fall onto the floor.
    game.addBody(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), btScalar(0)), btVector3(0, 0, 0), 0);
    game.addBody(std::make_unique<btBoxShape>(btVector3(6, 1.5f, 0.25f)), btVector3(0, 1.5f, 8), 0);
    game.addBody(std::make_unique<btCylinderShape>(btVector3(0.4f, 0.6f, 0.4f)), btVector3(3, 0.6f, 4), 0);
    game.addBody(std::make_unique<btBoxShape>(btVector3(0.5f, 0.5f, 0.5f)), btVector3(-2, 3, 5), 10);
    for (int i = 0; i < 120; ++i) game.world.stepSimulation(btScalar(1) / 60, 1, btScalar(1) / 60);

    // The one line: the game's world as a foresight collision world.
    const foresight::BulletWorld world(game.world);

    bool ok = throwGrenade(world, 0.0f);    // a point (Bullet ray tests)
    ok = throwGrenade(world, 0.05f) && ok;  // a 5 cm ball (Bullet sphere sweeps)
    return ok ? 0 : 1;
}
