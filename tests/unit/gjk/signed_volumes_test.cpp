// GJK's distance sub-algorithm on tetrahedra (gjk/signed_volumes.hpp, closest_on_tetrahedron()),
// which offers first the face whose plane lies farthest from the origin. Checked against an
// independent answer in long double: 0 when the origin is inside (the four barycentric volumes'
// signs), else the least distance over the four faces, each by the Voronoi regions of a triangle
// (its vertices, edges and interior), which shares no code with mink. Also: every ordering of the
// same four points gives the same distance, and the weights are a convex combination that lands
// on the point returned.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "mink/mink.hpp"
#include "oracle/random.hpp"

// Named, not anonymous: the tests compile in unity batches (tests/CMakeLists.txt).
namespace signed_volumes_test {

using mink::Vec3;
using Long = long double;
using Point = std::array<Long, 3>;

Point to_long(const Vec3& v) {
  return {Long(v.x()), Long(v.y()), Long(v.z())};
}
Point sub(const Point& a, const Point& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Long dot(const Point& a, const Point& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Point axpy(const Point& p, Long s, const Point& d) {
  return {p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]};
}

// The squared distance from the origin to triangle (a, b, c) by its Voronoi regions (vertex,
// edge, face), in the style of Ericson's "Real-Time Collision Detection" 5.1.5.
Long triangle_distance_sq(const Point& a, const Point& b, const Point& c) {
  const Point ab = sub(b, a), ac = sub(c, a), ap = sub(Point{0, 0, 0}, a);
  const Long d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return dot(a, a);
  const Point bp = sub(Point{0, 0, 0}, b);
  const Long d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dot(b, b);
  const Long vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const Point q = axpy(a, d1 / (d1 - d3), ab);
    return dot(q, q);
  }
  const Point cp = sub(Point{0, 0, 0}, c);
  const Long d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dot(c, c);
  const Long vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const Point q = axpy(a, d2 / (d2 - d6), ac);
    return dot(q, q);
  }
  const Long va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const Point q = axpy(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), sub(c, b));
    return dot(q, q);
  }
  const Long denom = 1 / (va + vb + vc);
  const Point q = axpy(axpy(a, vb * denom, ab), vc * denom, ac);
  return dot(q, q);
}

