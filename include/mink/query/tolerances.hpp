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
  /// Curved pairs (a cylinder, cone or ellipsoid on either side): refine the normal, and the
  /// points with it, by Newton's method on the support function after GJK and EPA
  /// (gjk/support_newton.hpp). Their value tolerances leave a smooth minimum's normal off by
  /// their square root (up to 2e-5 rad); refined, it is good to about 1e-9 (a cone's kink, 1e-6),
  /// for 10-90 % more time on those pairs (docs/benchmarks.md, "Stop 49"). Off: GJK's and EPA's
  /// own normal.
  bool refine_curved_normals = true;
};

using Tolerances = TolerancesT<double>;

}  // namespace mink
