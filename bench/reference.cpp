#include "reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

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

// ---- Penetration depth ----------------------------------------------------------------------
//
// Let Z = A - B = {a - b}, whose support function is h_Z(n) = h_A(n) + h_B(-n). Moving B by t n
// (n unit) leaves the shapes overlapping exactly while t n is in Z, so the shortest separating
// translation has the length of the distance from the origin (inside Z) to Z's boundary, which for
// a convex set holding the origin is min over unit n of h_Z(n). Any unit n gives an upper bound
// h_Z(n) >= depth; the reference evaluates h_Z exactly on a finite set of normals that contains a
// minimiser, so their minimum is the depth.
//
// Polytopes and boxes: Z is the polytope A + (-B), and the distance from an interior point to its
// boundary is the least offset of a facet plane, attained at a facet normal. The facet normals of
// a Minkowski sum are the vertices of the overlay of the two Gauss maps: the outward face normals
// of A, those of -B (minus B's), and the points where an arc of A's map (an edge of A: the great
// arc between its two faces' normals) crosses an arc of -B's map; the crossing is along the cross
// product of the two edges. So the candidates are: every face normal of A and of -B, and every
// crossing of an A arc with a -B arc. The crossing test is done in double with a tolerance, so it
// may admit a few pairs that do not quite cross but never drops one that does; admitting extra
// normals is harmless because every candidate's h_Z is computed in full (all vertices, long
// double), so each is an upper bound. Pairs of parallel edges are skipped: their arcs lie on one
// great circle and the facets they border have the arcs' end points, face normals, as normals.
//
// Sphere (centre c, radius r) against a polytope B: h_Z(n) = r + h_{c - B}(n), so the depth is r
// plus the depth of c in B (the least distance to a face plane when c is inside B) or minus c's
// distance to B (outside: min over n of h_X(n) is minus the distance from the origin to X).
//
// Capsules (core segments S_A, S_B, radii r_A, r_B): Z = (S_A - S_B) + ball(r_A + r_B), where
// S_A - S_B is a flat parallelogram. If it misses the origin, min h_{S_A - S_B} is minus the
// segments' distance; if it holds it (the segments cross), that minimum is 0 (h >= 0 everywhere,
// and 0 along the parallelogram's normal), which is again minus their distance. So the depth is
// r_A + r_B - dist(S_A, S_B) in every case.

using Vd = Eigen::Vector3d;

/// A polytope (or box) placed in the world, or its negation (for -B): vertices, outward unit face
/// normals and the arcs of its Gauss map.
struct GaussMap {
  struct Arc {
    Vd from, to;   // unit outward normals of the two faces at the edge
    Vd axis;       // unit edge direction, normal to the great circle through from and to
    V3 axis_l;     // the same in long double
    Vd mid;        // unit midpoint of the arc
    double chord;  // |from - mid|: every point of the arc lies within this of mid
    int vertex;    // an end of the edge
  };
  std::vector<V3> v;
  std::vector<Vd> vd;  // v rounded to double: finds the support vertex candidates quickly
  std::vector<V3> normals;
  std::vector<Arc> arcs;
};

GaussMap gauss_map(const ShapeDesc& s, const Eigen::Matrix3d& r, const Eigen::Vector3d& t,
                   bool negate) {
  GaussMap g;
  const Real sign = negate ? -1 : 1;
  for (const auto& p : s.points) {
    g.v.push_back(sign * to_world(r, t, p));
    g.vd.push_back(g.v.back().cast<double>());
  }
  // Negating the vertices keeps each triangle's cross product but the outward normal flips.
  for (const auto& f : s.triangles)
    g.normals.push_back(sign * (g.v[f[1]] - g.v[f[0]]).cross(g.v[f[2]] - g.v[f[0]]).normalized());
  std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
  for (std::size_t k = 0; k < s.triangles.size(); ++k)
    for (int j = 0; j < 3; ++j) {
      const int p = s.triangles[k][j], q = s.triangles[k][(j + 1) % 3];
      faces_of_edge[{std::min(p, q), std::max(p, q)}].push_back(static_cast<int>(k));
    }
  for (const auto& e : s.edges) {
    const auto& faces = faces_of_edge.at({e[0], e[1]});
    if (faces.size() != 2) throw std::logic_error("reference_depth: edge without two faces");
    GaussMap::Arc a;
    a.from = g.normals[faces[0]].cast<double>();
    a.to = g.normals[faces[1]].cast<double>();
    a.axis_l = (g.v[e[1]] - g.v[e[0]]).normalized();
    a.axis = a.axis_l.cast<double>();
    a.mid = a.from + a.to;
    // Coplanar faces (a box face's diagonal): the arc is one point, already a face normal.
    if (a.mid.norm() < 1e-9 || (a.from - a.to).norm() < 1e-12) continue;
    a.mid.normalize();
    a.chord = (a.from - a.mid).norm();
    a.vertex = e[0];
    g.arcs.push_back(a);
  }
  return g;
}

