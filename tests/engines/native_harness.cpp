// foresight_engine_harness CASES.json OUT.json
//
// Runs the "bullet" and "box2d" cases of a case file in the real engines, linked natively, and
// writes the result file (formats: README.md beside this file). Cases for other engines are
// listed in "skipped".
//
//   bullet  Debian's libbullet (btScalar as the linked flavour defines it): one
//           btDiscreteDynamicsWorld per case with btDefaultCollisionConfiguration,
//           btCollisionDispatcher, btDbvtBroadphase and btSequentialImpulseConstraintSolver,
//           every solver setting at its default; stepSimulation(dt, 0), i.e. exactly one
//           internal step of dt per call. The sphere is a btSphereShape with Bullet's inertia
//           for it, deactivation disabled; the boxes are static btBoxShape bodies (mass 0) whose
//           collision margin is the case's rounding (absent: Bullet's default).
//   box2d   Debian's libbox2d (v2.4): one b2World per case, Step(dt, 8, 3). The body is a
//           dynamic circle (bullet off, sleeping not allowed) whose mass is the case's mass
//           and whose rotational inertia is a disc's, m r^2 / 2 (set with SetMassData, so the
//           mass is exactly the case's rather than density * pi r^2 rounded); the boxes are
//           polygons SetAsBox(hx, hy, center, angle) on one static body at the origin. Fixture
//           fields the case does not name (restitutionThreshold, ...) keep Box2D's defaults.
//           Runs in the x-y plane: z components are ignored and written as 0; the angular
//           velocity is [0, 0, w].
//
// A material value or damping the case leaves out keeps the engine's default for a new body or
// fixture. Row 0 is the state once the body is in the world, row k the state after k steps; the
// numbers are the engine's own (float or double) values, printed as the shortest decimal that
// reads back to the same double (which is exactly the engine's value).
#include <box2d/box2d.h>
#include <btBulletDynamicsCommon.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using json = nlohmann::json;
using Vec3 = std::array<double, 3>;

struct BoxSpec {
    Vec3 center{};
    Vec3 half_extents{};
    std::array<double, 4> rotation{0.0, 0.0, 0.0, 1.0};  // x, y, z, w
    std::optional<double> restitution;
    std::optional<double> friction;
    std::optional<double> rounding;  // Bullet: the box's collision margin
};

struct BodySpec {
    double radius = 0.0;
    double mass = 0.0;
    Vec3 position{};
    Vec3 velocity{};
    Vec3 angular_velocity{};
    std::optional<double> linear_damping;
    std::optional<double> angular_damping;
    std::optional<double> restitution;
    std::optional<double> friction;
};

struct CaseSpec {
    json id_value;   // as the case file has it (written back unchanged)
    std::string id;  // for messages
    std::string engine;
    double timestep = 0.0;
    int steps = 0;
    Vec3 gravity{};
    BodySpec body;
    std::vector<BoxSpec> boxes;
};

struct Trajectory {
    std::vector<Vec3> positions;
    std::vector<Vec3> velocities;
    std::vector<Vec3> angular_velocities;
};

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error(message); }

// --- case file -------------------------------------------------------------------------------

const json& member(const json& object, const char* key, const std::string& where) {
    if (!object.is_object() || !object.contains(key)) {
        fail(where + ": missing \"" + key + "\"");
    }
    return object.at(key);
}

double number(const json& value, const std::string& where) {
    if (!value.is_number()) {
        fail(where + ": expected a number");
    }
    return value.get<double>();
}

std::optional<double> optional_number(const json& object, const char* key, const std::string& where) {
    if (!object.contains(key) || object.at(key).is_null()) {
        return std::nullopt;
    }
    return number(object.at(key), where + "." + key);
}

template <std::size_t N>
std::array<double, N> numbers(const json& value, const std::string& where) {
    if (!value.is_array() || value.size() != N) {
        fail(where + ": expected an array of " + std::to_string(N) + " numbers");
    }
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
        out[i] = number(value[i], where);
    }
    return out;
}

