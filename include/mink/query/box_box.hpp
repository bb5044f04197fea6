/// @file box_box.hpp
/// Two boxes (Box, or Rounded<Box>: the run-time Shape's box core) need no GJK or EPA while the
/// separating axis test can answer: intersect() asks box_box_verdict() as it computes the axes
/// (and, for overlapping boxes, first looks for a point of B at A, which spares the edge
/// axes); distance() and contact() compute all 15 (box_pair_axes()) once, for the verdict, the best
/// axis (box_best_axis()) and the closest or deepest points (box_box_closest()); manifold() asks
/// box_box_axis().
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

/// bounding_radius() of two boxes (Box or Rounded<Box>) to the last bit, with one square root
/// for both (lengths_of()).
template <class A, class B>
[[gnu::always_inline]] inline void box_bounding_radii(const A& a, const B& b,
                                                      typename A::Scalar& bound_a,
                                                      typename A::Scalar& bound_b) {
  lengths_of(BoxCore<A>::half_extents(a), BoxCore<B>::half_extents(b), bound_a, bound_b);
  bound_a += a.core_radius();
  bound_b += b.core_radius();
}

/// a.bounding_radius() and b.bounding_radius(), for two boxes with one square root
/// (box_bounding_radii()): the separating axis test's verdict waits on them.
template <class A, class B>
[[gnu::always_inline]] inline void bounding_radii(const A& a, const B& b,
                                                  typename A::Scalar& bound_a,
                                                  typename A::Scalar& bound_b) {
  if constexpr (BoxCore<A>::value && BoxCore<B>::value) {
    box_bounding_radii(a, b, bound_a, bound_b);
  } else {
    bound_a = a.bounding_radius();
    bound_b = b.bounding_radius();
  }
}

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

/// |r| entry by entry with each column padded to four entries, so that every column starts on a
/// 16-byte boundary: the pairs of entries that the compiler reads together (rows 0 and 1 of a
/// column) then come from a single store. Packed 3 x 3, the pair in the middle column straddled
/// two stores, and the load stalled on store forwarding (a sixth of the separating axis test).
template <class S>
using AbsRotation = Eigen::Matrix<S, 4, 3>;

template <class S>
[[gnu::always_inline]] inline AbsRotation<S> abs_rotation(const Mat3T<S>& r) {
  AbsRotation<S> a;
  a.template topRows<3>() = r.cwiseAbs();
  a.row(3).setZero();
  return a;
}

/// The overlaps along A's three face axes (unit: length), with packed arithmetic.
template <class S>
[[gnu::always_inline]] inline Vec3T<S> box_face_overlaps_a(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                           const AbsRotation<S>& abs_r,
                                                           const Vec3T<S>& t) {
  return ha + abs_r.col(0).template head<3>() * hb[0] + abs_r.col(1).template head<3>() * hb[1] +
         abs_r.col(2).template head<3>() * hb[2] - t.cwiseAbs();
}
/// The overlaps along B's three face axes given B's centre along them (r^T t); `rows` is r^T (its
/// columns are r's rows). B's terms come from r itself, not from AbsRotation: read from there,
/// GCC loaded rows 2 and 3 of a column as one pair, written by two separate stores, and stalled
/// on store forwarding.
template <class S>
[[gnu::always_inline]] inline Vec3T<S> box_face_overlaps_b(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                           const Mat3T<S>& rows,
                                                           const Vec3T<S>& offset_along_b) {
  return hb + rows.col(0).cwiseAbs() * ha[0] + rows.col(1).cwiseAbs() * ha[1] +
         rows.col(2).cwiseAbs() * ha[2] - offset_along_b.cwiseAbs();
}

/// Fills the face terms of `out` (the 6 face axes and offset_along_b). `rows` is r^T.
template <class S>
[[gnu::always_inline]] inline void box_face_axes(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                 const AbsRotation<S>& abs_r, const Mat3T<S>& r,
                                                 const Mat3T<S>& rows, const Vec3T<S>& t,
                                                 BoxPairAxes<S>& out) {
  using Column = Eigen::Map<Vec3T<S>>;
  Column(out.face_overlap) = box_face_overlaps_a(ha, hb, abs_r, t);
  // As box_box_verdict() computes it: the same offsets to the last bit.
  const Vec3T<S> offset_along_b = r.transpose() * t;
  Column(out.offset_along_b) = offset_along_b;
  Column(out.face_overlap + 3) = box_face_overlaps_b(ha, hb, rows, offset_along_b);
}

