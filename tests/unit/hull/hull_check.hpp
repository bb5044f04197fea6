// Checks of a ConvexHull against its input that need no oracle: structure (twins, Euler,
// fans), containment of every input point, flatness and convexity of every face, and the
// reported volume and area against an independent recomputation.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <set>
#include <span>
#include <vector>

#include "mink/hull/convex_hull.hpp"

namespace hull_check {

using mink::ConvexHull;
using mink::HullStatus;
using mink::Vec3;

/// Worst measurements of one hull, in input units.
struct Report {
  double worst_outside = -HUGE_VAL;  ///< max over points and faces of normal . p - offset
  double worst_flatness = 0;         ///< max over faces of offset - normal . v for its vertices
  double worst_convexity = 0;        ///< max depth of a face vertex on the outer side of an edge
  int degree_two_vertices = 0;       ///< vertices shared by two faces only
};

inline double magnitude(std::span<const Vec3> points) {
  double m = 0;
  for (const Vec3& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

/// Slack for evaluating normal . p - offset in double at points of magnitude m.
inline double rounding_slack(double m) {
  return 16 * DBL_EPSILON * std::max(m, 1e-300);
}

/// Checks every invariant the header promises; returns the worst values seen.
inline Report check_hull(std::span<const Vec3> points, const ConvexHull& h) {
  Report r;
  const double tol = h.tolerance;
  const double slack = rounding_slack(magnitude(points));
  // Vertices are input points.
  for (const auto& v : h.vertices) {
    EXPECT_LT(v.input_index, points.size());
    if (v.input_index < points.size()) {
      EXPECT_EQ(v.position, points[v.input_index]);
    }
  }
  EXPECT_EQ(h.neighbor_offsets.size(), h.vertices.size() + 1);
  if (h.status == HullStatus::Point) {
    EXPECT_EQ(h.vertices.size(), 1u);
    EXPECT_TRUE(h.faces.empty());
    for (const Vec3& p : points) EXPECT_LE((p - h.vertices[0].position).norm(), tol + slack);
    return r;
  }
  if (h.status == HullStatus::Segment) {
    EXPECT_EQ(h.vertices.size(), 2u);
    EXPECT_TRUE(h.faces.empty());
    const Vec3 a = h.vertices[0].position, b = h.vertices[1].position;
    const Vec3 d = (b - a).normalized();
    for (const Vec3& p : points) {
      const double t = (p - a).dot(d);
      EXPECT_GE(t, -slack);
      EXPECT_LE(t, (b - a).norm() + slack);
      EXPECT_LE(((p - a) - t * d).norm(), tol + slack);
    }
    return r;
  }

  const std::size_t v_count = h.vertices.size(), f_count = h.faces.size(),
                    e_count = h.half_edges.size();
  if (h.status == HullStatus::Flat) {
    EXPECT_EQ(f_count, 2u);
    EXPECT_EQ(h.volume, 0.0);
  } else {
    EXPECT_GE(f_count, 4u);
    EXPECT_GT(h.volume, 0.0);
  }
  // Half-edges: twins, faces, Euler.
  std::uint32_t expected_first = 0;
  for (std::size_t f = 0; f < f_count; ++f) {
    const auto& face = h.faces[f];
    EXPECT_EQ(face.first, expected_first);
    expected_first += face.count;
    EXPECT_GE(face.count, 3u);
    EXPECT_NEAR(face.normal.norm(), 1.0, 1e-12);
    std::set<std::uint32_t> loop;
    for (std::uint32_t k = 0; k < face.count; ++k) {
      const std::uint32_t e = face.first + k;
      EXPECT_EQ(h.half_edges[e].face, f);
      loop.insert(h.half_edges[e].vertex);
    }
    EXPECT_EQ(loop.size(), face.count) << "face " << f << " repeats a vertex";
  }
  EXPECT_EQ(expected_first, e_count);
  for (std::uint32_t e = 0; e < e_count; ++e) {
    const auto& he = h.half_edges[e];
    EXPECT_LT(he.twin, e_count);
    if (he.twin >= e_count) return r;
    const auto& tw = h.half_edges[he.twin];
    EXPECT_EQ(tw.twin, e);
    EXPECT_NE(tw.face, he.face);
    EXPECT_EQ(tw.vertex, h.half_edges[h.next(e)].vertex);
    EXPECT_EQ(he.vertex, h.half_edges[h.next(he.twin)].vertex);
  }
  EXPECT_EQ(
      static_cast<long>(v_count) - static_cast<long>(e_count / 2) + static_cast<long>(f_count), 2)
      << "Euler";
  // Vertex fans and neighbour lists.
  std::vector<std::set<std::uint32_t>> out(v_count), faces_of(v_count);
  for (std::uint32_t e = 0; e < e_count; ++e) {
    out[h.half_edges[e].vertex].insert(h.half_edges[h.next(e)].vertex);
    faces_of[h.half_edges[e].vertex].insert(h.half_edges[e].face);
  }
  for (std::size_t v = 0; v < v_count; ++v) {
    const std::set<std::uint32_t> nb(h.neighbors.begin() + h.neighbor_offsets[v],
                                     h.neighbors.begin() + h.neighbor_offsets[v + 1]);
    EXPECT_EQ(nb, out[v]) << "vertex " << v;
    EXPECT_EQ(h.neighbor_offsets[v + 1] - h.neighbor_offsets[v], out[v].size());
    if (h.status == HullStatus::Full) {
      EXPECT_GE(faces_of[v].size(), 2u);
      if (faces_of[v].size() == 2) ++r.degree_two_vertices;
    }
  }
  // Containment, flatness, convexity.
  for (const auto& face : h.faces) {
    for (const Vec3& p : points)
      r.worst_outside = std::max(r.worst_outside, face.normal.dot(p) - face.offset);
    for (std::uint32_t k = 0; k < face.count; ++k) {
      const Vec3 a = h.vertices[h.half_edges[face.first + k].vertex].position;
      const Vec3 b = h.vertices[h.half_edges[face.first + (k + 1) % face.count].vertex].position;
      r.worst_flatness = std::max(r.worst_flatness, face.offset - face.normal.dot(a));
      const Vec3 edge = (b - a).normalized();
      for (std::uint32_t j = 0; j < face.count; ++j) {
        const Vec3 c = h.vertices[h.half_edges[face.first + j].vertex].position;
        // c must lie on the inner (left) side of the edge a -> b, seen along the normal.
        const double depth = -edge.cross(c - a).dot(face.normal);
        r.worst_convexity = std::max(r.worst_convexity, depth);
      }
    }
  }
  if (h.complete) {
    EXPECT_LE(r.worst_outside, slack) << "an input point is outside a face plane";
  }
  EXPECT_LE(r.worst_flatness, tol + slack) << "a face vertex is farther than tol from its plane";
  EXPECT_LE(r.worst_convexity, tol + slack) << "a face is not convex";
  // Volume and area recomputed with a different fan origin (the centroid of the vertices). The
  // volume in quadruple precision: in double, the tetrahedra of a needle 1e-12 thin round to more
  // than its volume.
  if (h.status == HullStatus::Full) {
    Vec3 o = Vec3::Zero();
    for (const auto& v : h.vertices) o += v.position;
    o /= static_cast<double>(v_count);
#if defined(__SIZEOF_FLOAT128__)
    using Wide = __float128;
#else
    using Wide = long double;
#endif
    auto wide = [&o](const Vec3& p) {
      return std::array<Wide, 3>{Wide(p.x()) - Wide(o.x()), Wide(p.y()) - Wide(o.y()),
                                 Wide(p.z()) - Wide(o.z())};
    };
    Wide wide_volume = 0;
    double area = 0;
    for (const auto& face : h.faces) {
      Vec3 va = Vec3::Zero();
      const Vec3& pa = h.vertices[h.half_edges[face.first].vertex].position;
      const auto a = wide(pa);
      for (std::uint32_t k = 1; k + 1 < face.count; ++k) {
        const Vec3& pb = h.vertices[h.half_edges[face.first + k].vertex].position;
        const Vec3& pc = h.vertices[h.half_edges[face.first + k + 1].vertex].position;
        const auto b = wide(pb), c = wide(pc);
        wide_volume += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                       a[2] * (b[0] * c[1] - b[1] * c[0]);
        va += (pb - pa).cross(pc - pa);
      }
      area += va.stableNorm() / 2;
    }
    const double volume = static_cast<double>(wide_volume / 6);
    // A face's vertices lie within tol of its plane, not on it, so each fan (the hull's and this
    // one) is within tol * area of the volume the planes bound: 2 tol * area apart at most (a
    // needle 1e-7 wide 700 from the origin, tol 6e-10, showed 1.4 tol * area).
    EXPECT_NEAR(h.volume, volume, 1e-9 * volume + 2 * tol * area);
    EXPECT_NEAR(h.area, area, 1e-9 * area + tol * std::sqrt(area));
  }
  return r;
}

}  // namespace hull_check
