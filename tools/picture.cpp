#include "picture.h"

#include "svg.h"
#include "svg_writer.h"
#include "text_file.h"

#ifdef FORESIGHT_CLI_WITH_EMBREE
#include <foresight/embree_world.h>
#endif
#ifdef FORESIGHT_CLI_WITH_VIEWER
#include "viewer_bundle.h"
#endif

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace foresight_cli {

namespace {

using foresight::RVec3;
using foresight::Vec3;

/// The drawn size of a vehicle (half extents, local axes, forward +Z) [m].
const Vec3 kVehicleHalfExtents(0.9f, 0.7f, 2.2f);

struct Bounds {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec3& p) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const glm::dvec3& center, const glm::dvec3& half) {
        add(center - half);
        add(center + half);
    }
    bool empty() const { return !(lo.x <= hi.x); }
};

Json jsonDVec(const glm::dvec3& v) { return Json::array({jsonDouble(v.x), jsonDouble(v.y), jsonDouble(v.z)}); }

const char* methodName(const Prediction& p) {
    switch (p.model) {
        case Model::Linear:
            return "linear";
        case Model::Accelerated:
            return "accelerated";
        case Model::Orientation:
            return "orientation";
        case Model::Projectile:
            return projectileMethodName(p.projectile.method);
        case Model::Vehicle:
            return p.vehicleIterative ? "iterative" : "exact";
        case Model::DeadReckoning:
            return foresight::deadReckoningAlgorithmName(p.deadReckoning);
    }
    return "";
}

/// "faithful": the reference article's method; "exact": the exact one; "engine": the flight as a
/// physics engine steps it (docs/viewer-format.md).
const char* variantName(const Prediction& p) {
    switch (p.model) {
        case Model::Linear:
            return "faithful";
        case Model::Accelerated:
            return "exact";
        case Model::Orientation:
            return "exact";
        case Model::Projectile:
            if (p.projectile.method == foresight::ProjectileMethod::Engine) return "engine";
            return p.projectile.method == foresight::ProjectileMethod::Stepped ? "faithful" : "exact";
        case Model::Vehicle:
            return p.vehicleIterative ? "faithful" : "exact";
        case Model::DeadReckoning:
            return "exact";
    }
    return "exact";
}

/// Sample times of a path over [0, time]: at least kPictureSamplesPerSecond per second, and the end.
std::vector<double> sampleTimes(double time) {
    const auto intervals = static_cast<std::size_t>(std::max(1.0, std::ceil(time * kPictureSamplesPerSecond)));
    std::vector<double> times;
    times.reserve(intervals + 1);
    for (std::size_t i = 0; i <= intervals; ++i)
        times.push_back(time * static_cast<double>(i) / static_cast<double>(intervals));
    return times;
}

Json pathPoint(double t, const RVec3& position, const Vec3& velocity, const char* event) {
    Json point = Json::object();
    point["t"] = jsonFloat(static_cast<float>(t));
    point["position"] = jsonPosition(position);
    point["velocity"] = jsonVector(velocity);
    point["event"] = event;
    return point;
}

/// A character's or vehicle's path: the prediction run again for each sample time.
Json sampledPath(const Scenario& scenario, const Prediction& p, Bounds& bounds) {
    Json path = Json::array();
    for (const double t : sampleTimes(p.time)) {
        Prediction at = p;
        at.time = static_cast<float>(t);
        PredictionResult result;
        if (runPrediction(scenario, at, result) != foresight::Status::Ok) continue;  // nothing to draw there
        Json point = pathPoint(t, result.position, result.velocity, "sample");
        if (p.model == Model::Vehicle) point["orientation"] = jsonQuaternion(result.orientation);
        bounds.add(glm::dvec3(result.position));
        path.push_back(std::move(point));
    }
    return path;
}

Json projectilePath(const PredictionResult& result, Bounds& bounds) {
    Json path = Json::array();
    for (const auto& point : result.trajectory) {
        Json entry = pathPoint(point.time, point.position, point.velocity, eventName(point.event));
        const bool impact =
            point.event == foresight::TrajectoryEvent::Bounce || point.event == foresight::TrajectoryEvent::Hit;
        if (impact) entry["normal"] = jsonVector(point.normal);
        bounds.add(glm::dvec3(point.position));
        path.push_back(std::move(entry));
    }
    return path;
}

