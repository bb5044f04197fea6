// `mink hull` end to end (the real binary, MINK_EXE): answers read back with simdjson and checked
// against values known independently (volumes and areas of a cube, a tetrahedron, a square) and
// against the invariants protocol.md promises (unit outward normals, offsets, Euler's formula,
// consistent face and vertex adjacency, vertices that are input points); malformed lines, mesh
// files (OBJ, binary STL), --obj and the command-line checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <simdjson.h>

#include "answer_check.hpp"
#include "mink/math/vec.hpp"
#include "run_mink.hpp"

namespace mink::cli::test {
namespace {

namespace dom = simdjson::dom;

/// One answer line of `mink hull`, read back.
struct HullAnswer {
  bool valid_json = false;
  std::string raw;
  std::set<std::string> keys;
  std::string id;  ///< re-serialised by simdjson (strings quoted)
  std::string status;
  std::string error;
  std::vector<Vec3> vertices;
  std::vector<std::int64_t> input_indices;
  std::vector<std::vector<std::int64_t>> faces;
  std::vector<Vec3> normals;
  std::vector<double> offsets;
  std::vector<std::vector<std::int64_t>> vertex_neighbors;
  std::vector<std::vector<std::int64_t>> face_neighbors;
  double volume = -1;
  double area = -1;
  double tolerance = -1;
  bool complete = false;
  double max_outside = -1;
};

std::vector<Vec3> read_vec3s(dom::element e) {
  std::vector<Vec3> out;
  for (const dom::element item : e.get_array()) {
    Vec3 v;
    int i = 0;
    for (const dom::element c : item.get_array()) v[i++] = c.get_double();
    EXPECT_EQ(i, 3);
    out.push_back(v);
  }
  return out;
}

std::vector<std::int64_t> read_integers(dom::element e) {
  std::vector<std::int64_t> out;
  for (const dom::element item : e.get_array()) out.push_back(item.get_int64());
  return out;
}

std::vector<std::vector<std::int64_t>> read_loops(dom::element e) {
  std::vector<std::vector<std::int64_t>> out;
  for (const dom::element item : e.get_array()) out.push_back(read_integers(item));
  return out;
}

HullAnswer parse_hull_answer(std::string_view line) {
  HullAnswer a;
  a.raw = std::string(line);
  dom::parser parser;
  dom::element root;
  dom::object object;
  if (parser.parse(a.raw).get(root) || root.get_object().get(object)) return a;
  a.valid_json = true;
  for (const auto [key, value] : object) {
    a.keys.insert(std::string(key));
    std::string_view text;
    if (key == "id") a.id = simdjson::minify(value);
    if (key == "status" && !value.get_string().get(text)) a.status = std::string(text);
    if (key == "error" && !value.get_string().get(text)) a.error = std::string(text);
    if (key == "vertices") a.vertices = read_vec3s(value);
    if (key == "input_indices") a.input_indices = read_integers(value);
    if (key == "faces") a.faces = read_loops(value);
    if (key == "normals") a.normals = read_vec3s(value);
    if (key == "offsets")
      for (const dom::element o : value.get_array()) a.offsets.push_back(o.get_double());
    if (key == "vertex_neighbors") a.vertex_neighbors = read_loops(value);
    if (key == "face_neighbors") a.face_neighbors = read_loops(value);
    if (key == "volume") a.volume = value.get_double();
    if (key == "area") a.area = value.get_double();
    if (key == "tolerance") a.tolerance = value.get_double();
    if (key == "complete") a.complete = value.get_bool();
    if (key == "max_outside") a.max_outside = value.get_double();
  }
  return a;
}

std::vector<HullAnswer> parse_hull_answers(std::string_view text) {
  std::vector<HullAnswer> answers;
  for (const std::string_view line : split_lines(text)) answers.push_back(parse_hull_answer(line));
  return answers;
}

std::string points_json(const std::vector<Vec3>& points) {
  std::ostringstream out;
  out.precision(17);
  out << '[';
  for (std::size_t i = 0; i < points.size(); ++i)
    out << (i ? "," : "") << '[' << points[i].x() << ',' << points[i].y() << ',' << points[i].z()
        << ']';
  out << ']';
  return out.str();
}

std::string hull_line(const std::string& id, const std::vector<Vec3>& points,
                      const std::string& extra = "") {
  return "{\"id\":\"" + id + "\",\"points\":" + points_json(points) + extra + "}\n";
}

/// Runs `mink hull <arguments> <input written to a file>` and parses the answers.
std::vector<HullAnswer> run_hull(const std::string& name, const std::string& input,
                                 const std::string& arguments = "") {
  const ProcessResult r =
      run_mink("hull " + arguments + " " + shell_quoted(write_temp(name, input)));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return parse_hull_answers(r.out);
}

std::vector<Vec3> cube_corners() {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  return corners;
}

/// The unit cube's corners first, then its centre and points in the middle of faces and edges
/// (none of which may become vertices).
std::vector<Vec3> cube_with_inner_points() {
  std::vector<Vec3> points = cube_corners();
  points.emplace_back(0.5, 0.5, 0.5);
  points.emplace_back(0.5, 0.5, 0);
  points.emplace_back(1, 0.5, 0.5);
  points.emplace_back(0.5, 1, 0.5);
  points.emplace_back(0.5, 0, 0);
  points.emplace_back(1, 1, 0.5);
  points.emplace_back(0, 0.5, 1);
  return points;
}

std::vector<Vec3> tetrahedron() {
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
}

/// Points spread evenly over the unit sphere (a Fibonacci spiral): all of them are vertices.
std::vector<Vec3> sphere_points(int n) {
  std::vector<Vec3> points;
  const double golden_angle = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n;
    const double r = std::sqrt(1 - z * z);
    points.emplace_back(r * std::cos(golden_angle * i), r * std::sin(golden_angle * i), z);
  }
  return points;
}

/// Checks what protocol.md promises of every answer with faces (full and flat hulls), computing
/// the volume and the area anew from the faces; `input` is the point set the hull was built from
/// (every point of it inside the hull unless max_vertices stopped the build).
void check_hull(const HullAnswer& h, const std::vector<Vec3>& input) {
  SCOPED_TRACE(h.raw.substr(0, 200));
  ASSERT_TRUE(h.valid_json);
  const std::set<std::string> keys = {
      "id",      "status",    "vertices",         "input_indices",  "faces",
      "normals", "offsets",   "vertex_neighbors", "face_neighbors", "volume",
      "area",    "tolerance", "complete",         "max_outside"};
  EXPECT_EQ(h.keys, keys);
  const std::size_t nv = h.vertices.size(), nf = h.faces.size();
  ASSERT_EQ(h.input_indices.size(), nv);
  ASSERT_EQ(h.vertex_neighbors.size(), nv);
  ASSERT_EQ(h.normals.size(), nf);
  ASSERT_EQ(h.offsets.size(), nf);
  ASSERT_EQ(h.face_neighbors.size(), nf);

  // Vertices are input points, bit for bit, and distinct.
  for (std::size_t v = 0; v < nv; ++v) {
    ASSERT_GE(h.input_indices[v], 0);
    ASSERT_LT(h.input_indices[v], static_cast<std::int64_t>(input.size()));
    EXPECT_EQ(h.vertices[v], input[h.input_indices[v]]) << "vertex " << v;
    for (std::size_t u = 0; u < v; ++u) EXPECT_NE(h.vertices[u], h.vertices[v]);
  }

  double scale = 0;
  for (const Vec3& p : input) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  const double slack = 1e-12 * std::max(scale, 1.0) + h.tolerance;

  // Faces: unit outward normals, offsets = max over the vertices of normal . v (reached by the
  // face's own vertices), every input point below, loops counter-clockwise from outside.
  std::map<std::pair<std::int64_t, std::int64_t>, std::pair<std::size_t, std::size_t>> edges;
  double volume = 0, area = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    SCOPED_TRACE("face " + std::to_string(f));
    const auto& loop = h.faces[f];
    ASSERT_GE(loop.size(), 3u);
    ASSERT_EQ(h.face_neighbors[f].size(), loop.size());
    const Vec3& n = h.normals[f];
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    double max_dot = -INFINITY;
    for (const Vec3& v : h.vertices) max_dot = std::max(max_dot, n.dot(v));
    EXPECT_NEAR(h.offsets[f], max_dot, slack);
    if (h.complete) {
      for (const Vec3& p : input) EXPECT_LE(n.dot(p), h.offsets[f] + slack);
    }
    Vec3 twice_area = Vec3::Zero();
    for (std::size_t k = 0; k < loop.size(); ++k) {
      ASSERT_GE(loop[k], 0);
      ASSERT_LT(loop[k], static_cast<std::int64_t>(nv));
      EXPECT_NEAR(n.dot(h.vertices[loop[k]]), h.offsets[f], slack) << "vertex " << k;
      const std::int64_t next = loop[(k + 1) % loop.size()];
      EXPECT_TRUE(edges.emplace(std::pair(loop[k], next), std::pair(f, k)).second)
          << "directed edge " << loop[k] << "-" << next << " twice";
      if (k >= 1 && k + 1 < loop.size()) {
        const Vec3 a = h.vertices[loop[0]], b = h.vertices[loop[k]], c = h.vertices[loop[k + 1]];
        twice_area += (b - a).cross(c - a);
        volume += a.dot(b.cross(c)) / 6;
      }
    }
    EXPECT_GT(twice_area.dot(n), 0) << "loop not counter-clockwise about the normal";
    area += twice_area.norm() / 2;
  }
  EXPECT_NEAR(h.volume, volume, 1e-12 * std::max(1.0, std::abs(volume)));
  EXPECT_NEAR(h.area, area, 1e-12 * std::max(1.0, area));

