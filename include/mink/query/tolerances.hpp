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
  /// Cap on support evaluations per GJK run (and per plane of query/axial_pair.hpp's planar path,
  /// which solids of revolution with parallel or nearly parallel axes take); hitting it gives
  /// Status::IterationLimit. Polytopes need about 3 + log(points) iterations and GJK on curved
  /// shapes a few dozen.
  int max_iterations = 512;
  /// Curved pairs (a cylinder, cone or ellipsoid on either side): refine the normal, and the
  /// points with it, by Newton's method on the support function after GJK and EPA
  /// (gjk/support_newton.hpp). Their value tolerances leave a smooth minimum's normal off by
  /// their square root (up to 2e-5 rad); refined, it is good to about 1e-9 (a cone's kink, 1e-6),
  /// for 10-90 % more time on those pairs (docs/benchmarks.md, "Stop 49"). Off: GJK's and EPA's
  /// own normal.
  bool refine_curved_normals = true;
  /// Cap on support evaluations per EPA run (three quarters for expanding its polytope, the rest
  /// for the polish of its upper end); hitting it gives Status::IterationLimit with the least
  /// support value seen and its bracket. EPA on penetrating curved shapes needs hundreds; where
  /// many normals are nearly as good it needs more: 500 to 3,000 on near-coincident ellipsoids
  /// (A - B nearly symmetric, with two nearly equal minima on a flat support function) and on unit
  /// curved shapes at the corner of a face 1e3 times larger, about 0.2 us each on those polytopes
  /// of 1,000 to 6,000 faces (docs/benchmarks.md, "Stop 50"). Where a whole circle of normals is
  /// as good it runs to the cap (docs/conventions.md).
  /// (Last, as refine_curved_normals before it: fields are only ever appended, so that braced
  /// initialisers in order keep their meaning.)
  int max_epa_iterations = 2048;
};

using Tolerances = TolerancesT<double>;

}  // namespace mink
