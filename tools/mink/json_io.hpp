/// @file json_io.hpp
/// Reading one query line of the JSON-lines protocol (docs/protocol.md) into shapes, poses and
/// what the caller wants answered, with a reader of checked JSON values that the other
/// subcommands' line parsers share. Every field is checked: unknown or duplicate
/// fields at any level, missing fields, wrong types, wrong array lengths, numbers that are not
/// finite or out of range, negative lengths, empty point sets, non-unit quaternions and unknown
/// names are errors that say what was wrong and where ("a.shapes[1].radius must be >= 0").
#pragma once

#include <cstdint>
#include <span>
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

/// `text` in single quotes for an error message, cut to a sane length (at a UTF-8 character
/// boundary, so the message stays valid UTF-8) because it comes from the input.
std::string quoted(std::string_view text);

/// Reading one JSON line with every field checked, shared by the parsers of each subcommand's
/// lines (QueryParser below, HullRequestParser in hull_json.hpp): the line's object and its
/// top-level fields, ids, numbers, vectors and point lists. Each helper returns false when the
/// value is wrong, with error() saying what was wrong and where ("a.points[1][2] must be a
/// number").
class JsonLineReader {
 public:
  /// Why the last parse failed.
  const std::string& error() const { return error_; }

 protected:
  /// Where a value sits in the line, for error messages. Paths live on the stack of the
  /// recursive descent and are only turned into text when something is wrong, so a valid line
  /// builds no strings.
  struct Path {
    const Path* parent = nullptr;
    std::string_view key;     ///< field name, when this is a field
    std::int64_t index = -1;  ///< position, when this is an array element

    void append_to(std::string& out) const;
  };

  /// Parses `line` in place (the memory after it must stay readable for
  /// simdjson::SIMDJSON_PADDING bytes) and checks that it is a JSON object; `what` names the line
  /// in the error ("a query line must be a JSON object").
  bool parse_object(std::string_view line, std::string_view what, simdjson::dom::object& object);

  /// Collects the fields of a line's object: fields[i] is the value of names[i] when present[i].
  /// names[0] must be "id": it is read into `id` (as JSON text) before an unknown or duplicate
  /// field is reported, so that the error line carries it. `what` names the line in the error
  /// ("unknown field 'x' (a query has id, a, ...)").
  bool read_fields(simdjson::dom::object object, std::span<const std::string_view> names,
                   std::string_view what, std::span<simdjson::dom::element> fields,
                   std::span<bool> present, std::string& id);

  /// A string or a number, as JSON text (strings quoted, numbers in shortest form); `id` is
  /// left unchanged when the value is neither.
  bool parse_id(simdjson::dom::element value, std::string& id);
  /// A finite number of magnitude at most kMaxMagnitude.
  bool parse_number(simdjson::dom::element value, const Path& path, double& number);
  /// The same, >= 0.
  bool parse_length(simdjson::dom::element value, const Path& path, double& length);
  /// [x, y, z] of numbers (of lengths when `lengths`).
  bool parse_vec3(simdjson::dom::element value, const Path& path, bool lengths, Vec3& v);
  /// [[x, y, z], ...]: exactly `exact_count` points, or at least one when it is 0.
  bool parse_points(simdjson::dom::element value, const Path& path, std::size_t exact_count,
                    std::vector<Vec3>& points);
  bool fail(const Path& path, std::string_view what);
  bool fail(std::string_view what);

  simdjson::dom::parser parser_;
  std::string error_;
};

/// Parses query lines. Keep one per thread and reuse it: the JSON parser and scratch buffers are
/// allocated once and reused for every line.
class QueryParser : public JsonLineReader {
 public:
  /// Parses `line` (without its newline) into `query`. The memory after the line must stay
  /// readable for simdjson::SIMDJSON_PADDING bytes (its contents do not matter): lines are parsed
  /// in place, inside the input buffer. Returns false when the line is malformed; error() then
  /// says why. In both cases `query.id` is set: from the line when its id is valid, else to
  /// `line_number`.
  bool parse(std::string_view line, std::int64_t line_number, Query& query);

 private:
  bool parse_shape(simdjson::dom::element value, const Path& path, Shape& shape);
  bool parse_pose(simdjson::dom::element value, const Path& path, Pose& pose);
  bool parse_want(simdjson::dom::element value, Want& want);

  std::vector<Vec3> points_;  ///< scratch for point lists, reused across lines
};

}  // namespace mink::cli