  // The neighbour across edge k of face f has f as its neighbour across the reversed edge.
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& loop = h.faces[f];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const std::int64_t a = loop[k], b = loop[(k + 1) % loop.size()];
      const auto twin = edges.find({b, a});
      ASSERT_NE(twin, edges.end()) << "edge " << a << "-" << b << " of face " << f << " open";
      EXPECT_EQ(h.face_neighbors[f][k], static_cast<std::int64_t>(twin->second.first));
      EXPECT_EQ(h.face_neighbors[twin->second.first][twin->second.second],
                static_cast<std::int64_t>(f));
    }
  }

  // Euler's formula for a closed surface of genus 0 (a flat hull's two faces count as one).
  const std::size_t ne = edges.size() / 2;
  EXPECT_EQ(
      static_cast<std::int64_t>(nv) - static_cast<std::int64_t>(ne) + static_cast<std::int64_t>(nf),
      2);

  // Vertex neighbours: symmetric, and exactly the ends of the edges of the faces.
  for (std::size_t v = 0; v < nv; ++v) {
    std::set<std::int64_t> from_edges;
    for (const auto& [edge, where] : edges)
      if (edge.first == static_cast<std::int64_t>(v)) from_edges.insert(edge.second);
    const std::set<std::int64_t> listed(h.vertex_neighbors[v].begin(), h.vertex_neighbors[v].end());
    EXPECT_EQ(listed.size(), h.vertex_neighbors[v].size()) << "vertex " << v << " repeats";
    EXPECT_EQ(listed, from_edges) << "vertex " << v;
    for (const std::int64_t u : listed) {
      ASSERT_GE(u, 0);
      ASSERT_LT(u, static_cast<std::int64_t>(nv));
      const auto& back = h.vertex_neighbors[u];
      EXPECT_NE(std::find(back.begin(), back.end(), static_cast<std::int64_t>(v)), back.end())
          << u << " lists no " << v;
    }
  }
}

