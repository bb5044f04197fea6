/// @file brute_force.hpp
/// Brute-force answers for polytope pairs, independent of mink and in long double:
///   - the distance from the origin to the convex hull of a small point set, by the minimum over
///     its hull facets (found by brute force over triples), all its edges and vertices, with an
///     inside test against every facet plane;
///   - polytope-pair distance through the Minkowski difference of their points;
///   - box-box separating-axis test over the 15 candidate axes.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "oracle/analytic.hpp"

namespace oracle {

/// Closest point of triangle (a, b, c) to x, by Voronoi regions (vertex, edge, face) using only
/// dot products. The triangle must not be degenerate.
inline V3 closest_on_triangle(const V3& x, const V3& a, const V3& b, const V3& c) {
  const V3 ab = b - a, ac = c - a, ap = x - a;
  const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const V3 bp = x - b;
  const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const V3 cp = x - c;
  const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const Real denom = Real(1) / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

/// Distance from the origin to conv(points).
struct HullAnswer {
  Real distance = 0;        ///< 0 when the origin is inside
  V3 closest = V3::Zero();  ///< closest point of the hull to the origin
  bool full_dimensional = false;
  /// Full-dimensional hull with the origin inside: distance from the origin to the nearest facet
  /// plane (the depth). Otherwise 0.
  Real depth = 0;
  int facets = 0;  ///< facet triples found (for the oracle's own tests)
};

inline HullAnswer hull_distance(const std::vector<V3>& points) {
  HullAnswer ans;
  const std::size_t n = points.size();
  Real best = std::numeric_limits<Real>::infinity();
  auto consider = [&](const V3& c) {
    const Real d = c.norm();
    if (d < best) {
      best = d;
      ans.closest = c;
    }
  };
  // Vertices and every edge: segments between points of the set lie in the hull, so each is an
  // upper bound that is attained, and with the facets they cover the hull's boundary.
  for (std::size_t i = 0; i < n; ++i) {
    consider(points[i]);
    for (std::size_t j = i + 1; j < n; ++j)
      consider(closest_on_segment(points[i], points[j], V3::Zero()).point);
  }
  // Affine dimension, decided once for the whole set with a relative tolerance: the farthest
  // point from points[0], the farthest from that line, the farthest from that plane.
  Real scale = 0;
  std::size_t i1 = 0;
  for (std::size_t i = 0; i < n; ++i)
    if ((points[i] - points[0]).norm() > scale) scale = (points[i] - points[0]).norm(), i1 = i;
  const Real flat_tol = Real(1e-12) * scale;
  Real line_dist = 0;
  std::size_t i2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const V3 axis = points[i1] - points[0], rel = points[i] - points[0];
    const Real d = scale > 0 ? (rel - axis * (rel.dot(axis) / axis.squaredNorm())).norm() : Real(0);
    if (d > line_dist) line_dist = d, i2 = i;
  }
  if (!(line_dist > flat_tol)) {  // a point or collinear: the edges decided
    ans.distance = best;
    return ans;
  }
  const V3 plane = (points[i1] - points[0]).cross(points[i2] - points[0]).normalized();
  Real thickness = 0;
  for (const V3& p : points) thickness = std::max(thickness, std::abs(plane.dot(p - points[0])));
  const bool flat = !(thickness > flat_tol);
  ans.full_dimensional = !flat;
  // Scan order for the side test: a stride through the set, so that points built next to each
  // other (as in a Minkowski difference) are not tested one after the other.
  std::vector<std::size_t> order(n);
  std::size_t stride = 7;  // coprime with n, so that the order is a permutation
  while (std::gcd(stride, n) != 1) stride += 2;
  for (std::size_t m = 0; m < n; ++m) order[m] = (m * stride) % n;
  bool origin_outside_a_facet = false;
  Real min_facet_distance = std::numeric_limits<Real>::infinity();
  // The side test runs in double (4x faster than long double here); its tolerance, 1e-12 of the
  // scale, is far above double rounding, and a plane it admits is a supporting plane up to that.
  std::vector<Eigen::Vector3d> pd(n);
  for (std::size_t m = 0; m < n; ++m) pd[m] = points[m].cast<double>();
  const double side_tol = 1e-12 * static_cast<double>(scale);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        const Eigen::Vector3d nd = (pd[j] - pd[i]).cross(pd[k] - pd[i]);
        const double lend = nd.norm();
        if (!(lend > 1e-13 * static_cast<double>(scale * scale))) continue;  // collinear: edges
        if (flat) {  // every triangle of a flat set lies in its hull; the minimum is attained
          ++ans.facets;
          consider(closest_on_triangle(V3::Zero(), points[i], points[j], points[k]));
          continue;
        }
        // A facet plane has no point strictly on both sides. Planes admitted by the tolerance
        // are still supporting planes up to it, so the inside test stays right; a missed facet is
        // what would be wrong.
        const Eigen::Vector3d ud = nd / lend;
        bool pos = false, neg = false;
        for (std::size_t m = 0; m < n && !(pos && neg); ++m) {
          const double sd = ud.dot(pd[order[m]] - pd[i]);
          pos |= sd > side_tol;
          neg |= sd < -side_tol;
        }
        if (pos && neg) continue;
        ++ans.facets;
        consider(closest_on_triangle(V3::Zero(), points[i], points[j], points[k]));
        const V3 u = (points[j] - points[i]).cross(points[k] - points[i]).normalized();
        const V3 outward = neg ? u : V3(-u);               // the points lie on the inner side
        const Real origin_side = -outward.dot(points[i]);  // signed distance of the origin
        if (origin_side > 0) origin_outside_a_facet = true;
        min_facet_distance = std::min(min_facet_distance, -origin_side);
      }
  if (!flat && !origin_outside_a_facet) {
    ans.distance = 0;
    ans.closest = V3::Zero();
    ans.depth = std::max(Real(0), min_facet_distance);
    return ans;
  }
  ans.distance = best;
  return ans;
}

