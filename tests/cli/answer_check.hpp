/// @file answer_check.hpp
/// Reading answer lines back for the tests, with simdjson (a parser mink's writer does not share
/// code with), so that every answer is also checked to be valid JSON.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "mink/math/vec.hpp"

namespace mink::cli::test {

/// One point of an answer's manifold.
struct ManifoldPointAnswer {
  Vec3 position = Vec3::Zero();
  double depth = 0;
  Vec3 point_a = Vec3::Zero();
  Vec3 point_b = Vec3::Zero();
};

/// The fields of one answer line. `id` is the id re-serialised by simdjson (strings quoted).
struct Answer {
  bool valid_json = false;
  std::string raw;
  std::set<std::string> keys;
  std::string id;
  std::string status;
  std::string error;
  std::optional<bool> intersect;
  std::optional<double> distance;
  std::optional<double> depth;
  std::optional<Vec3> normal;
  std::optional<Vec3> point_a;
  std::optional<Vec3> point_b;
  std::optional<long> iterations;
  std::optional<double> us;
  std::optional<Vec3> manifold_normal;  ///< manifold.normal, when there is a manifold
  std::vector<ManifoldPointAnswer> manifold_points;
};

/// Parses one answer line; `valid_json` is false when it is not a JSON object.
Answer parse_answer(std::string_view line);

/// The lines of `text`, without their newlines (a last line without one included).
std::vector<std::string_view> split_lines(std::string_view text);

/// Splits `text` into lines (without the newlines) and parses each.
std::vector<Answer> parse_answers(std::string_view text);

/// Answers `input` with a fresh QueryStream and parses the answers.
std::vector<Answer> answer(std::string_view input, bool timing = false);

/// Answers a single line and returns its one answer (an empty Answer if there is not exactly one).
Answer answer_one(std::string_view line);

}  // namespace mink::cli::test
