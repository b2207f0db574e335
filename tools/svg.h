#pragma once
/// @file svg.h
/// `--svg FILE`: a static picture of a picture document (docs/viewer-format.md) for documents and
/// reports: a top view (X to the right, Z up the page) above a side view (Z to the right, Y up),
/// both with axes and grid lines in metres, the world's shapes in grey, every path as a line
/// (the article's "faithful" methods dashed in orange, the exact ones solid in blue), bounce
/// markers as circles, rest markers as squares, vehicles as their box at the end of the path,
/// and a legend.

#include "json_output.h"

#include <string>

namespace foresight_cli {

/// The SVG text (a complete document) of `document`. Never throws on a well-formed picture
/// document; fields it does not know are ignored.
std::string svgPicture(const Json& document);

}  // namespace foresight_cli
