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
  /// Cap on support evaluations; hitting it gives Status::IterationLimit. Polytopes need about
  /// 3 + log(points) iterations; curved shapes converge linearly and need up to a few dozen.
  int max_iterations = 256;
};

using Tolerances = TolerancesT<double>;

}  // namespace mink
