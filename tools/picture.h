#pragma once
/// @file picture.h
/// Pictures of a scenario and its predictions: the picture document (docs/viewer-format.md),
/// which the HTML viewer and the SVG writer draw, and the self-contained HTML page.

#include "json_output.h"
#include "picture_options.h"
#include "scenario.h"

#include <string>
#include <vector>

namespace foresight_cli {

/// Writes the pictures `options` asks for; on failure returns false with a message naming the file.
bool writePictures(const PictureOptions& options, const Json& document, const std::string& title, std::string& error);

/// Samples per second of the drawn paths of characters and vehicles (plus the end time).
inline constexpr double kPictureSamplesPerSecond = 30.0;

/// The picture document of `scenario` and its `results` (runScenario with
/// Scenario::recordTrajectories set, so that every projectile has its path). Positions print
/// as doubles, everything else as floats. `title` names the picture.
Json pictureDocument(const Scenario& scenario, const std::vector<PredictionResult>& results, const std::string& title);

/// Whether this build embeds the HTML viewer (it needs Node.js and npm at build time).
bool viewerAvailable();

/// One line saying why --html cannot work in this build (empty when it can).
std::string viewerUnavailableReason();

/// The self-contained HTML page (no network) showing `document`. Empty without the viewer.
std::string htmlPage(const Json& document, const std::string& title);

/// Writes the page to `file`; on failure returns false with `reason`.
bool writeHtml(const std::string& file, const Json& document, const std::string& title, std::string& reason);

}  // namespace foresight_cli
