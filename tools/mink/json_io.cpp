#include "json_io.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "json_writer.hpp"

namespace mink::cli {

namespace dom = simdjson::dom;

void JsonLineReader::Path::append_to(std::string& out) const {
  if (parent) parent->append_to(out);
  if (index >= 0) {
    out += '[';
    append_integer(out, index);
    out += ']';
    return;
  }
  if (parent) out += '.';
  out += key;
}

std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxLength = 64;
  std::string out = "'";
  if (text.size() <= kMaxLength) {
    out += text;
  } else {
    std::size_t cut = kMaxLength;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    out += text.substr(0, cut);
    out += "...";
  }
  out += '\'';
  return out;
}

namespace {

enum class ShapeType {
  Sphere,
  Box,
  Capsule,
  Cylinder,
  Cone,
  Ellipsoid,
  Polytope,
  Sum,
  Rounded,
  Point,
  Segment,
  Triangle
};

/// The fields of each shape type besides `type`, as protocol.md lists them.
struct ShapeSpec {
  std::string_view name;
  ShapeType type;
  std::array<std::string_view, 2> fields;
  int field_count;
};

constexpr ShapeSpec kShapeSpecs[] = {
    {"sphere", ShapeType::Sphere, {"radius"}, 1},
    {"box", ShapeType::Box, {"half_extents"}, 1},
    {"capsule", ShapeType::Capsule, {"radius", "half_height"}, 2},
    {"cylinder", ShapeType::Cylinder, {"radius", "half_height"}, 2},
    {"cone", ShapeType::Cone, {"radius", "half_height"}, 2},
    {"ellipsoid", ShapeType::Ellipsoid, {"radii"}, 1},
    {"polytope", ShapeType::Polytope, {"points"}, 1},
    {"sum", ShapeType::Sum, {"shapes"}, 1},
    {"rounded", ShapeType::Rounded, {"shape", "radius"}, 2},
    {"point", ShapeType::Point, {"points"}, 1},
    {"segment", ShapeType::Segment, {"points"}, 1},
    {"triangle", ShapeType::Triangle, {"points"}, 1},
};

constexpr std::string_view kShapeTypeList =
    "sphere, box, capsule, cylinder, cone, ellipsoid, polytope, sum, rounded, point, segment, "
    "triangle";

std::string field_list(const ShapeSpec& spec) {
  std::string out = "type";
  for (int i = 0; i < spec.field_count; ++i) {
    out += ", ";
    out += spec.fields[i];
  }
  return out;
}

}  // namespace

bool JsonLineReader::fail(const Path& path, std::string_view what) {
  error_.clear();
  path.append_to(error_);
  error_ += what;
  return false;
}

bool JsonLineReader::fail(std::string_view what) {
  error_.assign(what);
  return false;
}

bool JsonLineReader::parse_object(std::string_view line, std::string_view what,
                                  dom::object& object) {
  error_.clear();
  dom::element root;
  // realloc_if_needed = false: parse in place; the caller guarantees the padding.
  if (const auto err = parser_.parse(line.data(), line.size(), false).get(root)) {
    // simdjson's own message for numbers ("Problem while parsing a number") hides the usual
    // cause: a number beyond the range of a double, such as 1e400.
    if (err == simdjson::NUMBER_ERROR)
      return fail(
          "invalid JSON: a number is malformed or out of range (beyond a double, or an integer "
          "beyond 64 bits)");
    return fail(std::string("invalid JSON: ") + simdjson::error_message(err));
  }
  if (root.get_object().get(object)) return fail(std::string(what) + " must be a JSON object");
  return true;
}

bool JsonLineReader::read_fields(dom::object object, std::span<const std::string_view> names,
                                 std::string_view what, std::span<dom::element> fields,
                                 std::span<bool> present, std::string& id) {
  std::fill(present.begin(), present.end(), false);
  // The id is read before any other error is reported, so that the error line carries it.
  std::string layout_error;
  for (const auto [key, value] : object) {
    std::size_t i = 0;
    while (i < names.size() && names[i] != key) ++i;
    if (i == names.size()) {
      if (layout_error.empty()) {
        layout_error = "unknown field " + quoted(key) + " (" + std::string(what) + " has ";
        for (std::size_t k = 0; k < names.size(); ++k) {
          if (k > 0) layout_error += ", ";
          layout_error += names[k];
        }
        layout_error += ')';
      }
      continue;
    }
    if (present[i]) {
      if (layout_error.empty()) layout_error = "duplicate field " + quoted(key);
      continue;
    }
    present[i] = true;
    fields[i] = value;
  }
  if (present[0] && !parse_id(fields[0], id)) return false;
  if (!layout_error.empty()) return fail(layout_error);
  return true;
}