/// Adds a triangle list as a mesh (positions shared by nothing: 3 vertices per triangle).
void addMesh(Json& meshes, const std::string& name, std::span<const foresight::Triangle> triangles, Bounds& bounds) {
    if (triangles.empty()) return;
    Json positions = Json::array();
    Json indices = Json::array();
    std::uint32_t next = 0;
    for (const auto& triangle : triangles) {
        for (const RVec3& vertex : {triangle.a, triangle.b, triangle.c}) {
            const glm::dvec3 v(vertex);
            bounds.add(v);
            positions.push_back(jsonDouble(v.x));
            positions.push_back(jsonDouble(v.y));
            positions.push_back(jsonDouble(v.z));
            indices.push_back(next++);
        }
    }
    Json mesh = Json::object();
    mesh["name"] = name;
    mesh["positions"] = std::move(positions);
    mesh["indices"] = std::move(indices);
    meshes.push_back(std::move(mesh));
}

Json worldJson(const Scenario& scenario, Bounds& bounds) {
    Json world = Json::object();
    Json planes = Json::array();
    for (const auto& plane : scenario.world.planes()) {
        Json entry = Json::object();
        entry["normal"] = jsonVector(plane.normal);
        entry["distance"] = jsonDouble(static_cast<double>(plane.distance));
        planes.push_back(std::move(entry));
    }
    Json boxes = Json::array();
    for (const auto& box : scenario.world.boxes()) {
        Json entry = Json::object();
        entry["center"] = jsonPosition(box.center);
        entry["half_extents"] = jsonVector(box.halfExtents);
        entry["orientation"] = jsonQuaternion(box.orientation);
        // The box's axis-aligned bounds: |R| h around the centre.
        const glm::dmat3 rotation = glm::mat3_cast(glm::dquat(box.orientation));
        glm::dvec3 half(0.0);
        for (int axis = 0; axis < 3; ++axis)
            half += glm::abs(rotation[axis]) * static_cast<double>(box.halfExtents[axis]);
        bounds.add(glm::dvec3(box.center), half);
        boxes.push_back(std::move(entry));
    }
    Json spheres = Json::array();
    for (const auto& sphere : scenario.world.spheres()) {
        Json entry = Json::object();
        entry["center"] = jsonPosition(sphere.center);
        entry["radius"] = jsonFloat(sphere.radius);
        bounds.add(glm::dvec3(sphere.center), glm::dvec3(static_cast<double>(sphere.radius)));
        spheres.push_back(std::move(entry));
    }
    Json meshes = Json::array();
    addMesh(meshes, "triangles", scenario.world.triangles(), bounds);
#ifdef FORESIGHT_CLI_WITH_EMBREE
    if (scenario.meshWorld) {
        const auto* embree = static_cast<const foresight::EmbreeWorld*>(scenario.meshWorld.get());
        addMesh(meshes, "meshes", embree->meshTriangles(), bounds);
    }
#endif
    world["planes"] = std::move(planes);
    world["boxes"] = std::move(boxes);
    world["spheres"] = std::move(spheres);
    world["meshes"] = std::move(meshes);
    return world;
}

}  // namespace

