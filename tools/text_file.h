#pragma once
/// @file text_file.h
/// Whole-file reads and writes with a human-readable reason on failure (strerror).

#include <filesystem>
#include <string>

namespace foresight_cli {

/// Reads all of `file` ("-" reads standard input). On failure returns false and sets
/// `reason`, e.g. "No such file or directory" or "is a directory".
bool readTextFile(const std::string& file, std::string& text, std::string& reason);

/// Writes `text` to `file` ("-" writes standard output). On failure returns false and sets
/// `reason`.
bool writeTextFile(const std::string& file, const std::string& text, std::string& reason);

} // namespace foresight_cli