bool QueryParser::parse(std::string_view line, std::int64_t line_number, Query& query) {
  query.id.clear();
  append_integer(query.id, line_number);
  dom::object object;
  if (!parse_object(line, "a query line", object)) return false;

  enum Field { kId, kA, kPoseA, kB, kPoseB, kWant, kMargin, kFieldCount };
  static constexpr std::array<std::string_view, kFieldCount> kNames = {"id", "a",    "pa",    "b",
                                                                       "pb", "want", "margin"};
  std::array<dom::element, kFieldCount> fields;
  std::array<bool, kFieldCount> present;
  if (!read_fields(object, kNames, "a query", fields, present, query.id)) return false;
  if (!present[kA]) return fail("a is missing (the first shape)");
  if (!present[kB]) return fail("b is missing (the second shape)");

  if (!parse_shape(fields[kA], Path{nullptr, "a"}, query.a)) return false;
  query.pose_a = Pose::identity();
  if (present[kPoseA] && !parse_pose(fields[kPoseA], Path{nullptr, "pa"}, query.pose_a))
    return false;
  if (!parse_shape(fields[kB], Path{nullptr, "b"}, query.b)) return false;
  query.pose_b = Pose::identity();
  if (present[kPoseB] && !parse_pose(fields[kPoseB], Path{nullptr, "pb"}, query.pose_b))
    return false;
  query.want = Want::Contact;
  if (present[kWant] && !parse_want(fields[kWant], query.want)) return false;
  query.margin = 0;
  if (present[kMargin]) {
    if (query.want != Want::Manifold)
      return fail("margin is only for want manifold (speculative contact points)");
    if (!parse_length(fields[kMargin], Path{nullptr, "margin"}, query.margin)) return false;
  }
  return true;
}

bool JsonLineReader::parse_id(dom::element value, std::string& id) {
  std::string_view text;
  std::int64_t integer;
  std::uint64_t unsigned_integer;
  double number;
  // Written into a copy so that a bad id leaves the line number in place.
  std::string out;
  if (!value.get_string().get(text)) {
    append_string(out, text);
  } else if (!value.get_int64().get(integer)) {
    append_integer(out, integer);
  } else if (!value.get_uint64().get(unsigned_integer)) {
    out = std::to_string(unsigned_integer);
  } else if (!value.get_double().get(number)) {
    append_number(out, number);
  } else {
    return fail("id must be a string or a number");
  }
  id.swap(out);
  return true;
}

bool QueryParser::parse_want(dom::element value, Want& want) {
  std::string_view text;
  if (value.get_string().get(text)) return fail("want must be a string");
  if (text == "intersect") {
    want = Want::Intersect;
  } else if (text == "distance") {
    want = Want::Distance;
  } else if (text == "contact") {
    want = Want::Contact;
  } else if (text == "manifold") {
    want = Want::Manifold;
  } else {
    return fail("want " + quoted(text) + " is unknown (intersect, distance, contact, manifold)");
  }
  return true;
}

bool JsonLineReader::parse_number(dom::element value, const Path& path, double& number) {
  if (value.get_double().get(number)) return fail(path, " must be a number");
  // The comparison is false for NaN, so NaN fails too (simdjson never yields one, but a later
  // change of parser must not let it through).
  if (!(std::abs(number) <= kMaxMagnitude)) {
    if (!std::isfinite(number)) return fail(path, " is not finite");
    return fail(path, " is out of range (magnitude above 1e50)");
  }
  return true;
}

bool JsonLineReader::parse_length(dom::element value, const Path& path, double& length) {
  if (!parse_number(value, path, length)) return false;
  if (length < 0) return fail(path, " must be >= 0");
  return true;
}

bool JsonLineReader::parse_vec3(dom::element value, const Path& path, bool lengths, Vec3& v) {
  dom::array array;
  if (value.get_array().get(array) || array.size() != 3)
    return fail(path, " must be an array of 3 numbers");
  int i = 0;
  for (const dom::element component : array) {
    const Path component_path{&path, {}, i};
    if (lengths ? !parse_length(component, component_path, v[i])
                : !parse_number(component, component_path, v[i]))
      return false;
    ++i;
  }
  return true;
}

bool JsonLineReader::parse_points(dom::element value, const Path& path, std::size_t exact_count,
                                  std::vector<Vec3>& points) {
  dom::array array;
  if (value.get_array().get(array)) return fail(path, " must be an array of [x, y, z] points");
  const std::size_t count = array.size();
  if (exact_count == 0 && count == 0) return fail(path, " must hold at least one point");
  if (exact_count != 0 && count != exact_count)
    return fail(path, " must hold exactly " + std::to_string(exact_count) +
                          (exact_count == 1 ? " point" : " points"));
  points.clear();
  points.reserve(count);
  std::int64_t i = 0;
  for (const dom::element point : array) {
    Vec3 p;
    if (!parse_vec3(point, Path{&path, {}, i}, false, p)) return false;
    points.push_back(p);
    ++i;
  }
  return true;
}

