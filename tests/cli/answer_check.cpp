#include "answer_check.hpp"

#include <simdjson.h>

#include "query_stream.hpp"

namespace mink::cli::test {

namespace {

std::optional<Vec3> read_vec3(simdjson::dom::element e) {
  simdjson::dom::array array;
  if (e.get_array().get(array) || array.size() != 3) return std::nullopt;
  Vec3 v;
  int i = 0;
  for (auto c : array) {
    if (c.get_double().get(v[i])) return std::nullopt;
    ++i;
  }
  return v;
}

/// `{"normal": [...], "points": [{"position", "depth", "point_a", "point_b"}, ...]}`; a point
/// with a field missing or of the wrong type is left out (so the count check fails).
void read_manifold(simdjson::dom::element e, Answer& a) {
  const auto field = [](simdjson::dom::element object, std::string_view key) {
    simdjson::dom::element value;
    return object[key].get(value) ? std::nullopt : read_vec3(value);
  };
  a.manifold_normal = field(e, "normal");
  simdjson::dom::array points;
  if (e["points"].get_array().get(points)) return;
  for (const simdjson::dom::element point : points) {
    ManifoldPointAnswer p;
    const auto position = field(point, "position");
    const auto point_a = field(point, "point_a");
    const auto point_b = field(point, "point_b");
    if (!position || !point_a || !point_b || point["depth"].get_double().get(p.depth)) continue;
    p.position = *position;
    p.point_a = *point_a;
    p.point_b = *point_b;
    a.manifold_points.push_back(p);
  }
}

}  // namespace

Answer parse_answer(std::string_view line) {
  Answer a;
  a.raw = std::string(line);
  simdjson::dom::parser parser;
  simdjson::dom::element root;
  if (parser.parse(a.raw).get(root)) return a;
  simdjson::dom::object object;
  if (root.get_object().get(object)) return a;
  a.valid_json = true;
  for (const auto [key, value] : object) {
    a.keys.insert(std::string(key));
    std::string_view text;
    double number;
    bool flag;
    if (key == "id") a.id = simdjson::minify(value);
    if (key == "status" && !value.get_string().get(text)) a.status = std::string(text);
    if (key == "error" && !value.get_string().get(text)) a.error = std::string(text);
    if (key == "intersect" && !value.get_bool().get(flag)) a.intersect = flag;
    if (key == "distance" && !value.get_double().get(number)) a.distance = number;
    if (key == "depth" && !value.get_double().get(number)) a.depth = number;
    if (key == "us" && !value.get_double().get(number)) a.us = number;
    if (key == "iterations" && !value.get_double().get(number)) a.iterations = long(number);
    if (key == "normal") a.normal = read_vec3(value);
    if (key == "point_a") a.point_a = read_vec3(value);
    if (key == "point_b") a.point_b = read_vec3(value);
    if (key == "manifold") read_manifold(value, a);
  }
  return a;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    lines.push_back(text.substr(0, newline));
    if (newline == std::string_view::npos) break;
    text.remove_prefix(newline + 1);
  }
  return lines;
}

std::vector<Answer> parse_answers(std::string_view text) {
  std::vector<Answer> answers;
  for (const std::string_view line : split_lines(text)) answers.push_back(parse_answer(line));
  return answers;
}

std::vector<Answer> answer(std::string_view input, bool timing) {
  QueryStream stream(AnswerOptions{timing});
  return parse_answers(stream.answer_text(input));
}

Answer answer_one(std::string_view line) {
  auto answers = answer(line);
  return answers.size() == 1 ? answers[0] : Answer{};
}

}  // namespace mink::cli::test