void expect_unit_cube(const HullAnswer& h, const std::vector<Vec3>& input) {
  check_hull(h, input);
  EXPECT_EQ(h.status, "full");
  EXPECT_TRUE(h.complete);
  EXPECT_EQ(h.max_outside, 0);
  ASSERT_EQ(h.vertices.size(), 8u);
  ASSERT_EQ(h.faces.size(), 6u);
  const std::vector<Vec3> corners = cube_corners();
  for (const Vec3& v : h.vertices)
    EXPECT_NE(std::find(corners.begin(), corners.end(), v), corners.end()) << v.transpose();
  // Each side one quad (its two coplanar triangles merged) with an axis normal.
  std::set<std::pair<int, int>> sides;
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(h.faces[f].size(), 4u);
    int axis;
    const double max = h.normals[f].cwiseAbs().maxCoeff(&axis);
    EXPECT_EQ(max, 1.0);
    const int sign = h.normals[f][axis] > 0 ? 1 : -1;
    sides.emplace(axis, sign);
    EXPECT_EQ(h.offsets[f], sign > 0 ? 1.0 : 0.0);
  }
  EXPECT_EQ(sides.size(), 6u);
  EXPECT_NEAR(h.volume, 1, 1e-14);
  EXPECT_NEAR(h.area, 6, 1e-14);
}

