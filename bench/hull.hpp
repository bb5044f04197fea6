// A small incremental 3D convex hull for the benchmark inputs (points in general position, as the
// generator makes them). It gives FCL's Convex its faces and the reference its features.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace mink_bench {

/// Outward triangles of the hull of `points`; assumes no four hull points are coplanar.
std::vector<std::array<int, 3>> compute_hull(const std::vector<Eigen::Vector3d>& points);

/// The edges of a closed triangle mesh, each once.
std::vector<std::array<int, 2>> collect_edges(const std::vector<std::array<int, 3>>& triangles);

}  // namespace mink_bench