/// Fills the edge terms of `out` (the 9 edge axes), apart from the face terms: most separated
/// pairs are told apart by a face axis, and then these are not needed. For each of A's axes e_i,
/// the three axes e_i x r.col(j) at once, from rows i1 and i2 of r (columns of `rows`, r^T).
template <class S>
[[gnu::always_inline]] inline void box_edge_axes(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                 const Mat3T<S>& rows, const Vec3T<S>& t,
                                                 BoxPairAxes<S>& out) {
  using Column = Eigen::Map<Vec3T<S>>;
  for (int i = 0; i < 3; ++i) {
    const int i1 = kNextAxis[i], i2 = kPrevAxis[i];
    const Vec3T<S> u = rows.col(i1), v = rows.col(i2);
    // B's radius on e_i x r.col(j) is the sum over B's axes k != j of hb[k] |r.col(k) . axis|,
    // the 2x2 minors of rows i1, i2 of r: the entries of u x v, m_12, m_02 and m_01 up to sign.
    // They are computed from r as given: for an exact rotation they equal entries of r, but that
    // identity is off by r's rounding divided by the axis length, which nearly parallel edges
    // make large.
    const Vec3T<S> m = u.cross(v).cwiseAbs();
    const Vec3T<S> rb(hb[1] * m[2] + hb[2] * m[1], hb[0] * m[2] + hb[2] * m[0],
                      hb[0] * m[1] + hb[1] * m[0]);
    const Vec3T<S> ra = ha[i1] * v.cwiseAbs() + ha[i2] * u.cwiseAbs();
    const Vec3T<S> offset = t[i2] * u - t[i1] * v;
    Column(out.edge_overlap + 3 * i) = ra + rb - offset.cwiseAbs();
    Column(out.edge_length_sq + 3 * i) = u.cwiseProduct(u) + v.cwiseProduct(v);
  }
}

template <class S>
struct BoxBoxAxis {
  S overlap;        ///< least overlap (unit: length); negative when an axis separates the boxes
  Vec3T<S> normal;  ///< unit, in A's frame, from A towards B
  /// 0..2: A's face axis; 3..5: B's face axis 0..2; 6 + 3 i + j: the edge axis e_i x r.col(j).
  int index;
};

/// All 15 axes of box A (half extents ha) and box B (half extents hb) whose pose in A's frame is
/// (r, t).
template <class S>
BoxPairAxes<S> box_pair_axes(const Vec3T<S>& ha, const Vec3T<S>& hb, const Mat3T<S>& r,
                             const Vec3T<S>& t) {
  const AbsRotation<S> abs_r = abs_rotation(r);
  const Mat3T<S> rows = r.transpose();
  BoxPairAxes<S> axes;
  box_face_axes(ha, hb, abs_r, r, rows, t, axes);
  box_edge_axes(ha, hb, rows, t, axes);
  return axes;
}