// The distance from the origin to the tetrahedron w[0..4).
Long tetrahedron_distance(const Vec3* w) {
  Point p[4];
  for (int i = 0; i < 4; ++i) p[i] = to_long(w[i]);
  // The origin is inside when it lies on the inner side of every face (the side of the vertex
  // the face leaves out).
  const int faces[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
  bool inside = true;
  Long least = std::numeric_limits<Long>::infinity();
  for (const auto& f : faces) {
    const Point n = cross(sub(p[f[1]], p[f[0]]), sub(p[f[2]], p[f[0]]));
    const Long side_of_vertex = dot(n, sub(p[f[3]], p[f[0]]));
    const Long side_of_origin = -dot(n, p[f[0]]);
    if (side_of_vertex * side_of_origin < 0) inside = false;
    least = std::min(least, triangle_distance_sq(p[f[0]], p[f[1]], p[f[2]]));
  }
  return inside ? Long(0) : std::sqrt(least);
}

// Four points of a tetrahedron in one of the regimes GJK meets: well shaped near the origin,
// slivers (a vertex 1e-9 to 1e-3 of the size off the others' plane), far from the origin, the
// origin just outside a face, and long thin ones.
void random_tetrahedron(oracle::Rng& rng, Vec3* w) {
  const int kind = rng.integer(0, 4);
  const double size = rng.log_uniform(1e-3, 1e3);
  for (int i = 0; i < 4; ++i)
    w[i] = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * size;
  if (kind == 1) {  // a sliver: w[3] pressed onto the plane of the others
    const Vec3 n = (w[1] - w[0]).cross(w[2] - w[0]).normalized();
    w[3] -= n * (n.dot(w[3] - w[0]) * (1 - rng.log_uniform(1e-9, 1e-3)));
  } else if (kind == 2) {  // far from the origin
    const Vec3 offset = rng.unit() * size * rng.log_uniform(1e2, 1e5);
    for (int i = 0; i < 4; ++i) w[i] += offset;
  } else if (kind == 3) {  // the origin just beyond face (w0, w1, w2), over its interior
    const Vec3 centre = (w[0] + w[1] + w[2]) / 3;
    const Vec3 n = (w[1] - w[0]).cross(w[2] - w[0]).normalized();
    const double beyond = size * rng.log_uniform(1e-9, 1e-1);
    const double side = n.dot(w[3] - w[0]) > 0 ? -1 : 1;  // away from w3
    const Vec3 origin = centre + n * (side * beyond);
    for (int i = 0; i < 4; ++i) w[i] -= origin;
  } else if (kind == 4) {  // long and thin: stretched 1e3 along a random axis
    const Vec3 axis = rng.unit();
    for (int i = 0; i < 4; ++i) w[i] += axis * (axis.dot(w[i]) * 1e3);
  }
}

double scale_of(const Vec3* w) {
  double scale = 0;
  for (int i = 0; i < 4; ++i) scale = std::max(scale, w[i].cwiseAbs().maxCoeff());
  return scale;
}

TEST(SignedVolumes, TetrahedronDistanceMatchesLongDoubleRegions) {
  oracle::Rng rng(20261207);
  int checked = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3 w[4];
    random_tetrahedron(rng, w);
    const auto closest = mink::detail::closest_on_tetrahedron(w);
    const double expected = double(tetrahedron_distance(w));
    const double scale = scale_of(w);
    // The points carry eps * scale each; the sub-algorithm's answer is a point of the hull to
    // rounding, within a few times that.
    const double tolerance = 64 * std::numeric_limits<double>::epsilon() * scale;
    ASSERT_TRUE(std::isfinite(closest.dist_sq)) << "trial " << trial;
    EXPECT_NEAR(std::sqrt(closest.dist_sq), expected, tolerance) << "trial " << trial;
    // The weights: on the vertices of `mask` only, non-negative, summing to 1.
    double sum = 0;
    Vec3 combination = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {
      EXPECT_GE(closest.weights[i], 0.0);
      if (!(closest.mask >> i & 1u)) EXPECT_EQ(closest.weights[i], 0.0);
      sum += closest.weights[i];
      combination += closest.weights[i] * w[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << "trial " << trial;
    // The combination lands on the point returned, but where that point is a face's projection
    // and the face a sliver (the weights then carry its rounding divided by its thinness).
    const double thinness =
        std::abs((w[1] - w[0]).cross(w[2] - w[0]).dot(w[3] - w[0])) / std::pow(scale, 3);
    if (thinness > 1e-3) {
      EXPECT_LE((combination - closest.v).norm(), 1e-9 * scale) << "trial " << trial;
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);  // the well-shaped share of the regimes above
}

// The face order is chosen by the planes' distances: any order of the four points must give the
// same distance, to rounding.
TEST(SignedVolumes, TetrahedronDistanceDoesNotDependOnTheOrder) {
  oracle::Rng rng(7122026);
  for (int trial = 0; trial < 2000; ++trial) {
    Vec3 w[4];
    random_tetrahedron(rng, w);
    const double reference = std::sqrt(mink::detail::closest_on_tetrahedron(w).dist_sq);
    const double tolerance = 64 * std::numeric_limits<double>::epsilon() * scale_of(w);
    std::array<int, 4> order = {0, 1, 2, 3};
    do {
      const Vec3 permuted[4] = {w[order[0]], w[order[1]], w[order[2]], w[order[3]]};
      const auto closest = mink::detail::closest_on_tetrahedron(permuted);
      EXPECT_NEAR(std::sqrt(closest.dist_sq), reference, tolerance) << "trial " << trial;
    } while (std::next_permutation(order.begin(), order.end()));
  }
}

}  // namespace signed_volumes_test
