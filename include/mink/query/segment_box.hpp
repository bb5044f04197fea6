/// @file segment_box.hpp
/// A segment core (capsules, segments, and their rounded versions) against a box core (boxes,
/// rounded boxes): their closest points in closed form while the cores are apart.
///
/// Why: GJK on a needle against a needle (a capsule of radius 3e-9 lying 6e-9 from a box 1e-6
/// thick and 3 long, the two nearly parallel) builds simplices too thin for their weights to be
/// trusted; it stopped at its cap with the distance off by the whole gap (2.8e-9 apart where they
/// touch). A capsule resting by a box is also the commonest pair of a character against a level.
///
/// How: in the box's frame the segment is c + t d for t in [-1, 1]. The squared distance of its
/// point to the box, f(t) = sum_i max(0, |c_i + t d_i| - h_i)^2, is convex and, between the (at
/// most six) parameters where the point crosses a face's plane, a quadratic whose minimum is in
/// closed form: t = sum (s_i h_i - c_i) d_i / sum d_i^2 over the axes on which the point lies
/// beyond the face on side s_i. A stretch whose minimum lies inside it holds the minimum; else it
/// is at a crossing. Where f is flat (the segment parallel to a face or an edge), the middle of
/// the stretch of least f is taken, so that the points do not jump from one end to the other.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "mink/gjk/segment_cores.hpp"
#include "mink/math/orthogonal.hpp"
#include "mink/query/box_box.hpp"
#include "mink/query/point_solid.hpp"

