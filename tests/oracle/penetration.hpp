/// @file penetration.hpp
/// Penetration depths written independently of mink (no mink algorithm is called; only Eigen types
/// are shared) and evaluated in long double:
///   - the depth of the origin inside the convex hull of a small point set, by brute-force facet
///     enumeration over triples of points, with the support function h(u) = max_i u . p_i;
///   - polytope-pair depth through the Minkowski difference A - B of their world points, and the
///     least support value of A - B (depth inside, minus the distance outside) for point and
///     segment cores grown by a radius (spheres and capsules against polytopes);
///   - sphere-sphere, sphere-box, sphere-cylinder, capsule-capsule depths in closed form;
///   - box-box depth as the least overlap over the 15 separating-axis candidates.
/// Cost: the facet enumeration of an 8 + 8 point pair takes about 0.2 ms, 0.08 ms for 4 to 8
/// points (early exit, and only triples that can span a facet of a Minkowski difference).
///
/// Convention (mink's contact()): the normal n is unit, from A towards B, the direction B must
/// move by `depth` to separate. Moving B by t shifts A - B by -t, so the origin leaves A - B
/// exactly when t reaches the boundary of A - B: depth * n is the boundary point of A - B nearest
/// the origin, n its outward normal, and h_{A-B}(n) = depth. For any unit u, h_{A-B}(u) >= depth
/// (moving B by h(u) u separates too), which is how the tests check a normal for optimality when
/// several are equally good.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "oracle/analytic.hpp"
#include "oracle/brute_force.hpp"

namespace oracle {

/// Support function of a point set: h(u) = max_i u . p_i (u need not be unit).
inline Real support_of(const std::vector<V3>& points, const V3& u) {
  Real best = -std::numeric_limits<Real>::infinity();
  for (const V3& p : points) best = std::max(best, u.dot(p));
  return best;
}

/// A point of `points` at which support_of(points, u) is reached (the first one, on ties).
inline V3 support_point_of(const std::vector<V3>& points, const V3& u) {
  V3 best = points.front();
  for (const V3& p : points)
    if (u.dot(p) > u.dot(best)) best = p;
  return best;
}

/// Support function of the Minkowski difference A - B: h_A(u) + h_B(-u).
inline Real support_of_difference(const std::vector<V3>& a, const std::vector<V3>& b, const V3& u) {
  return support_of(a, u) + support_of(b, V3(-u));
}

/// Depth of the origin inside conv(points).
struct DepthAnswer {
  /// Least distance of the origin below a facet plane (= min over unit u of h(u)): > 0 when the
  /// origin is inside, negative when it is outside (then it is not a distance), <= 0 when the hull
  /// has no volume.
  Real depth = 0;
  V3 normal = V3::UnitZ();        ///< unit outward normal of a nearest facet (h(normal) = depth)
  bool full_dimensional = false;  ///< the hull has volume (thicker than 1e-12 of its extent)
  long triples = 0;               ///< triples with a plane (not collinear), for the self test
  long scanned = 0;               ///< orientations whose scan ran to the end
};

/// Brute-force facet enumeration over triples of a point set, one plane at a time. A triple of
/// points spans a facet plane, with outward normal o, when every point lies on its inner side:
/// o . p <= o . p_i, i.e. h(o) = o . p_i, and the depth is the least such offset. Every facet of a
/// full-dimensional hull is spanned by some triple, and no unit u has h(u) below the depth, so the
/// least offset over facet planes is also the least h(+-n) over the normals n of any family of
/// triples that contains one spanning each facet: a triple that is not a facet plane only has a
/// larger h. That form needs no tolerance to tell facets apart, and it allows the early exit that
/// makes the enumeration fast: the scan of the points stops as soon as a point lies on the wrong
/// side of each orientation of the plane by more than the best value so far (then neither
/// orientation can improve it), usually after a few points. When the origin is outside, the facet
/// it lies beyond has h(o) < 0, so the sign of the depth is right either way.
class PlaneScan {
 public:
  explicit PlaneScan(const std::vector<V3>& points) : points_(points) {
    const std::size_t n = points.size();
    for (const V3& p : points) scale_ = std::max(scale_, (p - points[0]).norm());
    // Seed the bound with the six axis directions (any unit u bounds the minimum from above).
    for (int axis = 0; axis < 6; ++axis) {
      V3 u = V3::Zero();
      u[axis / 2] = axis % 2 ? Real(-1) : Real(1);
      const Real h = support_of(points, u);
      if (h < ans_.depth) ans_.depth = h, ans_.normal = u;
    }
    // Scan order: a stride through the set, so that neighbouring points (as in a Minkowski
    // difference, where p_{i+1} - p_i is often small) are not tested one after the other.
    order_.resize(n);
    std::size_t stride = 7;
    while (n > 1 && std::gcd(stride, n) != 1) stride += 2;
    for (std::size_t m = 0; m < n; ++m) order_[m] = (m * stride) % n;
  }

