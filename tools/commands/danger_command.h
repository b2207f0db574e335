#pragma once
/// @file danger_command.h
/// `foresight danger FILE`: danger for AI (include/foresight/danger.h) from a scenario file.
///
/// The input is a scenario (the format of `foresight predict`, validated by the same code, so
/// its problems have the same paths) whose projectile and vehicle predictions carry danger keys
/// (see docs/danger-format.md): projectiles `blast_radius` (required), `contact_radius` and
/// `points`; vehicles `half_extents`, `box_center` and `characters`; the root `tolerance`.
/// The output is one JSON document: per prediction its danger zone and per-point answers
/// (projectiles), or per character its first contact and closest approach (vehicles).

#include "json_output.h"
#include "picture_options.h"
#include "scenario.h"

#include <foresight/danger.h>

#include <string>
#include <vector>

namespace foresight_cli {

/// A query point of a projectile.
struct DangerPoint {
    foresight::RVec3 position{0};  ///< [Units: m]
    bool hasTime = false;          ///< "time" given: the output says whether it is safe then.
    float time = 0;                ///< [Units: s]
};

/// The danger keys of one prediction (by index into Scenario::predictions).
struct DangerQuery {
    std::size_t prediction = 0;                        ///< index into Scenario::predictions.
    float blastRadius = 0;                             ///< projectile [Units: m].
    float contactRadius = 0;                           ///< projectile [Units: m].
    std::vector<DangerPoint> points;                   ///< projectile.
    foresight::Vec3 halfExtents{0.9f, 0.7f, 2.2f};     ///< vehicle [Units: m].
    foresight::Vec3 boxCenter{0};                      ///< vehicle, local axes [Units: m].
    std::vector<foresight::CharacterBody> characters;  ///< vehicle.
    std::vector<Json> characterIds;                    ///< echoed; null when absent.
};

/// A validated danger file.
struct DangerInput {
    Scenario scenario;                     ///< predictions with the danger keys removed.
    std::vector<DangerQuery> queries;      ///< one per prediction, same order.
    foresight::ApproachSettings approach;  ///< `tolerance` from the root.
};

/// Validates a parsed danger document (the scenario's rules plus the danger keys).
/// Returns diagnostics.ok().
bool buildDangerInput(const Json& document, const std::filesystem::path& baseDirectory, DangerInput& input,
                      Diagnostics& diagnostics);

/// Runs the predictions and the danger queries; the output document, or errors. With
/// `results`, the predictions' results are kept there (for pictures).
bool runDanger(const DangerInput& input, Json& output, Diagnostics& diagnostics,
               std::vector<PredictionResult>* results = nullptr);

/// The picture document's `danger_zones` (docs/viewer-format.md) of the projectiles of `input`,
/// from `results` (runScenario on input.scenario, which records every trajectory): one
/// {"id", "center", "radius", "time"} per projectile, `id` as the picture's predictions name
/// them (the prediction's id, else its path). For the picture writer to add.
Json dangerZonesJson(const DangerInput& input, const std::vector<PredictionResult>& results);

/// `foresight danger FILE` ("-": standard input). Returns the exit status: 0, or 2 with nothing
/// on standard output (problems on standard error, `path: message`). With `pictures`, also
/// writes the viewer page and/or the SVG of the predictions with their danger zones.
int dangerCommand(const std::string& file, const PictureOptions& pictures = {});

}  // namespace foresight_cli
