// The benchmark's pairs as `mink query` lines, so that `mink query --timing` can be compared with
// gjk_bench on the same inputs (bench/cli_report.py; scripts/bench runs both).
//
// Usage: bench_queries QUERIES.jsonl REFERENCES.jsonl
// QUERIES: for every case of bench/cases.hpp, every pair, and each of intersect, distance and
// contact, one query line with the id "<want>/<case>/<pair>". The poses' rotations are written as
// the unit quaternions of the benchmark's matrices (mink rebuilds the matrices from them, within
// rounding of the benchmark's). REFERENCES: per case and pair, {"id": "<case>/<pair>",
// "reference": distance (separated cases) or depth (overlap cases), "size": the sum of the
// bounding radii, "intersecting": ...}, the values gjk_bench grades the libraries against.
#include <Eigen/Geometry>
#include <fstream>
#include <iostream>
#include <string>

#include "cases.hpp"
#include "json_writer.hpp"  // the mink tool's: numbers in shortest round-trip form

namespace {

using mink::cli::append_number;
using mink::cli::append_vec3;
using mink_bench::Case;
using mink_bench::ShapeDesc;
using mink_bench::ShapeKind;

void append_shape(std::string& out, const ShapeDesc& s) {
  switch (s.kind) {
    case ShapeKind::Box:
      out += R"({"type":"box","half_extents":)";
      append_vec3(out, s.half_extents);
      break;
    case ShapeKind::Capsule:
      out += R"({"type":"capsule","radius":)";
      append_number(out, s.radius);
      out += R"(,"half_height":)";
      append_number(out, s.half_height);
      break;
    case ShapeKind::Sphere:
      out += R"({"type":"sphere","radius":)";
      append_number(out, s.radius);
      break;
    case ShapeKind::Polytope:
      out += R"({"type":"polytope","points":[)";
      for (std::size_t i = 0; i < s.points.size(); ++i) {
        if (i) out += ',';
        append_vec3(out, s.points[i]);
      }
      out += ']';
      break;
  }
  out += '}';
}

void append_pose(std::string& out, const Eigen::Matrix3d& rotation,
                 const Eigen::Vector3d& translation) {
  const Eigen::Quaterniond q = Eigen::Quaterniond(rotation).normalized();
  out += R"({"t":)";
  append_vec3(out, translation);
  out += R"(,"q":[)";
  append_number(out, q.w());
  for (const double x : {q.x(), q.y(), q.z()}) {
    out += ',';
    append_number(out, x);
  }
  out += "]}";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: bench_queries QUERIES.jsonl REFERENCES.jsonl\n";
    return 2;
  }
  std::ofstream queries(argv[1]), references(argv[2]);
  if (!queries || !references) {
    std::cerr << "bench_queries: cannot write " << argv[1] << " or " << argv[2] << "\n";
    return 1;
  }
  std::string line;
  for (const Case& c : mink_bench::all_cases()) {
    for (std::size_t i = 0; i < c.pairs.size(); ++i) {
      const auto& p = c.pairs[i];
      const std::string pair_id = c.name() + "/" + std::to_string(i);
      line = R"({"id":")" + pair_id + R"(","reference":)";
      append_number(line, static_cast<double>(c.reference[i]));
      line += R"(,"size":)";
      append_number(line, c.size(i));
      line += c.intersecting ? R"(,"intersecting":true})" : R"(,"intersecting":false})";
      references << line << '\n';
      for (const char* want : {"intersect", "distance", "contact"}) {
        line = R"({"id":")" + std::string(want) + "/" + pair_id + R"(","a":)";
        append_shape(line, c.shapes_a[p.a]);
        line += R"(,"pa":)";
        append_pose(line, p.rotation_a, p.translation_a);
        line += R"(,"b":)";
        append_shape(line, c.shapes_b[p.b]);
        line += R"(,"pb":)";
        append_pose(line, p.rotation_b, p.translation_b);
        line += R"(,"want":")" + std::string(want) + "\"}";
        queries << line << '\n';
      }
    }
  }
  queries.flush();
  references.flush();
  if (!queries || !references) {
    std::cerr << "bench_queries: write failed\n";
    return 1;
  }
  return 0;
}