  /// The plane through points i, j, k (skipped when they are collinear to 1e-12 of the extent).
  void consider(std::size_t i, std::size_t j, std::size_t k) {
    const V3 c = (points_[j] - points_[i]).cross(points_[k] - points_[i]);
    const Real cc = c.squaredNorm();
    if (!(cc > Real(1e-24) * scale_ * scale_ * scale_ * scale_)) return;
    ++ans_.triples;
    const V3 u = c / std::sqrt(cc);
    const Real offset = u.dot(points_[i]);
    // hi = max of u.p - offset, lo = min of u.p - offset over the points scanned so far; the
    // triple's own points give 0. h(u) = offset + hi, h(-u) = -offset - lo.
    Real hi = 0, lo = 0;
    const Real best = ans_.depth;
    for (const std::size_t m : order_) {
      const Real s = u.dot(points_[m]) - offset;
      hi = std::max(hi, s);
      lo = std::min(lo, s);
      if (offset + hi > best && -offset - lo > best) return;
    }
    ++ans_.scanned;
    if (offset + hi < ans_.depth) ans_.depth = offset + hi, ans_.normal = u;
    if (-offset - lo < ans_.depth) ans_.depth = -offset - lo, ans_.normal = -u;
  }

  /// The answer, with the volume decided once for the whole set with a relative tolerance: the
  /// farthest point from points[0], the farthest from that line, then the farthest from that
  /// plane (thicker than 1e-12 of the extent).
  DepthAnswer finish() {
    const std::size_t n = points_.size();
    std::size_t i1 = 0, i2 = 0;
    Real far1 = 0, far2 = 0;
    for (std::size_t i = 0; i < n; ++i)
      if ((points_[i] - points_[0]).norm() > far1) far1 = (points_[i] - points_[0]).norm(), i1 = i;
    const V3 axis = points_[i1] - points_[0];
    for (std::size_t i = 0; i < n && far1 > 0; ++i) {
      const Real d = axis.cross(points_[i] - points_[0]).norm() / axis.norm();
      if (d > far2) far2 = d, i2 = i;
    }
    if (far2 > Real(1e-12) * scale_) {
      const V3 plane = axis.cross(points_[i2] - points_[0]).normalized();
      Real t = 0;
      for (const V3& p : points_) t = std::max(t, std::abs(plane.dot(p - points_[0])));
      ans_.full_dimensional = t > Real(1e-12) * scale_;
    }
    // No volume: the origin is not inside (and the planes tried may all miss the set's own
    // directions, e.g. a point minus a segment has no triple at all).
    if (!ans_.full_dimensional) ans_.depth = std::min(ans_.depth, Real(0));
    return ans_;
  }

