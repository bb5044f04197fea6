/// @file clip.hpp
/// The two steps of a contact manifold after the features are known: clipping the incident
/// feature against the side planes of the reference feature (Sutherland–Hodgman), and reducing the
/// clipped points to at most four.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/math/vec.hpp"

namespace mink::detail {

/// Most points a clipped polygon can have: an incident polygon of 16 points cut by 16 side planes.
inline constexpr int kMaxClipPoints = 40;

/// Clips the polygon (count >= 3, closed), segment (count 2) or point (count 1) `in` by the
/// half-space s . p >= w - slack and writes the result to `out`; returns its number of points.
/// Points on the plane are kept; new points are where an edge crosses the plane.
template <class S>
int clip_by_plane(const Vec3T<S>* in, int count, const Vec3T<S>& s, S w, S slack, Vec3T<S>* out) {
  auto inside = [&](const Vec3T<S>& p) { return s.dot(p) - w >= -slack; };
  auto cross = [&](const Vec3T<S>& p, const Vec3T<S>& q) {
    // p and q are on opposite sides, so the heights differ and the division is safe.
    const S hp = s.dot(p) - w, hq = s.dot(q) - w;
    const S t = std::clamp(hp / (hp - hq), S(0), S(1));
    return Vec3T<S>(p + t * (q - p));
  };
  if (count == 1) {
    if (!inside(in[0])) return 0;
    out[0] = in[0];
    return 1;
  }
  if (count == 2) {
    const bool a = inside(in[0]), b = inside(in[1]);
    if (!a && !b) return 0;
    out[0] = a ? in[0] : cross(in[1], in[0]);
    out[1] = b ? in[1] : cross(in[0], in[1]);
    return 2;
  }
  int n = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3T<S>& p = in[i];
    const Vec3T<S>& q = in[(i + 1) % count];
    const bool a = inside(p), b = inside(q);
    if (a) out[n++] = p;
    if (a != b && n < kMaxClipPoints) out[n++] = cross(p, q);
    if (n >= kMaxClipPoints) break;
  }
  return n;
}

/// Index of the first of `count` values within `slack` of their maximum, or -1 when that maximum
/// is not above `floor`. Taking the first near-maximum rather than the maximum makes the choice
/// depend on the order of the points (fixed by the shapes' local frames) instead of on rounding:
/// the same points survive a rigid motion of both shapes and tiny perturbations.
template <class S, class Value>
int first_near_max(int count, S floor, S slack, Value&& value) {
  S best = floor;
  for (int i = 0; i < count; ++i) best = std::max(best, value(i));
  if (!(best > floor)) return -1;
  for (int i = 0; i < count; ++i)
    if (value(i) >= best - slack) return i;
  return -1;
}

/// Indices of at most four of the `count` points (with depths) that keep the deepest point and as
/// much of the contact area as possible, seen along the unit normal n: the deepest point, the
/// point farthest from it, the point making the largest triangle with those two, and the point
/// that adds the most area outside that triangle. Points closer than `min_length` to a kept point
/// (or to the line or triangle of the kept ones) are dropped as repeats; candidates within
/// `min_length` (or the matching area) of the best count as ties and the first one wins. Returns
/// the number kept.
template <class S>
int reduce_to_four(const Vec3T<S>* points, const S* depths, int count, const Vec3T<S>& n,
                   S min_length, int* keep) {
  if (count <= 0) return 0;
  const int a = first_near_max(count, -std::numeric_limits<S>::infinity(), min_length,
                               [&](int i) { return depths[i]; });
  keep[0] = a < 0 ? 0 : a;
  const Vec3T<S> pa = points[keep[0]];
  // Lengths measured across the normal: two points above one another are one contact.
  auto across = [&](const Vec3T<S>& v) { return Vec3T<S>(v - v.dot(n) * n); };
  const int b = first_near_max(count, min_length, min_length,
                               [&](int i) { return across(points[i] - pa).norm(); });
  if (b < 0) return 1;
  keep[1] = b;
  const Vec3T<S> pb = points[b];
  // Twice the area, signed about n.
  auto area = [&](const Vec3T<S>& o, const Vec3T<S>& p, const Vec3T<S>& q) {
    return (p - o).cross(q - o).dot(n);
  };
  const S min_area = min_length * across(pb - pa).norm();
  const int c = first_near_max(count, min_area, min_area,
                               [&](int i) { return std::abs(area(pa, pb, points[i])); });
  if (c < 0) return 2;
  keep[2] = c;
  // Counter-clockwise about n, so that a point outside an edge has a negative area with it.
  Vec3T<S> t0 = pa, t1 = pb, t2 = points[c];
  if (area(t0, t1, t2) < S(0)) std::swap(t1, t2);
  const int d = first_near_max(count, min_area, min_area, [&](int i) {
    const Vec3T<S>& p = points[i];
    return std::max({-area(t0, t1, p), -area(t1, t2, p), -area(t2, t0, p)});
  });
  if (d < 0) return 3;
  keep[3] = d;
  return 4;
}

}  // namespace mink::detail
