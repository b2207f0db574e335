#pragma once
/// @file text_file.h
/// Whole-file reads and writes with a human-readable reason on failure (strerror).

#include <cstddef>
#include <filesystem>
#include <string>

namespace foresight_cli {

/// Largest input file the commands read by default [bytes]: 256 MiB.
inline constexpr std::size_t kMaxInputBytes = std::size_t(256) << 20;

/// Reads all of `file` ("-" reads standard input): a regular file, a pipe or standard input; a
/// device (/dev/zero), socket or directory is refused, and so is more than `maxBytes`. A named
/// pipe that no program writes to reads as empty instead of blocking. On failure returns false
/// and sets `reason`, e.g. "No such file or directory" or "is a directory".
bool readTextFile(const std::string& file, std::string& text, std::string& reason,
                  std::size_t maxBytes = kMaxInputBytes);

/// Reads all of `file`, which must be a regular file of at most `maxBytes` (meshes and the files
/// they name: never a device, pipe or directory).
bool readRegularFile(const std::filesystem::path& file, std::size_t maxBytes, std::string& text, std::string& reason);

/// Writes `text` to `file` ("-" writes standard output). On failure returns false and sets
/// `reason`.
bool writeTextFile(const std::string& file, const std::string& text, std::string& reason);

}  // namespace foresight_cli