 private:
  const std::vector<V3>& points_;
  std::vector<std::size_t> order_;
  Real scale_ = 0;
  DepthAnswer ans_{std::numeric_limits<Real>::infinity()};
};

/// Depth of the origin inside conv(points), by facet enumeration over all triples: O(n^3) planes,
/// each scanned with the early exit above. Sets without volume give a depth <= 0 (about 0 when
/// the origin lies in their plane or line).
inline DepthAnswer hull_depth(const std::vector<V3>& points) {
  if (points.empty()) return {};
  PlaneScan scan(points);
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) scan.consider(i, j, k);
  return scan.finish();
}

/// Penetration of conv(a_points) and conv(b_points), world points: the depth of the origin inside
/// conv(A - B) and the outward normal there (the direction B moves to separate), by facet
/// enumeration over the points a_i - b_j. Only triples that can span a facet of a Minkowski
/// difference are tried: a facet of A - B is F_A - F_B for faces F_A of A and F_B of B supported
/// by the same direction, with F_A or F_B two-dimensional or both non-parallel edges, so its plane
/// is spanned by (a1 - b, a2 - b, a3 - b), by (a - b1, a - b2, a - b3) or by (a1 - b1, a2 - b1,
/// a1 - b2). That is about 1,700 planes for 8 + 8 points instead of 41,664 triples (the all-triples
/// hull_depth on the same points is the oracle's self test).
inline DepthAnswer polytope_penetration(const std::vector<V3>& a_input,
                                        const std::vector<V3>& b_input) {
  // Repeated points change nothing but the cost: drop exact duplicates.
  auto unique = [](const std::vector<V3>& in) {
    std::vector<V3> out;
    for (const V3& p : in)
      if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
    return out;
  };
  const std::vector<V3> a_points = unique(a_input), b_points = unique(b_input);
  const std::size_t na = a_points.size(), nb = b_points.size();
  if (na == 0 || nb == 0) return {};
  std::vector<V3> diff;
  diff.reserve(na * nb);
  for (const V3& a : a_points)
    for (const V3& b : b_points) diff.push_back(a - b);
  auto at = [nb](std::size_t ia, std::size_t ib) { return ia * nb + ib; };
  PlaneScan scan(diff);
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = i + 1; j < na; ++j) {
      for (std::size_t k = j + 1; k < na; ++k)
        for (std::size_t b = 0; b < nb; ++b) scan.consider(at(i, b), at(j, b), at(k, b));
      for (std::size_t b1 = 0; b1 < nb; ++b1)
        for (std::size_t b2 = b1 + 1; b2 < nb; ++b2) scan.consider(at(i, b1), at(j, b1), at(i, b2));
    }
  for (std::size_t i = 0; i < nb; ++i)
    for (std::size_t j = i + 1; j < nb; ++j)
      for (std::size_t k = j + 1; k < nb; ++k)
        for (std::size_t a = 0; a < na; ++a) scan.consider(at(a, i), at(a, j), at(a, k));
  return scan.finish();
}

/// Distance from the origin to conv(points) when the origin is outside it: the least distance to
/// a point, a segment or a triangle of the set. Every such piece lies in the hull, and the hull's
/// nearest point lies on a boundary facet, which the triangles of its points cover, so the least
/// is attained; no inside test or tolerance is needed (inside, the result is not 0 but the
/// distance to the nearest triangle, hence "when outside").
inline Real outside_distance(const std::vector<V3>& points) {
  const std::size_t n = points.size();
  Real scale = 0;
  for (const V3& p : points) scale = std::max(scale, (p - points[0]).norm());
  Real best = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    best = std::min(best, points[i].norm());
    for (std::size_t j = i + 1; j < n; ++j) {
      best = std::min(best, closest_on_segment(points[i], points[j], V3::Zero()).point.norm());
      for (std::size_t k = j + 1; k < n; ++k) {
        const Real cc = (points[j] - points[i]).cross(points[k] - points[i]).squaredNorm();
        if (!(cc > Real(1e-24) * scale * scale * scale * scale)) continue;  // its edges decide
        best =
            std::min(best, closest_on_triangle(V3::Zero(), points[i], points[j], points[k]).norm());
      }
    }
  }
  return best;
}

