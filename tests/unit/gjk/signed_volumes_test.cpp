// GJK's distance sub-algorithm on tetrahedra (gjk/signed_volumes.hpp, closest_on_tetrahedron()),
// which offers first the face whose plane lies farthest from the origin. Checked against an
// independent answer in long double (oracle::hull_distance(): 0 inside, else the least distance
// over the facets by their Voronoi regions, the edges and the vertices), which shares no code
// with mink. Also: every ordering of the same four points gives the same distance, and the
// weights are a convex combination that lands on the point returned.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/random.hpp"

// Named, not anonymous: the tests compile in unity batches (tests/CMakeLists.txt).
namespace signed_volumes_test {

using mink::Vec3;
// The distance from the origin to the tetrahedron w[0..4), in long double: oracle::hull_distance(),
// the brute force over facets, edges and vertices with an inside test that tests/unit/gjk's
// brute-force polytope tests use.
double tetrahedron_distance(const Vec3* w) {
  std::vector<oracle::V3> points;
  for (int i = 0; i < 4; ++i) points.push_back(w[i].cast<oracle::Real>());
  return double(oracle::hull_distance(points).distance);
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
    const double expected = tetrahedron_distance(w);
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
