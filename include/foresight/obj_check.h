#pragma once
/// @file obj_check.h
/// A strict check of Wavefront OBJ text, run before a lenient parser (tinyobjloader) reads it,
/// so that a damaged file is refused instead of silently read as something else.

#include <foresight/config.h>

#include <cstddef>
#include <string>
#include <string_view>

FORESIGHT_NAMESPACE_BEGIN

/// Largest OBJ text checkObjText accepts [bytes]: 1 GiB (about 25 million triangles).
inline constexpr std::size_t kMaxObjBytes = std::size_t(1) << 30;

/// Checks the lines a triangle loader reads, strictly; other lines (vt, vn, l, g, usemtl, ...) are
/// ignored, as the loaders ignore them.
/// - `v x y z [w]` and `v x y z r g b`: 3, 4 or 6 numbers, each in plain decimal syntax
///   (`[+-]digits[.digits][e[+-]digits]`, no `nan`, `inf`, hexadecimal, comma or trailing text)
///   and within float range.
/// - `f a b c ...`: at least 3 corners, each `v`, `v/t`, `v/t/n` or `v//n` with plain decimal
///   integers, none 0; a vertex index must name a vertex of the file (negative indices count
///   back from the vertices read so far).
/// - no NUL byte, at most kMaxObjBytes.
/// @return true when the text passes; otherwise false and `reason` names the first problem with
///         its 1-based line, e.g. "line 12: vertex coordinate \"1,5\" is not a number".
bool checkObjText(std::string_view text, std::string& reason);

FORESIGHT_NAMESPACE_END