/// The least support value of conv(a) - conv(b) over unit directions, min_u h_{A-B}(u): the depth
/// of the origin in it when inside (facet enumeration, polytope_penetration), minus its distance
/// when outside (outside_distance), 0 when A - B has no volume and holds the origin. Shapes grown
/// by radii r_a and r_b (spheres and capsules around point and segment cores) penetrate by
/// r_a + r_b + this.
inline Real least_support_of_difference(const std::vector<V3>& a, const std::vector<V3>& b) {
  const DepthAnswer inside = polytope_penetration(a, b);
  if (inside.depth > 0) return inside.depth;
  std::vector<V3> diff;
  for (const V3& p : a)
    for (const V3& q : b) diff.push_back(p - q);
  return -outside_distance(diff);
}

/// A depth with its normal (the direction B moves to separate) from a closed form.
struct Penetration {
  Real depth = 0;  ///< negative when the shapes are apart (minus the distance)
  V3 normal = V3::UnitZ();
  /// How much deeper the next best candidate normal is (infinite when the normal is unique by
  /// geometry, 0 when several normals are equally good): compare normals only when it is clearly
  /// positive.
  Real tie_margin = std::numeric_limits<Real>::infinity();
};

/// Spheres A (centre ca, radius ra) and B: B moves away from A along the line of centres.
inline Penetration sphere_sphere_penetration(const V3& ca, Real ra, const V3& cb, Real rb) {
  Penetration p;
  const V3 d = cb - ca;
  const Real len = d.norm();
  p.depth = ra + rb - len;
  if (len > 0) p.normal = d / len;
  if (!(len > 0)) p.tie_margin = 0;
  return p;
}

/// Sphere A (centre c, radius r) and box B. Centre outside the box: the box moves away from the
/// centre along the line from the centre to its nearest box point, depth r - distance. Centre
/// inside: the box moves so that its face nearest the centre passes the sphere, i.e. along minus
/// that face's outward normal, depth r + (distance of the centre below that face).
inline Penetration sphere_box_penetration(const V3& c, Real r, const WorldBox& box) {
  Penetration p;
  const V3 local = box.rotation.transpose() * (c - box.center);
  V3 clamped;
  bool inside = true;
  for (int i = 0; i < 3; ++i) {
    clamped[i] = std::clamp(local[i], -box.half[i], box.half[i]);
    if (std::abs(local[i]) > box.half[i]) inside = false;
  }
  if (!inside) {
    const V3 q = box.rotation * clamped + box.center;
    const V3 d = q - c;
    const Real len = d.norm();
    p.depth = r - len;
    p.normal = d / len;
    return p;
  }
  // Nearest face: the smallest half[i] - |local[i]|; ties leave several normals equally good.
  int axis = 0;
  Real below = std::numeric_limits<Real>::infinity(), second = below;
  for (int i = 0; i < 3; ++i) {
    const Real g = box.half[i] - std::abs(local[i]);
    if (g < below) {
      second = below;
      below = g, axis = i;
    } else {
      second = std::min(second, g);
    }
  }
  const Real sign = local[axis] >= 0 ? Real(1) : Real(-1);
  p.depth = r + below;
  p.normal = -sign * box.rotation.col(axis);
  // The other candidates: the other faces, and the opposite face, 2 |local[axis]| deeper.
  p.tie_margin = std::min(second - below, 2 * std::abs(local[axis]));
  return p;
}

/// Cylinder in the world: radius, half height along its local z, rotation and centre.
struct WorldCylinder {
  Real radius, half_height;
  M3 rotation;
  V3 center;
};