namespace mink::detail {

/// A shape whose core is a segment or a point that may be one (capsules, segments), not a sphere
/// or point: those have the point core's closed forms (point_solid.hpp).
template <class T>
inline constexpr bool kLineCore = SegmentCore<T>::value && !PointCore<T>::value;

/// A segment core against a box core, either order.
template <class A, class B>
inline constexpr bool kSegmentBox = (kLineCore<A> && BoxCore<B>::value) ||
                                    (BoxCore<A>::value && kLineCore<B>);

/// The closest points of the segment c + t d (t in [-1, 1]) and the box of half extents h (both
/// in the box's frame), and the segment's point minus the box's (0 when they meet), with the
/// segment's parameter t and direction d. Nothing when the arithmetic overflows.
template <class S>
struct SegmentBoxLocal {
  Vec3T<S> on_segment, on_box, gap;
  Vec3T<S> along;         ///< d
  Vec3T<S> half_extents;  ///< h
  S t;
  S terms_sq;  ///< |c|^2 + |d|^2 + |h|^2: the scale of the points' rounding
};

template <class S>
std::optional<SegmentBoxLocal<S>> segment_box_local(const Vec3T<S>& c, const Vec3T<S>& d,
                                                    const Vec3T<S>& h) {
  // The parameters where the point crosses a face's plane, inside (-1, 1), and the ends.
  S cuts[8];
  int count = 0;
  cuts[count++] = S(-1);
  for (int i = 0; i < 3; ++i) {
    if (d[i] == S(0)) continue;
    for (const S side : {S(-1), S(1)}) {
      const S t = (side * h[i] - c[i]) / d[i];
      if (t > S(-1) && t < S(1)) cuts[count++] = t;
    }
  }
  // In order, by insertion: at most six (std::sort on the array drew GCC's -Warray-bounds).
  for (int k = 2; k < count; ++k)
    for (int j = k; j > 1 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
  cuts[count++] = S(1);
  auto excess = [&](S t) {
    const Vec3T<S> p = c + t * d;
    return Vec3T<S>(p - p.cwiseMax(-h).cwiseMin(h));
  };
  auto answer = [&](S t) -> std::optional<SegmentBoxLocal<S>> {
    SegmentBoxLocal<S> out;
    out.on_segment = c + t * d;
    out.on_box = out.on_segment.cwiseMax(-h).cwiseMin(h);
    out.gap = out.on_segment - out.on_box;
    out.along = d;
    out.half_extents = h;
    out.t = t;
    out.terms_sq = c.squaredNorm() + d.squaredNorm() + h.squaredNorm();
    if (!is_finite(out.on_segment) || !is_finite(out.gap)) return std::nullopt;
    return out;
  };
  // f at the cuts, and each value's rounding: each gap coordinate is good to a few ulps of its
  // own terms, |c_i| + |d_i| + h_i, and f's rounding is about eps times the sum of those times the
  // gap's coordinates. Not the largest input for every coordinate: a box 4.5e15 long in z made
  // both ends of a segment 1.7e10 away along x ties, whose middle then gave the gap's direction
  // 90 degrees off (orthogonal to the segment, segment_box_direction()).
  S values[8], roundings[8];
  const Vec3T<S> terms = c.cwiseAbs() + d.cwiseAbs() + h;
  for (int k = 0; k < count; ++k) {
    const Vec3T<S> e = excess(cuts[k]);
    values[k] = e.squaredNorm();
    roundings[k] = e.cwiseAbs().dot(terms);
  }
  const int best_cut = int(std::min_element(values, values + count) - values);
  const S best = values[best_cut];
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  auto within_rounding_of_best = [&](S value, S rounding) {
    return value - best <= S(8) * kEps * (rounding + roundings[best_cut]);
  };
  // A stretch whose own minimum lies inside it holds the minimum, the only one (f is convex, and
  // strictly so there). Its value may differ from a cut's by less than f's rounding (tilted by
  // 1e-7, the least f lies 8e-9 past a cut and 3e-17 of f below it), so it need only not exceed
  // the least cut's value by more than that. A minimum that lies inside only by the rounding of t
  // does exceed it: a segment 1e-8 rad off a face's plane, its end 8e-9 beyond the face, lies on
  // the face over half its length (f = 0 there) but took that end, 8e-9 apart.
  for (int k = 0; k + 1 < count; ++k) {
    if (!(cuts[k + 1] > cuts[k])) continue;
    const Vec3T<S> mid = c + (S(0.5) * (cuts[k] + cuts[k + 1])) * d;
    S numerator = S(0), denominator = S(0);
    for (int i = 0; i < 3; ++i) {
      if (std::abs(mid[i]) <= h[i]) continue;
      const S side = mid[i] > S(0) ? S(1) : S(-1);
      numerator += (side * h[i] - c[i]) * d[i];
      denominator += d[i] * d[i];
    }
    if (denominator > S(0)) {
      const S t = numerator / denominator;
      if (t > cuts[k] && t < cuts[k + 1]) {
        const Vec3T<S> e = excess(t);
        if (within_rounding_of_best(e.squaredNorm(), e.cwiseAbs().dot(terms))) return answer(t);
      }
    }
  }
  if (!std::isfinite(best)) return std::nullopt;
  // Else the minimum is at a cut, or on a stretch where f is flat (the segment parallel to a face
  // or an edge, or through the box): the middle of the cuts where f is least, to its rounding. A
  // segment parallel to a face to rounding (a quarter turn's cosine, 6e-17) would otherwise end at
  // one end or the other by a coin toss.
  S first = S(1), last = S(-1);
  for (int k = 0; k < count; ++k) {
    if (!within_rounding_of_best(values[k], roundings[k])) continue;
    first = std::min(first, cuts[k]);
    last = std::max(last, cuts[k]);
  }
  return answer(S(0.5) * (first + last));
}

/// The unit direction of the gap of segment_box_local()'s answer when it is tiny next to the
/// points it came from, `plain` its plain quotient: the gap is a difference of points some L from
/// the box's centre, good to eps L in each coordinate on which the point lies beyond a face, and
/// cores 1e-11 L apart had a normal 1e-5 rad off, whose support value along it missed the distance
/// by 1e-5 of the size. The true direction is orthogonal to the segment where its point is
/// interior, and to every box axis on which the point lies inside the box's slab (below).
template <class S>
Vec3T<S> segment_box_direction(const SegmentBoxLocal<S>& local, const Vec3T<S>& plain) {
  if (!(std::abs(local.t) < S(1))) return plain;  // an end point: no constraint along the segment
  // An interior point where the segment crosses a face's plane (a kink of the distance) need not
  // be a stationary one: its gap is then not orthogonal to the segment beyond rounding (a few eps
  // of the terms), and it is left as it is. (A segment's end 4e-16 beyond a face's plane had its
  // point at the crossing, 4e-16 from the end; made orthogonal to the segment, the normal was 85
  // degrees off.)
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  if (!(std::abs(plain.dot(local.along)) * local.gap.norm() <=
        S(16) * kEps * std::sqrt(local.terms_sq) * local.along.norm()))
    return plain;
  // The normal's component is 0 on the axes where the point lies inside the box's slab by more
  // than rounding (the gap is 0 there); on the others, beyond a face or on a slab's boundary
  // (over an edge or a corner), it is free, but must point out of the box. The distance is
  // stationary past the point where a segment tilted from a face passes over its edge, by less
  // than t's rounding, and there the gap leans off the face's axis by the tilt (a segment 1.7e-8
  // rad from a face, 1.9e-9 above its edge: the face's axis was 1.7e-8 rad off, and its support
  // value 4.5e-8 of the size short). A coordinate equal to a half extent is on the boundary, not
  // inside: a segment 4e-9 rad from a face, over its corner 5.6e-10 away, had its normal held to
  // that face's axis (it carried 2e-16 of rounding beyond a third face), and 1.5e-9 short.
  const S rounding = S(16) * kEps * std::sqrt(local.terms_sq);
  int inside = 0, slab = -1;
  for (int i = 0; i < 3; ++i)
    if (local.half_extents[i] - std::abs(local.on_segment[i]) > rounding) {
      ++inside;
      slab = i;
    }
  if (inside >= 2) return plain;  // over a face: along its axis exactly
  Vec3T<S> n = local.gap;
  const Vec3T<S> held = inside == 1 ? Vec3T<S>(Vec3T<S>::Unit(slab)) : Vec3T<S>(Vec3T<S>::Zero());
  if (!make_orthogonal(n, local.along, held)) return plain;
  // Out of the box: no component against the point's side beyond rounding (a segment parallel to
  // a face, its point 7e-18 beyond a side face, has a normal of -6e-17 along that side's axis).
  for (int i = 0; i < 3; ++i)
    if (i != slab && n[i] * local.on_segment[i] < -S(16) * kEps * std::abs(local.on_segment[i]))
      return plain;
  return n;
}

/// segment_box_local() for a pair (either order): in the box's frame.
template <class A, class B>
std::optional<SegmentBoxLocal<typename A::Scalar>> segment_box_pair_local(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  if constexpr (BoxCore<A>::value) {
    const CoreSegment<S> segment = SegmentCore<B>::world(b, pose_b, pose_a.translation);
    return segment_box_local(pose_a.inverse_rotate(segment.centre),
                             pose_a.inverse_rotate(segment.half),
                             Vec3T<S>(BoxCore<A>::half_extents(a)));
  } else {
    const CoreSegment<S> segment = SegmentCore<A>::world(a, pose_a, pose_b.translation);
    return segment_box_local(pose_b.inverse_rotate(segment.centre),
                             pose_b.inverse_rotate(segment.half),
                             Vec3T<S>(BoxCore<B>::half_extents(b)));
  }
}

/// segment_box_pair_local() in the world frame: the cores' closest points, their distance and
/// the unit normal from A's core towards B's (valid when the distance is > 0).
template <class A, class B>
std::optional<CorePair<typename A::Scalar>> segment_box_world(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  constexpr bool kBoxIsA = BoxCore<A>::value;
  const PoseT<S>& box_pose = kBoxIsA ? pose_a : pose_b;
  const auto local = segment_box_pair_local(a, pose_a, b, pose_b);
  if (!local) return std::nullopt;
  const S gap_sq = local->gap.squaredNorm();
  const S distance = length_of(local->gap, gap_sq);
  // From the box towards the segment; +z of the box when they meet (unused then).
  Vec3T<S> out_of_box =
      distance > S(0) ? Vec3T<S>(unit_of(local->gap, gap_sq, distance)) : Vec3T<S>::UnitZ();
  if (distance > S(0) && gap_sq < S(1e-6) * local->terms_sq)
    out_of_box = segment_box_direction(*local, out_of_box);
  const CorePair<S> out =
      ordered_core_pair<kBoxIsA>(box_pose.apply(local->on_box), box_pose.apply(local->on_segment),
                                 box_pose.rotate(out_of_box), distance, false);
  if (!std::isfinite(out.distance) || !is_finite(out.on_a) || !is_finite(out.on_b))
    return std::nullopt;
  return out;
}

}  // namespace mink::detail