bool QueryParser::parse_pose(dom::element value, const Path& path, Pose& pose) {
  dom::object object;
  if (value.get_object().get(object))
    return fail(path, " must be an object {\"t\": [x, y, z], \"q\": [w, x, y, z]}");
  Vec3 t = Vec3::Zero();
  Quat q = Quat::Identity();
  bool has_t = false, has_q = false;
  for (const auto [key, field] : object) {
    const Path field_path{&path, key};
    if (key == "t") {
      if (has_t) return fail(field_path, " appears twice");
      has_t = true;
      if (!parse_vec3(field, field_path, false, t)) return false;
    } else if (key == "q") {
      if (has_q) return fail(field_path, " appears twice");
      has_q = true;
      dom::array array;
      if (field.get_array().get(array) || array.size() != 4)
        return fail(field_path, " must be an array of 4 numbers [w, x, y, z]");
      std::array<double, 4> wxyz;
      int i = 0;
      for (const dom::element component : array) {
        if (!parse_number(component, Path{&field_path, {}, i}, wxyz[i])) return false;
        ++i;
      }
      q = Quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
      if (const char* e = quaternion_error(q)) return fail(field_path, std::string(": ") + e);
    } else {
      return fail(path, " has an unknown field " + quoted(key) + " (a pose has t, q)");
    }
  }
  pose = Pose::from(t, q);
  return true;
}

bool QueryParser::parse_shape(dom::element value, const Path& path, Shape& shape) {
  dom::object object;
  if (value.get_object().get(object))
    return fail(path, " must be an object (a shape with a \"type\")");

  std::string_view type_name;
  bool has_type = false;
  for (const auto [key, field] : object) {
    if (key != "type") continue;
    const Path type_path{&path, "type"};
    if (has_type) return fail(type_path, " appears twice");
    has_type = true;
    if (field.get_string().get(type_name)) return fail(type_path, " must be a string");
  }
  if (!has_type) return fail(Path{&path, "type"}, " is missing");
  const ShapeSpec* spec = nullptr;
  for (const ShapeSpec& s : kShapeSpecs)
    if (s.name == type_name) spec = &s;
  if (!spec)
    return fail(Path{&path, "type"}, " " + quoted(type_name) + " is not a shape type (" +
                                         std::string(kShapeTypeList) + ")");

  std::array<dom::element, 2> fields;
  std::array<bool, 2> present = {};
  for (const auto [key, field] : object) {
    if (key == "type") continue;
    int i = 0;
    while (i < spec->field_count && spec->fields[i] != key) ++i;
    if (i == spec->field_count)
      return fail(path, " has an unknown field " + quoted(key) + " (a " + std::string(spec->name) +
                            " has " + field_list(*spec) + ")");
    if (present[i]) return fail(Path{&path, key}, " appears twice");
    present[i] = true;
    fields[i] = field;
  }
  for (int i = 0; i < spec->field_count; ++i)
    if (!present[i]) return fail(Path{&path, spec->fields[i]}, " is missing");
  const Path path0{&path, spec->fields[0]};
  const Path path1{&path, spec->fields[1]};

  Expected<Shape> made = Expected<Shape>::failure("");
  double length0 = 0, length1 = 0;
  Vec3 v;
  switch (spec->type) {
    case ShapeType::Sphere:
      if (!parse_length(fields[0], path0, length0)) return false;
      made = Shape::sphere(length0);
      break;
    case ShapeType::Box:
      if (!parse_vec3(fields[0], path0, true, v)) return false;
      made = Shape::box(v);
      break;
    case ShapeType::Capsule:
    case ShapeType::Cylinder:
    case ShapeType::Cone:
      if (!parse_length(fields[0], path0, length0) || !parse_length(fields[1], path1, length1))
        return false;
      made = spec->type == ShapeType::Capsule    ? Shape::capsule(length0, length1)
             : spec->type == ShapeType::Cylinder ? Shape::cylinder(length0, length1)
                                                 : Shape::cone(length0, length1);
      break;
    case ShapeType::Ellipsoid:
      if (!parse_vec3(fields[0], path0, true, v)) return false;
      made = Shape::ellipsoid(v);
      break;
    case ShapeType::Polytope:
      if (!parse_points(fields[0], path0, 0, points_)) return false;
      made = Shape::polytope(points_);
      break;
    case ShapeType::Point:
      if (!parse_points(fields[0], path0, 1, points_)) return false;
      made = Shape::point(points_[0]);
      break;
    case ShapeType::Segment:
      if (!parse_points(fields[0], path0, 2, points_)) return false;
      made = Shape::segment(points_[0], points_[1]);
      break;
    case ShapeType::Triangle:
      if (!parse_points(fields[0], path0, 3, points_)) return false;
      made = Shape::triangle(points_[0], points_[1], points_[2]);
      break;
    case ShapeType::Sum: {
      dom::array array;
      if (fields[0].get_array().get(array) || array.size() != 2)
        return fail(path0, " must be an array of 2 shapes");
      std::array<Shape, 2> parts;
      int i = 0;
      for (const dom::element part : array) {
        if (!parse_shape(part, Path{&path0, {}, i}, parts[i])) return false;
        ++i;
      }
      made = Shape::sum(parts[0], parts[1]);
      break;
    }
    case ShapeType::Rounded: {
      Shape inner;
      if (!parse_shape(fields[0], path0, inner) || !parse_length(fields[1], path1, length1))
        return false;
      made = Shape::rounded(inner, length1);
      break;
    }
  }
  if (!made) return fail(path, ": " + made.error());
  shape = std::move(made).value();
  return true;
}

}  // namespace mink::cli
