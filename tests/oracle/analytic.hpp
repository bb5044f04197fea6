/// @file analytic.hpp
/// Closed-form answers for the distance between simple shapes, written independently of mink (no
/// mink algorithm is called; only Eigen types are shared) and evaluated in long double.
///
/// Conventions match mink's queries: points in the world frame, the normal unit from A to B, and
/// point_b - point_a = distance * normal when the shapes are apart.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace oracle {

using Real = long double;
using V3 = Eigen::Matrix<Real, 3, 1>;
using M3 = Eigen::Matrix<Real, 3, 3>;

template <class S>
V3 widen(const Eigen::Matrix<S, 3, 1>& v) {
  return v.template cast<Real>();
}
template <class S>
M3 widen(const Eigen::Matrix<S, 3, 3>& m) {
  return m.template cast<Real>();
}

/// Answer of a distance oracle. `distance` is the Euclidean distance (0 when the shapes overlap);
/// `gap` is signed: positive when apart, negative (or zero) when overlapping, so that callers can
/// tell clear overlap from touching. Points and normal are meaningful only when `gap > 0`.
struct Answer {
  Real distance = 0;
  Real gap = 0;
  V3 point_a = V3::Zero();
  V3 point_b = V3::Zero();
  V3 normal = V3::Zero();
};

/// Closest point of the segment [p, q] to x, with its parameter in [0, 1].
struct SegmentPoint {
  V3 point;
  Real t;
};

inline SegmentPoint closest_on_segment(const V3& p, const V3& q, const V3& x) {
  const V3 d = q - p;
  const Real dd = d.squaredNorm();
  if (dd == 0) return {p, 0};
  Real t = (x - p).dot(d) / dd;
  t = std::clamp(t, Real(0), Real(1));
  return {p + t * d, t};
}