/// The separating-axis answer from the axes of box_pair_axes() for the same pose (r, t) of B in
/// A's frame. Face axes win ties with edge axes, and an edge axis must beat the best
/// face by `edge_bias` (unit: length) to be taken, so that a box resting on another keeps the face
/// normal under rounding. Edge axes from nearly parallel edges (|cross| < 1e-6) carry no
/// information beyond the face axes and are skipped.
template <class S>
BoxBoxAxis<S> box_best_axis(const BoxPairAxes<S>& axes, const Mat3T<S>& r, const Vec3T<S>& t,
                            S edge_bias) {
  // The least face overlap (the first on ties), carried along: read back as face_overlap[best],
  // each step waited on a load whose address the previous step chose.
  int best = 0;
  S least = axes.face_overlap[0];
  for (int k = 1; k < 6; ++k) {
    const S overlap = axes.face_overlap[k];
    if (overlap < least) {
      least = overlap;
      best = k;
    }
  }
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
  // The normals are built by arithmetic, not written coordinate by coordinate: a vector written
  // in parts and then read whole stalls on store forwarding.
  BoxBoxAxis<S> result{least, Vec3T<S>::Zero(), best};
  if (best < 3) {
    result.normal = Vec3T<S>::Unit(best) * sign_nonneg(t[best]);
  } else if (best < 6) {
    result.normal = r.col(best - 3) * sign_nonneg(axes.offset_along_b[best - 3]);
  } else {
    const int i = (best - 6) / 3, j = (best - 6) % 3;
    const S length = std::sqrt(axes.edge_length_sq[best - 6]);
    result.overlap = axes.edge_overlap[best - 6] / length;
    const Vec3T<S> axis = Vec3T<S>::Unit(i).cross(r.col(j));  // exact: products with 0 and 1
    result.normal = axis * (sign_nonneg(axis.dot(t)) / length);
  }
  return result;
}

/// box_best_axis() of box_pair_axes(): the separating-axis answer for boxes A and B. Flattened
/// (both inlined here, not in distance() and contact(), which got slower): the manifold's
/// separating axis test then keeps the axes in registers instead of writing and rereading
/// them (3 % of a box pair's manifold).
template <class S>
[[gnu::flatten]] BoxBoxAxis<S> box_box_axis(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                            const Mat3T<S>& r, const Vec3T<S>& t, S edge_bias) {
  return box_best_axis(box_pair_axes(ha, hb, r, t), r, t, edge_bias);
}

/// What the separating axis test (with the common points of box_box_verdict()) can tell about two
/// boxes without GJK: `gap` (unit: length, >= 0) is
/// how far apart their cores may be and still count as intersecting (the radii plus the touching
/// tolerance).
enum class BoxBoxVerdict { Separated, Overlapping, Unsure };

