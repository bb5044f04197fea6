#include "hull_json.hpp"

#include <array>
#include <span>

#include "answer.hpp"
#include "json_io.hpp"
#include "json_writer.hpp"

namespace mink::cli {

namespace dom = simdjson::dom;

namespace {

/// The largest relative tolerance build_convex_hull() accepts (HullOptions).
constexpr double kMaxRelativeTolerance = 1e-2;

template <class Range, class Append>
void append_array(std::string& out, const Range& range, Append&& append) {
  out += '[';
  bool first = true;
  for (const auto& item : range) {
    if (!first) out += ',';
    first = false;
    append(item);
  }
  out += ']';
}

/// append_array over the indices first..last-1. (std::views::iota would do, but clang 14 with
/// libstdc++ 12, the sanitizer build's pair on Debian 12, cannot compile it.)
template <class Index, class Append>
void append_index_array(std::string& out, Index first, Index last, Append&& append) {
  out += '[';
  for (Index i = first; i < last; ++i) {
    if (i != first) out += ',';
    append(i);
  }
  out += ']';
}

}  // namespace

bool HullRequestParser::parse(std::string_view line, std::int64_t line_number,
                              HullRequest& request) {
  request.id.clear();
  append_integer(request.id, line_number);
  request.points.clear();
  request.max_vertices.reset();
  request.relative_tolerance.reset();
  dom::object object;
  if (!parse_object(line, "a hull line", object)) return false;

  enum Field { kId, kPoints, kMaxVertices, kTolerance, kFieldCount };
  static constexpr std::array<std::string_view, kFieldCount> kNames = {
      "id", "points", "max_vertices", "relative_tolerance"};
  std::array<dom::element, kFieldCount> fields;
  std::array<bool, kFieldCount> present;
  if (!read_fields(object, kNames, "a hull line", fields, present, request.id)) return false;
  if (!present[kPoints]) return fail("points is missing");
  if (!parse_points(fields[kPoints], Path{nullptr, "points"}, 0, request.points)) return false;
  if (present[kMaxVertices]) {
    std::uint64_t max_vertices;
    if (fields[kMaxVertices].get_uint64().get(max_vertices) ||
        (max_vertices != 0 && max_vertices < 4))
      return fail("max_vertices must be 0 (no limit) or an integer >= 4");
    request.max_vertices = static_cast<std::size_t>(max_vertices);
  }
  if (present[kTolerance]) {
    double tolerance;
    if (fields[kTolerance].get_double().get(tolerance) ||
        !(tolerance >= 0 && tolerance <= kMaxRelativeTolerance))
      return fail("relative_tolerance must be a number in [0, 1e-2]");
    request.relative_tolerance = tolerance;
  }
  return true;
}

void write_hull(std::string_view id_json, const ConvexHull& hull, std::string& out) {
  begin_answer(id_json, to_string(hull.status), out);
  append_field(out, "vertices");
  append_array(out, hull.vertices, [&](const HullVertex& v) { append_vec3(out, v.position); });
  append_field(out, "input_indices");
  append_array(out, hull.vertices,
               [&](const HullVertex& v) { append_integer(out, v.input_index); });

  // Face loops and, edge by edge, the face on the other side.
  const auto append_loops = [&](bool neighbours) {
    append_array(out, hull.faces, [&](const HullFace& face) {
      append_index_array(out, face.first, face.first + face.count, [&](std::uint32_t h) {
        append_integer(out, neighbours ? hull.neighbor_face(h) : hull.half_edges[h].vertex);
      });
    });
  };
  append_field(out, "faces");
  append_loops(false);
  append_field(out, "normals");
  append_array(out, hull.faces, [&](const HullFace& f) { append_vec3(out, f.normal); });
  append_field(out, "offsets");
  append_array(out, hull.faces, [&](const HullFace& f) { append_number(out, f.offset); });

  append_field(out, "vertex_neighbors");
  const auto neighbors_of = [&](std::size_t v) {
    const std::uint32_t first = hull.neighbor_offsets[v];
    return std::span(hull.neighbors).subspan(first, hull.neighbor_offsets[v + 1] - first);
  };
  append_index_array(out, std::size_t(0), hull.vertices.size(), [&](std::size_t v) {
    append_array(out, neighbors_of(v), [&](std::uint32_t u) { append_integer(out, u); });
  });
  append_field(out, "face_neighbors");
  append_loops(true);

  append_field(out, "volume");
  append_number(out, hull.volume);
  append_field(out, "area");
  append_number(out, hull.area);
  append_field(out, "tolerance");
  append_number(out, hull.tolerance);
  append_field(out, "complete");
  out += hull.complete ? "true" : "false";
  append_field(out, "max_outside");
  append_number(out, hull.max_outside);
  out += "}\n";
}

void write_hull_obj(std::string_view name, const ConvexHull& hull, std::size_t vertex_base,
                    std::string& out) {
  // An OBJ name is one token: whitespace would split it.
  out += "o ";
  for (const char c : name) out += (c == ' ' || c == '\t' || c == '\n' || c == '\r') ? '_' : c;
  out += '\n';
  for (const HullVertex& v : hull.vertices) {
    out += "v ";
    append_components(out, v.position, ' ');
    out += '\n';
  }
  const auto index = [&](std::uint32_t v) {
    append_integer(out, static_cast<std::int64_t>(vertex_base + v + 1));
  };
  switch (hull.status) {
    case HullStatus::Full:
    case HullStatus::Flat:
      for (std::size_t f = 0; f < hull.faces.size(); ++f) {
        out += 'f';
        for (std::uint32_t k = 0; k < hull.faces[f].count; ++k) {
          out += ' ';
          index(hull.face_vertex(f, k));
        }
        out += '\n';
      }
      break;
    case HullStatus::Segment:
      if (hull.vertices.size() == 2) {
        out += "l ";
        index(0);
        out += ' ';
        index(1);
        out += '\n';
      }
      break;
    case HullStatus::Point:
      if (!hull.vertices.empty()) {
        out += "p ";
        index(0);
        out += '\n';
      }
      break;
  }
}

}  // namespace mink::cli