CaseSpec parse_case(const json& c, std::size_t index) {
    CaseSpec spec;
    const std::string where0 = "case " + std::to_string(index);
    const json& id = member(c, "id", where0);
    spec.id_value = id;
    spec.id = id.is_string() ? id.get<std::string>() : id.dump();
    const std::string where = "case " + spec.id;
    spec.engine = member(c, "engine", where).get<std::string>();
    if (spec.engine != "bullet" && spec.engine != "box2d") {
        return spec;  // skipped: nothing else is read
    }
    spec.timestep = number(member(c, "timestep", where), where + ".timestep");
    if (!(spec.timestep > 0.0)) {
        fail(where + ": timestep must be positive");
    }
    const double steps = number(member(c, "steps", where), where + ".steps");
    if (!(steps >= 0.0 && steps <= 1e7 && steps == std::floor(steps))) {
        fail(where + ": steps must be a non-negative integer");
    }
    spec.steps = static_cast<int>(steps);
    spec.gravity = numbers<3>(member(c, "gravity", where), where + ".gravity");

    const json& body = member(c, "body", where);
    const std::string bw = where + ".body";
    spec.body.radius = number(member(body, "radius", bw), bw + ".radius");
    spec.body.mass = number(member(body, "mass", bw), bw + ".mass");
    if (!(spec.body.radius > 0.0) || !(spec.body.mass > 0.0)) {
        fail(bw + ": radius and mass must be positive");
    }
    spec.body.position = numbers<3>(member(body, "position", bw), bw + ".position");
    spec.body.velocity = numbers<3>(member(body, "velocity", bw), bw + ".velocity");
    if (body.contains("angular_velocity")) {
        spec.body.angular_velocity = numbers<3>(body.at("angular_velocity"), bw + ".angular_velocity");
    }
    spec.body.linear_damping = optional_number(body, "linear_damping", bw);
    spec.body.angular_damping = optional_number(body, "angular_damping", bw);
    spec.body.restitution = optional_number(body, "restitution", bw);
    spec.body.friction = optional_number(body, "friction", bw);

    if (c.contains("boxes")) {
        const json& boxes = c.at("boxes");
        if (!boxes.is_array()) {
            fail(where + ": boxes must be an array");
        }
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const std::string xw = where + ".boxes[" + std::to_string(i) + "]";
            BoxSpec box;
            box.center = numbers<3>(member(boxes[i], "center", xw), xw + ".center");
            box.half_extents = numbers<3>(member(boxes[i], "half_extents", xw), xw + ".half_extents");
            if (boxes[i].contains("rotation")) {
                box.rotation = numbers<4>(boxes[i].at("rotation"), xw + ".rotation");
            }
            box.restitution = optional_number(boxes[i], "restitution", xw);
            box.friction = optional_number(boxes[i], "friction", xw);
            box.rounding = optional_number(boxes[i], "rounding", xw);
            if (box.rounding) {
                const double smallest = std::min({box.half_extents[0], box.half_extents[1], box.half_extents[2]});
                if (!(*box.rounding >= 0.0 && *box.rounding <= smallest)) {
                    fail(xw + ".rounding: must be from 0 to the smallest half extent");
                }
                if (spec.engine == "box2d" && *box.rounding > 0.0) {
                    fail(xw + ".rounding: must be 0: box2d builds sharp boxes here");
                }
            }
            spec.boxes.push_back(box);
        }
    }
    return spec;
}

// --- Bullet ----------------------------------------------------------------------------------

btScalar bt(double value) { return static_cast<btScalar>(value); }
btVector3 bt(const Vec3& v) { return {bt(v[0]), bt(v[1]), bt(v[2])}; }
Vec3 from_bt(const btVector3& v) {
    return {static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z())};
}

std::string bullet_version() {
    const int version = btGetVersion();
    std::string text = std::to_string(version / 100) + "." + std::to_string(version % 100);
#ifdef BT_USE_DOUBLE_PRECISION
    text += " (btScalar double)";
#else
    text += " (btScalar float)";
#endif
    return text;
}

