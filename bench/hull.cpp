#include "hull.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace mink_bench {

namespace {

// Six times the signed volume of (a, b, c, d): positive when d is on the side the normal
// (b - a) x (c - a) points to. Long double, so that the sign is right for the generator's points.
long double orient(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& d) {
  const long double bx = (long double)b.x() - a.x(), by = (long double)b.y() - a.y(),
                    bz = (long double)b.z() - a.z();
  const long double cx = (long double)c.x() - a.x(), cy = (long double)c.y() - a.y(),
                    cz = (long double)c.z() - a.z();
  const long double dx = (long double)d.x() - a.x(), dy = (long double)d.y() - a.y(),
                    dz = (long double)d.z() - a.z();
  return (by * cz - bz * cy) * dx + (bz * cx - bx * cz) * dy + (bx * cy - by * cx) * dz;
}

}  // namespace

std::vector<std::array<int, 3>> compute_hull(const std::vector<Eigen::Vector3d>& points) {
  const int n = static_cast<int>(points.size());
  if (n < 4) throw std::invalid_argument("compute_hull: fewer than 4 points");
  // Initial tetrahedron: 0, 1, 2 and the point farthest from their plane.
  int d = 3;
  long double best = 0;
  for (int i = 3; i < n; ++i) {
    const long double v = std::fabs(orient(points[0], points[1], points[2], points[i]));
    if (v > best) {
      best = v;
      d = i;
    }
  }
  if (!(best > 0)) throw std::invalid_argument("compute_hull: flat input");
  std::vector<std::array<int, 3>> faces;
  if (orient(points[0], points[1], points[2], points[d]) < 0)
    faces = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  else
    faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  for (auto& f : faces)
    for (int& v : f)
      if (v == 3) v = d;

  std::vector<std::array<int, 2>> directed;
  std::vector<std::array<int, 3>> kept;
  for (int q = 3; q < n; ++q) {
    if (q == d) continue;
    directed.clear();
    kept.clear();
    for (const auto& f : faces) {
      if (orient(points[f[0]], points[f[1]], points[f[2]], points[q]) > 0) {
        directed.push_back({f[0], f[1]});
        directed.push_back({f[1], f[2]});
        directed.push_back({f[2], f[0]});
      } else {
        kept.push_back(f);
      }
    }
    if (directed.empty()) continue;  // inside the current hull
    for (const auto& e : directed) {
      const bool shared = std::any_of(directed.begin(), directed.end(),
                                      [&](const auto& o) { return o[0] == e[1] && o[1] == e[0]; });
      if (!shared) kept.push_back({e[0], e[1], q});  // horizon edge: keeps its winding
    }
    std::swap(faces, kept);
  }
  return faces;
}

std::vector<std::array<int, 2>> collect_edges(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<std::array<int, 2>> edges;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3];
      if (i < j) edges.push_back({i, j});  // each edge of a closed mesh appears once as i < j
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace mink_bench