/// The parameter t in [0, 1] of the point x = p + t (q - p) nearest a convex set, given the
/// set's closest point to any x. The squared distance is convex in t, and its slope is
/// 2 (x - closest(x)) . (q - p): bisection on the slope's sign in long double (200 halvings, to the
/// rounding of t; a search on the values would stop at the square root of their rounding).
template <class Closest>
Real least_along_segment(const V3& p, const V3& q, Closest closest) {
  auto slope = [&](Real t) {
    const V3 x = p + t * (q - p);
    return (x - closest(x)).dot(q - p);
  };
  if (!(slope(0) < 0)) return 0;
  if (!(slope(1) > 0)) return 1;
  Real lo = 0, hi = 1;
  for (int step = 0; step < 200; ++step) {
    const Real mid = (lo + hi) / 2;
    (slope(mid) < 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

/// Closest points of segments [p1, q1] and [p2, q2]. The squared distance over the parameter
/// square is a convex quadratic: its minimum is at the interior critical point (when the segments
/// are not parallel and it lies in the square) or on the boundary, where one segment sits at an
/// endpoint. Taking the best of the interior candidate and the four endpoint-to-segment answers
/// needs no special case for parallel or degenerate segments (a near-singular interior solve can
/// only produce a candidate that loses to the boundary, since every candidate is a real pair).
/// Segments 1e-12 to 1e-8 rad from parallel are the exception: the interior solve is noise there
/// (1 % off at a distance of 1e-8), yet the boundary is worse. A golden-section search over the
/// first one's parameter, on the values (the distance of its point to the second is convex in it
/// and good to rounding everywhere), then answers; only where it beats the others by more than
/// rounding, since it places the points to the square root of the rounding only.
struct SegmentPair {
  V3 on_first, on_second;
  Real distance;
};

inline SegmentPair closest_segment_segment(const V3& p1, const V3& q1, const V3& p2, const V3& q2) {
  SegmentPair best{p1, p2, (p2 - p1).norm()};
  auto consider = [&best](const V3& x, const V3& y) {
    const Real d = (y - x).norm();
    if (d < best.distance) best = {x, y, d};
  };
  const V3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const Real a = d1.squaredNorm(), e = d2.squaredNorm(), b = d1.dot(d2);
  const Real c = d1.dot(r), f = d2.dot(r);
  const Real denom = a * e - b * b;
  if (denom > Real(1e-30) * a * e && a > 0 && e > 0) {
    // Stationary point of |p1 + s d1 - p2 - t d2|^2: a s - b t = -c, b s - e t = -f.
    const Real s = (b * f - c * e) / denom;
    const Real t = (a * f - b * c) / denom;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) consider(p1 + s * d1, p2 + t * d2);
  }
  consider(p1, closest_on_segment(p2, q2, p1).point);
  consider(q1, closest_on_segment(p2, q2, q1).point);
  consider(closest_on_segment(p1, q1, p2).point, p2);
  consider(closest_on_segment(p1, q1, q2).point, q2);

  auto on_first = [&](Real s) { return V3(p1 + s * d1); };
  auto distance_at = [&](Real s) {
    const V3 x = on_first(s);
    return (closest_on_segment(p2, q2, x).point - x).norm();
  };
  const Real ratio = (std::sqrt(Real(5)) - 1) / 2;
  Real low = 0, high = 1;
  for (int step = 0; step < 200; ++step) {
    const Real left = high - ratio * (high - low), right = low + ratio * (high - low);
    if (distance_at(left) <= distance_at(right))
      high = right;
    else
      low = left;
  }
  const Real scale = std::max({p1.norm(), q1.norm(), p2.norm(), q2.norm()});
  const Real rounding = 64 * std::numeric_limits<Real>::epsilon() * scale;
  const V3 x = on_first((low + high) / 2);
  const V3 y = closest_on_segment(p2, q2, x).point;
  if ((y - x).norm() < best.distance - rounding) best = {x, y, (y - x).norm()};
  return best;
}

/// Fills points, normal and distance of an Answer from core closest points and radii.
inline Answer from_cores(const V3& core_a, const V3& core_b, Real radius_a, Real radius_b) {
  Answer ans;
  const V3 d = core_b - core_a;
  const Real len = d.norm();
  ans.gap = len - radius_a - radius_b;
  ans.distance = std::max(Real(0), ans.gap);
  if (len > 0) {
    ans.normal = d / len;
    ans.point_a = core_a + radius_a * ans.normal;
    ans.point_b = core_b - radius_b * ans.normal;
  }
  return ans;
}

inline Answer sphere_sphere(const V3& ca, Real ra, const V3& cb, Real rb) {
  return from_cores(ca, cb, ra, rb);
}

/// Capsule in the world: its core segment's endpoints and its radius.
struct WorldCapsule {
  V3 p, q;
  Real radius;
};

/// A capsule along local z (half_height, radius) at rotation R, translation t.
inline WorldCapsule make_capsule(Real radius, Real half_height, const M3& rotation,
                                 const V3& translation) {
  const V3 axis = rotation.col(2) * half_height;
  return {translation - axis, translation + axis, radius};
}

inline Answer sphere_capsule(const V3& center, Real radius, const WorldCapsule& c) {
  return from_cores(center, closest_on_segment(c.p, c.q, center).point, radius, c.radius);
}

inline Answer capsule_capsule(const WorldCapsule& a, const WorldCapsule& b) {
  const SegmentPair s = closest_segment_segment(a.p, a.q, b.p, b.q);
  return from_cores(s.on_first, s.on_second, a.radius, b.radius);
}

/// Box in the world: half extents, rotation (columns are the box axes) and centre.
struct WorldBox {
  V3 half;
  M3 rotation;
  V3 center;
};

/// Closest point of a solid box to x (x itself when inside) and the signed distance of x from the
/// box surface (negative inside: minus the distance to the nearest face).
struct BoxPoint {
  V3 closest;
  Real signed_distance;
};

inline BoxPoint point_box(const WorldBox& box, const V3& x) {
  const V3 local = box.rotation.transpose() * (x - box.center);
  V3 clamped;
  bool inside = true;
  Real depth = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < 3; ++i) {
    clamped[i] = std::clamp(local[i], -box.half[i], box.half[i]);
    if (std::abs(local[i]) > box.half[i]) inside = false;
    depth = std::min(depth, box.half[i] - std::abs(local[i]));
  }
  const V3 closest = box.rotation * clamped + box.center;
  if (inside) return {x, -depth};
  return {closest, (local - clamped).norm()};
}

/// Point (A) against box (B).
inline Answer point_box_answer(const V3& x, const WorldBox& box) {
  const BoxPoint bp = point_box(box, x);
  Answer ans;
  ans.gap = bp.signed_distance;
  ans.distance = std::max(Real(0), ans.gap);
  if (ans.gap > 0) {
    ans.point_a = x;
    ans.point_b = bp.closest;
    ans.normal = (bp.closest - x) / (bp.closest - x).norm();
  }
  return ans;
}

/// Sphere (A) against box (B).
inline Answer sphere_box(const V3& center, Real radius, const WorldBox& box) {
  const BoxPoint bp = point_box(box, center);
  Answer ans;
  ans.gap = bp.signed_distance - radius;
  ans.distance = std::max(Real(0), ans.gap);
  if (bp.signed_distance > 0) {
    ans.normal = (bp.closest - center) / (bp.closest - center).norm();
    ans.point_a = center + radius * ans.normal;
    ans.point_b = bp.closest;
  }
  return ans;
}

/// Capsule (A) against box (B): the core segment's point nearest the box (least_along_segment()),
/// then the box's closest point.
inline Answer capsule_box(const WorldCapsule& c, const WorldBox& box) {
  const Real t =
      least_along_segment(c.p, c.q, [&](const V3& x) { return V3(point_box(box, x).closest); });
  const V3 on_segment = c.p + t * (c.q - c.p);
  const BoxPoint bp = point_box(box, on_segment);
  if (bp.signed_distance <= 0) return from_cores(on_segment, on_segment, c.radius, 0);
  return from_cores(on_segment, bp.closest, c.radius, 0);
}
}  // namespace oracle
