/// @file clip.hpp
/// The two steps of a contact manifold after the features are known: clipping the incident
/// feature against the side planes of the reference feature (Sutherland–Hodgman), and reducing the
/// clipped points to at most four.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "mink/math/vec.hpp"

namespace mink::detail {

/// Most points a clipped polygon can have: an incident polygon of 16 points cut by 16 side planes.
inline constexpr int kMaxClipPoints = 40;

/// A clipped point seen along the contact normal: its coordinates in a plane it is projected onto
/// along the normal (across the normal, or a box's reference face, where lengths stretch by at
/// most 1 / |face normal . normal|; unit: length) and its depth below the reference feature along
/// the normal (> 0 penetrating).
template <class S>
struct PlanarPoint {
  S x, y, depth;
};

/// Sets `p` to (x, y, depth), x and y stored as one pair: clip_by_line() copies and interpolates
/// them as a pair, and a pair loaded from two separate stores stalls on store forwarding.
template <class S>
[[gnu::always_inline]] inline void set_planar(PlanarPoint<S>& p, S x, S y, S depth) {
  static_assert(offsetof(PlanarPoint<S>, y) == offsetof(PlanarPoint<S>, x) + sizeof(S));
  using Pair = Eigen::Array<S, 2, 1>;
  Eigen::Map<Pair>(&p.x) = Pair(x, y);
  p.depth = depth;
}

/// Clips the polygon (count >= 3, closed), segment (count 2) or point (count 1) `in` to the
/// points where height(p) >= -slack, carrying the depths along, and writes the result to `out`;
/// returns its number of points. `height` is affine in (x, y) (a signed distance to a line).
/// Points on the line are kept; new points are where an edge crosses it. (Clipping in 2D after
/// projecting along the normal is clipping in 3D by the planes that contain the normal, at a
/// third of the cost.)
template <class S, class Height>
int clip_by_line(const PlanarPoint<S>* in, int count, Height&& height, S slack,
                 PlanarPoint<S>* out) {
  auto cross = [](const PlanarPoint<S>& p, S hp, const PlanarPoint<S>& q, S hq) {
    // p and q are on opposite sides, so the heights differ and the division is safe.
    const S t = std::clamp(hp / (hp - hq), S(0), S(1));
    return PlanarPoint<S>{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y),
                          p.depth + t * (q.depth - p.depth)};
  };
  if (count == 1) {
    if (!(height(in[0]) >= -slack)) return 0;
    out[0] = in[0];
    return 1;
  }
  if (count == 2) {
    const S h0 = height(in[0]), h1 = height(in[1]);
    const bool a0 = h0 >= -slack, a1 = h1 >= -slack;
    if (!a0 && !a1) return 0;
    out[0] = a0 ? in[0] : cross(in[1], h1, in[0], h0);
    out[1] = a1 ? in[1] : cross(in[0], h0, in[1], h1);
    return 2;
  }
  S heights[kMaxClipPoints];
  for (int i = 0; i < count; ++i) heights[i] = height(in[i]);
  int n = 0;
  for (int i = 0; i < count && n < kMaxClipPoints; ++i) {
    // The edge from p to the next point q: keep p when inside, add the crossing when q is not on
    // p's side.
    const int j = i + 1 == count ? 0 : i + 1;
    const bool ap = heights[i] >= -slack, aq = heights[j] >= -slack;
    if (ap) out[n++] = in[i];
    if (ap != aq && n < kMaxClipPoints) out[n++] = cross(in[i], heights[i], in[j], heights[j]);
  }
  return n;
}

/// Index of the first of `count` (<= kCapacity) values within `slack` of their maximum, or -1
/// when that maximum is not above `floor`. Taking the first near-maximum rather than the maximum
/// makes the choice depend on the order of the points (fixed by the shapes' local frames) instead
/// of on rounding: the same points survive a rigid motion of both shapes and tiny perturbations.
template <int kCapacity = kMaxClipPoints, class S, class Value>
[[gnu::always_inline]] inline int first_near_max(int count, S floor, S slack, Value&& value) {
  S values[kCapacity];
  S best = floor;
  for (int i = 0; i < count; ++i) best = std::max(best, values[i] = value(i));
  if (!(best > floor)) return -1;
  for (int i = 0; i < count; ++i)
    if (values[i] >= best - slack) return i;
  return -1;
}

