/// @file json_io.hpp
/// Reading one query line of the JSON-lines protocol (docs: /work/shared/design/protocol.md) into
/// shapes, poses and what the caller wants answered. Every field is checked: unknown or duplicate
/// fields at any level, missing fields, wrong types, wrong array lengths, numbers that are not
/// finite or out of range, negative lengths, empty point sets, non-unit quaternions and unknown
/// names are errors that say what was wrong and where ("a.shapes[1].radius must be >= 0").
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <simdjson.h>

#include "mink/math/pose.hpp"
#include "mink/support/shape.hpp"

namespace mink::cli {

/// What a query line asks for (`want`).
enum class Want {
  Intersect,  ///< boolean only
  Distance,   ///< distance, and the normal and closest points when separated
  Contact,    ///< distance plus penetration depth (the default)
  Manifold,   ///< contact plus a contact manifold (up to 4 points)
};

/// The largest magnitude accepted for any number of a shape or pose (unit: length). Beyond it the
/// products GJK forms (cubes of coordinates in the signed volumes) could overflow a double, and
/// the answer would be infinite or NaN instead of an error. Far beyond any physical scene in any
/// unit.
inline constexpr double kMaxMagnitude = 1e50;

/// One query line, parsed.
struct Query {
  std::string id;  ///< the id as JSON text (quoted string or number), else the 1-based line number
  Shape a;
  Shape b;
  Pose pose_a;
  Pose pose_b;
  Want want = Want::Contact;
  /// `margin` (want manifold only): separated shapes closer than this get speculative manifold
  /// points, with negative depth (ManifoldOptions::margin). 0 when absent.
  double margin = 0;
};

/// Parses query lines. Keep one per thread and reuse it: the JSON parser and scratch buffers are
/// allocated once and reused for every line.
class QueryParser {
 public:
  /// Parses `line` (without its newline) into `query`. The memory after the line must stay
  /// readable for simdjson::SIMDJSON_PADDING bytes (its contents do not matter): lines are parsed
  /// in place, inside the input buffer. Returns false when the line is malformed; error() then
  /// says why. In both cases `query.id` is set: from the line when its id is valid, else to
  /// `line_number`.
  bool parse(std::string_view line, std::int64_t line_number, Query& query);

  /// Why the last parse() failed.
  const std::string& error() const { return error_; }

 private:
  struct Path;

  bool parse_id(simdjson::dom::element value, std::string& id);
  bool parse_shape(simdjson::dom::element value, const Path& path, Shape& shape);
  bool parse_pose(simdjson::dom::element value, const Path& path, Pose& pose);
  bool parse_want(simdjson::dom::element value, Want& want);
  bool parse_number(simdjson::dom::element value, const Path& path, double& number);
  bool parse_length(simdjson::dom::element value, const Path& path, double& length);
  bool parse_vec3(simdjson::dom::element value, const Path& path, bool lengths, Vec3& v);
  bool parse_points(simdjson::dom::element value, const Path& path, std::size_t exact_count);
  bool fail(const Path& path, std::string_view what);
  bool fail(std::string_view what);

  simdjson::dom::parser parser_;
  std::vector<Vec3> points_;  ///< scratch for point lists, reused across lines
  std::string error_;
};

}  // namespace mink::cli
