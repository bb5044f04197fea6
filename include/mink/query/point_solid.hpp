/// @file point_solid.hpp
/// A point core (Sphere, Point, and their Rounded versions) against a box or cylinder core (Box,
/// Cylinder, and their Rounded versions) in closed form: the solid's point nearest to the point
/// core is the point clamped to the solid, and a point inside leaves through the nearest part of
/// the surface (a box's nearest face; a cylinder's side or nearer cap). intersect(), distance()
/// and contact() take this path for such pairs, in either order: exact to rounding, 0
/// iterations, and for a sphere inside the solid no EPA (whose answer for a sphere near a
/// cylinder's axis, where every radial direction is nearly as good, could only be bracketed).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "mink/gjk/segment_cores.hpp"
#include "mink/math/pose.hpp"
#include "mink/query/box_box.hpp"
#include "mink/shapes/cylinder.hpp"

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

/// A point `p` in a solid core's frame against that solid: the solid's point nearest to p
/// (outside) or below it on the nearest part of the surface (inside), the solid's outward normal
/// there, and the signed distance (negative inside: minus the depth).
template <class S>
struct PointSolidLocal {
  Vec3T<S> p, on_solid, out_of_solid;
  S signed_distance;
  /// Inside only: another direction is as good (see the solid's local()); `out_of_solid` is then
  /// the one the solid's local() names.
  bool tie;
};

/// Solid cores with a closed-form nearest point: SolidCore<T>::core(t) is the solid (a Box or a
/// Cylinder), SolidCore<T>::local(core, p) the answer above, SolidCore<T>::clamp(core, p) the
/// solid's point nearest to p.
template <class T>
struct SolidCore : std::false_type {};

/// A box: the clamp to its extents; inside, out through the face nearest to p. Ties: p as deep
/// below two faces, or on the centre plane of the nearest one (then the + face).
template <class S>
struct SolidCore<BoxT<S>> : std::true_type {
  using Core = BoxT<S>;
  static const Core& core(const BoxT<S>& b) { return b; }
  static Vec3T<S> clamp(const Core& b, const Vec3T<S>& p) {
    return p.cwiseMax(-b.half_extents).cwiseMin(b.half_extents);
  }
  static PointSolidLocal<S> local(const Core& b, const Vec3T<S>& p) {
    const Vec3T<S>& h = b.half_extents;
    PointSolidLocal<S> out;
    out.p = p;
    out.on_solid = clamp(b, p);
    out.tie = false;
    const Vec3T<S> gap = p - out.on_solid;
    if (gap != Vec3T<S>::Zero()) {  // a coordinate was clamped: outside
      const S gap_sq = gap.squaredNorm();
      out.signed_distance = length_of(gap, gap_sq);
      out.out_of_solid = unit_of(gap, gap_sq, out.signed_distance);
      return out;
    }
    // Inside (or on the surface): out through the face nearest to p.
    const Vec3T<S> below = h - p.cwiseAbs();
    int k = 0;
    if (below[1] < below[k]) k = 1;
    if (below[2] < below[k]) k = 2;
    out.tie = p[k] == S(0);
    for (int i = 0; i < 3; ++i) out.tie |= i != k && below[i] == below[k];
    out.out_of_solid = Vec3T<S>::Zero();
    out.out_of_solid[k] = sign_nonneg(p[k]);
    out.on_solid[k] = out.out_of_solid[k] * h[k];
    out.signed_distance = -below[k];
    return out;
  }
};

/// A cylinder (axis z): p's distance from the axis and from the caps' planes, each clamped, in
/// the plane through the axis and p, where the cylinder is a rectangle. Inside, out through the
/// side or the nearer cap, whichever is nearer (the side on a tie). Ties: side and cap equally
/// near; p on the axis with the side nearest (every radial direction: then +x); p on the centre
/// plane with a cap nearest (then the + cap).
template <class S>
struct SolidCore<CylinderT<S>> : std::true_type {
  using Core = CylinderT<S>;
  static const Core& core(const CylinderT<S>& c) { return c; }

  /// p's radial direction (ux, uy) and distance from the axis (0 and +x on the axis).
  static S radial(const Vec3T<S>& p, S& ux, S& uy) {
    if (!planar_unit(p.x(), p.y(), ux, uy)) {
      ux = S(1);
      uy = S(0);
      return S(0);
    }
    // The distance along the unit direction: no square of a tiny or huge coordinate.
    return std::max(S(0), ux * p.x() + uy * p.y());
  }
  static Vec3T<S> clamp(const Core& c, const Vec3T<S>& p) {
    S ux, uy;
    const S rho = radial(p, ux, uy);
    const S z = std::clamp(p.z(), -c.half_height, c.half_height);
    if (rho <= c.radius) return {p.x(), p.y(), z};
    return {ux * c.radius, uy * c.radius, z};
  }
  static PointSolidLocal<S> local(const Core& c, const Vec3T<S>& p) {
    PointSolidLocal<S> out;
    out.p = p;
    out.tie = false;
    S ux, uy;
    const S rho = radial(p, ux, uy);
    const S beyond_side = rho - c.radius, beyond_cap = std::abs(p.z()) - c.half_height;
    const S side_z = std::clamp(p.z(), -c.half_height, c.half_height);
    const S cap_sign = sign_nonneg(p.z());
    if (beyond_side > S(0) || beyond_cap > S(0)) {
      // Outside: the gap in the (radial, axial) plane, from the clamped distances, which carry
      // no cancellation of p's coordinates against the clamp.
      const S radial_gap = std::max(S(0), beyond_side), axial_gap = std::max(S(0), beyond_cap);
      const Vec3T<S> gap(ux * radial_gap, uy * radial_gap, cap_sign * axial_gap);
      const S gap_sq = gap.squaredNorm();
      out.signed_distance = length_of(gap, gap_sq);
      out.out_of_solid = unit_of(gap, gap_sq, out.signed_distance);
      out.on_solid = beyond_side > S(0) ? Vec3T<S>(ux * c.radius, uy * c.radius, side_z)
                                        : Vec3T<S>(p.x(), p.y(), side_z);
      return out;
    }
    const S below_side = -beyond_side, below_cap = -beyond_cap;
    out.tie = below_side == below_cap;
    if (below_side <= below_cap) {
      out.tie |= rho == S(0);
      out.out_of_solid = Vec3T<S>(ux, uy, S(0));
      out.on_solid = Vec3T<S>(ux * c.radius, uy * c.radius, p.z());
      out.signed_distance = -below_side;
    } else {
      out.tie |= p.z() == S(0);
      out.out_of_solid = Vec3T<S>(S(0), S(0), cap_sign);
      out.on_solid = Vec3T<S>(p.x(), p.y(), cap_sign * c.half_height);
      out.signed_distance = -below_cap;
    }
    return out;
  }
};

