#include "scenario.h"

#include "json_input.h"

#include "obj_mesh.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <set>
#include <string_view>

#ifdef FORESIGHT_CLI_WITH_EMBREE
#include <foresight/embree_world.h>

#include <cctype>
#include <memory>
#endif

namespace foresight_cli {

using foresight::Status;

const char* projectileMethodName(foresight::ProjectileMethod method) {
    switch (method) {
        case foresight::ProjectileMethod::Stepped:
            return "stepped";
        case foresight::ProjectileMethod::Exact:
            return "exact";
        case foresight::ProjectileMethod::Engine:
            return "engine";
    }
    return "exact";
}

const char* modelName(Model model) {
    switch (model) {
        case Model::Linear:
            return "linear";
        case Model::Accelerated:
            return "accelerated";
        case Model::Orientation:
            return "orientation";
        case Model::Projectile:
            return "projectile";
        case Model::Vehicle:
            return "vehicle";
        case Model::DeadReckoning:
            return "dead_reckoning";
    }
    return "?";
}

const char* eventName(foresight::TrajectoryEvent event) {
    switch (event) {
        case foresight::TrajectoryEvent::Start:
            return "start";
        case foresight::TrajectoryEvent::Step:
            return "step";
        case foresight::TrajectoryEvent::Bounce:
            return "bounce";
        case foresight::TrajectoryEvent::Rest:
            return "rest";
        case foresight::TrajectoryEvent::Hit:
            return "hit";
        case foresight::TrajectoryEvent::End:
            return "end";
    }
    return "?";
}

// ---------------------------------------------------------------------------------------------
// Validation

namespace {

void addShape(foresight::StaticWorld& world, const auto& shape, const foresight::SurfaceMaterial& material,
              const std::string& path, Diagnostics& d) {
    const Status status = world.add(shape, material);
    if (status != Status::Ok) d.error(path, foresight::statusMessage(status));
}

// A shape's own "restitution" (0 to 1) and "friction" (>= 0), both optional: the surface's
// material, which the engine method combines with the projectile's (docs/scenario-format.md).
bool readMaterial(Fields& fields, foresight::SurfaceMaterial& material, Diagnostics& d) {
    bool ok = true;
    if (fields.floatNumber("restitution", false, material.restitution) &&
        !(material.restitution >= 0.0f && material.restitution <= 1.0f)) {
        d.error(fields.at("restitution"), "expected a restitution in [0, 1]");
        ok = false;
    }
    if (fields.floatNumber("friction", false, material.friction) && !(material.friction >= 0.0f)) {
        d.error(fields.at("friction"), "expected a friction >= 0");
        ok = false;
    }
    return ok;
}

#ifdef FORESIGHT_CLI_WITH_EMBREE
// With Embree, `world.meshes[]` go into an EmbreeWorld (Scenario::meshWorld, which also gets a
// copy of the primitives) instead of StaticWorld triangles.
foresight::EmbreeWorld& meshWorldFor(std::unique_ptr<foresight::CollisionWorld>& slot) {
    if (!slot) slot = std::make_unique<foresight::EmbreeWorld>();
    return static_cast<foresight::EmbreeWorld&>(*slot);  // the only kind this file puts there
}

bool isGltf(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".gltf" || extension == ".glb";
}
#endif

void buildWorld(const Json& value, const std::filesystem::path& baseDirectory, foresight::StaticWorld& world,
                [[maybe_unused]] std::unique_ptr<foresight::CollisionWorld>& meshWorld, Diagnostics& d) {
    if (!expectObject(value, "world", d, "{\"planes\", \"boxes\", \"spheres\", \"triangles\", \"meshes\"}")) return;
    Fields fields(value, "world", d);

    forEachElement(fields, "planes", [&](const Json& item, const std::string& path) {
        if (!expectObject(item, path, d, "{\"normal\", \"distance\"}")) return;
        Fields plane(item, path, d);
        foresight::Plane shape;
        foresight::SurfaceMaterial material;
        double distance = 0;
        const bool okNormal = plane.vector("normal", true, shape.normal);
        const bool okDistance = plane.number("distance", true, distance);
        const bool okMaterial = readMaterial(plane, material, d);
        plane.finish();
        if (!okNormal || !okDistance || !okMaterial) return;
        shape.distance = static_cast<foresight::Real>(distance);
        const Status status = foresight::validatePlane(shape);
        if (status != Status::Ok) {
            d.error(status == Status::ZeroVector ? plane.at("normal") : path, foresight::statusMessage(status));
            return;
        }
        addShape(world, shape, material, path, d);
    });

    forEachElement(fields, "boxes", [&](const Json& item, const std::string& path) {
        if (!expectObject(item, path, d, "{\"center\", \"half_extents\", \"orientation\"}")) return;
        Fields box(item, path, d);
        foresight::OrientedBox shape;
        foresight::SurfaceMaterial material;
        const bool okCenter = box.position("center", true, shape.center);
        const bool okExtents = box.vector("half_extents", true, shape.halfExtents);
        const bool okOrientation = box.quaternion("orientation", true, shape.orientation);
        const bool okMaterial = readMaterial(box, material, d);
        box.floatNumber("rounding", false, shape.rounding);
        box.finish();
        if (okExtents) {
            // The half extents alone, so that their problem is named even if others fail.
            foresight::OrientedBox probe;
            probe.halfExtents = shape.halfExtents;
            const Status status = foresight::validateBox(probe);
            if (status != Status::Ok) {
                d.error(box.at("half_extents"),
                        std::string(foresight::statusMessage(status)) + ": each half extent must be > 0");
                return;
            }
        }
        if (!okCenter || !okExtents || !okOrientation || !okMaterial) return;
        const Status status = foresight::validateBox(shape);
        if (status != Status::Ok) {
            d.error(path, foresight::statusMessage(status));
            return;
        }
        addShape(world, shape, material, path, d);
    });

    forEachElement(fields, "spheres", [&](const Json& item, const std::string& path) {
        if (!expectObject(item, path, d, "{\"center\", \"radius\"}")) return;
        Fields sphere(item, path, d);
        foresight::Sphere shape;
        foresight::SurfaceMaterial material;
        const bool okCenter = sphere.position("center", true, shape.center);
        const bool okRadius = sphere.floatNumber("radius", true, shape.radius);
        const bool okMaterial = readMaterial(sphere, material, d);
        sphere.finish();
        if (okRadius) {
            foresight::Sphere probe;
            probe.radius = shape.radius;
            const Status status = foresight::validateSphere(probe);
            if (status != Status::Ok) {
                d.error(sphere.at("radius"),
                        std::string(foresight::statusMessage(status)) + ": a sphere's radius must be > 0");
                return;
            }
        }
        if (!okCenter || !okRadius || !okMaterial) return;
        const Status status = foresight::validateSphere(shape);
        if (status != Status::Ok) {
            d.error(path, foresight::statusMessage(status));
            return;
        }
        addShape(world, shape, material, path, d);
    });

    forEachElement(fields, "triangles", [&](const Json& item, const std::string& path) {
        if (!item.is_array() || item.size() != 3) {
            d.error(path, "expected 3 vertices [[x, y, z], [x, y, z], [x, y, z]]");
            return;
        }
        foresight::Triangle shape;
        const bool okA = toPosition(item[0], path + "[0]", d, shape.a);
        const bool okB = toPosition(item[1], path + "[1]", d, shape.b);
        const bool okC = toPosition(item[2], path + "[2]", d, shape.c);
        if (!okA || !okB || !okC) return;
        const Status status = foresight::validateTriangle(shape);
        if (status != Status::Ok) {
            d.error(path, foresight::statusMessage(status));
            return;
        }
        addShape(world, shape, foresight::SurfaceMaterial{}, path, d);
    });

    forEachElement(fields, "meshes", [&](const Json& item, const std::string& path) {
        if (!expectObject(item, path, d, "{\"file\"}")) return;
        Fields mesh(item, path, d);
        std::string file;
        const bool okFile = mesh.string("file", true, file);
        mesh.finish();
        if (!okFile) return;
        const std::string filePath = mesh.at("file");
        if (file.empty() || file.find('\0') != std::string::npos) {
            d.error(filePath, "expected a file name");
            return;
        }
        std::filesystem::path resolved(file);
        if (resolved.is_relative()) resolved = baseDirectory / resolved;
        const std::string where = resolved.string() == file ? std::string() : " (" + resolved.string() + ")";
#ifdef FORESIGHT_CLI_WITH_EMBREE
        if (isGltf(resolved)) {
            const foresight::MeshLoadResult gltf = meshWorldFor(meshWorld).loadGltf(resolved);
            if (!gltf.ok) {
                // The loader's message starts with the path, already in ours.
                std::string message = gltf.error;
                const std::string prefix = resolved.string() + ": ";
                if (message.compare(0, prefix.size(), prefix) == 0) message.erase(0, prefix.size());
                d.error(filePath, "cannot load " + jsonQuoted(file) + where + ": " + message);
            } else if (gltf.report.degenerateTriangles > 0) {
                d.warning(filePath, jsonQuoted(file) + ": skipped " + std::to_string(gltf.report.degenerateTriangles) +
                                        " degenerate triangle(s) (the first is triangle " +
                                        std::to_string(gltf.report.firstDegenerateTriangle + 1) + ")");
            }
            return;
        }
#endif
        ObjMesh loaded;
        std::string reason;
        if (!loadObjMesh(resolved, loaded, reason)) {
            d.error(filePath, "cannot load " + jsonQuoted(file) + where + ": " + reason);
            return;
        }
        for (const auto& warning : loaded.warnings) d.warning(filePath, jsonQuoted(file) + ": " + warning);
        if (loaded.degenerateTriangles > 0) {
            d.warning(filePath, jsonQuoted(file) + ": skipped " + std::to_string(loaded.degenerateTriangles) +
                                    " degenerate triangle(s) (the first in face " +
                                    std::to_string(loaded.firstDegenerateFace) + ")");
        }
#ifdef FORESIGHT_CLI_WITH_EMBREE
        std::vector<foresight::RVec3> vertices;
        std::vector<std::uint32_t> indices;
        vertices.reserve(3 * loaded.triangles.size());
        for (const auto& triangle : loaded.triangles) {
            for (const auto& vertex : {triangle.a, triangle.b, triangle.c}) {
                indices.push_back(static_cast<std::uint32_t>(vertices.size()));
                vertices.push_back(vertex);
            }
        }
        foresight::MeshReport report;
        if (meshWorldFor(meshWorld).addMesh(vertices, indices, &report) != Status::Ok)
            d.error(filePath, "cannot load " + jsonQuoted(file) + where + ": " + report.error);
#else
        for (const auto& triangle : loaded.triangles) addShape(world, triangle, foresight::SurfaceMaterial{}, filePath, d);
#endif
    });

    fields.finish();
}

bool readFrame(Fields& fields, foresight::AngularFrame& frame) {
    std::string name;
    if (!fields.string("frame", false, name)) return false;
    if (name == "body") {
        frame = foresight::AngularFrame::Body;
    } else if (name == "world") {
        frame = foresight::AngularFrame::World;
    } else {
        fields.diagnostics().error(fields.at("frame"),
                                   "unknown frame " + jsonQuoted(name) + " (expected \"body\" or \"world\")");
        return false;
    }
    return true;
}

/// A projectile setting checked alone by the library's validator (the defaults are valid), so
/// that every bad setting is named, not only the first.
template <class Set>
void checkProjectileSetting(Fields& fields, const char* key, Set&& set) {
    foresight::ProjectileSettings probe;
    set(probe);
    const Status status = foresight::validateProjectileSettings(probe);
    if (status != Status::Ok) {
        fields.diagnostics().error(fields.at(key), foresight::statusMessage(status));
    }
}

/// Reads a name among `names` (JSON strings) into `out`; an unknown one is reported with the list.
template <class Enum, std::size_t N>
void readEnumName(Fields& f, const char* key, const std::pair<const char*, Enum> (&names)[N], Enum& out) {
    std::string name;
    if (!f.string(key, false, name)) return;
    std::string expected;
    for (const auto& [text, value] : names) {
        if (name == text) {
            out = value;
            return;
        }
        expected += std::string(expected.empty() ? "" : ", ") + "\"" + text + "\"";
    }
    f.diagnostics().error(f.at(key), "unknown value " + jsonQuoted(name) + " (expected one of " + expected + ")");
}

/// `engine`: a named profile (or "custom") and overrides of its fields (docs/scenario-format.md).
void readEngine(Fields& parent, foresight::ProjectileSettings& settings) {
    const Json* object = parent.get("engine", true);
    if (object == nullptr) return;
    if (!object->is_object()) {
        parent.diagnostics().error(parent.at("engine"), "expected an object, got " + typeName(*object));
        return;
    }
    Fields f(*object, parent.at("engine"), parent.diagnostics());
    using foresight::PhysicsEngine;
    static const std::pair<const char*, PhysicsEngine> profiles[] = {
        {"jolt", PhysicsEngine::Jolt},     {"physx", PhysicsEngine::PhysX},
        {"rapier", PhysicsEngine::Rapier}, {"bullet", PhysicsEngine::Bullet},
        {"godot3", PhysicsEngine::Godot3}, {"godot3-bullet", PhysicsEngine::Godot3Bullet},
        {"box2d", PhysicsEngine::Box2D},   {"custom", PhysicsEngine::Custom},
        {"ammo", PhysicsEngine::Bullet}};
    PhysicsEngine engine = PhysicsEngine::Custom;
    std::string name;
    if (!f.string("profile", true, name)) {
        f.finish();
        return;
    }
    bool known = false;
    for (const auto& [text, value] : profiles)
        if (name == text) {
            engine = value;
            known = true;
        }
    if (!known) {
        f.diagnostics().error(f.at("profile"), "unknown profile " + jsonQuoted(name) +
                                                   " (expected \"jolt\", \"physx\", \"rapier\", \"bullet\", \"ammo\", "
                                                   "\"godot3\", \"godot3-bullet\", \"box2d\" or \"custom\")");
    }
    foresight::EngineProfile profile = name == "ammo" ? foresight::ammoJsProfile() : foresight::engineProfile(engine);
    f.positive("timestep", false, true, profile.timestep);
    f.positive("linear_damping", false, false, profile.linearDamping);
    f.positive("added_linear_damping", false, false, profile.addedLinearDamping);
    f.positive("angular_damping", false, false, profile.angularDamping);
    f.integer("substeps", false, 1u, 64u, profile.substeps);
    using foresight::CombineRule;
    static const std::pair<const char*, foresight::DampingOrder> orders[] = {
        {"gravity_then_damping", foresight::DampingOrder::GravityThenDamping},
        {"damping_then_gravity", foresight::DampingOrder::DampingThenGravity}};
    readEnumName(f, "order", orders, profile.order);
    static const std::pair<const char*, foresight::DampingLaw> laws[] = {
        {"none", foresight::DampingLaw::None},
        {"linear_clamped", foresight::DampingLaw::LinearClamped},
        {"rational", foresight::DampingLaw::Rational},
        {"power", foresight::DampingLaw::Power}};
    readEnumName(f, "damping", laws, profile.damping);
    static const std::pair<const char*, foresight::FirstStepRule> firsts[] = {
        {"normal", foresight::FirstStepRule::Normal},
        {"no_gravity", foresight::FirstStepRule::NoGravity},
        {"damping_only", foresight::FirstStepRule::DampingOnly}};
    readEnumName(f, "first_step", firsts, profile.firstStep);
    f.positive("restitution_threshold", false, false, profile.restitutionThreshold);
    static const std::pair<const char*, foresight::RestitutionBase> bases[] = {
        {"step_start", foresight::RestitutionBase::StepStart},
        {"after_gravity", foresight::RestitutionBase::AfterGravity}};
    readEnumName(f, "restitution_base", bases, profile.restitutionBase);
    static const std::pair<const char*, CombineRule> rules[] = {{"average", CombineRule::Average},
                                                                {"min", CombineRule::Min},
                                                                {"max", CombineRule::Max},
                                                                {"multiply", CombineRule::Multiply},
                                                                {"geometric_mean", CombineRule::GeometricMean},
                                                                {"sum_clamped", CombineRule::SumClamped}};
    readEnumName(f, "restitution_combine", rules, profile.restitutionCombine);
    readEnumName(f, "friction_combine", rules, profile.frictionCombine);
    static const std::pair<const char*, foresight::ContactMethod> contacts[] = {
        {"speculative", foresight::ContactMethod::Speculative}, {"penetration", foresight::ContactMethod::Penetration}};
    readEnumName(f, "contact", contacts, profile.contact);
    f.positive("contact_distance", false, false, profile.contactDistance);
    f.positive("penetration_slop", false, false, profile.penetrationSlop);
    // A fraction: from 0 to 1.
    const auto fraction = [&f](const char* field, float& value) {
        if (f.positive(field, false, false, value) && value > 1.0f)
            f.diagnostics().error(f.at(field), "must be in [0, 1] (got " + shortNumber(value) + ")");
    };
    fraction("position_correction", profile.positionCorrection);
    f.boolean("correction_is_velocity", false, profile.correctionIsVelocity);
    fraction("split_impulse_correction", profile.splitImpulseCorrection);
    fraction("friction_warm_start", profile.frictionWarmStart);
    f.positive("max_linear_speed", false, true, profile.maxLinearSpeed);
    f.positive("max_step_distance", false, true, profile.maxStepDistance);
    f.boolean("planar", false, profile.planar);
    f.boolean("rotates", false, profile.rotates);
    f.boolean("triangle_mesh", false, profile.triangleMesh);
    f.finish();
    if (profile.timestep > 1.0f || profile.timestep < 1e-5f) {
        f.diagnostics().error(f.at("timestep"), "must be in [1e-05, 1] s (got " + shortNumber(profile.timestep) + ")");
    }
    settings.engine = profile;
}

void readProjectile(Fields& f, Prediction& p, const foresight::Vec3& gravity) {
    auto& settings = p.projectile;
    settings.gravity = gravity;
    f.position("position", true, p.position);
    f.vector("velocity", true, p.velocity);
    const bool okTime = f.time("time", true, p.time);

    std::string method;
    if (f.string("method", false, method)) {
        if (method == "exact") {
            settings.method = foresight::ProjectileMethod::Exact;
        } else if (method == "stepped") {
            settings.method = foresight::ProjectileMethod::Stepped;
        } else if (method == "engine") {
            settings.method = foresight::ProjectileMethod::Engine;
            readEngine(f, settings);
        } else {
            f.diagnostics().error(f.at("method"),
                                  "unknown method " + jsonQuoted(method) +
                                      " for a projectile (expected \"exact\", \"stepped\" or \"engine\")");
        }
    }
    const bool okStep = f.floatNumber("step", false, settings.step);
    if (okStep) checkProjectileSetting(f, "step", [&](auto& s) { s.step = settings.step; });
    if (f.floatNumber("restitution", false, settings.restitution)) {
        checkProjectileSetting(f, "restitution", [&](auto& s) { s.restitution = settings.restitution; });
    }
    if (f.floatNumber("friction", false, settings.friction)) {
        checkProjectileSetting(f, "friction", [&](auto& s) { s.friction = settings.friction; });
    }
    if (f.floatNumber("radius", false, settings.radius)) {
        checkProjectileSetting(f, "radius", [&](auto& s) { s.radius = settings.radius; });
    }
    std::int64_t maxBounces = 0;
    const bool hasMaxBounces = f.integer("max_bounces", false, 0, foresight::kUnlimitedBounces, maxBounces);
    bool stopAtFirstHit = false;
    f.boolean("stop_at_first_hit", false, stopAtFirstHit);
    if (stopAtFirstHit) {
        settings.maxBounces = 0;
    } else if (hasMaxBounces) {
        settings.maxBounces = static_cast<std::uint32_t>(maxBounces);
    }
    f.boolean("trajectory", false, p.trajectory);

    // The work cap, checked before anything is allocated for the trajectory.
    const float step = foresight::settingsStep(settings);
    if (okTime && (okStep || f.get("step", false) == nullptr) && step > 0.0f && std::isfinite(step)) {
        const double quotient = static_cast<double>(p.time) / static_cast<double>(step);
        const bool tooMany = quotient > 2.0 * static_cast<double>(settings.maxSteps) ||
                             foresight::steppedStepCount(p.time, step) > settings.maxSteps;
        if (tooMany) {
            f.diagnostics().error(p.path, std::string(foresight::statusMessage(Status::TooManySteps)) +
                                              ": time / step = " + shortNumber(quotient) + " steps, the cap is " +
                                              std::to_string(settings.maxSteps));
        }
    }
}

void readVehicle(Fields& f, Prediction& p) {
    f.position("position", true, p.position);
    f.vector("velocity", true, p.velocity);
    f.quaternion("orientation", true, p.orientation);
    f.vector("angular_velocity", true, p.angularVelocity);
    readFrame(f, p.frame);
    f.time("time", true, p.time);
    std::string method;
    if (f.string("method", false, method)) {
        if (method == "exact") {
            p.vehicleIterative = false;
        } else if (method == "iterative") {
            p.vehicleIterative = true;
        } else {
            f.diagnostics().error(f.at("method"), "unknown method " + jsonQuoted(method) +
                                                      " for a vehicle (expected \"exact\" or \"iterative\")");
        }
    }
    std::int64_t iterations = 0;
    if (f.integer("iterations", false, 1, foresight::kMaxVehicleIterations, iterations)) {
        p.iterations = static_cast<int>(iterations);
    }
}

/// The DIS models. `acceleration` and `angular_velocity` are required when the algorithm uses
/// them and accepted (checked, then ignored) when it does not: a DIS entity state carries both.
void readDeadReckoning(Fields& f, Prediction& p) {
    std::string algorithm;
    bool known = false;
    if (f.string("algorithm", true, algorithm)) {
        known = foresight::findDeadReckoningAlgorithm(algorithm, p.deadReckoning);
        if (!known) {
            f.diagnostics().error(f.at("algorithm"),
                                  "unknown algorithm " + jsonQuoted(algorithm) +
                                      " (expected STATIC, FPW, RPW, RVW, FVW, FPB, RPB, RVB or FVB)");
        }
    }
    f.position("position", true, p.position);
    f.vector("velocity", true, p.velocity);
    f.vector("acceleration", known && foresight::deadReckoningUsesAcceleration(p.deadReckoning), p.acceleration);
    f.quaternion("orientation", true, p.orientation);
    f.vector("angular_velocity", known && foresight::deadReckoningRotates(p.deadReckoning), p.angularVelocity);
    f.time("time", true, p.time);
}

void readPrediction(const Json& item, const std::string& path, Scenario& scenario, Diagnostics& d) {
    if (!expectObject(item, path, d, "{\"model\", ...}")) return;
    const std::size_t errorsBefore = d.errors.size();
    Fields f(item, path, d);
    Prediction p;
    p.path = path;
    f.id(p.id);
    std::string model;
    if (!f.string("model", true, model)) return;  // without a model the allowed keys are unknown
    if (model == "linear") {
        p.model = Model::Linear;
    } else if (model == "accelerated") {
        p.model = Model::Accelerated;
    } else if (model == "orientation") {
        p.model = Model::Orientation;
    } else if (model == "projectile") {
        p.model = Model::Projectile;
    } else if (model == "vehicle") {
        p.model = Model::Vehicle;
    } else if (model == "dead_reckoning") {
        p.model = Model::DeadReckoning;
    } else {
        d.error(f.at("model"),
                "unknown model " + jsonQuoted(model) +
                    " (expected linear, accelerated, orientation, projectile, vehicle or dead_reckoning)");
        return;
    }

    switch (p.model) {
        case Model::Linear:
        case Model::Accelerated:
            f.position("position", true, p.position);
            f.vector("velocity", true, p.velocity);
            if (p.model == Model::Accelerated) f.vector("acceleration", true, p.acceleration);
            f.time("time", true, p.time);
            break;
        case Model::Orientation:
            f.quaternion("orientation", true, p.orientation);
            f.vector("angular_velocity", true, p.angularVelocity);
            readFrame(f, p.frame);
            f.time("time", true, p.time);
            break;
        case Model::Projectile:
            readProjectile(f, p, scenario.gravity);
            break;
        case Model::Vehicle:
            readVehicle(f, p);
            break;
        case Model::DeadReckoning:
            readDeadReckoning(f, p);
            break;
    }
    f.finish();
    if (d.errors.size() == errorsBefore) scenario.predictions.push_back(std::move(p));
}

}  // namespace

namespace {
// The steps one projectile prediction takes at most (its time over its step, up to maxSteps).
std::uint64_t projectileSteps(const Prediction& p) {
    return std::min<std::uint64_t>(foresight::steppedStepCount(p.time, foresight::settingsStep(p.projectile)),
                                   p.projectile.maxSteps);
}
}  // namespace

std::uint64_t scenarioProjectileSteps(const Scenario& scenario) {
    std::uint64_t steps = 0;
    for (const Prediction& p : scenario.predictions)
        if (p.model == Model::Projectile) steps += projectileSteps(p);
    return steps;
}

bool buildScenario(const Json& document, const std::filesystem::path& baseDirectory, Scenario& scenario,
                   Diagnostics& diagnostics) {
    if (!document.is_object()) {
        diagnostics.error("", "expected a JSON object {\"predictions\": [...]}, got " + typeName(document));
        return false;
    }
    Fields root(document, "", diagnostics);
    root.vector("gravity", false, scenario.gravity);
#ifdef FORESIGHT_CLI_WITH_EMBREE
    scenario.meshWorld.reset();
#endif
    if (const Json* world = root.get("world", false))
        buildWorld(*world, baseDirectory, scenario.world, scenario.meshWorld, diagnostics);
#ifdef FORESIGHT_CLI_WITH_EMBREE
    if (diagnostics.ok()) {
        if (scenario.meshWorld) {
            auto* meshWorld = static_cast<foresight::EmbreeWorld*>(scenario.meshWorld.get());
            // The mesh world answers the casts: it gets the primitives too.
            meshWorld->addPrimitives(scenario.world);
            std::string reason;
            if (!meshWorld->commit(&reason)) diagnostics.error("world.meshes", reason);
        }
    }
#endif
    if (const Json* predictions = root.get("predictions", true)) {
        if (!predictions->is_array()) {
            diagnostics.error("predictions", "expected an array, got " + typeName(*predictions));
        } else {
            for (std::size_t i = 0; i < predictions->size(); ++i) {
                readPrediction((*predictions)[i], "predictions[" + std::to_string(i) + "]", scenario, diagnostics);
            }
        }
    }
    root.finish();
    // The whole file's budget: each prediction is capped, and so is their sum (four predictions
    // just under their cap printed 554 MB and took 3.3 GB).
    const std::uint64_t steps = scenarioProjectileSteps(scenario);
    std::uint64_t points = 0;
    for (const Prediction& p : scenario.predictions)
        if (p.model == Model::Projectile && p.trajectory) points += projectileSteps(p) + 1;
    if (steps > kMaxScenarioSteps)
        diagnostics.error("predictions", "the projectile predictions take " + std::to_string(steps) +
                                             " steps in all; one file may take at most " +
                                             std::to_string(kMaxScenarioSteps) + " (split the file)");
    else if (points > kMaxScenarioPoints)
        diagnostics.error("predictions", "the projectile trajectories have " + std::to_string(points) +
                                             " points in all; one file may print at most " +
                                             std::to_string(kMaxScenarioPoints) +
                                             " (\"trajectory\": false leaves a prediction's out, or split the file)");
    return diagnostics.ok();
}

// ---------------------------------------------------------------------------------------------
// Running

namespace {

bool finite(const foresight::RVec3& v) {
    return std::isfinite(static_cast<double>(v.x)) && std::isfinite(static_cast<double>(v.y)) &&
           std::isfinite(static_cast<double>(v.z));
}
bool finite(const foresight::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const foresight::Quat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

Status runProjectile(const Scenario& scenario, const Prediction& p, PredictionResult& result) {
    const foresight::CollisionWorld* world = scenario.world.shapeCount() > 0 ? &scenario.world : nullptr;
#ifdef FORESIGHT_CLI_WITH_EMBREE
    if (scenario.meshWorld) world = scenario.meshWorld.get();
#endif
    const bool record = p.trajectory || scenario.recordTrajectories;
    std::vector<foresight::TrajectoryPoint> points;
    if (record) points.resize(foresight::trajectoryCapacity(p.time, p.projectile));
    foresight::ProjectileResult out;
    Status status = foresight::predictProjectile(p.position, p.velocity, p.time, p.projectile, world, points, out);
    if (status == Status::Ok && record && out.trajectoryNeeded > points.size()) {
        // More bounces and contact changes than the first guess: run again with room for all.
        points.resize(out.trajectoryNeeded);
        status = foresight::predictProjectile(p.position, p.velocity, p.time, p.projectile, world, points, out);
    }
    if (status != Status::Ok) return status;
    points.resize(std::min(out.trajectorySize, points.size()));
    result.position = out.position;
    result.velocity = out.velocity;
    result.projectile = out;
    result.trajectory = std::move(points);
    return Status::Ok;
}

/// Runs one prediction; `detail` may explain a refusal.
Status runPrediction(const Scenario& scenario, const Prediction& p, PredictionResult& result, std::string& detail) {
    switch (p.model) {
        case Model::Linear:
        case Model::Accelerated: {
            const foresight::PointState start{p.position, p.velocity};
            foresight::PointState out;
            const Status status = p.model == Model::Linear
                                      ? foresight::predictLinear(start, p.time, out)
                                      : foresight::predictAccelerated(start, p.acceleration, p.time, out);
            if (status != Status::Ok) return status;
            result.position = out.position;
            result.velocity = out.velocity;
            return Status::Ok;
        }
        case Model::Orientation:
            return foresight::predictOrientation(p.orientation, p.angularVelocity, p.frame, p.time, result.orientation);
        case Model::Projectile: {
            const Status status = runProjectile(scenario, p, result);
            if (status == Status::TooManySteps) {
                detail = "time / step = " +
                         shortNumber(static_cast<double>(p.time) / static_cast<double>(p.projectile.step)) +
                         " steps, the cap is " + std::to_string(p.projectile.maxSteps);
            } else if (status == Status::TooManyEvents) {
                detail = "the cap is " + std::to_string(p.projectile.maxEvents);
            }
            return status;
        }
        case Model::Vehicle: {
            foresight::VehicleState start;
            start.position = p.position;
            start.velocity = p.velocity;
            start.orientation = p.orientation;
            start.angularVelocity = p.angularVelocity;
            foresight::VehicleSettings settings;
            settings.frame = p.frame;
            foresight::VehicleState out;
            const Status status = p.vehicleIterative
                                      ? foresight::predictVehicleIterative(start, p.time, p.iterations, settings, out)
                                      : foresight::predictVehicleExact(start, p.time, settings, out);
            if (status != Status::Ok) return status;
            result.position = out.position;
            result.velocity = out.velocity;
            result.orientation = out.orientation;
            return Status::Ok;
        }
        case Model::DeadReckoning: {
            foresight::DeadReckoningState start;
            start.algorithm = p.deadReckoning;
            start.position = p.position;
            start.velocity = p.velocity;
            start.acceleration = p.acceleration;
            start.orientation = p.orientation;
            start.angularVelocity = p.angularVelocity;
            foresight::DeadReckoningResult out;
            const Status status = foresight::predictDeadReckoning(start, p.time, out);
            if (status != Status::Ok) return status;
            result.position = out.position;
            result.velocity = out.velocity;
            result.orientation = out.orientation;
            return Status::Ok;
        }
    }
    return Status::Ok;
}

bool resultIsFinite(const PredictionResult& result) {
    if (!finite(result.position) || !finite(result.velocity) || !finite(result.orientation)) return false;
    if (!std::isfinite(result.projectile.time) || !finite(result.projectile.hitNormal)) return false;
    return std::all_of(result.trajectory.begin(), result.trajectory.end(), [](const foresight::TrajectoryPoint& point) {
        return std::isfinite(point.time) && finite(point.position) && finite(point.velocity) && finite(point.normal);
    });
}

}  // namespace

Status runPrediction(const Scenario& scenario, const Prediction& prediction, PredictionResult& result) {
    std::string detail;
    return runPrediction(scenario, prediction, result, detail);
}

bool runScenario(const Scenario& scenario, const ResultConsumer& consume, Diagnostics& diagnostics) {
    const std::size_t errorsBefore = diagnostics.errors.size();
    bool taken = true;         // every result so far went to `consume`
    std::uint64_t points = 0;  // trajectory points to print, against kMaxScenarioPoints
    PredictionResult result;
    for (std::size_t i = 0; i < scenario.predictions.size(); ++i) {
        const Prediction& p = scenario.predictions[i];
        result = PredictionResult{};
        std::string detail;
        Status status = runPrediction(scenario, p, result, detail);
        if (status == Status::Ok && !resultIsFinite(result)) status = Status::NonFiniteResult;
        if (status != Status::Ok) {
            std::string message = foresight::statusMessage(status);
            if (!detail.empty()) message += ": " + detail;
            diagnostics.error(p.path, message);
        }
        // Bounces add points beyond the steps buildScenario counted: the budget holds here too.
        if (p.model == Model::Projectile && p.trajectory) points += result.trajectory.size();
        if (points > kMaxScenarioPoints) {
            diagnostics.error(p.path, "the trajectories up to here have " + std::to_string(points) +
                                          " points; one file may print at most " + std::to_string(kMaxScenarioPoints) +
                                          " (\"trajectory\": false leaves a prediction's out, or split the file)");
            return false;
        }
        if (taken && diagnostics.errors.size() == errorsBefore && !consume(i, result)) return false;
        taken = taken && diagnostics.errors.size() == errorsBefore;
    }
    return taken;
}

bool runScenario(const Scenario& scenario, std::vector<PredictionResult>& results, Diagnostics& diagnostics) {
    results.clear();
    results.reserve(scenario.predictions.size());
    const bool ok = runScenario(
        scenario,
        [&results](std::size_t, PredictionResult& result) {
            results.push_back(std::move(result));
            return true;
        },
        diagnostics);
    if (!ok) results.clear();
    return ok && diagnostics.ok();
}

// ---------------------------------------------------------------------------------------------
// Output

Json resultJson(const Prediction& p, const PredictionResult& result) {
    Json out = Json::object();
    if (!p.id.is_null()) out["id"] = p.id;
    out["model"] = modelName(p.model);
    switch (p.model) {
        case Model::Linear:
        case Model::Accelerated:
            out["position"] = jsonPosition(result.position);
            out["velocity"] = jsonVector(result.velocity);
            break;
        case Model::Orientation:
            out["orientation"] = jsonQuaternion(result.orientation);
            break;
        case Model::Projectile: {
            const auto& r = result.projectile;
            out["method"] = projectileMethodName(p.projectile.method);
            out["position"] = jsonPosition(r.position);
            out["velocity"] = jsonVector(r.velocity);
            out["time"] = jsonFloat(r.time);
            out["bounces"] = r.bounces;
            out["at_rest"] = r.atRest;
            out["stopped_at_hit"] = r.stoppedAtHit;
            if (r.stoppedAtHit) out["hit_normal"] = jsonVector(r.hitNormal);
            if (p.trajectory) {
                Json points = Json::array();
                for (const auto& point : result.trajectory) {
                    Json entry = Json::object();
                    entry["t"] = jsonFloat(point.time);
                    entry["position"] = jsonPosition(point.position);
                    entry["velocity"] = jsonVector(point.velocity);
                    entry["event"] = eventName(point.event);
                    const bool impact = point.event == foresight::TrajectoryEvent::Bounce ||
                                        point.event == foresight::TrajectoryEvent::Hit;
                    if (impact || point.normal != foresight::Vec3(0.0f)) entry["normal"] = jsonVector(point.normal);
                    points.push_back(std::move(entry));
                }
                out["trajectory"] = std::move(points);
            }
            break;
        }
        case Model::Vehicle:
            out["method"] = p.vehicleIterative ? "iterative" : "exact";
            if (p.vehicleIterative) out["iterations"] = p.iterations;
            out["position"] = jsonPosition(result.position);
            out["velocity"] = jsonVector(result.velocity);
            out["orientation"] = jsonQuaternion(result.orientation);
            break;
        case Model::DeadReckoning:
            out["algorithm"] = foresight::deadReckoningAlgorithmName(p.deadReckoning);
            out["position"] = jsonPosition(result.position);
            out["velocity"] = jsonVector(result.velocity);
            out["orientation"] = jsonQuaternion(result.orientation);
            break;
    }
    return out;
}

void writeResult(JsonStreamWriter& w, const Prediction& p, const PredictionResult& result) {
    // Member for member as resultJson: the same keys in the same order.
    w.beginObject();
    if (!p.id.is_null()) {
        w.key("id");
        w.value(p.id);
    }
    w.key("model");
    w.string(modelName(p.model));
    switch (p.model) {
        case Model::Linear:
        case Model::Accelerated:
            w.key("position");
            w.position(result.position);
            w.key("velocity");
            w.vector(result.velocity);
            break;
        case Model::Orientation:
            w.key("orientation");
            w.quaternion(result.orientation);
            break;
        case Model::Projectile: {
            const auto& r = result.projectile;
            w.key("method");
            w.string(projectileMethodName(p.projectile.method));
            w.key("position");
            w.position(r.position);
            w.key("velocity");
            w.vector(r.velocity);
            w.key("time");
            w.floatNumber(r.time);
            w.key("bounces");
            w.unsignedInteger(r.bounces);
            w.key("at_rest");
            w.boolean(r.atRest);
            w.key("stopped_at_hit");
            w.boolean(r.stoppedAtHit);
            if (r.stoppedAtHit) {
                w.key("hit_normal");
                w.vector(r.hitNormal);
            }
            if (p.trajectory) {
                w.key("trajectory");
                w.beginArray();
                for (const auto& point : result.trajectory) {
                    const bool impact = point.event == foresight::TrajectoryEvent::Bounce ||
                                        point.event == foresight::TrajectoryEvent::Hit;
                    const bool normal = impact || point.normal != foresight::Vec3(0.0f);
                    w.trajectoryPoint(point.time, point.position, point.velocity, eventName(point.event),
                                      normal ? &point.normal : nullptr);
                }
                w.end();
            }
            break;
        }
        case Model::Vehicle:
            w.key("method");
            w.string(p.vehicleIterative ? "iterative" : "exact");
            if (p.vehicleIterative) {
                w.key("iterations");
                w.integer(p.iterations);
            }
            w.key("position");
            w.position(result.position);
            w.key("velocity");
            w.vector(result.velocity);
            w.key("orientation");
            w.quaternion(result.orientation);
            break;
        case Model::DeadReckoning:
            w.key("algorithm");
            w.string(foresight::deadReckoningAlgorithmName(p.deadReckoning));
            w.key("position");
            w.position(result.position);
            w.key("velocity");
            w.vector(result.velocity);
            w.key("orientation");
            w.quaternion(result.orientation);
            break;
    }
    w.end();
}

ResultDocumentWriter::ResultDocumentWriter(JsonStreamWriter::Sink sink, std::size_t flushBytes)
    : mWriter(std::move(sink), flushBytes) {}

void ResultDocumentWriter::begin() {
    mWriter.beginObject();
    mWriter.key("predictions");
    mWriter.beginArray();
}

void ResultDocumentWriter::add(const Prediction& prediction, const PredictionResult& result) {
    writeResult(mWriter, prediction, result);
}

bool ResultDocumentWriter::finish() {
    mWriter.end();
    mWriter.end();
    return mWriter.finish();
}

Json resultDocument(const Scenario& scenario, const std::vector<PredictionResult>& results) {
    Json predictions = Json::array();
    for (std::size_t i = 0; i < scenario.predictions.size() && i < results.size(); ++i) {
        predictions.push_back(resultJson(scenario.predictions[i], results[i]));
    }
    Json document = Json::object();
    document["predictions"] = std::move(predictions);
    return document;
}

}  // namespace foresight_cli