/// Sphere A (centre c, radius r) and cylinder B. Centre outside: B moves away from the centre
/// along the line to its nearest cylinder point, depth r - distance. Centre inside: B moves so
/// that its nearest surface (the side, or a cap) passes the sphere, depth r + (distance of the
/// centre below that surface): along minus the radial direction for the side, minus the cap's
/// normal for a cap.
inline Penetration sphere_cylinder_penetration(const V3& c, Real r, const WorldCylinder& cyl) {
  Penetration p;
  const V3 local = cyl.rotation.transpose() * (c - cyl.center);
  const Real rho = std::sqrt(local.x() * local.x() + local.y() * local.y());
  const V3 radial = rho > 0 ? V3(local.x() / rho, local.y() / rho, 0) : V3(1, 0, 0);
  if (rho > cyl.radius || std::abs(local.z()) > cyl.half_height) {
    const V3 q_local = std::min(rho, cyl.radius) * radial +
                       V3(0, 0, std::clamp(local.z(), -cyl.half_height, cyl.half_height));
    const V3 d = cyl.rotation * q_local + cyl.center - c;
    const Real len = d.norm();
    p.depth = r - len;
    p.normal = d / len;
    return p;
  }
  const Real side = cyl.radius - rho, cap = cyl.half_height - std::abs(local.z());
  if (side <= cap) {
    p.depth = r + side;
    p.normal = -(cyl.rotation * radial);
    p.tie_margin = std::min(cap - side, 2 * rho);  // a cap; the far side of the rim
  } else {
    p.depth = r + cap;
    p.normal = -(local.z() >= 0 ? Real(1) : Real(-1)) * cyl.rotation.col(2);
    p.tie_margin = std::min(side - cap, 2 * std::abs(local.z()));  // the side; the other cap
  }
  return p;
}

/// Capsules: r1 + r2 minus the distance of the core segments, B moving away from A's segment
/// along the line of the closest points. When the segments meet the normal is not unique.
inline Penetration capsule_capsule_penetration(const WorldCapsule& a, const WorldCapsule& b) {
  Penetration p;
  const SegmentPair s = closest_segment_segment(a.p, a.q, b.p, b.q);
  p.depth = a.radius + b.radius - s.distance;
  if (!(s.distance > 0)) p.tie_margin = 0;
  if (s.distance > 0) p.normal = (s.on_second - s.on_first) / s.distance;
  return p;
}

/// Boxes: the least overlap of the projections over the 15 candidate axes (3 + 3 face normals,
/// 9 cross products of edge directions, skipped when the edges are parallel to 1e-9). These axes
/// include every facet normal of A - B, so the least overlap is the depth (negative when some axis
/// separates them). The normal points from A's centre towards B's along the axis.
inline Penetration box_box_penetration(const WorldBox& a, const WorldBox& b) {
  std::vector<V3> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(a.rotation.col(i));
  for (int i = 0; i < 3; ++i) axes.push_back(b.rotation.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const V3 c = a.rotation.col(i).cross(b.rotation.col(j));
      if (c.norm() > Real(1e-9)) axes.push_back(c.normalized());
    }
  Penetration best;
  best.depth = std::numeric_limits<Real>::infinity();
  Real second = best.depth;
  const V3 t = b.center - a.center;
  for (const V3& l : axes) {
    Real ra = 0, rb = 0;
    for (int i = 0; i < 3; ++i) {
      ra += a.half[i] * std::abs(l.dot(a.rotation.col(i)));
      rb += b.half[i] * std::abs(l.dot(b.rotation.col(i)));
    }
    const Real overlap = ra + rb - std::abs(l.dot(t));
    if (overlap < best.depth) {
      second = best.depth;
      best.depth = overlap, best.normal = l.dot(t) >= 0 ? l : V3(-l);
    } else {
      second = std::min(second, overlap);
    }
  }
  // Ties are common (coincident or aligned boxes, and l.t = 0 leaves both signs): compare
  // h_{A-B}(normal) with the depth rather than the normal itself.
  best.tie_margin = std::abs(best.normal.dot(t)) > 0 ? second - best.depth : Real(0);
  return best;
}

}  // namespace oracle
