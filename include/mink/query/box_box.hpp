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

/// The 15 separating axes of box A (half extents ha) and box B (half extents hb) whose pose in
/// A's frame is (r, t): on each axis, the sum of the two radii minus the distance between the
/// centres (> 0 overlapping, < 0 a gap). Face axes are unit; edge axes e_i x r.col(j) (index
/// 3 i + j) are not: their terms carry the factor |e_i x r.col(j)|, whose square is
/// `edge_length_sq`, so that no square root is needed to compare or test them.
template <class S>
struct BoxPairAxes {
  S face_overlap[6];    ///< A's x, y, z, then B's x, y, z (unit: length)
  S edge_overlap[9];    ///< times the axis length (unit: length)
  S edge_length_sq[9];  ///< sin^2 of the angle between the edges
  S offset_along_b[3];  ///< B's centre along B's own axes, (r^T t)
};

/// Overlap along A's face axis i, and along B's face axis j given B's centre along it.
template <class S>
[[gnu::always_inline]] inline S box_face_overlap_a(int i, const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                   const Mat3T<S>& abs_r, const Vec3T<S>& t) {
  return ha[i] + abs_r(i, 0) * hb[0] + abs_r(i, 1) * hb[1] + abs_r(i, 2) * hb[2] - std::abs(t[i]);
}
template <class S>
[[gnu::always_inline]] inline S box_face_overlap_b(int j, const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                   const Mat3T<S>& abs_r, S offset_along_b) {
  return hb[j] + abs_r(0, j) * ha[0] + abs_r(1, j) * ha[1] + abs_r(2, j) * ha[2] -
         std::abs(offset_along_b);
}

/// Fills the face terms of `out` (the 6 face axes and offset_along_b).
template <class S>
[[gnu::always_inline]] inline void box_face_axes(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                 const Mat3T<S>& abs_r, const Mat3T<S>& r,
                                                 const Vec3T<S>& t, BoxPairAxes<S>& out) {
  for (int i = 0; i < 3; ++i) out.face_overlap[i] = box_face_overlap_a(i, ha, hb, abs_r, t);
  for (int j = 0; j < 3; ++j) {
    out.offset_along_b[j] = r.col(j).dot(t);
    out.face_overlap[3 + j] = box_face_overlap_b(j, ha, hb, abs_r, out.offset_along_b[j]);
  }
}