/// The verdict's part from the edge axes of `axes`, the face axes having shown no gap above `gap`
/// (`apart`: some showed a gap above 0).
template <class S>
BoxBoxVerdict box_edge_verdict(const BoxPairAxes<S>& axes, S gap, bool apart) {
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

/// Whether B's point x (in B's frame, inside B: half extents hb) lies within `gap` (unit: length)
/// of box A (half extents ha), B being at (r, t) in A's frame: a point of B that close to A proves
/// that the boxes count as intersecting, at the cost of one or two points' transforms. x is taken
/// to A's frame as r x + t, the map of B's support points, so the proof holds for r as given (to
/// rounding), even when r is orthonormal only to the 1e-6 that pose_error() allows; checking a
/// point of A in B's frame would need r's inverse, not its transpose. Each coordinate may exceed
/// A's extent by gap / sqrt(3), which bounds the distance by gap, with no squares to underflow. (A
/// NaN from an overflowed product compares false and leaves the answer to the axes.)
template <class S>
[[gnu::always_inline]] inline bool box_point_of_b_near_a(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                         const Mat3T<S>& r, const Vec3T<S>& t,
                                                         const Vec3T<S>& x, S gap) {
  const Vec3T<S> on_b = x.cwiseMax(-hb).cwiseMin(hb);
  const Vec3T<S> y = r * on_b + t;
  const S slack = gap * S(0.577);  // a little under gap / sqrt(3)
  return ((y.cwiseAbs() - ha).array() <= slack).all();
}

/// Separated as soon as one of the 15 axes separates the boxes by more than `separation_gap` (the
/// distance is at least that, to rounding, for the rotation r as given); Overlapping when no axis
/// separates them at all (the separating axis theorem), or when a point of B lies within
/// `proof_gap` of A
/// (box_point_of_b_near_a(), tried after each box's face axes, which tell most separated pairs
/// apart first). The points tried: B's point nearest to A's point nearest to B's centre, and B's
/// point nearest to A's centre; one of them is in A for most overlapping pairs (resting contact,
/// three quarters of random overlaps), where the axes would all be needed. Unsure in between, and
/// also when an edge axis is nearly degenerate (edges parallel to 1e-6 but not exactly) and no
/// point proved the overlap, where the theorem's axis cannot be trusted to rounding. For the
/// verdict on a gap g (unit: length; the core distance that still counts as intersecting),
/// proof_gap <= g <= separation_gap: Unsure where the bounds leave it open. This form
/// computes the axes as it goes, for intersect(), which is its only caller: always inlined there,
/// so that the relative pose stays in registers instead of going to the call through memory
/// (a separated box pair's boolean 18.0 -> 15.9 ns in a driver).
template <class S>
[[gnu::always_inline]] inline BoxBoxVerdict box_box_verdict(const Vec3T<S>& ha, const Vec3T<S>& hb,
                                                            const Mat3T<S>& r, const Vec3T<S>& t,
                                                            S proof_gap, S separation_gap) {
  const AbsRotation<S> abs_r = abs_rotation(r);
  bool apart = false;  // some axis shows a gap > 0 (but not > `separation_gap`)
  const Vec3T<S> face_a = box_face_overlaps_a(ha, hb, abs_r, t);
  for (int i = 0; i < 3; ++i) {
    const S g = -face_a[i];
    if (g > separation_gap) return BoxBoxVerdict::Separated;
    apart |= g > S(0);
  }
  // A's point nearest to B's centre, taken to B's frame (then clamped to B).
  const Vec3T<S> near_b_centre = r.transpose() * (Vec3T<S>(t.cwiseMax(-ha).cwiseMin(ha)) - t);
  if (box_point_of_b_near_a(ha, hb, r, t, near_b_centre, proof_gap))
    return BoxBoxVerdict::Overlapping;
  // B's centre along B's axes, whole (built entry by entry, it would stall when read whole): A's
  // centre is at -offset_along_b in B's frame.
  const Vec3T<S> offset_along_b = r.transpose() * t;
  const Mat3T<S> rows = r.transpose();
  const Vec3T<S> face_b = box_face_overlaps_b(ha, hb, rows, offset_along_b);
  for (int j = 0; j < 3; ++j) {
    const S g = -face_b[j];
    if (g > separation_gap) return BoxBoxVerdict::Separated;
    apart |= g > S(0);
  }
  if (box_point_of_b_near_a(ha, hb, r, t, Vec3T<S>(-offset_along_b), proof_gap))
    return BoxBoxVerdict::Overlapping;
  BoxPairAxes<S> axes;
  box_edge_axes(ha, hb, rows, t, axes);
  return box_edge_verdict(axes, separation_gap, apart);
}

/// The same verdict from all 15 axes already computed (box_pair_axes()), for the queries that
/// need the best axis as well.
template <class S>
BoxBoxVerdict box_box_verdict(const BoxPairAxes<S>& axes, S gap) {
  bool apart = false;
  for (int k = 0; k < 6; ++k) {
    const S g = -axes.face_overlap[k];
    if (g > gap) return BoxBoxVerdict::Separated;
    apart |= g > S(0);
  }
  return box_edge_verdict(axes, gap, apart);
}

/// The corner of a box (half extents h) farthest along d, except that a coordinate whose |d_k| is
/// at most `tie` is a tie (the support feature is an edge or a face along it) and is taken as
/// `towards_k` clamped to the box: the point of the support feature nearest to the line through
/// `towards` along d, when d is orthogonal to the tied axes (the box's axes are orthonormal, so
/// the coordinates separate). Its support value falls short of the maximum by at most
/// 2 tie (h_0 + h_1 + h_2).
template <class S>
[[gnu::always_inline]] inline Vec3T<S> box_support_towards(const Vec3T<S>& h, const Vec3T<S>& d,
                                                           const Vec3T<S>& towards, S tie) {
  Vec3T<S> p;
  for (int k = 0; k < 3; ++k)
    p[k] = std::abs(d[k]) > tie ? sign_nonneg(d[k]) * h[k] : std::clamp(towards[k], -h[k], h[k]);
  return p;
}

/// Support features within this (relative to a unit direction) of a tie count as ties.
inline constexpr double kBoxTie = 1e-12;

/// An edge of box A (half extents ha) along A's axis i and an edge of box B (half extents hb, at
/// (r, t) in A's frame) along B's axis j, in A's frame: each through the corner of its box whose
/// other coordinates take the signs of a direction (`along_a` in A's frame, `along_b` in B's; the
/// edges of the support features along them). Their directions are unit, e_i and v = r.col(j),
/// which makes the closest points a few products and one division, where the general segment
/// code (closest_points_of_segments()) takes squared lengths, reciprocals and range checks (190
/// instructions a pair, a sixth of a box manifold on crossing edges). Unit directions also keep
/// every product within the range of the coordinates: no squared length underflows or overflows.
template <class S>
struct BoxEdgePair {
  int i, j;
  S half_a, half_b;              // the edges' half lengths, ha[i] and hb[j]
  Vec3T<S> ca, cb, v, cross;     // centres, B's direction, and e_i x v (the common perpendicular)
  S cross_sq, inverse_cross_sq;  // sin^2 of the edges' angle and its reciprocal (0 if parallel)

  BoxEdgePair(const Vec3T<S>& ha, int axis_a, const Vec3T<S>& along_a, const Vec3T<S>& hb,
              int axis_b, const Vec3T<S>& along_b, const Mat3T<S>& r, const Vec3T<S>& t)
      : i(axis_a), j(axis_b), half_a(ha[axis_a]), half_b(hb[axis_b]) {
    // The box's support corner along the direction, the edge's own coordinate then set to 0
    // (exactly) by arithmetic on the whole vector: written coordinate by coordinate and read
    // whole, it would stall.
    auto centre = [](const Vec3T<S>& h, const Vec3T<S>& d, int k) {
      const Vec3T<S> corner = BoxT<S>{h}.support_core(d);
      return Vec3T<S>(corner - Vec3T<S>::Unit(k) * corner[k]);
    };
    ca = centre(ha, along_a, i);
    v = r.col(j);
    cb = r * centre(hb, along_b, j) + t;
    cross = Vec3T<S>::Unit(i).cross(v);  // exact: products with 0 and 1
    cross_sq = cross.squaredNorm();
    // Ready while the centres are built: the division stays off the chain to the points.
    inverse_cross_sq = cross_sq > S(0) ? S(1) / cross_sq : S(0);
  }

  /// Whether the edges are parallel to within `limit` (unit: length): |da x db| <= limit
  /// max(|da|, |db|) for the whole edges da = 2 half_a e_i and db = 2 half_b v.
  bool parallel(S limit) const {
    const S shorter = S(2) * std::min(half_a, half_b);
    return shorter * shorter * cross_sq <= limit * limit;
  }

  /// The closest points of the two edges, on_a on A's and on_b on B's; returns whether both lie
  /// strictly inside their edges. With w = cb - ca, |s e_i - t v - w|^2 is minimised over
  /// |s| <= half_a and |t| <= half_b by the lines' critical s clamped, the best t for it clamped,
  /// and the best s for that t clamped (Ericson's order, exact for a convex quadratic on a
  /// rectangle; the last step without a branch: when t needs no clamp it gives s again). The
  /// critical s is (w x v).(e_i x v) / |e_i x v|^2, whose error grows as 1 / sin of the edges'
  /// angle, not as its square like Cramer's rule's; parallel lines take s = 0.
  bool closest_points(Vec3T<S>& on_a, Vec3T<S>& on_b) const {
    const Vec3T<S> w = cb - ca;
    const S b = v[i], c = w[i], f = v.dot(w);
    S s = std::clamp(w.cross(v).dot(cross) * inverse_cross_sq, -half_a, half_a);
    const S t = std::clamp(b * s - f, -half_b, half_b);
    s = std::clamp(c + b * t, -half_a, half_a);
    on_a = ca + Vec3T<S>::Unit(i) * s;
    on_b = cb + v * t;
    return std::abs(s) < half_a && std::abs(t) < half_b;
  }
};

/// The closest points of A's and B's support edges along the edge axis `axis` (A's frame), when
/// both lie inside their edges: two crossing edges, whose closest points differ along the axis
/// only. False when an edge has no length (1e-12 of the boxes' size), the support feature along the
/// axis is a face (a tie), a closest point is an end point, or the points differ off the axis.
template <class S>
bool box_box_crossing_edges(const Vec3T<S>& ha, const Vec3T<S>& hb, const Mat3T<S>& r,
                            const Vec3T<S>& t, const BoxBoxAxis<S>& axis, Vec3T<S>& on_a,
                            Vec3T<S>& on_b) {
  const S tie = S(kBoxTie);
  const Vec3T<S>& n = axis.normal;
  const int i = (axis.index - 6) / 3, j = (axis.index - 6) % 3;
  // Edges shorter than the tie tolerance of the boxes' size are corners (a box flat to 1e-300):
  // their closest points need not differ along the axis.
  const S shortest = tie * std::max(ha.maxCoeff(), hb.maxCoeff());
  if (!(ha[i] > shortest && hb[j] > shortest)) return false;
  const Vec3T<S> d_b = -(r.transpose() * n);
  for (int k = 0; k < 3; ++k)
    if ((k != i && !(std::abs(n[k]) > tie)) || (k != j && !(std::abs(d_b[k]) > tie))) return false;
  if (!BoxEdgePair<S>(ha, i, n, hb, j, d_b, r, t).closest_points(on_a, on_b)) return false;
  // Crossing edges' closest points differ along the axis only; a check against rounding
  // gone wrong far from the boxes (true crossings stay within 3 eps of the pair's magnitude,
  // 2e6 random ones).
  const Vec3T<S> gap = on_b - on_a;
  const S off_axis = (gap - gap.dot(n) * n).cwiseAbs().maxCoeff();
  const S magnitude = t.cwiseAbs().maxCoeff() + ha.maxCoeff() + hb.maxCoeff();
  return off_axis <= S(64) * std::numeric_limits<S>::epsilon() * magnitude;
}

/// Closest points over a face: the reference box (half extents h_ref, at the origin of its frame)
/// has its face i with outward normal side * e_i towards the other box (half extents h_other,
/// pose (r, t) in the reference frame). The other box's support point along -side * e_i, q, is
/// a closest point when its projection p on the face's plane lies on the face: q - p is then the
/// gap along the face normal, which no pair of points can beat. When the other box's support
/// feature is an edge or a face (ties), q is its point nearest to the line through the face's
/// centre, and if that misses the face, its point nearest to the face's nearest point to it (one
/// step of alternating projections between the two). Returns false when q misses the face; on
/// true, on_ref and on_other are in the reference frame and `distance` is the gap (negative: the
/// depth of q below the face, whose deepest point it then is).
template <class S>
bool closest_over_face(const Vec3T<S>& h_ref, const Vec3T<S>& h_other, const Mat3T<S>& r,
                       const Vec3T<S>& t, int i, S side, Vec3T<S>& on_ref, Vec3T<S>& on_other,
                       S& distance) {
  const S tie = S(kBoxTie);
  const Vec3T<S> d = -side * r.row(i).transpose();  // -side e_i in the other box's frame
  const int j = kNextAxis[i], k = kPrevAxis[i];
  auto over_face = [&](const Vec3T<S>& p) {
    return std::abs(p[j]) <= h_ref[j] && std::abs(p[k]) <= h_ref[k];
  };
  on_other = r * box_support_towards(h_other, d, Vec3T<S>(-(r.transpose() * t)), tie) + t;
  if (!over_face(on_other)) {
    if (!(d.cwiseAbs().minCoeff() <= tie)) return false;  // a single vertex: no other choice
    Vec3T<S> target = on_other;
    target[j] = std::clamp(target[j], -h_ref[j], h_ref[j]);
    target[k] = std::clamp(target[k], -h_ref[k], h_ref[k]);
    on_other = r * box_support_towards(h_other, d, Vec3T<S>(r.transpose() * (target - t)), tie) + t;
    if (!over_face(on_other)) return false;
  }
  on_ref = on_other;
  on_ref[i] = side * h_ref[i];
  distance = side * on_other[i] - h_ref[i];
  return true;
}

/// Closest points of two boxes (A: half extents ha; B: half extents hb, pose (r, t) in A's frame)
/// in closed form, from their axes (box_pair_axes()) and the separating axis that box_best_axis()
/// found in them, or their deepest points when they overlap.
///
/// Apart (`apart`: axis.overlap < 0): the distance of two separated convex sets is the largest
/// gap over all directions, so a point p of A and a point q of B with q - p = gap * n for some
/// direction n with a positive gap are closest points:
///   - a face axis: q on the other box's support feature, p its projection on the face, which
///     must lie on the face (a vertex, edge or face over a face; closest_over_face());
///   - an edge axis: the closest points of A's and B's support edges, both interior to their
///     edges (crossing edges), where q - p is orthogonal to both, hence along n.
/// When the best axis fails, the best face axis of each box is tried: an edge axis wins over a
/// parallel face by rounding alone when two faces are parallel.
///
/// Overlapping: on the least-overlap axis only (the depth is that overlap), the same features give
/// the deepest points, B's deepest point and its projection on A's face (or the reverse), or the
/// crossing edges' closest points; `distance` is then minus the depth.
///
/// Otherwise (apart: the closest features are a vertex and a vertex or an edge, whose direction is
/// none of the 15 axes, or parallel edges; overlapping: the deepest point is not over the face)
/// it returns false and the caller runs GJK or clips. On true, on_a and on_b are in A's frame,
/// `normal` (unit, from A towards B) is the axis used and `distance` = (on_b - on_a) . normal. A
/// support feature tied to within 1e-12 of the axis (boxes turned by quarter turns, rounded)
/// counts as an edge or a face, which changes the distance by at most 2e-12 of the boxes' size.
template <class S>
bool box_box_closest(const Vec3T<S>& ha, const Vec3T<S>& hb, const Mat3T<S>& r, const Vec3T<S>& t,
                     const BoxPairAxes<S>& axes, const BoxBoxAxis<S>& axis, bool apart,
                     Vec3T<S>& on_a, Vec3T<S>& on_b, Vec3T<S>& normal, S& distance) {
  // A's face i on the `side` towards B.
  auto over_a = [&](int i, S side) {
    if (!closest_over_face(ha, hb, r, t, i, side, on_a, on_b, distance)) return false;
    normal = Vec3T<S>::Zero();
    normal[i] = side;
    return !apart || distance > S(0);
  };
  // B's face j on the `side` towards A, as the reference box: A's pose in B's frame is
  // (r^T, -r^T t).
  auto over_b = [&](int j, S side) {
    const Mat3T<S> rt = r.transpose();
    const Vec3T<S> tb = -(rt * t);
    Vec3T<S> on_b_local, on_a_local;
    if (!closest_over_face(hb, ha, rt, tb, j, side, on_b_local, on_a_local, distance)) return false;
    on_a = r * on_a_local + t;
    on_b = r * on_b_local + t;
    normal = -side * r.col(j);
    return !apart || distance > S(0);
  };
  // The face axis of each box with the largest gap (least overlap), on its side towards the
  // other box.
  auto over_best_face_a = [&] {
    int best = 0;
    for (int i = 1; i < 3; ++i)
      if (axes.face_overlap[i] < axes.face_overlap[best]) best = i;
    return over_a(best, sign_nonneg(t[best]));
  };
  auto over_best_face_b = [&] {
    int best = 0;
    for (int j = 1; j < 3; ++j)
      if (axes.face_overlap[3 + j] < axes.face_overlap[3 + best]) best = j;
    return over_b(best, -sign_nonneg(axes.offset_along_b[best]));
  };
  if (axis.index < 3)
    return over_a(axis.index, axis.normal[axis.index]) || (apart && over_best_face_b());
  if (axis.index < 6) {
    const int j = axis.index - 3;
    return over_b(j, axis.normal.dot(r.col(j)) > S(0) ? S(-1) : S(1)) ||
           (apart && over_best_face_a());
  }
  if (box_box_crossing_edges(ha, hb, r, t, axis, on_a, on_b)) {
    normal = axis.normal;
    distance = (on_b - on_a).dot(normal);
    if (!apart || distance > S(0)) return true;
  }
  return apart && (over_best_face_a() || over_best_face_b());
}

}  // namespace mink::detail
