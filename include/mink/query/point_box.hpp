/// @file point_box.hpp
/// A point core (Sphere, Point, and their Rounded versions) against a box core (Box,
/// Rounded<Box>) in closed form: the box's point nearest to the point core is the point clamped to
/// the box, and a point inside leaves through its nearest face. intersect(), distance() and
/// contact() take this path for such pairs, in either order: exact to rounding, 0 iterations,
/// and for a sphere inside a box no EPA.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
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
  /// Overlapping only: another direction is as good (the point as deep below two faces, or on
  /// the box's centre plane); `normal` is then the first such face axis in x, y, z order, on the
  /// point's side of the centre (the + side on the centre plane).
  bool tie;
};

/// The point core of a point-core shape in the frame of a box-core shape (either order), and the
/// box's half extents.
template <class A, class B>
const Vec3T<typename A::Scalar>& point_in_box_frame(const A& a,
                                                    const PoseT<typename A::Scalar>& pose_a,
                                                    const B& b,
                                                    const PoseT<typename A::Scalar>& pose_b,
                                                    Vec3T<typename A::Scalar>& p) {
  if constexpr (BoxCore<A>::value) {
    p = pose_a.inverse_rotate(SegmentCore<B>::world(b, pose_b, pose_a.translation).centre);
    return BoxCore<A>::half_extents(a);
  } else {
    p = pose_b.inverse_rotate(SegmentCore<A>::world(a, pose_a, pose_b.translation).centre);
    return BoxCore<B>::half_extents(b);
  }
}

/// The point core minus its clamp into the box core, in the box's frame (0 when the point is
/// inside), for the yes/no test: no square root, no points.
template <class A, class B>
Vec3T<typename A::Scalar> point_box_gap(const A& a, const PoseT<typename A::Scalar>& pose_a,
                                        const B& b, const PoseT<typename A::Scalar>& pose_b) {
  Vec3T<typename A::Scalar> p;
  const auto& h = point_in_box_frame(a, pose_a, b, pose_b, p);
  return p - p.cwiseMax(-h).cwiseMin(h);
}

/// The point core against the box core in the box's frame: the point `p`, the box's point nearest
/// to it (outside) or below it on the nearest face (inside), the box's outward normal there, and
/// the signed distance (negative inside: minus the depth). The point's depth below a face ties
/// another when they are equal in floating point.
template <class S>
struct PointBoxLocal {
  Vec3T<S> p, on_box, out_of_box;
  S signed_distance;
  bool tie;
};

template <class A, class B>
PointBoxLocal<typename A::Scalar> point_box_local(const A& a,
                                                  const PoseT<typename A::Scalar>& pose_a,
                                                  const B& b,
                                                  const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  PointBoxLocal<S> out;
  const Vec3T<S>& h = point_in_box_frame(a, pose_a, b, pose_b, out.p);
  const Vec3T<S>& p = out.p;
  out.on_box = p.cwiseMax(-h).cwiseMin(h);
  out.tie = false;
  const Vec3T<S> gap = p - out.on_box;
  if (gap != Vec3T<S>::Zero()) {  // a coordinate was clamped: outside
    const S gap_sq = gap.squaredNorm();
    out.signed_distance = length_of(gap, gap_sq);
    out.out_of_box = unit_of(gap, gap_sq, out.signed_distance);
  } else {
    // Inside (or on the surface): out through the face nearest to p.
    const Vec3T<S> below = h - p.cwiseAbs();
    int k = 0;
    if (below[1] < below[k]) k = 1;
    if (below[2] < below[k]) k = 2;
    out.tie = p[k] == S(0);
    for (int i = 0; i < 3; ++i) out.tie |= i != k && below[i] == below[k];
    out.out_of_box = Vec3T<S>::Zero();
    out.out_of_box[k] = sign_nonneg(p[k]);
    out.on_box[k] = out.out_of_box[k] * h[k];
    out.signed_distance = -below[k];
  }
  return out;
}

/// point_box_local()'s answer as the cores' points and normal in the world frame, A's and B's.
template <class A, class B>
CorePair<typename A::Scalar> point_box_world(const PointBoxLocal<typename A::Scalar>& local,
                                             const PoseT<typename A::Scalar>& pose_a,
                                             const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  constexpr bool kBoxIsA = BoxCore<A>::value;
  const PoseT<S>& box_pose = kBoxIsA ? pose_a : pose_b;
  const Vec3T<S> point_world = box_pose.apply(local.p), box_world = box_pose.apply(local.on_box);
  const Vec3T<S> normal = box_pose.rotate(local.out_of_box);
  CorePair<S> out;
  out.distance = local.signed_distance;
  out.tie = local.tie;
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
