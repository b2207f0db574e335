#pragma once
/// @file predict_command.h
/// `foresight predict FILE|-`: a scenario (scenario.h) in, its predictions out as JSON, and
/// pictures of them on request (picture.h).

#include "picture_options.h"

#include <string>

namespace foresight_cli {

/// `foresight predict FILE`: reads FILE ("-": standard input), writes the result to standard
/// output. Returns the exit status: 0, or 2 with nothing on standard output.
/// With `pictures`, also writes the HTML viewer page and/or the SVG of the scenario and its
/// results (picture.h); a picture that cannot be written is an error (status 2).
int predictCommand(const std::string& file, const PictureOptions& pictures);

}  // namespace foresight_cli