TEST(HullCli, CubeWithInnerPoints) {
  const std::vector<Vec3> points = cube_with_inner_points();
  const auto answers = run_hull("hull_cube.jsonl", hull_line("cube", points));
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(answers[0].id, "\"cube\"");
  expect_unit_cube(answers[0], points);
  for (const std::int64_t i : answers[0].input_indices) EXPECT_LT(i, 8);
}

TEST(HullCli, Tetrahedron) {
  const auto answers = run_hull("hull_tetra.jsonl", hull_line("t", tetrahedron()));
  ASSERT_EQ(answers.size(), 1u);
  const HullAnswer& h = answers[0];
  check_hull(h, tetrahedron());
  EXPECT_EQ(h.status, "full");
  EXPECT_EQ(h.vertices.size(), 4u);
  EXPECT_EQ(h.faces.size(), 4u);
  EXPECT_NEAR(h.volume, 1.0 / 6, 1e-15);
  // Three right triangles of area 1/2 and an equilateral one of side sqrt(2).
  EXPECT_NEAR(h.area, 1.5 + std::sqrt(3.0) / 2, 1e-15);
}

TEST(HullCli, FlatSquareIsTwoOppositeFaces) {
  const std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(1, 0, 0),     Vec3(1, 1, 0),
                                    Vec3(0, 1, 0), Vec3(0.5, 0.5, 0), Vec3(0.5, 0, 0)};
  const auto answers = run_hull("hull_flat.jsonl", hull_line("sq", square));
  ASSERT_EQ(answers.size(), 1u);
  const HullAnswer& h = answers[0];
  check_hull(h, square);
  EXPECT_EQ(h.status, "flat");
  EXPECT_EQ(h.vertices.size(), 4u);
  ASSERT_EQ(h.faces.size(), 2u);
  EXPECT_EQ(h.normals[0], -h.normals[1]);
  EXPECT_EQ(std::abs(h.normals[0].z()), 1.0);
  EXPECT_EQ(h.volume, 0);
  EXPECT_NEAR(h.area, 2, 1e-15);  // both sides
}

TEST(HullCli, CollinearPointsAreASegment) {
  const std::vector<Vec3> line = {Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(3, 3, 3), Vec3(2, 2, 2)};
  const auto answers = run_hull("hull_segment.jsonl", hull_line("seg", line));
  ASSERT_EQ(answers.size(), 1u);
  const HullAnswer& h = answers[0];
  EXPECT_EQ(h.status, "segment");
  ASSERT_EQ(h.vertices.size(), 2u);
  const std::set<std::int64_t> ends(h.input_indices.begin(), h.input_indices.end());
  EXPECT_EQ(ends, (std::set<std::int64_t>{1, 2}));
  EXPECT_TRUE(h.faces.empty());
  EXPECT_EQ(h.vertex_neighbors, (std::vector<std::vector<std::int64_t>>{{1}, {0}}));
  EXPECT_EQ(h.volume, 0);
  EXPECT_EQ(h.area, 0);
}

