// Benchmark inputs shared by every library: shape pairs with poses, generated once from fixed
// seeds, plus an independent reference answer for each pair (see reference.hpp).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace mink_bench {

enum class ShapeKind { Box, Capsule, Sphere, Polytope };

/// A shape in its local frame, described plainly so that every library can build its own.
struct ShapeDesc {
  ShapeKind kind = ShapeKind::Box;
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  ///< Box
  double radius = 0;                                       ///< Sphere, Capsule
  double half_height = 0;  ///< Capsule: core segment from (0,0,-h) to (0,0,+h)
  /// Polytope: the points, every one a vertex of the hull (they lie on an ellipsoid). Box: the
  /// eight corners.
  std::vector<Eigen::Vector3d> points;
  /// Polytope and Box: the hull as outward (counter-clockwise) triangles over `points`.
  std::vector<std::array<int, 3>> triangles;
  /// Polytope and Box: the hull's edges (each once).
  std::vector<std::array<int, 2>> edges;

  double bounding_radius() const;
  /// Support point of the whole shape (radius included) in the local frame.
  Eigen::Vector3d support(const Eigen::Vector3d& d) const;
};

/// One query: shape index on each side, and the two world poses.
struct PairPose {
  int a = 0;
  int b = 0;
  Eigen::Matrix3d rotation_a = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d rotation_b = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d translation_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  ///< the direction B was moved along from A
};

struct Case {
  std::string family;  ///< e.g. "box-box", "polytope128-polytope128"
  bool intersecting = false;
  std::vector<ShapeDesc> shapes_a;
  std::vector<ShapeDesc> shapes_b;
  std::vector<PairPose> pairs;
  /// The reference answer of each pair (reference.hpp): separated cases, the distance;
  /// intersecting cases, the penetration depth.
  std::vector<long double> reference;

  std::string name() const { return family + (intersecting ? "/overlap" : "/separated"); }
  /// The scale errors are measured against: the sum of the bounding radii.
  double size(std::size_t i) const {
    return shapes_a[pairs[i].a].bounding_radius() + shapes_b[pairs[i].b].bounding_radius();
  }
};

inline constexpr std::size_t kPairsPerCase = 256;

/// Every case, generated on the first call (fixed seeds: identical in every executable).
const std::vector<Case>& all_cases();

}  // namespace mink_bench
