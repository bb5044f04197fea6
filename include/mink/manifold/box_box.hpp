/// @file box_box.hpp
/// Penetration depth and normal of two overlapping boxes by the separating axis test: the 3 + 3
/// face axes and the 9 edge-edge cross products. For two boxes the least overlap over these
/// axes is the penetration depth (the Minkowski difference of two boxes is a polytope whose
/// facet normals are among them), so the answer is EPA's, in a fixed number of flops.
#pragma once

#include <cmath>

#include "mink/math/pose.hpp"
#include "mink/shapes/box.hpp"

namespace mink::detail {

template <class S>
struct BoxBoxAxis {
  S overlap;        ///< least overlap (unit: length); negative when an axis separates the boxes
  Vec3T<S> normal;  ///< unit, in A's frame, from A towards B
};

/// The separating-axis answer for box A (half extents ha) and box B (half extents hb) whose pose
/// in A's frame is (r, t). Face axes win ties with edge axes, and an edge axis must beat the best
/// face by `edge_bias` (unit: length) to be taken, so that a box resting on another keeps the face
/// normal under rounding. Edge axes from nearly parallel edges (|cross| < 1e-6) carry no
/// information beyond the face axes and are skipped.
template <class S>
BoxBoxAxis<S> box_box_axis(const Vec3T<S>& ha, const Vec3T<S>& hb, const Mat3T<S>& r,
                           const Vec3T<S>& t, S edge_bias) {
  Mat3T<S> abs_r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) abs_r(i, j) = std::abs(r(i, j));
  BoxBoxAxis<S> best{std::numeric_limits<S>::infinity(), Vec3T<S>::UnitZ()};
  for (int i = 0; i < 3; ++i) {
    const S overlap = ha[i] + abs_r.row(i).dot(hb) - std::abs(t[i]);
    if (overlap < best.overlap) {
      best.overlap = overlap;
      best.normal = Vec3T<S>::Unit(i) * sign_nonneg(t[i]);
    }
  }
  for (int j = 0; j < 3; ++j) {
    const Vec3T<S> axis = r.col(j);
    const S tj = axis.dot(t);
    const S overlap = hb[j] + abs_r.col(j).dot(ha) - std::abs(tj);
    if (overlap < best.overlap) {
      best.overlap = overlap;
      best.normal = axis * sign_nonneg(tj);
    }
  }
  const S face = best.overlap - edge_bias;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3T<S> axis = Vec3T<S>::Unit(i).cross(r.col(j));
      const S length = axis.norm();
      if (!(length > S(1e-6))) continue;
      // Radii of A and B projected on the axis (unnormalised), then the overlap per unit length.
      const S ra = ha.dot(axis.cwiseAbs());
      const S rb = hb.dot((r.transpose() * axis).cwiseAbs());
      const S ta = axis.dot(t);
      const S overlap = (ra + rb - std::abs(ta)) / length;
      if (overlap < face && overlap < best.overlap) {
        best.overlap = overlap;
        best.normal = axis * (sign_nonneg(ta) / length);
      }
    }
  }
  return best;
}

}  // namespace mink::detail