TEST(HullCli, IdenticalPointsAreAPoint) {
  const std::vector<Vec3> same(5, Vec3(-2, 0.5, 7));
  const auto answers = run_hull("hull_point.jsonl", hull_line("p", same));
  ASSERT_EQ(answers.size(), 1u);
  const HullAnswer& h = answers[0];
  EXPECT_EQ(h.status, "point");
  ASSERT_EQ(h.vertices.size(), 1u);
  EXPECT_EQ(h.vertices[0], Vec3(-2, 0.5, 7));
  EXPECT_EQ(h.input_indices[0], 0);
  EXPECT_TRUE(h.faces.empty());
  EXPECT_EQ(h.volume, 0);
}

TEST(HullCli, MaxVerticesStopsEarly) {
  const std::vector<Vec3> sphere = sphere_points(200);
  const std::string input = hull_line("all", sphere) +
                            hull_line("ten", sphere, ",\"max_vertices\":10") +
                            hull_line("unlimited", sphere, ",\"max_vertices\":0");
  // The flag is the default; a line's max_vertices overrides it.
  const auto answers = run_hull("hull_max.jsonl", input, "--max-vertices 12");
  ASSERT_EQ(answers.size(), 3u);
  for (const HullAnswer& h : answers) check_hull(h, sphere);
  EXPECT_FALSE(answers[0].complete);
  EXPECT_LE(answers[0].vertices.size(), 12u);
  EXPECT_GT(answers[0].max_outside, 0);
  EXPECT_FALSE(answers[1].complete);
  EXPECT_LE(answers[1].vertices.size(), 10u);
  EXPECT_GT(answers[1].max_outside, 0);
  EXPECT_LT(answers[1].max_outside, 1);
  EXPECT_TRUE(answers[2].complete);
  EXPECT_EQ(answers[2].vertices.size(), 200u);
  EXPECT_EQ(answers[2].max_outside, 0);
}