/// Distance between conv(a_points) and conv(b_points), both in the world frame, through the
/// Minkowski difference B - A (so that its closest point to the origin is point_b - point_a).
inline Answer polytope_pair(const std::vector<V3>& a_points, const std::vector<V3>& b_points) {
  std::vector<V3> diff;
  diff.reserve(a_points.size() * b_points.size());
  for (const V3& b : b_points)
    for (const V3& a : a_points) diff.push_back(b - a);
  const HullAnswer h = hull_distance(diff);
  Answer ans;
  ans.distance = h.distance;
  ans.gap = h.distance > 0 ? h.distance : -h.depth;
  if (h.distance > 0) ans.normal = h.closest / h.distance;
  return ans;
}

/// The eight corners of a world box.
inline std::vector<V3> box_corners(const WorldBox& box) {
  std::vector<V3> corners;
  for (int i = 0; i < 8; ++i) {
    const V3 local((i & 1) ? box.half.x() : -box.half.x(), (i & 2) ? box.half.y() : -box.half.y(),
                   (i & 4) ? box.half.z() : -box.half.z());
    corners.push_back(box.rotation * local + box.center);
  }
  return corners;
}

/// Separating-axis test of two boxes over the 15 candidate axes (3 + 3 face normals, 9 edge
/// cross products). `separation` is the largest gap between the boxes' projections on a unit
/// axis: > 0 proves them apart (and bounds their distance from below), and when it is <= 0 on all
/// 15 axes the boxes intersect (the theorem for convex polyhedra).
struct SatAnswer {
  Real separation;
  V3 axis;
};

inline SatAnswer sat_box_box(const WorldBox& a, const WorldBox& b) {
  std::vector<V3> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(a.rotation.col(i));
  for (int i = 0; i < 3; ++i) axes.push_back(b.rotation.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const V3 c = a.rotation.col(i).cross(b.rotation.col(j));
      if (c.norm() > Real(1e-9)) axes.push_back(c.normalized());
    }
  SatAnswer best{-std::numeric_limits<Real>::infinity(), V3::UnitX()};
  const V3 t = b.center - a.center;
  for (const V3& l : axes) {
    Real ra = 0, rb = 0;
    for (int i = 0; i < 3; ++i) {
      ra += a.half[i] * std::abs(l.dot(a.rotation.col(i)));
      rb += b.half[i] * std::abs(l.dot(b.rotation.col(i)));
    }
    const Real s = std::abs(l.dot(t)) - ra - rb;
    if (s > best.separation) best = {s, l.dot(t) >= 0 ? l : V3(-l)};
  }
  return best;
}

}  // namespace oracle
