#pragma once
/// @file picture_options.h
/// Which pictures a command writes (`--html`, `--svg`): what the commands and picture.h share.

#include <string>

namespace foresight_cli {

/// The picture outputs a command was asked for (empty: none).
struct PictureOptions {
    std::string htmlFile;  ///< --html FILE: the self-contained 3D viewer page.
    std::string svgFile;   ///< --svg FILE: a top view and a side view.
    bool wanted() const { return !htmlFile.empty() || !svgFile.empty(); }
};

}  // namespace foresight_cli