TEST(HullCli, MalformedLinesGetErrorsAndTheToolGoesOn) {
  // Each bad line, the id its error line carries (the line number when the JSON cannot be read)
  // and what the error must say; a good line follows each one.
  struct Bad {
    std::string line, id, reason;
  };
  const std::vector<Bad> bad = {
      {"not json", "1", "invalid JSON"},
      {R"([1,2,3])", "3", "must be a JSON object"},
      {R"({"id":"no-points"})", "\"no-points\"", "points is missing"},
      {R"({"id":"empty","points":[]})", "\"empty\"", "points must hold at least one point"},
      {R"({"id":"not-array","points":{"x":1}})", "\"not-array\"",
       "points must be an array of [x, y, z] points"},
      {R"({"id":"nan","points":[[NaN,0,0]]})", "11", "invalid JSON"},
      {R"({"id":"huge","points":[[1e400,0,0]]})", "13", "out of range"},
      {R"({"id":"big","points":[[0,1e60,0]]})", "\"big\"", "points[0][1] is out of range"},
      {R"({"id":"two","points":[[0,0,0],[1,2]]})", "\"two\"",
       "points[1] must be an array of 3 numbers"},
      {R"({"id":"str","points":[[0,"1",0]]})", "\"str\"", "points[0][1] must be a number"},
      {R"({"id":"mv3","points":[[0,0,0]],"max_vertices":3})", "\"mv3\"",
       "max_vertices must be 0 (no limit) or an integer >= 4"},
      {R"({"id":"mv-","points":[[0,0,0]],"max_vertices":-4})", "\"mv-\"", "max_vertices"},
      {R"({"id":"mv.","points":[[0,0,0]],"max_vertices":4.5})", "\"mv.\"", "max_vertices"},
      {R"({"id":"mv\"","points":[[0,0,0]],"max_vertices":"8"})", "\"mv\\\"\"", "max_vertices"},
      {R"({"id":"tol","points":[[0,0,0]],"relative_tolerance":0.5})", "\"tol\"",
       "relative_tolerance must be a number in [0, 1e-2]"},
      {R"({"id":"extra","points":[[0,0,0]],"colour":1})", "\"extra\"", "unknown field 'colour'"},
      {R"({"id":"dup","points":[[0,0,0]],"points":[[1,1,1]]})", "\"dup\"",
       "duplicate field 'points'"},
      {R"({"id":[1],"points":[[0,0,0]]})", "35", "id must be a string or a number"},
  };
  std::string input;
  for (const Bad& b : bad) input += b.line + "\n" + R"({"id":"ok","points":[[0,0,0]]})" + "\n";
  const auto answers = run_hull("hull_bad.jsonl", input);
  ASSERT_EQ(answers.size(), 2 * bad.size());
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const HullAnswer& error = answers[2 * i];
    SCOPED_TRACE(bad[i].line);
    ASSERT_TRUE(error.valid_json) << error.raw;
    EXPECT_EQ(error.keys, (std::set<std::string>{"id", "status", "error"}));
    EXPECT_EQ(error.status, "error");
    EXPECT_EQ(error.id, bad[i].id);
    EXPECT_NE(error.error.find(bad[i].reason), std::string::npos) << error.error;
    EXPECT_EQ(answers[2 * i + 1].status, "point");
    EXPECT_EQ(answers[2 * i + 1].id, "\"ok\"");
  }
}

TEST(HullCli, IdsAreEchoedAsMinkQueryEchoesThem) {
  // Strings re-escaped, numbers in shortest round-trip form, integers beyond int64 exact.
  const std::string input = R"({"id":"a \"b\"","points":[[0,0,0]]})"
                            "\n"
                            R"({"id":-5,"points":[[0,0,0]]})"
                            "\n"
                            R"({"id":1.50,"points":[[0,0,0]]})"
                            "\n"
                            R"({"id":18446744073709551615,"points":[[0,0,0]]})"
                            "\n"
                            R"({"points":[[0,0,0]]})"
                            "\n";
  const ProcessResult r = run_mink("hull " + shell_quoted(write_temp("hull_ids.jsonl", input)));
  const std::vector<std::string_view> lines = split_lines(r.out);
  ASSERT_EQ(lines.size(), 5u) << r.out;
  const std::vector<std::string> ids = {R"("a \"b\"")", "-5", "1.5", "18446744073709551615", "5"};
  for (std::size_t i = 0; i < ids.size(); ++i)
    EXPECT_EQ(lines[i].substr(0, 7 + ids[i].size()), "{\"id\":" + ids[i] + ",") << lines[i];
}

TEST(HullCli, BlankLinesAreCountedAndCrlfIgnored) {
  // As in mink query: lines of blanks (carriage returns included) are skipped but counted, a
  // trailing "\r" is ignored, and a last line without its newline is answered.
  const std::string input = "\r\n \t\r \n{\"points\":[[0,0,0]]}\r\n\n{\"points\":[[1,1,1]]}";
  const auto answers = run_hull("hull_blank.jsonl", input);
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(answers[0].id, "3");
  EXPECT_EQ(answers[0].status, "point");
  EXPECT_EQ(answers[1].id, "5");
  EXPECT_EQ(answers[1].vertices, std::vector<Vec3>{Vec3(1, 1, 1)});
}

/// The unit cube as an OBJ file: 8 vertices, 6 quads.
const std::string kCubeObj =
    "# unit cube\no cube\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