Trajectory run_bullet(const CaseSpec& spec) {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(bt(spec.gravity));

    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;

    for (const BoxSpec& box : spec.boxes) {
        shapes.push_back(std::make_unique<btBoxShape>(bt(box.half_extents)));
        // The rounding is the collision margin (the outer size kept); absent, the constructor's
        // default: 0.04 m, or a tenth of the smallest half extent if less.
        if (box.rounding) {
            shapes.back()->setMargin(bt(*box.rounding));
        }
        const btQuaternion rotation(bt(box.rotation[0]), bt(box.rotation[1]), bt(box.rotation[2]), bt(box.rotation[3]));
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(0), nullptr, shapes.back().get());
        info.m_startWorldTransform = btTransform(rotation, bt(box.center));
        if (box.restitution) {
            info.m_restitution = bt(*box.restitution);
        }
        if (box.friction) {
            info.m_friction = bt(*box.friction);
        }
        bodies.push_back(std::make_unique<btRigidBody>(info));
        world.addRigidBody(bodies.back().get());
    }

    shapes.push_back(std::make_unique<btSphereShape>(bt(spec.body.radius)));
    btCollisionShape* sphere = shapes.back().get();
    const btScalar mass = bt(spec.body.mass);
    btVector3 inertia(0, 0, 0);
    sphere->calculateLocalInertia(mass, inertia);
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, sphere, inertia);
    info.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), bt(spec.body.position));
    if (spec.body.linear_damping) {
        info.m_linearDamping = bt(*spec.body.linear_damping);
    }
    if (spec.body.angular_damping) {
        info.m_angularDamping = bt(*spec.body.angular_damping);
    }
    if (spec.body.restitution) {
        info.m_restitution = bt(*spec.body.restitution);
    }
    if (spec.body.friction) {
        info.m_friction = bt(*spec.body.friction);
    }
    bodies.push_back(std::make_unique<btRigidBody>(info));
    btRigidBody* body = bodies.back().get();
    body->setLinearVelocity(bt(spec.body.velocity));
    body->setAngularVelocity(bt(spec.body.angular_velocity));
    body->setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(body);

    Trajectory out;
    const auto record = [&] {
        out.positions.push_back(from_bt(body->getWorldTransform().getOrigin()));
        out.velocities.push_back(from_bt(body->getLinearVelocity()));
        out.angular_velocities.push_back(from_bt(body->getAngularVelocity()));
    };
    record();
    const btScalar dt = bt(spec.timestep);
    for (int step = 0; step < spec.steps; ++step) {
        // maxSubSteps = 0: one internal step of exactly dt, no interpolation of motion states.
        world.stepSimulation(dt, 0);
        record();
    }

    for (auto& b : bodies) {
        world.removeRigidBody(b.get());
    }
    return out;
}

// --- Box2D -----------------------------------------------------------------------------------

float f32(double value) { return static_cast<float>(value); }

// Box2D 2.4.1 still says 2.4.0 in b2_version: the package's version (from CMake) comes first.
std::string box2d_version() {
    const std::string library = std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
                                std::to_string(b2_version.revision);
#ifdef FORESIGHT_BOX2D_PACKAGE_VERSION
    const std::string package = FORESIGHT_BOX2D_PACKAGE_VERSION;
    if (package != library) {
        return package + " (b2_version " + library + ")";
    }
#endif
    return library;
}

Trajectory run_box2d(const CaseSpec& spec) {
    b2World world(b2Vec2(f32(spec.gravity[0]), f32(spec.gravity[1])));

    if (!spec.boxes.empty()) {
        b2BodyDef ground_def;  // static, at the origin
        b2Body* ground = world.CreateBody(&ground_def);
        for (std::size_t i = 0; i < spec.boxes.size(); ++i) {
            const BoxSpec& box = spec.boxes[i];
            const auto& q = box.rotation;
            if (std::abs(q[0]) > 1e-12 || std::abs(q[1]) > 1e-12) {
                fail("case " + spec.id + ".boxes[" + std::to_string(i) +
                     "]: box2d needs a rotation about z only (x = y = 0)");
            }
            const double angle = 2.0 * std::atan2(q[2], q[3]);
            b2PolygonShape shape;
            shape.SetAsBox(f32(box.half_extents[0]), f32(box.half_extents[1]),
                           b2Vec2(f32(box.center[0]), f32(box.center[1])), f32(angle));
            b2FixtureDef fixture;
            fixture.shape = &shape;
            if (box.restitution) {
                fixture.restitution = f32(*box.restitution);
            }
            if (box.friction) {
                fixture.friction = f32(*box.friction);
            }
            ground->CreateFixture(&fixture);
        }
    }

    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(f32(spec.body.position[0]), f32(spec.body.position[1]));
    def.linearVelocity.Set(f32(spec.body.velocity[0]), f32(spec.body.velocity[1]));
    def.angularVelocity = f32(spec.body.angular_velocity[2]);
    if (spec.body.linear_damping) {
        def.linearDamping = f32(*spec.body.linear_damping);
    }
    if (spec.body.angular_damping) {
        def.angularDamping = f32(*spec.body.angular_damping);
    }
    def.bullet = false;
    def.allowSleep = false;
    b2Body* body = world.CreateBody(&def);
    body->SetSleepingAllowed(false);

    b2CircleShape circle;
    circle.m_radius = f32(spec.body.radius);
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = 1.0f;  // replaced by SetMassData below
    if (spec.body.restitution) {
        fixture.restitution = f32(*spec.body.restitution);
    }
    if (spec.body.friction) {
        fixture.friction = f32(*spec.body.friction);
    }
    body->CreateFixture(&fixture);
    b2MassData mass;
    mass.mass = f32(spec.body.mass);
    mass.center.SetZero();
    mass.I = mass.mass * (0.5f * circle.m_radius * circle.m_radius);
    body->SetMassData(&mass);

    Trajectory out;
    const auto record = [&] {
        const b2Vec2 p = body->GetPosition();
        const b2Vec2 v = body->GetLinearVelocity();
        out.positions.push_back({static_cast<double>(p.x), static_cast<double>(p.y), 0.0});
        out.velocities.push_back({static_cast<double>(v.x), static_cast<double>(v.y), 0.0});
        out.angular_velocities.push_back({0.0, 0.0, static_cast<double>(body->GetAngularVelocity())});
    };
    record();
    const float dt = f32(spec.timestep);
    for (int step = 0; step < spec.steps; ++step) {
        world.Step(dt, 8, 3);
        record();
    }
    return out;
}

