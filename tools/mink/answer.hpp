/// @file answer.hpp
/// Answering a parsed query and writing the answer line (protocol.md, "An answer line").
#pragma once

#include <string>
#include <string_view>

#include "json_io.hpp"

namespace mink::cli {

struct AnswerOptions {
  /// Add `us`: the median time of the query itself (parsing and printing excluded) over repeated
  /// runs, in microseconds.
  bool timing = false;
};

/// Runs `query` and appends its answer line, newline included, to `out`.
///
/// - `intersect`: id, status, intersect, iterations.
/// - `distance`: id, status, intersect, distance, then normal, point_a and point_b when the shapes
///   are separated, iterations.
/// - `contact`: id, status, intersect, distance, depth, normal, point_a, point_b (closest points
///   when separated, deepest points when penetrating: point_b - point_a = -depth * normal),
///   `normal_chosen: true` when several normals were equally good, iterations.
/// - `manifold`: the contact fields (point_a, point_b those of the deepest manifold point, omitted
///   when there is none) and `manifold`: {normal, points: [{position, depth, point_a, point_b}]},
///   with speculative points (depth < 0) for separated shapes within the query's margin.
///
/// Status: Separated and Intersecting are `ok`; IterationLimit is `iteration_limit` and adds
/// `error_bound`; a result the library refused, or one holding a number that is not finite, is an
/// error line (the second would be a library bug: the line is worth reporting).
void write_answer(const Query& query, const AnswerOptions& options, std::string& out);

/// Appends `{"id":<id_json>,"status":"<status>"`, the start of every answer line (of `mink hull`
/// too); the caller adds the other fields and the closing `}` and newline.
void begin_answer(std::string_view id_json, std::string_view status, std::string& out);

/// Appends `{"id":<id_json>,"status":"error","error":"<message>"}` and a newline to `out`.
void write_error(std::string_view id_json, std::string_view message, std::string& out);

}  // namespace mink::cli
