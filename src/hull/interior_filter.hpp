/// @file interior_filter.hpp
/// Discards points that cannot be hull vertices before Quickhull runs (internal): the
/// Akl-Toussaint idea, with the exact hull of a sample as the inner polytope.
#pragma once

#include <span>
#include <vector>

#include "mink/math/vec.hpp"

namespace mink::detail {

/// Indices of the points of `q` (local frame: coordinates of magnitude at most about 2) that may
/// be vertices of their convex hull, in increasing order. A point is left out only when it lies
/// strictly inside a ball or a box inscribed in the hull of a sample of the points, by a margin
/// far above every rounding error of the test: it is then strictly inside the hull of all the
/// points, so it is neither a vertex nor on the boundary. Points on or near the hull are always
/// kept. Returns all indices when the filter would not pay (small or flat input, samples whose
/// inner shapes hold few points, as on a sphere).
std::vector<int> hull_candidates(std::span<const Vec3> q);

/// Reorders idx (indices into q) along a Morton curve through the box of those points, so that
/// points near each other in space are near each other in memory once copied in this order:
/// Quickhull and the face stages then walk memory mostly in order. Only speed depends on it.
void sort_spatially(std::span<const Vec3> q, std::vector<int>& idx);

}  // namespace mink::detail
