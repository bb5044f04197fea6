/// @file box_box.hpp
/// Two boxes (Box, or Rounded<Box>: the run-time Shape's box core) need no GJK or EPA while the
/// separating axis test can answer: intersect() asks box_box_verdict(), contact() and manifold()
/// box_box_axis() when the cores overlap.
///
/// Penetration depth and normal of two overlapping boxes by the separating axis test: the 3 + 3
/// face axes and the 9 edge-edge cross products. For two boxes the least overlap over these
/// axes is the penetration depth (the Minkowski difference of two boxes is a polytope whose
/// facet normals are among them), so the answer is EPA's, in a fixed number of flops.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "mink/math/pose.hpp"
#include "mink/shapes/box.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// Box and Rounded<Box> (the run-time Shape's single box core), for the separating-axis path.
template <class T>
struct BoxCore : std::false_type {};
template <class S>
struct BoxCore<BoxT<S>> : std::true_type {
  static const Vec3T<S>& half_extents(const BoxT<S>& b) { return b.half_extents; }
};
template <class S>
struct BoxCore<Rounded<BoxT<S>>> : std::true_type {
  static const Vec3T<S>& half_extents(const Rounded<BoxT<S>>& b) { return b.shape.half_extents; }
};

/// B's radius along the edge axis e_i x r.col(j) (unnormalised; i1, i2 the other two indices in
/// cyclic order): the sum over B's axes k of hb[k] |r.col(k) . axis|, from r as given. (For an
/// exact rotation two of the terms are |r(i, .)| entries, but that identity is off by r's
/// rounding divided by the axis length, which near-parallel edges make large.)
template <class S>
S edge_axis_radius_b(const Vec3T<S>& hb, const Mat3T<S>& r, int i1, int i2, int j) {
  S sum = S(0);
  for (int k = 0; k < 3; ++k) sum += hb[k] * std::abs(r(i2, k) * r(i1, j) - r(i1, k) * r(i2, j));
  return sum;
}

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
      length[3 * i + j] = std::sqrt(r(i1, j) * r(i1, j) + r(i2, j) * r(i2, j));
      // Radii of A and B projected on the axis (unnormalised).
      const S ra = ha[i1] * abs_r(i2, j) + ha[i2] * abs_r(i1, j);
      const S rb = edge_axis_radius_b(hb, r, i1, i2, j);
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

/// What the separating axis test alone can tell about two boxes: `gap` (unit: length, >= 0) is
/// how far apart their cores may be and still count as intersecting (the radii plus the touching
/// tolerance).
enum class BoxBoxVerdict { Separated, Overlapping, Unsure };

/// Separated as soon as one of the 15 axes separates the boxes by more than `gap` (the distance
/// is at least that, to rounding, for the rotation r as given); Overlapping when no axis separates
/// them at all (the separating axis theorem); Unsure in between, and also when an edge axis is
/// nearly degenerate (edges parallel to 1e-6 but not exactly), where the theorem's axis cannot be
/// trusted to rounding.
template <class S>
BoxBoxVerdict box_box_verdict(const Vec3T<S>& ha, const Vec3T<S>& hb, const Mat3T<S>& r,
                              const Vec3T<S>& t, S gap) {
  const Mat3T<S> abs_r = r.cwiseAbs();
  S worst = -std::numeric_limits<S>::infinity();  // largest separation seen
  for (int i = 0; i < 3; ++i) {
    const S g = std::abs(t[i]) - ha[i] - abs_r.row(i).dot(hb);
    if (g > gap) return BoxBoxVerdict::Separated;
    worst = std::max(worst, g);
  }
  for (int j = 0; j < 3; ++j) {
    const S g = std::abs(r.col(j).dot(t)) - hb[j] - abs_r.col(j).dot(ha);
    if (g > gap) return BoxBoxVerdict::Separated;
    worst = std::max(worst, g);
  }
  static constexpr int kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
  bool degenerate = false;
  for (int i = 0; i < 3; ++i) {
    const int i1 = kNext[i], i2 = kPrev[i];
    for (int j = 0; j < 3; ++j) {
      // As in box_box_axis(), unnormalised; the square root only when the axis separates.
      const S ra = ha[i1] * abs_r(i2, j) + ha[i2] * abs_r(i1, j);
      const S rb = edge_axis_radius_b(hb, r, i1, i2, j);
      const S g = std::abs(t[i2] * r(i1, j) - t[i1] * r(i2, j)) - ra - rb;
      const S length2 = r(i1, j) * r(i1, j) + r(i2, j) * r(i2, j);
      if (length2 == S(0)) continue;  // exactly parallel edges: the face axes cover them
      if (length2 < S(1e-12)) {
        degenerate = true;
        continue;
      }
      if (g > S(0)) {
        const S length = std::sqrt(length2);
        if (g > gap * length) return BoxBoxVerdict::Separated;
        worst = std::max(worst, g / length);
      }
    }
  }
  return worst <= S(0) && !degenerate ? BoxBoxVerdict::Overlapping : BoxBoxVerdict::Unsure;
}

}  // namespace mink::detail