/// The corners of the unit cube's 12 triangles (two per side, outward), three by three.
std::vector<Vec3> cube_triangles() {
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const std::vector<Vec3> corners = cube_corners();
  std::vector<Vec3> out;
  for (const auto& q : quads)
    for (const int c : {q[0], q[1], q[2], q[0], q[2], q[3]}) out.push_back(corners[c]);
  return out;
}

/// cube_triangles() as a binary STL file, little-endian floats.
std::string cube_binary_stl() {
  static_assert(std::endian::native == std::endian::little, "the STL writer assumes it");
  const std::vector<Vec3> corners = cube_triangles();
  std::string out(80, ' ');
  out.replace(0, 20, "solid cube (binary) ");  // exporters often begin with "solid"
  const auto append_u32 = [&out](std::uint32_t v) {
    char bytes[4];
    std::memcpy(bytes, &v, 4);
    out.append(bytes, 4);
  };
  const auto append_vec = [&out](const Vec3& v) {
    for (int i = 0; i < 3; ++i) {
      const auto f = static_cast<float>(v[i]);
      char bytes[4];
      std::memcpy(bytes, &f, 4);
      out.append(bytes, 4);
    }
  };
  append_u32(12);
  for (std::size_t t = 0; t < 12; ++t) {
    append_vec(Vec3::Zero());  // the normal: not used
    for (std::size_t k = 0; k < 3; ++k) append_vec(corners[3 * t + k]);
    out.append(2, '\0');  // attribute byte count
  }
  EXPECT_EQ(out.size(), 84u + 50u * 12u);
  return out;
}

TEST(HullCli, MeshFilesAreAnsweredWithTheirPathAsId) {
  const std::string obj = write_temp("hull_mesh_cube.obj", kCubeObj);
  const std::string stl = write_temp("hull_mesh_cube.stl", cube_binary_stl());
  const ProcessResult r =
      run_mink("hull --mesh " + shell_quoted(obj) + " --mesh " + shell_quoted(stl));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto answers = parse_hull_answers(r.out);
  ASSERT_EQ(answers.size(), 2u);  // standard input is not read when only meshes are given
  EXPECT_EQ(answers[0].id, "\"" + obj + "\"");
  EXPECT_EQ(answers[1].id, "\"" + stl + "\"");
  expect_unit_cube(answers[0], cube_corners());    // the OBJ file's vertices
  expect_unit_cube(answers[1], cube_triangles());  // the STL file's: three per triangle
}

TEST(HullCli, UnreadableMeshIsAnErrorLineAndExitCode1) {
  const std::string missing = ::testing::TempDir() + "hull_no_such_mesh.obj";
  const std::string broken = write_temp("hull_broken.obj", "v 0 0 0\nv 1 2\n");
  const std::string good = write_temp("hull_good.obj", kCubeObj);
  const ProcessResult r = run_mink("hull --mesh " + shell_quoted(missing) + " --mesh " +
                                   shell_quoted(broken) + " --mesh " + shell_quoted(good));
  EXPECT_EQ(r.exit_code, 1);
  const auto answers = parse_hull_answers(r.out);
  ASSERT_EQ(answers.size(), 3u);
  EXPECT_EQ(answers[0].id, "\"" + missing + "\"");
  EXPECT_EQ(answers[0].status, "error");
  EXPECT_NE(answers[0].error.find(missing), std::string::npos) << answers[0].error;
  EXPECT_EQ(answers[1].id, "\"" + broken + "\"");
  EXPECT_EQ(answers[1].status, "error");
  EXPECT_NE(answers[1].error.find(":2"), std::string::npos) << answers[1].error;  // the line
  expect_unit_cube(answers[2], cube_corners());
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
}