/// Fills the edge terms of `out` (the 9 edge axes), apart from the face terms: most separated
/// pairs are told apart by a face axis, and then these are not needed.
template <class S>
[[gnu::always_inline]] inline void box_edge_axes(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                 const Mat3T<S>& abs_r, const Mat3T<S>& r,
                                                 const Vec3T<S>& t, BoxPairAxes<S>& out) {
  for (int i = 0; i < 3; ++i) {
    const int i1 = kNextAxis[i], i2 = kPrevAxis[i];
    // B's radius on e_i x r.col(j) is the sum over B's axes k of hb[k] |r.col(k) . axis|, the 2x2
    // minors of rows i1, i2 of r. They are computed from r as given: for an exact rotation they
    // equal entries of r, but that identity is off by r's rounding divided by the axis length,
    // which nearly parallel edges make large. The minor of (j, j) is 0 and (k, j) is -(j, k).
    const S m01 = std::abs(r(i1, 0) * r(i2, 1) - r(i2, 0) * r(i1, 1));
    const S m02 = std::abs(r(i1, 0) * r(i2, 2) - r(i2, 0) * r(i1, 2));
    const S m12 = std::abs(r(i1, 1) * r(i2, 2) - r(i2, 1) * r(i1, 2));
    const S rb[3] = {hb[1] * m01 + hb[2] * m02, hb[0] * m01 + hb[2] * m12,
                     hb[0] * m02 + hb[1] * m12};
    for (int j = 0; j < 3; ++j) {
      const S ra = ha[i1] * abs_r(i2, j) + ha[i2] * abs_r(i1, j);
      const S offset = t[i2] * r(i1, j) - t[i1] * r(i2, j);
      out.edge_overlap[3 * i + j] = ra + rb[j] - std::abs(offset);
      out.edge_length_sq[3 * i + j] = r(i1, j) * r(i1, j) + r(i2, j) * r(i2, j);
    }
  }
}

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
  const Mat3T<S> abs_r = r.cwiseAbs();
  BoxPairAxes<S> axes;
  box_face_axes(ha, hb, abs_r, r, t, axes);
  box_edge_axes(ha, hb, abs_r, r, t, axes);
  // The least face overlap (the first on ties).
  int best = 0;
  for (int k = 1; k < 6; ++k)
    if (axes.face_overlap[k] < axes.face_overlap[best]) best = k;
  S least = axes.face_overlap[best];
  // An edge axis k wins when overlap_k / length_k < min(least, face), compared as x |x|, which
  // keeps the order, times length_k^2: products instead of a square root and a division per
  // axis. The winner so far is key / key_length_sq in that form; comparing by cross products
  // keeps divisions, whose latency would chain from one axis to the next, out of the loop.
  auto signed_square = [](S x) { return x * std::abs(x); };
  const S face_key = signed_square(least - edge_bias);
  S key = signed_square(least), key_length_sq = S(1);
  for (int k = 0; k < 9; ++k) {
    const S length_sq = axes.edge_length_sq[k];
    if (!(length_sq > S(1e-12))) continue;
    const S o = signed_square(axes.edge_overlap[k]);
    if (o < face_key * length_sq && o * key_length_sq < key * length_sq) {
      best = 6 + k;
      key = o;
      key_length_sq = length_sq;
    }
  }

  // best: 0..2 A's face axis, 3..5 B's face axis 0..2, 6 + 3 i + j the edge axis e_i x r.col(j).
  BoxBoxAxis<S> result{least, Vec3T<S>::Zero()};
  if (best < 3) {
    result.normal[best] = sign_nonneg(t[best]);
  } else if (best < 6) {
    result.normal = r.col(best - 3) * sign_nonneg(axes.offset_along_b[best - 3]);
  } else {
    const int i = (best - 6) / 3, j = (best - 6) % 3;
    const S length = std::sqrt(axes.edge_length_sq[best - 6]);
    result.overlap = axes.edge_overlap[best - 6] / length;
    Vec3T<S> axis;
    axis[i] = S(0);
    axis[kNextAxis[i]] = -r(kPrevAxis[i], j);
    axis[kPrevAxis[i]] = r(kNextAxis[i], j);
    result.normal = axis * (sign_nonneg(axis.dot(t)) / length);
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
  // Face axes one at a time: most separated pairs are told apart by the first ones.
  bool apart = false;  // some axis shows a gap > 0 (but not > `gap`)
  for (int i = 0; i < 3; ++i) {
    const S g = -box_face_overlap_a(i, ha, hb, abs_r, t);
    if (g > gap) return BoxBoxVerdict::Separated;
    apart |= g > S(0);
  }
  for (int j = 0; j < 3; ++j) {
    const S g = -box_face_overlap_b(j, ha, hb, abs_r, S(r.col(j).dot(t)));
    if (g > gap) return BoxBoxVerdict::Separated;
    apart |= g > S(0);
  }
  BoxPairAxes<S> axes;
  box_edge_axes(ha, hb, abs_r, r, t, axes);
  bool degenerate = false;
  for (int k = 0; k < 9; ++k) {
    const S g = -axes.edge_overlap[k], length_sq = axes.edge_length_sq[k];
    if (length_sq == S(0)) continue;  // exactly parallel edges: the face axes cover them
    if (length_sq < S(1e-12)) {
      degenerate = true;
      continue;
    }
    // g / length > gap, squared (both sides positive).
    if (g > S(0) && g * g > gap * gap * length_sq) return BoxBoxVerdict::Separated;
    apart |= g > S(0);
  }
  return !apart && !degenerate ? BoxBoxVerdict::Overlapping : BoxBoxVerdict::Unsure;
}

}  // namespace mink::detail