/// reduce_to_four() (below) with the number of points fixed at compile time (kFixed > 0) or given
/// at run time (0): with a fixed count the loops unroll and their values stay in registers.
template <int kFixed, class S>
[[gnu::always_inline]] inline int reduce_points_to_four(const PlanarPoint<S>* points,
                                                        int run_time_count, S min_length,
                                                        int* keep) {
  constexpr int kCapacity = kFixed > 0 ? kFixed : kMaxClipPoints;
  const int count = kFixed > 0 ? kFixed : run_time_count;
  auto near_max = [count](S floor, S slack, auto&& value) {
    return first_near_max<kCapacity>(count, floor, slack, value);
  };
  const int a = near_max(-std::numeric_limits<S>::infinity(), min_length,
                         [&](int i) { return points[i].depth; });
  keep[0] = a < 0 ? 0 : a;
  const PlanarPoint<S> pa = points[keep[0]];
  // The farthest point, on squared lengths: one square root instead of one per point (a point
  // within min_length of the farthest length l counts as a tie: its squared length is at least
  // (l - min_length)^2).
  S length_sq[kCapacity];
  S farthest_sq = S(0);
  int farthest = 0;
  for (int i = 0; i < count; ++i) {
    const S x = points[i].x - pa.x, y = points[i].y - pa.y;
    length_sq[i] = x * x + y * y;
    if (length_sq[i] > farthest_sq) farthest_sq = length_sq[farthest = i];
  }
  if (!(farthest_sq > min_length * min_length)) return 1;
  const S tie = std::sqrt(farthest_sq) - min_length;
  int b = 0;
  while (b < farthest && !(length_sq[b] >= tie * tie)) ++b;
  keep[1] = b;
  const PlanarPoint<S> pb = points[b];
  // Twice the signed area of (o, p, q), counter-clockwise positive, as a x + b y + c in q.
  struct Edge {
    S a, b, c;
    S area(const PlanarPoint<S>& q) const { return a * q.x + b * q.y + c; }
  };
  auto edge = [](const PlanarPoint<S>& o, const PlanarPoint<S>& p) {
    const S dx = p.x - o.x, dy = p.y - o.y;
    return Edge{-dy, dx, dy * o.x - dx * o.y};
  };
  const Edge ab = edge(pa, pb);
  const S min_area = min_length * std::sqrt(length_sq[b]);
  const int c = near_max(min_area, min_area, [&](int i) { return std::abs(ab.area(points[i])); });
  if (c < 0) {
    // All on a line (skew edges): the deepest point may lie between the ends, so the end beyond
    // it, opposite the farthest one, is kept too.
    const S dx = pb.x - pa.x, dy = pb.y - pa.y;
    const int e = near_max(min_area, min_area, [&](int i) {
      return -((points[i].x - pa.x) * dx + (points[i].y - pa.y) * dy);
    });
    if (e < 0) return 2;
    keep[2] = e;
    return 3;
  }
  keep[2] = c;
  // Counter-clockwise, so that a point outside an edge has a negative area with it.
  PlanarPoint<S> t0 = pa, t1 = pb, t2 = points[c];
  if (ab.area(t2) < S(0)) std::swap(t1, t2);
  const Edge e0 = edge(t0, t1), e1 = edge(t1, t2), e2 = edge(t2, t0);
  const int d = near_max(min_area, min_area, [&](int i) {
    const PlanarPoint<S>& p = points[i];
    return -std::min(std::min(e0.area(p), e1.area(p)), e2.area(p));
  });
  if (d < 0) return 3;
  keep[3] = d;
  return 4;
}

/// Whether the general steps (reduce_points_to_four()) would keep all of the four points `p`: they
/// are in convex position, in cyclic order (as clipping a face by a convex face leaves them), and
/// each lies more than `min_length` from the line through any two others. Then the triangle of any
/// three has twice the area min_length times its longest side or more, which is what those steps
/// ask of their third and fourth points (a box's face on a face, the common resting contact,
/// spared their passes).
template <class S>
[[gnu::always_inline]] inline bool keeps_whole_quad(const PlanarPoint<S>* p, S min_length) {
  // The turns (cross products of consecutive sides) of the closed polygon p0 p1 p2 p3: of one
  // sign exactly when it is convex and simple; with four points, the four consecutive triples are
  // all the triples.
  S turn[4];
  S longest_sq = S(0);  // the longest side or diagonal bounds every side of every triangle
  for (int i = 0; i < 4; ++i) {
    const PlanarPoint<S>&o = p[i], &q = p[(i + 1) & 3], &r = p[(i + 2) & 3];
    const S ax = q.x - o.x, ay = q.y - o.y, bx = r.x - q.x, by = r.y - q.y;
    turn[i] = ax * by - ay * bx;
    longest_sq = std::max(longest_sq, ax * ax + ay * ay);
    if (i < 2)
      longest_sq = std::max(longest_sq, (r.x - o.x) * (r.x - o.x) + (r.y - o.y) * (r.y - o.y));
  }
  const S floor_sq = min_length * min_length * longest_sq;
  bool positive = true, negative = true, wide = true;
  for (int i = 0; i < 4; ++i) {
    positive &= turn[i] > S(0);
    negative &= turn[i] < S(0);
    wide &= turn[i] * turn[i] > floor_sq;
  }
  return (positive || negative) && wide;
}

/// Indices of at most four of the `count` points (seen along the normal, with depths) that keep
/// the deepest point and as much of the contact area as possible: the deepest point, the point
/// farthest from it, the point making the largest triangle with those two, and the point that
/// adds the most area outside that triangle. Points on a line keep the deepest and both ends.
/// Points closer than `min_length` to a kept point (or to the line or triangle of the kept ones)
/// are dropped as repeats; candidates within `min_length` (or the matching area) of the best count
/// as ties and the first one wins. Returns the number kept.
template <class S>
int reduce_to_four(const PlanarPoint<S>* points, int count, S min_length, int* keep) {
  if (count <= 0) return 0;
  if (count == 1) {  // most deep random overlaps: a vertex on a face, or crossing edges
    keep[0] = 0;
    return 1;
  }
  // Two points (an edge on a face) and four (a box's face on a face) are the common cases of
  // resting contact.
  if (count == 2) return reduce_points_to_four<2>(points, count, min_length, keep);
  if (count == 4) {
    if (keeps_whole_quad(points, min_length)) {
      // All four, the deepest first (as the steps choose it) and the rest in cyclic order.
      const int deepest = first_near_max<4>(4, -std::numeric_limits<S>::infinity(), min_length,
                                            [&](int i) { return points[i].depth; });
      const int first = deepest < 0 ? 0 : deepest;
      for (int i = 0; i < 4; ++i) keep[i] = (first + i) & 3;
      return 4;
    }
    return reduce_points_to_four<4>(points, count, min_length, keep);
  }
  return reduce_points_to_four<0>(points, count, min_length, keep);
}

}  // namespace mink::detail