TEST(HullCli, ObjRoundTrip) {
  // The hull of a cube written as OBJ and read back as a mesh: the same hull.
  const std::string out_path = ::testing::TempDir() + "hull_round_trip.obj";
  const std::vector<Vec3> cube = cube_with_inner_points();
  const ProcessResult written =
      run_mink("hull --obj " + shell_quoted(out_path) + " " +
               shell_quoted(write_temp("hull_rt.jsonl", hull_line("cube", cube))));
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const auto first = parse_hull_answers(written.out);
  ASSERT_EQ(first.size(), 1u);
  expect_unit_cube(first[0], cube);

  const ProcessResult back = run_mink("hull --mesh " + shell_quoted(out_path));
  ASSERT_EQ(back.exit_code, 0) << back.err;
  const auto second = parse_hull_answers(back.out);
  ASSERT_EQ(second.size(), 1u);
  expect_unit_cube(second[0], first[0].vertices);  // the OBJ file's vertices, in order
  EXPECT_EQ(second[0].volume, first[0].volume);
  EXPECT_EQ(second[0].area, first[0].area);
  std::set<std::vector<double>> before, after;
  for (const Vec3& v : first[0].vertices) before.insert({v.x(), v.y(), v.z()});
  for (const Vec3& v : second[0].vertices) after.insert({v.x(), v.y(), v.z()});
  EXPECT_EQ(before, after);
}

TEST(HullCli, ObjHoldsOneObjectPerHull) {
  // Objects named after their ids (no quotes, blanks replaced), faces referring to their own
  // object's vertices by global index (lines and points for a segment and a point).
  const std::string out_path = ::testing::TempDir() + "hull_objects.obj";
  std::vector<Vec3> tetra = tetrahedron();
  for (Vec3& p : tetra) p += Vec3(5, 0, 0);
  const std::string input =
      hull_line("cube", cube_with_inner_points()) + hull_line("tet ra", tetra) +
      hull_line("seg", {Vec3(0, 0, 0), Vec3(0, 0, 3)}) + hull_line("pt", {Vec3(1, 2, 3)});
  const ProcessResult written = run_mink("hull --obj " + shell_quoted(out_path) + " " +
                                         shell_quoted(write_temp("hull_objs.jsonl", input)));
  ASSERT_EQ(written.exit_code, 0) << written.err;
  EXPECT_EQ(parse_hull_answers(written.out).size(), 4u);

  std::ifstream file(out_path);
  std::vector<std::string> names;
  std::vector<std::size_t> vertex_counts, element_counts;
  std::size_t vertices = 0, object_base = 0;
  for (std::string line; std::getline(file, line);) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "o") {
      names.emplace_back();
      words >> names.back();
      vertex_counts.push_back(0);
      element_counts.push_back(0);
      object_base = vertices;
    } else if (keyword == "v") {
      ASSERT_FALSE(names.empty());
      ++vertices;
      ++vertex_counts.back();
    } else if (keyword == "f" || keyword == "l" || keyword == "p") {
      ASSERT_FALSE(names.empty());
      ++element_counts.back();
      for (std::size_t index; words >> index;) {
        EXPECT_GT(index, object_base) << line;
        EXPECT_LE(index, vertices) << line;
      }
    }
  }
  EXPECT_EQ(names, (std::vector<std::string>{"cube", "tet_ra", "seg", "pt"}));
  EXPECT_EQ(vertex_counts, (std::vector<std::size_t>{8, 4, 2, 1}));
  EXPECT_EQ(element_counts, (std::vector<std::size_t>{6, 4, 1, 1}));

  // The file reads back as one mesh (every index in range): the hull of all the vertices.
  const ProcessResult back = run_mink("hull --mesh " + shell_quoted(out_path));
  EXPECT_EQ(back.exit_code, 0) << back.err;
  const auto joint = parse_hull_answers(back.out);
  ASSERT_EQ(joint.size(), 1u);
  EXPECT_EQ(joint[0].status, "full");
}

TEST(HullCli, MaxVerticesFlagBelowFourIsAUsageError) {
  const std::string path = write_temp("hull_usage.jsonl", hull_line("c", cube_corners()));
  const ProcessResult r = run_mink("hull --max-vertices 3 " + shell_quoted(path));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("--max-vertices"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mink::cli::test
