/// @file tolerances.hpp
/// Stopping rules shared by the iterative queries.
#pragma once

#include <algorithm>
#include <limits>

namespace mink {

/// Tolerances of GJK. The defaults reach the accuracy of the scalar type; loosen them only to
/// trade accuracy for speed on curved shapes (polytopes converge exactly in a few iterations).
template <class S>
struct TolerancesT {
  /// GJK stops when the gap between its upper and lower bounds on the core distance is at most
  /// `relative * size`, where size is the sum of the shapes' bounding radii, or when an iteration
  /// makes no progress (the rounding floor, reached first when the shapes are far apart).
  /// (unit: dimensionless). Two shapes are touching, hence intersecting, when their distance is at
  /// most `relative * size`.
  S relative = std::max(S(1e-12), S(64) * std::numeric_limits<S>::epsilon());
  /// EPA stops when pushing out the face nearest the origin gains at most `relative_depth * size`;
  /// the depth is then within that of the exact one (polytopes and boxes converge exactly, curved
  /// cores linearly, hence a looser default than `relative`). (unit: dimensionless)
  S relative_depth = std::max(S(1e-10), S(64) * std::numeric_limits<S>::epsilon());
  /// Cap on support evaluations (per GJK run and per EPA run); hitting it gives
  /// Status::IterationLimit. Polytopes need about 3 + log(points) iterations and GJK on curved
  /// shapes a few dozen; EPA on penetrating curved shapes can need hundreds, and where a circle
  /// of normals is nearly as good it runs to the cap (docs/conventions.md). Solids of revolution
  /// with parallel or nearly parallel axes take the planar path of query/axial_pair.hpp instead,
  /// which this caps per plane.
  int max_iterations = 512;
};

using Tolerances = TolerancesT<double>;

}  // namespace mink
