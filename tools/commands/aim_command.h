#pragma once
/// @file aim_command.h
/// `foresight aim FILE|-`: firing solutions (contract: docs/aim-format.md).
/// JSON shots in, JSON solutions out, through foresight::aimProjectile. Errors follow the
/// scenario format's rules: one `path: message` line per problem, exit status 2, nothing on
/// standard output.

#include "json_input.h"

#include <string>

namespace foresight_cli {

/// What `foresight aim` does with a parsed document: validates it (problems go to
/// `diagnostics`), solves every shot and builds the output document {"shots": [...]}.
/// Returns diagnostics.ok(). (aimCommand is this plus the file and the printing; the fuzzers
/// call it on bytes.)
bool aimDocument(const Json& document, Json& output, Diagnostics& diagnostics);

/// `foresight aim FILE` ("-": standard input): writes {"shots": [...]} to standard output.
/// Returns the exit status: 0, 2 (invalid input or unreadable file; nothing on standard output)
/// or 1 (standard output cannot be written).
int aimCommand(const std::string& file);

}  // namespace foresight_cli