template <class T>
requires(SolidCore<T>::value) struct SolidCore<Rounded<T>> : std::true_type {
  using Core = typename SolidCore<T>::Core;
  static const Core& core(const Rounded<T>& r) { return SolidCore<T>::core(r.shape); }
  static Vec3T<typename T::Scalar> clamp(const Core& c, const Vec3T<typename T::Scalar>& p) {
    return SolidCore<T>::clamp(c, p);
  }
  static PointSolidLocal<typename T::Scalar> local(const Core& c,
                                                   const Vec3T<typename T::Scalar>& p) {
    return SolidCore<T>::local(c, p);
  }
};

/// A point core against a solid core, A first or B first.
template <class A, class B>
inline constexpr bool kPointSolid = (PointCore<A>::value && SolidCore<B>::value) ||
                                    (SolidCore<A>::value && PointCore<B>::value);

/// Closest (apart) or deepest (overlapping) points of two cores, in the world frame.
template <class S>
struct CorePair {
  Vec3T<S> on_a;    ///< on A's core
  Vec3T<S> on_b;    ///< on B's core
  Vec3T<S> normal;  ///< unit, from A towards B: the direction B moves to separate
  /// on_b - on_a = distance * normal; negative when the cores overlap (minus the depth).
  S distance;
  /// Overlapping only: another direction is as good (see the solid's local()).
  bool tie;
};

/// The point core of a point-core shape in the frame of a solid-core shape (either order).
template <class A, class B>
Vec3T<typename A::Scalar> point_in_solid_frame(const A& a, const PoseT<typename A::Scalar>& pose_a,
                                               const B& b,
                                               const PoseT<typename A::Scalar>& pose_b) {
  if constexpr (SolidCore<A>::value)
    return pose_a.inverse_rotate(SegmentCore<B>::world(b, pose_b, pose_a.translation).centre);
  else
    return pose_b.inverse_rotate(SegmentCore<A>::world(a, pose_a, pose_b.translation).centre);
}

/// The solid core of the pair (either order).
template <class A, class B>
const auto& solid_of(const A& a, const B& b) {
  if constexpr (SolidCore<A>::value)
    return SolidCore<A>::core(a);
  else
    return SolidCore<B>::core(b);
}

/// The point core minus its clamp into the solid core, in the solid's frame (0 when the point is
/// inside), for the yes/no test: no points.
template <class A, class B>
Vec3T<typename A::Scalar> point_solid_gap(const A& a, const PoseT<typename A::Scalar>& pose_a,
                                          const B& b, const PoseT<typename A::Scalar>& pose_b) {
  using Solid = std::conditional_t<SolidCore<A>::value, SolidCore<A>, SolidCore<B>>;
  const Vec3T<typename A::Scalar> p = point_in_solid_frame(a, pose_a, b, pose_b);
  return p - Solid::clamp(solid_of(a, b), p);
}

/// The point core against the solid core in the solid's frame (PointSolidLocal).
template <class A, class B>
PointSolidLocal<typename A::Scalar> point_solid_local(const A& a,
                                                      const PoseT<typename A::Scalar>& pose_a,
                                                      const B& b,
                                                      const PoseT<typename A::Scalar>& pose_b) {
  using Solid = std::conditional_t<SolidCore<A>::value, SolidCore<A>, SolidCore<B>>;
  return Solid::local(solid_of(a, b), point_in_solid_frame(a, pose_a, b, pose_b));
}

/// point_solid_local()'s answer as the cores' points and normal in the world frame, A's and B's.
template <class A, class B>
CorePair<typename A::Scalar> point_solid_world(const PointSolidLocal<typename A::Scalar>& local,
                                               const PoseT<typename A::Scalar>& pose_a,
                                               const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  constexpr bool kSolidIsA = SolidCore<A>::value;
  const PoseT<S>& solid_pose = kSolidIsA ? pose_a : pose_b;
  const Vec3T<S> point_world = solid_pose.apply(local.p);
  const Vec3T<S> solid_world = solid_pose.apply(local.on_solid);
  const Vec3T<S> normal = solid_pose.rotate(local.out_of_solid);
  CorePair<S> out;
  out.distance = local.signed_distance;
  out.tie = local.tie;
  if constexpr (kSolidIsA) {
    out.on_a = solid_world;
    out.on_b = point_world;
    out.normal = normal;
  } else {
    out.on_a = point_world;
    out.on_b = solid_world;
    out.normal = -normal;
  }
  return out;
}

}  // namespace mink::detail