/// h(n) = max over the vertices of n.v, exactly: the largest dot product in double singles out
/// the few vertices that can hold the maximum, which are then compared in long double.
Real support_of(const GaussMap& g, const V3& n) {
  const Vd nd = n.cast<double>();
  double best = -std::numeric_limits<double>::infinity();
  for (const auto& p : g.vd) best = std::max(best, nd.dot(p));
  Real h = -std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < g.vd.size(); ++i)
    if (nd.dot(g.vd[i]) >= best - 1e-9) h = std::max(h, n.dot(g.v[i]));
  return h;
}

Real polytope_depth(const GaussMap& a, const GaussMap& mb) {
  Real best = std::numeric_limits<Real>::infinity();
  for (const GaussMap* g : {&a, &mb})
    for (const V3& n : g->normals) best = std::min(best, support_of(a, n) + support_of(mb, n));
  constexpr double kTol = 1e-12;
  for (const auto& p : a.arcs)
    for (const auto& q : mb.arcs) {
      const double reach = p.chord + q.chord + 1e-9;
      if ((p.mid - q.mid).squaredNorm() > reach * reach) continue;  // caps apart
      // q's ends on both sides of p's great circle, and p's ends on both sides of q's.
      if (p.axis.dot(q.from) * p.axis.dot(q.to) > kTol) continue;
      if (q.axis.dot(p.from) * q.axis.dot(p.to) > kTol) continue;
      V3 n = p.axis_l.cross(q.axis_l);
      const Real len = n.norm();
      if (len < 1e-12L) continue;  // parallel edges
      n /= len;
      // Of the two crossings of the great circles, take the one on p's arc; it must be q's.
      if (n.cast<double>().dot(p.mid) < 0) n = -n;
      if (n.cast<double>().dot(q.mid) < -1e-9) continue;
      // n.(vertex of p's edge) + n.(vertex of q's edge) is a lower bound on h_Z(n): skip the
      // normal when even that cannot improve on the best.
      if (n.dot(a.v[p.vertex]) + n.dot(mb.v[q.vertex]) >= best) continue;
      best = std::min(best, support_of(a, n) + support_of(mb, n));
    }
  return best;
}

/// Signed depth of point c in the placed polytope h: positive inside (distance to the boundary),
/// negative outside (minus the distance).
Real point_depth(const V3& c, const WorldHull& h) {
  Real inside = std::numeric_limits<Real>::infinity();
  for (const auto& t : h.shape->triangles) {
    const V3 m = (h.v[t[1]] - h.v[t[0]]).cross(h.v[t[2]] - h.v[t[0]]).normalized();
    inside = std::min(inside, m.dot(h.v[t[0]] - c));
  }
  if (inside >= 0) return inside;
  Real best = std::numeric_limits<Real>::infinity();
  for (const auto& t : h.shape->triangles)
    best = std::min(best, point_triangle_sq(c, h.v[t[0]], h.v[t[1]], h.v[t[2]]));
  return -std::sqrt(best);
}

Real capsule_segment_distance(const Case& c, std::size_t i) {
  const PairPose& p = c.pairs[i];
  const ShapeDesc& sa = c.shapes_a[p.a];
  const ShapeDesc& sb = c.shapes_b[p.b];
  const Eigen::Vector3d za(0, 0, sa.half_height), zb(0, 0, sb.half_height);
  return std::sqrt(segment_segment_sq(
      to_world(p.rotation_a, p.translation_a, -za), to_world(p.rotation_a, p.translation_a, za),
      to_world(p.rotation_b, p.translation_b, -zb), to_world(p.rotation_b, p.translation_b, zb)));
}

}  // namespace

