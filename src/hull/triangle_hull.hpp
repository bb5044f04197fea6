/// @file triangle_hull.hpp
/// Quickhull with exact visibility: the triangulated convex hull of points in 3D (internal).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "mink/math/vec.hpp"

namespace mink::detail {

/// A triangle of the hull, counter-clockwise seen from outside. Half-edge k of triangle t has id
/// 3 t + k and runs from v[k] to v[(k + 1) % 3]; twin[k] is the id of the opposite half-edge.
struct HullTriangle {
  int v[3];
  int twin[3];
};

struct TriangleHull {
  std::vector<HullTriangle> triangles;
  /// Per triangle: input points still outside it when the build stopped at max_vertices.
  std::vector<std::vector<int>> outside;
  bool complete = true;
};

/// Builds the hull of `points` from the tetrahedron `simplex` (four point indices with a non-zero
/// exact orientation). Stops adding points once the hull has `max_vertices` vertices (0: never).
/// Returns false, with `error`, only when an internal cap or consistency check fails.
bool build_triangle_hull(std::span<const Vec3> points, const int simplex[4],
                         std::size_t max_vertices, TriangleHull& hull, std::string& error);

}  // namespace mink::detail