// --- result file -----------------------------------------------------------------------------

// The shortest decimal that reads back to the same double (the engine's float widens exactly).
void write_number(std::ostream& os, double value) {
    if (!std::isfinite(value)) {
        os << "null";
        return;
    }
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    os.write(buffer.data(), result.ptr - buffer.data());
}

void write_rows(std::ostream& os, const std::vector<Vec3>& rows) {
    os << '[';
    for (std::size_t i = 0; i < rows.size(); ++i) {
        os << (i == 0 ? "[" : ", [");
        write_number(os, rows[i][0]);
        os << ", ";
        write_number(os, rows[i][1]);
        os << ", ";
        write_number(os, rows[i][2]);
        os << ']';
    }
    os << ']';
}

int run(const char* cases_path, const char* out_path) {
    std::ifstream in(cases_path);
    if (!in) {
        fail(std::string("cannot read the case file ") + cases_path);
    }
    json document;
    try {
        in >> document;
    } catch (const json::exception& e) {
        fail(std::string(cases_path) + ": " + e.what());
    }
    const json& cases = member(document, "cases", cases_path);
    if (!cases.is_array()) {
        fail(std::string(cases_path) + ": \"cases\" must be an array");
    }

    std::vector<CaseSpec> specs;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        specs.push_back(parse_case(cases[i], i));
    }

    std::ostringstream results;
    std::vector<std::string> skipped;
    bool ran_bullet = false;
    bool ran_box2d = false;
    bool first = true;
    for (const CaseSpec& spec : specs) {
        Trajectory trajectory;
        if (spec.engine == "bullet") {
            trajectory = run_bullet(spec);
            ran_bullet = true;
        } else if (spec.engine == "box2d") {
            trajectory = run_box2d(spec);
            ran_box2d = true;
        } else {
            skipped.push_back(spec.id_value.dump());
            continue;
        }
        results << (first ? "" : ",\n") << "{\"id\": " << spec.id_value.dump()
                << ", \"engine\": " << json(spec.engine).dump() << ",\n \"positions\": ";
        write_rows(results, trajectory.positions);
        results << ",\n \"velocities\": ";
        write_rows(results, trajectory.velocities);
        results << ",\n \"angular_velocities\": ";
        write_rows(results, trajectory.angular_velocities);
        results << '}';
        first = false;
    }

    std::ofstream out(out_path);
    if (!out) {
        fail(std::string("cannot write ") + out_path);
    }
    out << "{\"engine_versions\": {";
    if (ran_bullet) {
        out << "\"bullet\": " << json(bullet_version()).dump();
    }
    if (ran_box2d) {
        out << (ran_bullet ? ", " : "") << "\"box2d\": " << json(box2d_version()).dump();
    }
    out << "},\n\"skipped\": [";
    for (std::size_t i = 0; i < skipped.size(); ++i) {
        out << (i == 0 ? "" : ", ") << skipped[i];
    }
    out << "],\n\"results\": [\n" << results.str() << "\n]}\n";
    out.close();
    if (!out) {
        fail(std::string("error writing ") + out_path);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: foresight_engine_harness CASES.json OUT.json\n";
        return 2;
    }
    try {
        return run(argv[1], argv[2]);
    } catch (const std::exception& e) {
        std::cerr << "foresight_engine_harness: " << e.what() << '\n';
        return 1;
    }
}