long double reference_depth(const Case& c, std::size_t i) {
  const PairPose& p = c.pairs[i];
  const ShapeDesc& sa = c.shapes_a[p.a];
  const ShapeDesc& sb = c.shapes_b[p.b];
  if (sa.kind == ShapeKind::Capsule && sb.kind == ShapeKind::Capsule)
    return Real(sa.radius) + Real(sb.radius) - capsule_segment_distance(c, i);
  if (sa.kind == ShapeKind::Sphere && !sb.triangles.empty())  // a polytope or a box
    return Real(sa.radius) +
           point_depth(p.translation_a.cast<Real>(), place(sb, p.rotation_b, p.translation_b));
  if (!sa.triangles.empty() && !sb.triangles.empty())
    return polytope_depth(gauss_map(sa, p.rotation_a, p.translation_a, false),
                          gauss_map(sb, p.rotation_b, p.translation_b, true));
  throw std::logic_error("reference_depth: no reference for this pair of shapes");
}

long double support_value(const Case& c, std::size_t i, bool side_b, const Vec3L& n) {
  const PairPose& p = c.pairs[i];
  const ShapeDesc& s = side_b ? c.shapes_b[p.b] : c.shapes_a[p.a];
  const Eigen::Matrix3d& r = side_b ? p.rotation_b : p.rotation_a;
  const Eigen::Vector3d& t = side_b ? p.translation_b : p.translation_a;
  switch (s.kind) {
    case ShapeKind::Sphere:
      return n.dot(t.cast<Real>()) + Real(s.radius) * n.norm();
    case ShapeKind::Capsule: {
      const Eigen::Vector3d z(0, 0, s.half_height);
      return std::max(n.dot(to_world(r, t, z)), n.dot(to_world(r, t, -z))) +
             Real(s.radius) * n.norm();
    }
    case ShapeKind::Box:
    case ShapeKind::Polytope: {
      Real h = -std::numeric_limits<Real>::infinity();
      for (const auto& q : s.points) h = std::max(h, n.dot(to_world(r, t, q)));
      return h;
    }
  }
  return 0;
}

long double separation_along(const Case& c, std::size_t i, const Eigen::Vector3d& normal) {
  const V3 n = normal.cast<Real>().normalized();
  return support_value(c, i, false, n) + support_value(c, i, true, -n);
}

long double outside(const Case& c, std::size_t i, bool side_b, const Eigen::Vector3d& point) {
  const PairPose& pp = c.pairs[i];
  const ShapeDesc& s = side_b ? c.shapes_b[pp.b] : c.shapes_a[pp.a];
  const Eigen::Matrix3d& r = side_b ? pp.rotation_b : pp.rotation_a;
  const Eigen::Vector3d& t = side_b ? pp.translation_b : pp.translation_a;
  const V3 p = point.cast<Real>();
  switch (s.kind) {
    case ShapeKind::Sphere:
      return (p - t.cast<Real>()).norm() - Real(s.radius);
    case ShapeKind::Capsule: {
      const Eigen::Vector3d z(0, 0, s.half_height);
      return std::sqrt(segment_segment_sq(p, p, to_world(r, t, -z), to_world(r, t, z))) -
             Real(s.radius);
    }
    case ShapeKind::Box:
    case ShapeKind::Polytope: {
      const WorldHull h = place(s, r, t);
      Real out = -std::numeric_limits<Real>::infinity();
      for (const auto& f : s.triangles) {
        const V3 m = (h.v[f[1]] - h.v[f[0]]).cross(h.v[f[2]] - h.v[f[0]]).normalized();
        out = std::max(out, m.dot(p - h.v[f[0]]));
      }
      return out;
    }
  }
  return 0;
}

long double reference_distance(const Case& c, std::size_t i) {
  const PairPose& p = c.pairs[i];
  const ShapeDesc& sa = c.shapes_a[p.a];
  const ShapeDesc& sb = c.shapes_b[p.b];
  if (sa.kind == ShapeKind::Capsule && sb.kind == ShapeKind::Capsule)
    return capsule_segment_distance(c, i) - Real(sa.radius) - Real(sb.radius);
  if (sa.kind == ShapeKind::Sphere && !sb.triangles.empty()) {  // a polytope or a box
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
