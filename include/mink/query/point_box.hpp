/// @file point_box.hpp
/// A point core (Sphere, Point, and their Rounded versions) against a box core (Box,
/// Rounded<Box>) in closed form: the box's point nearest to the point core is the point clamped to
/// the box, and a point inside leaves through its nearest face. intersect(), distance() and
/// contact() take this path for such pairs, in either order: exact to rounding, 0 iterations,
/// and for a sphere inside a box no EPA.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "mink/gjk/segment_cores.hpp"
#include "mink/math/pose.hpp"
#include "mink/query/box_box.hpp"

namespace mink::detail {

/// Shapes whose core is one point: Sphere, Point, and Rounded versions of them.
template <class T>
struct PointCore : std::false_type {};
template <class S>
struct PointCore<SphereT<S>> : std::true_type {};
template <class S>
struct PointCore<PointT<S>> : std::true_type {};
template <class T>
struct PointCore<Rounded<T>> : std::bool_constant<PointCore<T>::value> {};

/// A point core against a box core, A first or B first.
template <class A, class B>
inline constexpr bool kPointBox = (PointCore<A>::value && BoxCore<B>::value) ||
                                  (BoxCore<A>::value && PointCore<B>::value);

/// Closest (apart) or deepest (overlapping) points of two cores, in the world frame.
template <class S>
struct CorePair {
  Vec3T<S> on_a;    ///< on A's core
  Vec3T<S> on_b;    ///< on B's core
  Vec3T<S> normal;  ///< unit, from A towards B: the direction B moves to separate
  /// on_b - on_a = distance * normal; negative when the cores overlap (minus the depth).
  S distance;
  /// Overlapping only: another direction is as good (the point as deep below two faces, or at
  /// the box's centre plane); `normal` is the first face axis in x, y, z order, on the + side.
  bool tie;
};

/// The cores of a point-core shape and a box-core shape (either order), see the file comment.
/// The point's depth below a face ties another when they are equal in floating point.
template <class A, class B>
CorePair<typename A::Scalar> point_box_cores(const A& a, const PoseT<typename A::Scalar>& pose_a,
                                             const B& b, const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  constexpr bool kBoxIsA = BoxCore<A>::value;
  const PoseT<S>& box_pose = kBoxIsA ? pose_a : pose_b;
  const Vec3T<S>& h = [&]() -> const Vec3T<S>& {
    if constexpr (kBoxIsA)
      return BoxCore<A>::half_extents(a);
    else
      return BoxCore<B>::half_extents(b);
  }();
  // The point in the box's frame.
  Vec3T<S> p;
  if constexpr (kBoxIsA)
    p = pose_a.inverse_rotate(SegmentCore<B>::world(b, pose_b, pose_a.translation).centre);
  else
    p = pose_b.inverse_rotate(SegmentCore<A>::world(a, pose_a, pose_b.translation).centre);
  // The box's point nearest to p, and the direction from it to p (the box's outward normal).
  Vec3T<S> on_box = p.cwiseMax(-h).cwiseMin(h);
  Vec3T<S> out_of_box;
  S signed_distance;
  bool tie = false;
  const Vec3T<S> gap = p - on_box;
  const S gap_sq = gap.squaredNorm();
  if (gap_sq > S(0)) {
    signed_distance = std::sqrt(gap_sq);
    out_of_box = gap / signed_distance;
  } else {
    // Inside (or on the surface): out through the face nearest to p.
    const Vec3T<S> below = h - p.cwiseAbs();
    int k = 0;
    if (below[1] < below[k]) k = 1;
    if (below[2] < below[k]) k = 2;
    tie = p[k] == S(0);
    for (int i = 0; i < 3; ++i) tie |= i != k && below[i] == below[k];
    out_of_box = Vec3T<S>::Zero();
    out_of_box[k] = sign_nonneg(p[k]);
    on_box[k] = out_of_box[k] * h[k];
    signed_distance = -below[k];
  }
  CorePair<S> out;
  const Vec3T<S> point_world = box_pose.apply(p), box_world = box_pose.apply(on_box);
  const Vec3T<S> normal = box_pose.rotate(out_of_box);
  out.distance = signed_distance;
  out.tie = tie;
  if constexpr (kBoxIsA) {
    out.on_a = box_world;
    out.on_b = point_world;
    out.normal = normal;
  } else {
    out.on_a = point_world;
    out.on_b = box_world;
    out.normal = -normal;
  }
  return out;
}

}  // namespace mink::detail
