/// @file segment_cores.hpp
/// Closed-form queries for shapes whose core is a point or a segment: spheres, capsules, points,
/// segments, and their Rounded versions. Two such cores need no iteration: the distance between
/// two segments has a closed form, so sphere and capsule pairs are exact to rounding and cost a
/// few dozen flops. intersect() and distance() take this path automatically.
#pragma once

#include <algorithm>
#include <type_traits>

#include "mink/math/pose.hpp"
#include "mink/shapes/capsule.hpp"
#include "mink/shapes/point.hpp"
#include "mink/shapes/segment.hpp"
#include "mink/shapes/sphere.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// SegmentCore<T>::world(shape, pose, origin, p, q) gives the end points of T's core segment in
/// the world frame shifted to `origin` (equal points for a point core). Only for shapes whose core
/// is a point or a segment.
template <class T>
struct SegmentCore : std::false_type {};

template <class S>
struct SegmentCore<SphereT<S>> : std::true_type {
  static void world(const SphereT<S>&, const PoseT<S>& pose, const Vec3T<S>& origin, Vec3T<S>& p,
                    Vec3T<S>& q) {
    p = q = pose.translation - origin;
  }
};

template <class S>
struct SegmentCore<CapsuleT<S>> : std::true_type {
  static void world(const CapsuleT<S>& c, const PoseT<S>& pose, const Vec3T<S>& origin, Vec3T<S>& p,
                    Vec3T<S>& q) {
    // The core is (0, 0, +-h): the rotation's z column scaled, no matrix product needed.
    const Vec3T<S> centre = pose.translation - origin;
    const Vec3T<S> half = pose.rotation.col(2) * c.half_height;
    p = centre - half;
    q = centre + half;
  }
};

template <class S>
struct SegmentCore<PointT<S>> : std::true_type {
  static void world(const PointT<S>& point, const PoseT<S>& pose, const Vec3T<S>& origin,
                    Vec3T<S>& p, Vec3T<S>& q) {
    p = q = pose.rotation * point.position + (pose.translation - origin);
  }
};

template <class S>
struct SegmentCore<SegmentT<S>> : std::true_type {
  static void world(const SegmentT<S>& s, const PoseT<S>& pose, const Vec3T<S>& origin, Vec3T<S>& p,
                    Vec3T<S>& q) {
    const Vec3T<S> shift = pose.translation - origin;
    p = pose.rotation * s.a + shift;
    q = pose.rotation * s.b + shift;
  }
};

template <class T>
struct SegmentCore<Rounded<T>> : std::bool_constant<SegmentCore<T>::value> {
  static void world(const Rounded<T>& r, const PoseT<typename T::Scalar>& pose,
                    const Vec3T<typename T::Scalar>& origin, Vec3T<typename T::Scalar>& p,
                    Vec3T<typename T::Scalar>& q) {
    SegmentCore<T>::world(r.shape, pose, origin, p, q);
  }
};

template <class A, class B>
inline constexpr bool kSegmentCores = SegmentCore<A>::value&& SegmentCore<B>::value;

/// Closest point to x of the segment p + s d, s in [0, 1], as its parameter s.
template <class S>
S closest_parameter_on_segment(const Vec3T<S>& p, const Vec3T<S>& d, const Vec3T<S>& x) {
  const S dd = d.squaredNorm();
  if (!(dd > S(0))) return S(0);
  return std::clamp((x - p).dot(d) / dd, S(0), S(1));
}

/// Closest points of the segments p0-p1 and q0-q1 (either may be a point): on return
/// closest_p = p0 + s (p1 - p0) and closest_q = q0 + t (q1 - q0) with s, t in [0, 1].
///
/// The squared distance is a convex quadratic in (s, t). Its minimum over the unit square is the
/// critical point of the two lines when that lies in the square, else on an edge of the square,
/// where one segment sits at an end point: the best of the four end-point-to-segment answers.
/// The critical point comes from cross products, not from the textbook determinant
/// |d1|^2 |d2|^2 - (d1.d2)^2: that determinant cancels catastrophically for nearly parallel
/// segments (1e-8 errors in the distance at angles near 1e-8 rad), while |d1 x d2|^2 keeps its
/// relative accuracy however small it is.
template <class S>
void closest_points_of_segments(const Vec3T<S>& p0, const Vec3T<S>& p1, const Vec3T<S>& q0,
                                const Vec3T<S>& q1, Vec3T<S>& closest_p, Vec3T<S>& closest_q) {
  const Vec3T<S> d1 = p1 - p0, d2 = q1 - q0, r = q0 - p0;
  const Vec3T<S> n = d1.cross(d2);
  const S nn = n.squaredNorm();
  if (nn > S(0)) {
    // Lines p0 + s d1 and q0 + t d2: s = ((q0 - p0) x d2).n / |n|^2, t = ((q0 - p0) x d1).n /
    // |n|^2.
    const S s = r.cross(d2).dot(n) / nn;
    const S t = r.cross(d1).dot(n) / nn;
    if (s >= S(0) && s <= S(1) && t >= S(0) && t <= S(1)) {
      closest_p = p0 + s * d1;
      closest_q = q0 + t * d2;
      return;
    }
  }
  S best = std::numeric_limits<S>::infinity();
  auto consider = [&](const Vec3T<S>& on_p, const Vec3T<S>& on_q) {
    const S dist_sq = (on_q - on_p).squaredNorm();
    if (dist_sq < best) {
      best = dist_sq;
      closest_p = on_p;
      closest_q = on_q;
    }
  };
  consider(p0, q0 + closest_parameter_on_segment(q0, d2, p0) * d2);
  consider(p1, q0 + closest_parameter_on_segment(q0, d2, p1) * d2);
  consider(p0 + closest_parameter_on_segment(p0, d1, q0) * d1, q0);
  consider(p0 + closest_parameter_on_segment(p0, d1, q1) * d1, q1);
}

}  // namespace mink::detail