Json pictureDocument(const Scenario& scenario, const std::vector<PredictionResult>& results, const std::string& title) {
    Bounds bounds;
    Json document = Json::object();
    document["version"] = 1;
    document["title"] = title;
    document["gravity"] = jsonVector(scenario.gravity);
    Json world = worldJson(scenario, bounds);
    Json predictions = Json::array();
    for (std::size_t i = 0; i < scenario.predictions.size() && i < results.size(); ++i) {
        const Prediction& p = scenario.predictions[i];
        if (p.model == Model::Orientation) continue;  // nothing moves
        // Geocentric network entities are not drawn (the viewer's format has no such model).
        if (p.model == Model::DeadReckoning) continue;
        Json entry = Json::object();
        entry["id"] = p.id.is_null() ? Json(p.path) : p.id;
        entry["model"] = modelName(p.model);
        entry["method"] = methodName(p);
        entry["variant"] = variantName(p);
        entry["time"] = jsonFloat(p.time);
        if (p.model == Model::Projectile) {
            if (p.projectile.method == foresight::ProjectileMethod::Engine) {
                entry["engine"] = foresight::engineName(p.projectile.engine.engine);
                entry["timestep"] = jsonFloat(p.projectile.engine.timestep);
            }
            entry["radius"] = jsonFloat(p.projectile.radius);
            entry["path"] = projectilePath(results[i], bounds);
        } else {
            if (p.model == Model::Vehicle) entry["half_extents"] = jsonVector(kVehicleHalfExtents);
            entry["path"] = sampledPath(scenario, p, bounds);
        }
        predictions.push_back(std::move(entry));
    }
    if (bounds.empty()) {
        bounds.add(glm::dvec3(-10, 0, -10));
        bounds.add(glm::dvec3(10, 2, 10));
    }
    Json box = Json::object();
    box["min"] = jsonDVec(bounds.lo);
    box["max"] = jsonDVec(bounds.hi);
    document["bounds"] = std::move(box);
    document["world"] = std::move(world);
    document["predictions"] = std::move(predictions);
    return document;
}

namespace {

/// "</" becomes "<\/" so that neither the JSON nor the script can end their <script> element
/// early (valid in JSON strings and in JavaScript strings, regular expressions and comments).
[[maybe_unused]] std::string scriptSafe(const std::string& text) {
    // Built by appending (GCC 12 reports a false -Wrestrict for std::string::insert here).
    std::string out;
    out.reserve(text.size() + 64);
    std::size_t from = 0;
    for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 2)) {
        out.append(text, from, at + 1 - from);
        out += '\\';
        from = at + 1;
    }
    out.append(text, from, std::string::npos);
    return out;
}

}  // namespace

bool viewerAvailable() {
#ifdef FORESIGHT_CLI_WITH_VIEWER
    return true;
#else
    return false;
#endif
}

std::string viewerUnavailableReason() {
    if (viewerAvailable()) return {};
    return "the HTML viewer was not built into this foresight (it needs Node.js and npm at build time: run "
           "scripts/install-deps.sh, then rebuild)";
}

std::string htmlPage(const Json& document, const std::string& title) {
#ifdef FORESIGHT_CLI_WITH_VIEWER
    std::string page =
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>" +
        escapeXml(title) + "</title></head>\n<body><script type=\"application/json\" id=\"foresight-data\">";
    // Every '<' of the JSON (only ever inside its strings) as \u003c: no id or title can open
    // or close an element ("</script>", "<!--") inside the data block.
    std::string data = document.dump(-1, ' ', false, Json::error_handler_t::replace);
    std::string escaped;
    escaped.reserve(data.size());
    for (const char c : data) {
        if (c == '<') {
            escaped += "\\u003c";
        } else {
            escaped += c;
        }
    }
    page += escaped;
    page += "</script>\n<script>";
    page += scriptSafe(std::string(kViewerBundle, kViewerBundleSize));
    page += "</script></body></html>\n";
    return page;
#else
    (void)document;
    (void)title;
    return {};
#endif
}

bool writeHtml(const std::string& file, const Json& document, const std::string& title, std::string& reason) {
    if (!viewerAvailable()) {
        reason = viewerUnavailableReason();
        return false;
    }
    return writeTextFile(file, htmlPage(document, title), reason);
}

bool writePictures(const PictureOptions& options, const Json& document, const std::string& title, std::string& error) {
    std::string reason;
    if (!options.htmlFile.empty() && !writeHtml(options.htmlFile, document, title, reason)) {
        error = options.htmlFile + ": cannot write: " + reason;
        return false;
    }
    if (!options.svgFile.empty() && !writeTextFile(options.svgFile, svgPicture(document), reason)) {
        error = options.svgFile + ": cannot write: " + reason;
        return false;
    }
    return true;
}

}  // namespace foresight_cli
