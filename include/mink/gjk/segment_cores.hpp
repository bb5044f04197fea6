/// @file segment_cores.hpp
/// Closed-form queries for shapes whose core is a point or a segment: spheres, capsules, points,
/// segments, and their Rounded versions. Two such cores need no iteration: the distance between
/// two segments has a closed form, so sphere and capsule pairs are exact to rounding and cost a
/// few dozen flops. intersect() and distance() take this path automatically.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "mink/math/orthogonal.hpp"
#include "mink/math/pose.hpp"
#include "mink/shapes/capsule.hpp"
#include "mink/shapes/point.hpp"
#include "mink/shapes/segment.hpp"
#include "mink/shapes/sphere.hpp"
#include "mink/support/rounded.hpp"

#if defined(__clang__)
#define MINK_SEGMENT_CORES_INLINE [[gnu::always_inline]] inline
#else
#define MINK_SEGMENT_CORES_INLINE inline
#endif

namespace mink::detail {

/// A point or segment core in the world frame shifted to some origin: the points
/// centre + u half for u in [-1, 1] (half = 0 for a point core). The centre-and-half form saves
/// the end points' arithmetic: a capsule's core is its pose's z column scaled, about its centre.
template <class S>
struct CoreSegment {
  Vec3T<S> centre;
  Vec3T<S> half;
};

/// SegmentCore<T>::world(shape, pose, origin) gives T's core as a CoreSegment in the world frame
/// shifted to `origin`. Only for shapes whose core is a point or a segment. `kCentred`: the core's
/// centre is the pose's origin (spheres, capsules), so about that origin it is exactly 0.
template <class T>
struct SegmentCore : std::false_type {};

template <class S>
struct SegmentCore<SphereT<S>> : std::true_type {
  static constexpr bool kCentred = true;
  static CoreSegment<S> world(const SphereT<S>&, const PoseT<S>& pose, const Vec3T<S>& origin) {
    return {pose.translation - origin, Vec3T<S>::Zero()};
  }
};

template <class S>
struct SegmentCore<CapsuleT<S>> : std::true_type {
  static constexpr bool kCentred = true;
  static CoreSegment<S> world(const CapsuleT<S>& c, const PoseT<S>& pose, const Vec3T<S>& origin) {
    // The core is (0, 0, +-h): the rotation's z column scaled, no matrix product needed.
    return {pose.translation - origin, pose.rotation.col(2) * c.half_height};
  }
};

template <class S>
struct SegmentCore<PointT<S>> : std::true_type {
  static constexpr bool kCentred = false;
  static CoreSegment<S> world(const PointT<S>& point, const PoseT<S>& pose,
                              const Vec3T<S>& origin) {
    return {pose.rotation * point.position + (pose.translation - origin), Vec3T<S>::Zero()};
  }
};

template <class S>
struct SegmentCore<SegmentT<S>> : std::true_type {
  static constexpr bool kCentred = false;
  static CoreSegment<S> world(const SegmentT<S>& s, const PoseT<S>& pose, const Vec3T<S>& origin) {
    return {pose.rotation * (S(0.5) * (s.a + s.b)) + (pose.translation - origin),
            pose.rotation * (S(0.5) * (s.b - s.a))};
  }
};

template <class T>
struct SegmentCore<Rounded<T>> : std::bool_constant<SegmentCore<T>::value> {
  using S = typename T::Scalar;
  static constexpr bool kCentred = SegmentCore<T>::kCentred;
  static CoreSegment<S> world(const Rounded<T>& r, const PoseT<S>& pose, const Vec3T<S>& origin) {
    return SegmentCore<T>::world(r.shape, pose, origin);
  }
};

template <class A, class B>
inline constexpr bool kSegmentCores = SegmentCore<A>::value&& SegmentCore<B>::value;

/// The parameters u, v in [-1, 1] of closest_points_of_segments() below.
template <class S>
struct SegmentParameters {
  S u, v;
};

/// The parameters for half vectors hp, hq (squared lengths a, e) and centres w apart (q's minus
/// p's).
template <class S>
[[gnu::always_inline]] inline SegmentParameters<S> segment_parameters(const Vec3T<S>& hp,
                                                                      const Vec3T<S>& hq,
                                                                      const Vec3T<S>& w, S a, S e) {
  const S b = hp.dot(hq);
  const S c = hp.dot(w), f = hq.dot(w);  // the best u for a given v is (c + b v) / a
  S u = S(0), v = S(0);
  if (!(e > S(0))) {
    // q is a point: its projection on p (or p's centre when p is a point too).
    if (a > S(0)) u = std::clamp(c / a, S(-1), S(1));
  } else if (!(a > S(0))) {
    v = std::clamp(-f / e, S(-1), S(1));
  } else {
    const S ae = a * e, det = ae - b * b;
    if (det >= S(0.0625) * ae) {
      u = std::clamp((c * e - b * f) / det, S(-1), S(1));
    } else {
      // u = (w x hq).n / |n|^2 with n = hp x hq; parallel lines (n = 0) keep u = 0.
      const Vec3T<S> n = hp.cross(hq);
      const S nn = n.squaredNorm();
      if (nn > S(0)) u = std::clamp(w.cross(hq).dot(n) / nn, S(-1), S(1));
    }
    // Without branches (which way the clamps go is a coin toss on random poses): when v needs no
    // clamp, the best u for it is u again (to rounding); when the critical u was clamped to +-1,
    // so is the best u for v, which lies between the critical u and +-1.
    // The quotients by a and e are ready before u is: the chain u -> v -> u has no division in
    // it, and one product and one sum per step (capsule distance 4 % faster than with the
    // reciprocals applied after each sum).
    const S inverse_a = S(1) / a, inverse_e = S(1) / e;
    const S b_over_e = b * inverse_e, f_over_e = f * inverse_e;
    const S b_over_a = b * inverse_a, c_over_a = c * inverse_a;
    v = std::clamp(b_over_e * u - f_over_e, S(-1), S(1));
    u = std::clamp(c_over_a + b_over_a * v, S(-1), S(1));
  }
  return {u, v};
}

/// Squared half lengths below this (2^-511, about 1e-154 in double) are solved rescaled: their
/// products lose digits or underflow.
template <class S>
inline constexpr S kTinySegmentSq = power_of_two<S>(std::numeric_limits<S>::min_exponent / 2);

/// Squared lengths (of the half vectors and the centres' offset) above this (2^508, about 8e152 in
/// double) are solved rescaled too: segment_parameters() multiplies four lengths together, which
/// overflows from about 1e77 (boxes of 3e77 gave NaN manifold points).
template <class S>
inline constexpr S kHugeSegmentSq = power_of_two<S>(std::numeric_limits<S>::max_exponent / 2 - 4);

/// Whether segment_parameters() must run rescaled for half vectors hp, hq (squared lengths a_sq,
/// e_sq) and centres w_sq apart, squared: a segment shorter than kTinySegmentSq but not a point,
/// or a length beyond kHugeSegmentSq. closest_points_of_segments() and closest_core_points()
/// share it.
template <class S>
[[gnu::always_inline]] inline bool segments_out_of_range(const Vec3T<S>& hp, const Vec3T<S>& hq,
                                                         S a_sq, S e_sq, S w_sq) {
  return (a_sq < kTinySegmentSq<S> && hp != Vec3T<S>::Zero()) ||
         (e_sq < kTinySegmentSq<S> && hq != Vec3T<S>::Zero()) ||
         !(std::max(std::max(a_sq, e_sq), w_sq) <= kHugeSegmentSq<S>);
}

/// segment_parameters() on the pair scaled to its largest coordinate, for segments whose squared
/// lengths underflow or overflow (see closest_points_of_segments()); out of line, as it is rare.
template <class S>
[[gnu::noinline, gnu::cold]] SegmentParameters<S> segment_parameters_rescaled(const Vec3T<S>& hp,
                                                                              const Vec3T<S>& hq,
                                                                              const Vec3T<S>& w) {
  // By a division, not a power of two: 2^1074, which a subnormal coordinate would need, overflows.
  const S largest =
      std::max({hp.cwiseAbs().maxCoeff(), hq.cwiseAbs().maxCoeff(), w.cwiseAbs().maxCoeff()});
  const Vec3T<S> sp = hp / largest, sq = hq / largest;
  // A segment still shorter than 1e-77 of the largest coordinate is a point at this scale. Kept
  // as a segment, its square times the other's underflowed to 0 and Cramer's rule gave 0 / 0 (a
  // segment of 5e-158 some 2e4 from one 2e3 long).
  S a = sp.squaredNorm(), e = sq.squaredNorm();
  if (a < kTinySegmentSq<S>) a = S(0);
  if (e < kTinySegmentSq<S>) e = S(0);
  return segment_parameters(sp, sq, Vec3T<S>(w / largest), a, e);
}

/// Closest points of the core segments p and q (either may be a point): on return
/// closest_p = p.centre + u p.half and closest_q = q.centre + v q.half with u, v in [-1, 1].
///
/// The squared distance |u hp - v hq - w|^2 (w = q.centre - p.centre) is a convex quadratic in
/// (u, v). Its minimum over the square comes from the lines' critical u clamped to [-1, 1], the
/// best v for that u, and when that v leaves [-1, 1], v clamped and the best u for it: the order
/// of clamping of Ericson's "Real-Time Collision Detection" (5.1.9), exact for a convex quadratic
/// on a rectangle. The critical u is Cramer's rule while the lines' angle theta has
/// sin^2 theta >= 1/16; there the determinant |hp|^2 |hq|^2 - (hp.hq)^2 loses at most a few bits
/// and the distance stays within 1e-14 of the size. Closer to parallel it cancels catastrophically
/// (1e-8 errors at angles near 1e-8 rad), so u comes from cross products, whose error grows as
/// 1 / sin theta only, which the distance's slope sin theta cancels.
/// `u_out`, `v_out` (optional) receive u and v.
template <class S>
[[gnu::always_inline]] inline void closest_points_of_segments(
    const CoreSegment<S>& p, const CoreSegment<S>& q, Vec3T<S>& closest_p, Vec3T<S>& closest_q,
    S* u_out = nullptr, S* v_out = nullptr) {
  const Vec3T<S>&hp = p.half, &hq = q.half;
  const Vec3T<S> w = q.centre - p.centre;
  // Segments shorter than 1e-77 (in double, kTinySegmentSq): their squared lengths and the
  // products of those lose digits or underflow, and a segment of 1e-170 would count as a point.
  // u and v do not change with the scale, so such a pair is solved rescaled, as is one whose
  // lengths or offset are so large that products of four of them overflow (kHugeSegmentSq).
  const S a = hp.squaredNorm(), e = hq.squaredNorm();
  const SegmentParameters<S> t = segments_out_of_range(hp, hq, a, e, w.squaredNorm())
                                     ? segment_parameters_rescaled(hp, hq, w)
                                     : segment_parameters(hp, hq, w, a, e);
  closest_p = p.centre + t.u * hp;
  closest_q = q.centre + t.v * hq;
  if (u_out) *u_out = t.u;
  if (v_out) *v_out = t.v;
}

/// The unit direction of `gap` = closest_q - closest_p (> 0) for the closest points of segments p
/// and q at parameters u and v, made orthogonal to each segment whose closest point is interior
/// (|u| < 1): there the true direction is exactly orthogonal to it, but `gap`, a difference of
/// points some L from the origin, carries rounding of eps L in every direction. When the cores
/// nearly meet (a sphere's centre on a capsule's axis, crossing capsules) that tilts it by
/// eps L / |gap| along the segment, and every radian of tilt costs half the segment's length of
/// depth along the normal (1e-4 of the size for cores 1e-12 apart). Tilts within the plane
/// orthogonal to the segments are harmless: all those directions give the same depth to within
/// |gap|. `terms_sq` is the sum of the squared centres and half vectors: a segment no longer than
/// their rounding has no direction to speak of (its parameter is noise, and one of 1e-161 beside
/// one of 1e11 is solved as a point, v = 0, which made the gap orthogonal to it, 90 degrees off),
/// and a tilt along it costs less than that rounding.
template <class S>
Vec3T<S> segment_gap_direction(const CoreSegment<S>& p, const CoreSegment<S>& q, S u, S v,
                               const Vec3T<S>& gap, S terms_sq) {
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  const S floor_sq = kEps * kEps * terms_sq;
  const bool across_p = std::abs(u) < S(1) && p.half.squaredNorm() > floor_sq;
  const bool across_q = std::abs(v) < S(1) && q.half.squaredNorm() > floor_sq;
  Vec3T<S> n = gap;
  if (!make_orthogonal(n, across_p ? p.half : Vec3T<S>::Zero(),
                       across_q ? q.half : Vec3T<S>::Zero()))
    n = unit_of(gap);  // rounding only
  return n;
}

/// The normal of core segments p and q that meet (their distance within the touching tolerance),
/// when both have a direction and are not parallel to rounding; else nothing. Their difference
/// {p.centre + u p.half - q.centre - v q.half} is then a parallelogram, flat, that holds the
/// origin or nearly: no direction has a smaller support value on it than its plane's normal,
/// the segments' common perpendicular, which is this, on the side where q's centre lies. Built as
/// p's direction times q's part orthogonal to it: for segments a small angle t apart, q's part
/// is off by eps / t in direction, towards the parallelogram's width, which is t times its
/// length, so the support value along the normal stays within eps of the length (EPA on that
/// sliver ran into its cap, up to 4e-9 of the size off, for angles of 1e-8 to 6e-8).
template <class S>
std::optional<Vec3T<S>> meeting_segments_normal(const CoreSegment<S>& p, const CoreSegment<S>& q) {
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  const S pp = p.half.squaredNorm(), qq = q.half.squaredNorm();
  const S terms_sq = p.centre.squaredNorm() + pp + q.centre.squaredNorm() + qq;
  // A segment no longer than the rounding of the terms is a point: it has no direction.
  if (!(pp > kEps * kEps * terms_sq && qq > kEps * kEps * terms_sq)) return std::nullopt;
  const Vec3T<S> along = unit_of(p.half);
  const Vec3T<S> across = part_across(q.half, along);
  if (!(across.squaredNorm() > S(64 * 64) * kEps * kEps * qq)) return std::nullopt;  // parallel
  Vec3T<S> n = unit_of(Vec3T<S>(along.cross(across)));
  if (n.dot(q.centre - p.centre) < S(0)) n = -n;
  if (!is_finite(n)) return std::nullopt;
  return n;
}

/// The same for segments given by their end points p0-p1 and q0-q1.
template <class S>
void closest_points_of_segments(const Vec3T<S>& p0, const Vec3T<S>& p1, const Vec3T<S>& q0,
                                const Vec3T<S>& q1, Vec3T<S>& closest_p, Vec3T<S>& closest_q) {
  closest_points_of_segments(CoreSegment<S>{S(0.5) * (p0 + p1), S(0.5) * (p1 - p0)},
                             CoreSegment<S>{S(0.5) * (q0 + q1), S(0.5) * (q1 - q0)}, closest_p,
                             closest_q);
}

/// Whether the line of centres w = q.centre - p.centre separates cores p and q by more than
/// `reach` (>= 0): along w / |w| the cores reach |p.half . w| / |w| and |q.half . w| / |w| from
/// their centres, so the gap along it is (w.w - |p.half . w| - |q.half . w|) / |w|, a lower bound
/// on the distance. Compared squared, with no root or division: most separated pairs are apart
/// along this line, which costs two dot products where the closest points take a chain of
/// divisions and clamps. False (the closest points decide) when reach^2 w.w underflows.
template <class S>
[[gnu::always_inline]] inline bool line_of_centres_separates(const CoreSegment<S>& p,
                                                             const CoreSegment<S>& q, S reach) {
  const Vec3T<S> w = q.centre - p.centre;
  const S ww = w.squaredNorm();
  const S apart = ww - std::abs(p.half.dot(w)) - std::abs(q.half.dot(w));
  const S bound = reach * reach * ww;
  return apart > S(0) && bound >= std::numeric_limits<S>::min() && apart * apart > bound;
}

/// What closest_core_points() finds: the cores' closest points, the unit direction from on_a to
/// on_b and their distance.
template <class S>
struct CorePoints {
  Vec3T<S> on_a, on_b, unit;
  S length;
};

/// closest_core_points() for every pair, out of line: the pairs its common path turns away
/// (lengths beyond the range of segment_parameters(), cores that nearly meet or coincide). The
/// answer comes back by value: outputs passed by reference to a call, even a cold one, kept the
/// caller's points in memory on the common path as well. `unit` is `unit_default` when the
/// points coincide or `want_unit` is false.
template <class A, class B>
[[gnu::noinline, gnu::cold]] CorePoints<typename A::Scalar> closest_core_points_general(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, const Vec3T<typename A::Scalar>& unit_default,
    bool want_unit) {
  using S = typename A::Scalar;
  CorePoints<S> out;
  out.unit = unit_default;
  Vec3T<S>&on_a = out.on_a, &on_b = out.on_b;
  Vec3T<S>* unit = want_unit ? &out.unit : nullptr;
  const CoreSegment<S> p = SegmentCore<A>::world(a, pose_a, pose_a.translation);
  const CoreSegment<S> q = SegmentCore<B>::world(b, pose_b, pose_a.translation);
  S u = S(0), v = S(0);
  closest_points_of_segments(p, q, on_a, on_b, &u, &v);
  const Vec3T<S> gap = on_b - on_a;
  const S gap_sq = gap.squaredNorm();
  // length_of() with one range test: a square in the normal range has an exact enough root.
  const bool plain =
      gap_sq >= std::numeric_limits<S>::min() && gap_sq <= std::numeric_limits<S>::max();
  const S length = plain ? std::sqrt(gap_sq) : gap.stableNorm();
  if (unit && length > S(0)) {
    // The terms the gap was computed from set its rounding, not the points themselves (a
    // sphere's centre at A's origin and a point 1e-12 from it on a long capsule's axis).
    const S terms_sq = p.centre.squaredNorm() + p.half.squaredNorm() + q.centre.squaredNorm() +
                       q.half.squaredNorm();
    if (gap_sq >= S(1e-6) * terms_sq)
      *unit = unit_of(gap, gap_sq, length);
    else
      *unit = segment_gap_direction(p, q, u, v, gap, terms_sq);
  }
  out.length = length;
  return out;
}

/// closest_core_points_general()'s answer into closest_core_points()'s outputs. A function, not
/// a lambda: Clang left the lambda out of line, and its captures kept the outputs in memory.
template <class A, class B>
[[gnu::always_inline]] inline typename A::Scalar from_general(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, Vec3T<typename A::Scalar>& on_a,
    Vec3T<typename A::Scalar>& on_b, Vec3T<typename A::Scalar>* unit) {
  using S = typename A::Scalar;
  const CorePoints<S> r = closest_core_points_general(
      a, pose_a, b, pose_b, unit ? *unit : Vec3T<S>(Vec3T<S>::Zero()), unit != nullptr);
  on_a = r.on_a;
  on_b = r.on_b;
  if (unit) *unit = r.unit;
  return r.length;
}

/// from_general(), and for closest_core_points_until<true>() nothing where the cores are within
/// `reach` (on the root: these pairs are rare).
template <bool kStopWithinReach, class A, class B>
[[gnu::always_inline]] inline std::optional<typename A::Scalar> from_general_until(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, typename A::Scalar reach,
    Vec3T<typename A::Scalar>& on_a, Vec3T<typename A::Scalar>& on_b,
    Vec3T<typename A::Scalar>* unit) {
  const typename A::Scalar length = from_general(a, pose_a, b, pose_b, on_a, on_b, unit);
  if (kStopWithinReach && length <= reach) return std::nullopt;
  return length;
}

/// The closest points of the cores of a (at pose_a) and b (at pose_b), both points or segments,
/// in the world frame shifted to A's origin (which keeps far-away pairs precise), and their
/// distance: returns |on_b - on_a|; `unit` (optional) receives the direction from on_a to on_b
/// when they differ (else it is left as it was): the plain quotient while the gap is more than
/// 1e-3 of the segments' size and distance from A's origin (its rounding then tilts it by less
/// than 3e-13 rad), segment_gap_direction()'s when the cores nearly meet.
///
/// The common path (lengths in segment_parameters()'s range, cores apart by more than 1e-3 of
/// their terms) is inlined, with A's centre a constant 0 when the core is centred on its pose
/// (kCentred); every other pair goes to closest_core_points_general(), which gives the same
/// numbers on the common path (its centre is +0; a zero coordinate may differ in sign). Capsule
/// pairs' distance 10 % faster in a driver than the general path inlined, of which half was the
/// centre 0 computed and added, the rest outputs kept in memory.
/// Always inlined under Clang (segment_parameters() returns u and v by value for the same reason):
/// out of line, Clang passed its outputs and the parameters through memory. GCC kept them in
/// registers out of line and ran 6 % slower inlined, so it decides itself.
///
/// With kStopWithinReach, nothing (std::nullopt) where the cores are within `reach` of each other,
/// decided as intersect() decides it (length_at_most() on the gap, before the root): distance()
/// reports no points or direction there, and the root and the unit direction, the last links of
/// the query's chain of dependent operations, are not taken.
template <bool kStopWithinReach, class A, class B>
MINK_SEGMENT_CORES_INLINE std::optional<typename A::Scalar> closest_core_points_until(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, typename A::Scalar reach,
    Vec3T<typename A::Scalar>& on_a, Vec3T<typename A::Scalar>& on_b,
    Vec3T<typename A::Scalar>* unit) {
  using S = typename A::Scalar;
  constexpr bool kCentredA = SegmentCore<A>::kCentred;
  const CoreSegment<S> q = SegmentCore<B>::world(b, pose_b, pose_a.translation);
  CoreSegment<S> p;
  if constexpr (kCentredA)
    p.half = SegmentCore<A>::world(a, pose_a, pose_a.translation).half;
  else
    p = SegmentCore<A>::world(a, pose_a, pose_a.translation);
  const Vec3T<S>&hp = p.half, &hq = q.half;
  Vec3T<S> w;
  if constexpr (kCentredA)
    w = q.centre;
  else
    w = q.centre - p.centre;
  const S a_sq = hp.squaredNorm(), e_sq = hq.squaredNorm(), w_sq = w.squaredNorm();
  if (segments_out_of_range(hp, hq, a_sq, e_sq, w_sq)) [[unlikely]]
    return from_general_until<kStopWithinReach>(a, pose_a, b, pose_b, reach, on_a, on_b, unit);
  const SegmentParameters<S> t = segment_parameters(hp, hq, w, a_sq, e_sq);
  // The sums of closest_points_of_segments() and of the general path's terms_sq.
  S terms_sq;
  if constexpr (kCentredA) {
    on_a = t.u * hp;
    terms_sq = a_sq + w_sq + e_sq;
  } else {
    on_a = p.centre + t.u * hp;
    terms_sq = p.centre.squaredNorm() + a_sq + q.centre.squaredNorm() + e_sq;
  }
  on_b = q.centre + t.v * hq;
  const Vec3T<S> gap = on_b - on_a;
  const S gap_sq = gap.squaredNorm();
  // Before the routing: the general path gives the same gap.
  if constexpr (kStopWithinReach)
    if (length_at_most(gap, gap_sq, reach)) return std::nullopt;
  if (!(reciprocal_in_range(gap_sq) && gap_sq >= S(1e-6) * terms_sq)) [[unlikely]]
    return from_general_until<kStopWithinReach>(a, pose_a, b, pose_b, reach, on_a, on_b, unit);
  const S length = std::sqrt(gap_sq);
  if (unit) *unit = unit_beside_root(gap, gap_sq, length);
  return length;
}

/// See closest_core_points_until().
template <class A, class B>
MINK_SEGMENT_CORES_INLINE typename A::Scalar closest_core_points(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b, Vec3T<typename A::Scalar>& on_a,
    Vec3T<typename A::Scalar>& on_b, Vec3T<typename A::Scalar>* unit = nullptr) {
  return *closest_core_points_until<false>(a, pose_a, b, pose_b, typename A::Scalar(0), on_a, on_b,
                                           unit);
}

}  // namespace mink::detail

#undef MINK_SEGMENT_CORES_INLINE
