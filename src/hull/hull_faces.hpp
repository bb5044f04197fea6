/// @file hull_faces.hpp
/// From the exact triangulated hull to convex polygonal faces, merged within a tolerance
/// (internal). See the file comment of mink/hull/convex_hull.hpp, step 4.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "mink/math/vec.hpp"
#include "triangle_hull.hpp"

namespace mink::detail {

struct PolygonFaces {
  /// Vertex loops (point indices), face f is loop[start[f] .. start[f + 1]), counter-clockwise
  /// seen from outside.
  std::vector<int> loop;
  std::vector<int> start;
  std::vector<Vec3> normal;    ///< unit, outward
  std::vector<double> offset;  ///< exact support value along normal, rounded up
  /// For an incomplete hull: largest distance of a remaining point beyond the plane of the face
  /// holding its triangle; 0 otherwise.
  double max_outside = 0;
};

/// Groups the triangles of `hull` (over `points`) into convex faces flat within `tolerance`.
/// Returns false, with `error`, only when an internal cap or consistency check fails.
bool build_polygon_faces(std::span<const Vec3> points, const TriangleHull& hull, double tolerance,
                         PolygonFaces& faces, std::string& error);

}  // namespace mink::detail
