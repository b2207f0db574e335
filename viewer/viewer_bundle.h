#pragma once
// The HTML viewer's JavaScript (viewer/dist/foresight-viewer.js, built by npm at build time and
// embedded by viewer/CMakeLists.txt in the target foresight_viewer_bundle). The CLI writes it,
// with "</" escaped as "<\/", inside the page's second <script> element (viewer/README.md).

#include <cstddef>

namespace foresight_cli {

/// The bundle's UTF-8 bytes, followed by a terminating NUL (not counted in kViewerBundleSize).
extern const char kViewerBundle[];
/// The number of bytes of kViewerBundle, without the terminating NUL.
extern const std::size_t kViewerBundleSize;

}  // namespace foresight_cli
