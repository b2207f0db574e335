#pragma once
/// @file scenario.h
/// The scenario format of `foresight predict` (docs: docs/scenario-format.md):
/// JSON text -> validated library inputs -> library calls -> JSON result.
///
/// Every problem is reported as one line `path: message` (path as in `predictions[3].velocity`)
/// and collected, so one run lists all of them. A field is optional exactly when the format
/// gives it a default; everything else that a model uses is required.

#include "json_input.h"
#include "json_output.h"
#include "json_stream.h"

#include <foresight/foresight.h>

#include <filesystem>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace foresight_cli {

/// The prediction models of the format.
enum class Model { Linear, Accelerated, Orientation, Projectile, Vehicle, DeadReckoning };

/// The model's name in the format ("linear", ...).
const char* modelName(Model model);
/// A projectile method's name in the format ("exact", "stepped", "engine").
const char* projectileMethodName(foresight::ProjectileMethod method);

/// One validated entry of `predictions`.
struct Prediction {
    std::string path;  ///< "predictions[i]", for messages.
    Json id;           ///< echoed back; null when absent.
    Model model = Model::Linear;
    float time = 0;  ///< [Units: s]

    // linear, accelerated, projectile, vehicle, dead_reckoning
    foresight::RVec3 position{0};
    foresight::Vec3 velocity{0};
    // accelerated, dead_reckoning
    foresight::Vec3 acceleration{0};
    // orientation, vehicle, dead_reckoning
    foresight::Quat orientation = glm::identity<foresight::Quat>();
    foresight::Vec3 angularVelocity{0};
    foresight::AngularFrame frame = foresight::AngularFrame::Body;
    // projectile
    foresight::ProjectileSettings projectile;
    bool trajectory = true;
    // vehicle
    bool vehicleIterative = false;
    int iterations = 4;
    // dead_reckoning ("algorithm")
    foresight::DeadReckoningAlgorithm deadReckoning = foresight::DeadReckoningAlgorithm::Fpw;
};

/// Most projectile steps one scenario file may ask for in all (a whole-file budget beside each
/// prediction's maxSteps): 2^23, a few seconds of work.
inline constexpr std::uint64_t kMaxScenarioSteps = std::uint64_t(1) << 23;
/// Most trajectory points one scenario file may print in all: 2^20 (about 130 MB of JSON).
inline constexpr std::uint64_t kMaxScenarioPoints = std::uint64_t(1) << 20;

/// A validated scenario, ready to run.
struct Scenario {
    foresight::Vec3 gravity{0.0f, -9.81f, 0.0f};
    foresight::StaticWorld world;
    /// When meshes went into a BVH backend (EmbreeWorld, holding the primitives too), the world
    /// the casts go to; null otherwise (then `world` answers).
    std::unique_ptr<foresight::CollisionWorld> meshWorld;
    std::vector<Prediction> predictions;
    /// Record every projectile's trajectory, also those with "trajectory": false (which the
    /// JSON output still leaves out): pictures draw them.
    bool recordTrajectories = false;
};

/// What a prediction produced (the fields its model uses).
struct PredictionResult {
    foresight::RVec3 position{0};
    foresight::Vec3 velocity{0};
    foresight::Quat orientation = glm::identity<foresight::Quat>();
    foresight::ProjectileResult projectile;              ///< projectile only.
    std::vector<foresight::TrajectoryPoint> trajectory;  ///< projectile with "trajectory": true.
};

/// The projectile steps a scenario's predictions take in all (each at most its maxSteps), as
/// buildScenario compares them with kMaxScenarioSteps.
std::uint64_t scenarioProjectileSteps(const Scenario& scenario);

/// Validates a parsed scenario and loads its meshes (relative to `baseDirectory`).
/// Returns diagnostics.ok().
bool buildScenario(const Json& document, const std::filesystem::path& baseDirectory, Scenario& scenario,
                   Diagnostics& diagnostics);

/// Takes each result of runScenario as it comes: the index of its prediction and the result,
/// which the consumer may move from. Returns false to stop the run (the output failed).
using ResultConsumer = std::function<bool(std::size_t index, PredictionResult& result)>;

/// Runs every prediction in input order and hands each checked result to `consume` before the
/// next one runs, so that only one result is held at a time. Refusals of the library (work caps,
/// overflow, a non-finite result) become errors; from the first error on, results are no longer
/// handed on, but the remaining predictions still run so that every problem is reported in one
/// run, except over the file's budget of printed trajectory points, which stops the run at once.
/// Returns true when every prediction ran and every result was taken (diagnostics.ok() and
/// `consume` never returned false).
bool runScenario(const Scenario& scenario, const ResultConsumer& consume, Diagnostics& diagnostics);

/// Runs every prediction (runScenario above) and keeps every result, in input order.
/// Returns diagnostics.ok().
bool runScenario(const Scenario& scenario, std::vector<PredictionResult>& results, Diagnostics& diagnostics);

/// Runs one prediction (as runScenario does, without the checks of its result).
foresight::Status runPrediction(const Scenario& scenario, const Prediction& prediction, PredictionResult& result);

/// The output document: {"predictions": [...]} in input order.
Json resultDocument(const Scenario& scenario, const std::vector<PredictionResult>& results);

/// One prediction's output object.
Json resultJson(const Prediction& prediction, const PredictionResult& result);

/// Writes resultJson(prediction, result) to `writer`, member by member: the same text
/// formatJson prints for it, without building it.
void writeResult(JsonStreamWriter& writer, const Prediction& prediction, const PredictionResult& result);

/// Streams the output document of predictions that runScenario hands on: {"predictions": [...]},
/// the same bytes as formatJson(resultDocument(...)) for the same results. Call begin, then add
/// for each result in input order, then finish.
class ResultDocumentWriter {
public:
    /// Text goes to `sink` (JsonStreamWriter::Sink) in pieces of at least `flushBytes` bytes.
    explicit ResultDocumentWriter(JsonStreamWriter::Sink sink, std::size_t flushBytes = std::size_t(1) << 16);
    /// Opens the document.
    void begin();
    /// Writes one prediction's result object.
    void add(const Prediction& prediction, const PredictionResult& result);
    /// Closes the document and hands the rest to the sink; false if the sink refused text.
    bool finish();
    /// True once the sink refused text.
    bool failed() const { return mWriter.failed(); }
    /// Bytes handed to the sink so far.
    std::uint64_t bytesWritten() const { return mWriter.bytesWritten(); }

private:
    JsonStreamWriter mWriter;
};

/// Lower-case name of a trajectory event ("start", "step", "bounce", "rest", "hit", "end").
const char* eventName(foresight::TrajectoryEvent event);

}  // namespace foresight_cli
