/// @file json_writer.hpp
/// Appending JSON values to a std::string: the answer lines of the `mink` tool are built in one
/// reused buffer and written in large chunks, so nothing here allocates once the buffer is warm.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "mink/math/vec.hpp"

namespace mink::cli {

/// Appends `value` in the shortest form that reads back to the same double (std::to_chars without
/// a precision). -0 is written as 0. JSON cannot carry NaN or infinities: callers must not pass
/// them; if one slips through it is written as `null`, never as invalid JSON.
void append_number(std::string& out, double value);

/// Appends an integer in decimal.
void append_integer(std::string& out, std::int64_t value);

/// Appends `text` as a quoted JSON string, escaping quotes, backslashes and control characters.
/// Other bytes, including UTF-8 sequences, are copied unchanged.
void append_string(std::string& out, std::string_view text);

/// Appends `[x,y,z]`.
void append_vec3(std::string& out, const Vec3& v);

/// Appends `x`, `y`, `z` separated by `separator` (numbers as append_number writes them), e.g.
/// the coordinates of an OBJ vertex line with ' '.
void append_components(std::string& out, const Vec3& v, char separator);

/// Appends `,"key":`, the start of an object's field after its first one.
void append_field(std::string& out, std::string_view key);

}  // namespace mink::cli
