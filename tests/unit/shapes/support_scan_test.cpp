// The SIMD support scan against its scalar twin, which defines the answer (lowest index among the
// farthest points), including ties, tails shorter than a block and NaN directions.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "mink/shapes/polytope.hpp"
#include "mink/shapes/support_scan.hpp"

namespace mink {
namespace {

struct Soa {
  std::vector<double> x, y, z;
  std::size_t index(const Vec3& d) const {
    return detail::support_index(x.data(), y.data(), z.data(), x.size(), d.x(), d.y(), d.z());
  }
  std::size_t scalar(const Vec3& d) const {
    return detail::support_index_scalar(x.data(), y.data(), z.data(), x.size(), d.x(), d.y(),
                                        d.z());
  }
};

TEST(SupportScan, MatchesScalarTwinOnRandomClouds) {
  const unsigned seed = 20261122;
  SCOPED_TRACE(seed);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  for (std::size_t n = 1; n <= 70; ++n) {
    Soa s;
    for (std::size_t i = 0; i < n; ++i) {
      s.x.push_back(g(rng));
      s.y.push_back(g(rng));
      s.z.push_back(g(rng));
    }
    for (int k = 0; k < 200; ++k) {
      const Vec3 d(g(rng), g(rng), g(rng));
      ASSERT_EQ(s.index(d), s.scalar(d)) << "n = " << n;
    }
  }
}

TEST(SupportScan, TiesGoToTheLowestIndex) {
  // A lattice of points with many equal dot products: the first of them must win, whatever block
  // or lane it falls in.
  Soa s;
  for (int i = 0; i < 37; ++i) {
    s.x.push_back(double(i % 3));
    s.y.push_back(double(i % 2));
    s.z.push_back(0.0);
  }
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0, 0, 1), Vec3(-1, 0, 0)})
    EXPECT_EQ(s.index(d), s.scalar(d));
  EXPECT_EQ(s.index(Vec3(0, 0, 1)), 0u);  // every point ties: index 0
}

TEST(SupportScan, FewPointsTiesGoToTheLowestIndex) {
  // Up to 8 points take their own path (a tree maximum, then the first index that reaches it):
  // the first 1 to 8 corners of a cube against the scalar twin, in directions with ties.
  for (std::size_t n = 1; n <= 8; ++n) {
    Soa s;
    for (std::size_t i = 0; i < n; ++i) {
      s.x.push_back(i & 1 ? 1.0 : -1.0);
      s.y.push_back(i & 2 ? 1.0 : -1.0);
      s.z.push_back(i & 4 ? 1.0 : -1.0);
    }
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(-1, 0, 0),
                          Vec3(1, 1, 0), Vec3(0, -1, 1), Vec3(0, 0, 0), Vec3(1, 1, 1)})
      EXPECT_EQ(s.index(d), s.scalar(d)) << n << " points, direction " << d.transpose();
  }
}

TEST(SupportScan, FewPointsMatchTheScalarTwin) {
  // Random points and directions, 1 to 8 points (odd counts end in a half-filled pair), a NaN
  // direction (the twin answers 0) and infinite ones that make some dot products NaN.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t n = 1; n <= 8; ++n) {
    for (int trial = 0; trial < 200; ++trial) {
      Soa s;
      for (std::size_t i = 0; i < n; ++i) {
        s.x.push_back(u(rng));
        s.y.push_back(u(rng));
        s.z.push_back(u(rng));
      }
      const Vec3 d(u(rng), u(rng), u(rng));
      EXPECT_EQ(s.index(d), s.scalar(d)) << n << " points";
      EXPECT_EQ(s.index(Vec3(nan, d.y(), d.z())), s.scalar(Vec3(nan, d.y(), d.z())));
      // Some dot products NaN (inf times a 0 coordinate), the others +-inf or finite.
      for (std::size_t i = 0; i < n; i += 2) s.x[i] = 0;
      const Vec3 d_inf(trial % 2 ? inf : -inf, d.y(), d.z());
      EXPECT_EQ(s.index(d_inf), s.scalar(d_inf)) << n << " points, an infinite direction";
    }
  }
}

TEST(SupportScan, NanDirectionGivesAValidIndex) {
  Soa s;
  for (int i = 0; i < 20; ++i) {
    s.x.push_back(i);
    s.y.push_back(-i);
    s.z.push_back(1.0);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_LT(s.index(Vec3(nan, 0, 0)), s.x.size());
}

}  // namespace
}  // namespace mink
