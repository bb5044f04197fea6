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
  int axis;         ///< 0..2: A's face axis; 3..5: B's face axis 0..2; 6 + 3 i + j: edge i x j
};

/// The separating-axis answer for box A (half extents ha) and box B (half extents hb) whose pose
/// in A's frame is (r, t). Face axes win ties with edge axes, and an edge axis must beat the best
/// face by `edge_bias` (unit: length) to be taken, so that a box resting on another keeps the face
/// normal under rounding. Edge axes from nearly parallel edges (|cross| < 1e-6) carry no
/// information beyond the face axes and are skipped.
template <class S>
BoxBoxAxis<S> box_box_axis(const Vec3T<S>& ha, const Vec3T<S>& hb, const Mat3T<S>& r,
                           const Vec3T<S>& t, S edge_bias) {
  const Mat3T<S> abs_r = r.cwiseAbs();
  // B's offset along its own axes.
  const Vec3T<S> tb = r.transpose() * t;
  // Overlaps along the 6 face axes, then the least (the first on ties). Indices only in the
  // loops: the normal is built once at the end.
  S overlap[15];
  for (int i = 0; i < 3; ++i)
    overlap[i] =
        ha[i] + abs_r(i, 0) * hb[0] + abs_r(i, 1) * hb[1] + abs_r(i, 2) * hb[2] - std::abs(t[i]);
  for (int j = 0; j < 3; ++j)
    overlap[3 + j] =
        hb[j] + abs_r(0, j) * ha[0] + abs_r(1, j) * ha[1] + abs_r(2, j) * ha[2] - std::abs(tb[j]);
  int best = 0;
  for (int k = 1; k < 6; ++k)
    if (overlap[k] < overlap[best]) best = k;
  // The 9 edge-edge axes e_i x r.col(j), of length sin(angle between the edges) =
  // sqrt(r(i1, j)^2 + r(i2, j)^2); overlaps per unit length.
  static constexpr int kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
  S length[9];
  for (int i = 0; i < 3; ++i) {
    const int i1 = kNext[i], i2 = kPrev[i];
    for (int j = 0; j < 3; ++j) {
      const int j1 = kNext[j], j2 = kPrev[j];
      length[3 * i + j] = std::sqrt(r(i1, j) * r(i1, j) + r(i2, j) * r(i2, j));
      // Radii of A and B projected on the axis (unnormalised): for a rotation,
      // r^T (e_i x r.col(j)) has the entries r(i, j2) and -r(i, j1) at j1 and j2.
      const S ra = ha[i1] * abs_r(i2, j) + ha[i2] * abs_r(i1, j);
      const S rb = hb[j1] * abs_r(i, j2) + hb[j2] * abs_r(i, j1);
      const S ta = t[i2] * r(i1, j) - t[i1] * r(i2, j);
      overlap[6 + 3 * i + j] = ra + rb - std::abs(ta);
    }
  }
  const S face = overlap[best] - edge_bias;
  for (int k = 0; k < 9; ++k) {
    if (!(length[k] > S(1e-6))) continue;
    const S o = overlap[6 + k] / length[k];
    overlap[6 + k] = o;
    if (o < face && o < overlap[best]) best = 6 + k;
  }

  BoxBoxAxis<S> result{overlap[best], Vec3T<S>::Zero(), best};
  if (best < 3) {
    result.normal[best] = sign_nonneg(t[best]);
  } else if (best < 6) {
    result.normal = r.col(best - 3) * sign_nonneg(tb[best - 3]);
  } else {
    const int i = (best - 6) / 3, j = (best - 6) % 3;
    Vec3T<S> axis;
    axis[i] = S(0);
    axis[kNext[i]] = -r(kPrev[i], j);
    axis[kPrev[i]] = r(kNext[i], j);
    result.normal = axis * (sign_nonneg(axis.dot(t)) / length[best - 6]);
  }
  return result;
}

}  // namespace mink::detail
