#include "reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mink_bench {

namespace {

using Real = long double;
using V3 = Eigen::Matrix<Real, 3, 1>;

V3 to_world(const Eigen::Matrix3d& r, const Eigen::Vector3d& t, const Eigen::Vector3d& p) {
  return r.cast<Real>() * p.cast<Real>() + t.cast<Real>();
}

Real clamp01(Real x) {
  return std::min(Real(1), std::max(Real(0), x));
}

// Squared distance between segments p1-q1 and p2-q2 (Ericson, Real-Time Collision Detection,
// 5.1.9). Near-parallel segments may get a non-optimal parameter here, but their optimum is also
// reached at an endpoint, which the vertex-triangle pairs cover.
Real segment_segment_sq(const V3& p1, const V3& q1, const V3& p2, const V3& q2) {
  const V3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const Real a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  Real s = 0, t = 0;
  if (a == 0 && e == 0) return r.squaredNorm();
  if (a == 0) {
    t = clamp01(f / e);
  } else {
    const Real c = d1.dot(r);
    if (e == 0) {
      s = clamp01(-c / a);
    } else {
      const Real b = d1.dot(d2);
      const Real denom = a * e - b * b;
      s = denom > 0 ? clamp01((b * f - c * e) / denom) : Real(0);
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = clamp01(-c / a);
      } else if (t > 1) {
        t = 1;
        s = clamp01((b - c) / a);
      }
    }
  }
  return (p1 + s * d1 - (p2 + t * d2)).squaredNorm();
}

// Squared distance from p to triangle abc (Ericson 5.1.5, by Voronoi regions).
Real point_triangle_sq(const V3& p, const V3& a, const V3& b, const V3& c) {
  const V3 ab = b - a, ac = c - a, ap = p - a;
  const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const V3 bp = p - b;
  const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).squaredNorm();
  const V3 cp = p - c;
  const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).squaredNorm();
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).squaredNorm();
  const Real denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).squaredNorm();
}

struct WorldHull {
  std::vector<V3> v;
  const ShapeDesc* shape = nullptr;
};

WorldHull place(const ShapeDesc& s, const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
  WorldHull h;
  h.shape = &s;
  h.v.reserve(s.points.size());
  for (const auto& p : s.points) h.v.push_back(to_world(r, t, p));
  return h;
}

// Distance between two separated hulls: the closest pair lies on a vertex-triangle or an
// edge-edge pair. Features are pruned with a slab argument: for any unit n, the closest points
// x* (on A) and y* (on B) satisfy n.x* >= min_B n.y - U, where U is any upper bound on the
// distance (here the closest vertex pair), so only A's features reaching that far along n (and
// B's symmetrically) can hold them.
Real hull_hull_distance(const WorldHull& a, const WorldHull& b, const Eigen::Vector3d& axis) {
  Real upper_sq = std::numeric_limits<Real>::infinity();
  V3 best_dir = axis.cast<Real>();
  for (const auto& x : a.v)
    for (const auto& y : b.v) {
      const Real d = (y - x).squaredNorm();
      if (d < upper_sq) {
        upper_sq = d;
        best_dir = y - x;
      }
    }
  const Real upper = std::sqrt(upper_sq) * (1 + 1e-12L);
  V3 n = axis.cast<Real>().normalized();
  Real gap = -std::numeric_limits<Real>::infinity();
  Real max_a = 0, min_b = 0;
  for (const V3& dir : {n, V3(best_dir.normalized())}) {
    Real hi = -std::numeric_limits<Real>::infinity(), lo = std::numeric_limits<Real>::infinity();
    for (const auto& x : a.v) hi = std::max(hi, dir.dot(x));
    for (const auto& y : b.v) lo = std::min(lo, dir.dot(y));
    if (lo - hi > gap) {
      gap = lo - hi;
      n = dir;
      max_a = hi;
      min_b = lo;
    }
  }
  const Real slack = upper - gap;
  std::vector<char> in_a(a.v.size()), in_b(b.v.size());
  for (std::size_t i = 0; i < a.v.size(); ++i) in_a[i] = n.dot(a.v[i]) >= max_a - slack;
  for (std::size_t i = 0; i < b.v.size(); ++i) in_b[i] = n.dot(b.v[i]) <= min_b + slack;

  Real best = upper_sq;
  for (const auto& t : b.shape->triangles) {
    if (!in_b[t[0]] && !in_b[t[1]] && !in_b[t[2]]) continue;
    for (std::size_t i = 0; i < a.v.size(); ++i)
      if (in_a[i])
        best = std::min(best, point_triangle_sq(a.v[i], b.v[t[0]], b.v[t[1]], b.v[t[2]]));
  }
  for (const auto& t : a.shape->triangles) {
    if (!in_a[t[0]] && !in_a[t[1]] && !in_a[t[2]]) continue;
    for (std::size_t i = 0; i < b.v.size(); ++i)
      if (in_b[i])
        best = std::min(best, point_triangle_sq(b.v[i], a.v[t[0]], a.v[t[1]], a.v[t[2]]));
  }
  for (const auto& ea : a.shape->edges) {
    if (!in_a[ea[0]] && !in_a[ea[1]]) continue;
    for (const auto& eb : b.shape->edges) {
      if (!in_b[eb[0]] && !in_b[eb[1]]) continue;
      best = std::min(best, segment_segment_sq(a.v[ea[0]], a.v[ea[1]], b.v[eb[0]], b.v[eb[1]]));
    }
  }
  return std::sqrt(best);
}

}  // namespace

long double reference_distance(const Case& c, std::size_t i) {
  const PairPose& p = c.pairs[i];
  const ShapeDesc& sa = c.shapes_a[p.a];
  const ShapeDesc& sb = c.shapes_b[p.b];
  if (sa.kind == ShapeKind::Capsule && sb.kind == ShapeKind::Capsule) {
    const Eigen::Vector3d za(0, 0, sa.half_height), zb(0, 0, sb.half_height);
    const Real d = std::sqrt(segment_segment_sq(
        to_world(p.rotation_a, p.translation_a, -za), to_world(p.rotation_a, p.translation_a, za),
        to_world(p.rotation_b, p.translation_b, -zb), to_world(p.rotation_b, p.translation_b, zb)));
    return d - Real(sa.radius) - Real(sb.radius);
  }
  if (sa.kind == ShapeKind::Sphere && sb.kind == ShapeKind::Polytope) {
    // The centre is outside the hull (the pair is separated), so its distance to the hull is its
    // distance to the nearest boundary triangle.
    const V3 centre = p.translation_a.cast<Real>();
    const WorldHull hb = place(sb, p.rotation_b, p.translation_b);
    Real best = std::numeric_limits<Real>::infinity();
    for (const auto& t : sb.triangles)
      best = std::min(best, point_triangle_sq(centre, hb.v[t[0]], hb.v[t[1]], hb.v[t[2]]));
    return std::sqrt(best) - Real(sa.radius);
  }
  if (!sa.triangles.empty() && !sb.triangles.empty())
    return hull_hull_distance(place(sa, p.rotation_a, p.translation_a),
                              place(sb, p.rotation_b, p.translation_b), p.axis);
  throw std::logic_error("reference_distance: no reference for this pair of shapes");
}

}  // namespace mink_bench
