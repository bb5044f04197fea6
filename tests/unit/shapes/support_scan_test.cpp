// The SIMD support scan against its scalar twin, which defines the answer (lowest index among the
// farthest points), including ties, tails shorter than a block and NaN directions: the path the
// build chooses, and each instruction set's scan called directly (AVX2 where this CPU has it),
// each for both SupportPatterns (the index by a branch and by masks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "mink/shapes/polytope.hpp"
#include "mink/shapes/support_scan.hpp"

namespace mink {
namespace {

struct Soa {
  std::vector<double> x, y, z;
  template <SupportPattern P = SupportPattern::Coherent>
  std::size_t index(const Vec3& d) const {
    return detail::support_index<P>(x.data(), y.data(), z.data(), x.size(), d.x(), d.y(), d.z());
  }
  /// The index of both patterns, or SIZE_MAX when they differ.
  std::size_t both(const Vec3& d) const {
    const std::size_t i = index(d);
    return index<SupportPattern::Scattered>(d) == i ? i : SIZE_MAX;
  }
#if defined(__SSE2__)
  template <SupportPattern P = SupportPattern::Coherent>
  std::size_t sse2(const Vec3& d) const {
    return detail::support_index_many_sse2<P>(x.data(), y.data(), z.data(), x.size(), d.x(), d.y(),
                                              d.z());
  }
#endif
#if defined(__AVX2__) || defined(MINK_AVX2_DISPATCH)
  template <SupportPattern P = SupportPattern::Coherent>
  std::size_t avx2(const Vec3& d) const {
    return detail::support_index_many_avx2<P>(x.data(), y.data(), z.data(), x.size(), d.x(), d.y(),
                                              d.z());
  }
#endif
  std::size_t scalar(const Vec3& d) const {
    return detail::support_index_scalar(x.data(), y.data(), z.data(), x.size(), d.x(), d.y(),
                                        d.z());
  }
};

/// n points whose coordinates are drawn from `g`, point by point.
template <class Rng>
Soa random_soa(Rng& rng, std::normal_distribution<double>& g, std::size_t n) {
  Soa s;
  for (std::size_t i = 0; i < n; ++i) {
    s.x.push_back(g(rng));
    s.y.push_back(g(rng));
    s.z.push_back(g(rng));
  }
  return s;
}

/// Whether this machine can run the AVX2 scan (where it cannot, only the others are checked).
bool can_run_avx2() {
#if defined(__AVX2__)
  return true;
#elif defined(MINK_AVX2_DISPATCH)
  return detail::cpu_has_avx2;
#else
  return false;
#endif
}

/// Every scan against the scalar twin, for both patterns: the one the build chooses and, for more
/// than 8 points, SSE2 and AVX2 (where it runs) called directly.
void expect_every_scan_matches(const Soa& s, const Vec3& d, const char* what) {
  constexpr auto kScattered = SupportPattern::Scattered;
  const std::size_t want = s.scalar(d);
  EXPECT_EQ(s.index(d), want) << what << ", " << s.x.size() << " points";
  EXPECT_EQ(s.index<kScattered>(d), want) << what << ", scattered, " << s.x.size() << " points";
  if (s.x.size() <= 8) return;
#if defined(__SSE2__)
  EXPECT_EQ(s.sse2(d), want) << what << ", SSE2, " << s.x.size() << " points";
  EXPECT_EQ(s.sse2<kScattered>(d), want) << what << ", SSE2 scattered, " << s.x.size() << " points";
#endif
#if defined(__AVX2__) || defined(MINK_AVX2_DISPATCH)
  if (can_run_avx2()) {
    EXPECT_EQ(s.avx2(d), want) << what << ", AVX2, " << s.x.size() << " points";
    EXPECT_EQ(s.avx2<kScattered>(d), want)
        << what << ", AVX2 scattered, " << s.x.size() << " points";
  }
#endif
}

TEST(SupportScan, TiesGoToTheLowestIndex) {
  // A lattice with many equal dot products, 9 to 70 points: the first of the equals wins
  // whatever block or lane it falls in, on every path.
  for (std::size_t n = 9; n <= 70; ++n) {
    Soa s;
    for (std::size_t i = 0; i < n; ++i) {
      s.x.push_back(double(i % 3));
      s.y.push_back(double(i % 5));
      s.z.push_back(double(i % 2));
    }
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 0),
                          Vec3(-1, 0, 0), Vec3(0, -1, -1), Vec3(1, 1, 1)})
      expect_every_scan_matches(s, d, "lattice");
    EXPECT_EQ(s.both(Vec3(0, 0, 0)), 0u);  // every point ties: index 0
  }
}

TEST(SupportScan, MatchesScalarTwinOnRandomClouds) {
  // 1 to 100 points: the inlined path up to 8, then AVX2 blocks of 16 and SSE2 blocks of 8 with
  // every tail length. Random directions, then the first 7 points copied to the end and into the
  // middle (the farthest point now in two blocks: the first copy must win), then a zero and an
  // axis direction (many equal dot products).
  const unsigned seed = 20261122;
  SCOPED_TRACE(seed);
  if (!can_run_avx2()) std::printf("note: this CPU has no AVX2; its scan is not checked\n");
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  for (std::size_t n = 1; n <= 100; ++n) {
    Soa s = random_soa(rng, g, n);
    for (int k = 0; k < 200; ++k)
      expect_every_scan_matches(s, Vec3(g(rng), g(rng), g(rng)), "random");
    for (std::size_t i = 0; i < 7 && i < n; ++i) {
      const std::size_t middle = n / 2 + i % ((n + 1) / 2);
      s.x.push_back(s.x[i]);
      s.y.push_back(s.y[i]);
      s.z.push_back(s.z[i]);
      s.x[middle] = s.x[i];
      s.y[middle] = s.y[i];
      s.z[middle] = s.z[i];
    }
    for (int k = 0; k < 100; ++k)
      expect_every_scan_matches(s, Vec3(g(rng), g(rng), g(rng)), "repeated points");
    expect_every_scan_matches(s, Vec3(0, 0, 0), "zero direction");
    expect_every_scan_matches(s, Vec3(1, 0, 0), "axis direction");
  }
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
      EXPECT_EQ(s.both(d), s.scalar(d)) << n << " points, direction " << d.transpose();
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
      EXPECT_EQ(s.both(d), s.scalar(d)) << n << " points";
      EXPECT_EQ(s.both(Vec3(nan, d.y(), d.z())), s.scalar(Vec3(nan, d.y(), d.z())));
      // Some dot products NaN (inf times a 0 coordinate), the others +-inf or finite.
      for (std::size_t i = 0; i < n; i += 2) s.x[i] = 0;
      const Vec3 d_inf(trial % 2 ? inf : -inf, d.y(), d.z());
      EXPECT_EQ(s.both(d_inf), s.scalar(d_inf)) << n << " points, an infinite direction";
    }
  }
}

TEST(SupportScan, HitsCarryTheLargestDotProduct) {
  // support_hit(): the scan's index and, as its value, the largest dot product over the points,
  // taken here point by point; 1 to 40 points (the inlined path up to 8, the blocks beyond), and
  // Polytope::support_core_hit() the same, also once the polytope climbs its hull (64 and 200
  // points).
  std::mt19937_64 rng(94);
  std::normal_distribution<double> g;
  auto largest_dot = [](const Soa& s, const Vec3& d) {
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < s.x.size(); ++i)
      best = std::max(best, s.x[i] * d.x() + s.y[i] * d.y() + s.z[i] * d.z());
    return best;
  };
  for (std::size_t n = 1; n <= 40; ++n) {
    Soa s = random_soa(rng, g, n);
    for (int k = 0; k < 50; ++k) {
      const Vec3 d(g(rng), g(rng), g(rng));
      const detail::SupportHit<double> hit =
          detail::support_hit(s.x.data(), s.y.data(), s.z.data(), n, d.x(), d.y(), d.z());
      EXPECT_EQ(hit.index(), s.scalar(d)) << n << " points";
      EXPECT_EQ(hit.index<SupportPattern::Scattered>(), s.scalar(d)) << n << " points";
      EXPECT_EQ(hit.value, largest_dot(s, d)) << n << " points";
    }
  }
  for (std::size_t n : {5u, 8u, 30u, 64u, 200u}) {
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < n; ++i) points.emplace_back(g(rng), g(rng), g(rng));
    const Polytope p = Polytope::make(points).value();
    for (int k = 0; k < 2 * int(kPolytopeHullAfterSupports) + 20; ++k) {
      const Vec3 d(g(rng), g(rng), g(rng));
      const detail::SupportHit<double> hit = p.support_core_hit(d);
      const Vec3 point = p.support_core(d);
      // Scattered calls scan up to kScatteredScanMaxPoints points, also once the polytope climbs.
      EXPECT_EQ(p.support_core<SupportPattern::Scattered>(d),
                n <= kScatteredScanMaxPoints ? p.point(p.scan_index(d)) : point)
          << n << " points";
      EXPECT_EQ(p.point(hit.index()), point) << n << " points";
      EXPECT_NEAR(hit.value, point.dot(d), 1e-14 * point.norm() * d.norm()) << n << " points";
    }
    if (n >= kHullClimbMinVertices) EXPECT_TRUE(p.climbs());
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
  const Vec3 d(nan, 0, 0);
  EXPECT_LT(s.index(d), s.x.size());
  EXPECT_LT(s.index<SupportPattern::Scattered>(d), s.x.size());
#if defined(__SSE2__)
  EXPECT_LT(s.sse2(d), s.x.size());
  EXPECT_LT(s.sse2<SupportPattern::Scattered>(d), s.x.size());
#endif
#if defined(__AVX2__) || defined(MINK_AVX2_DISPATCH)
  if (can_run_avx2()) {
    EXPECT_LT(s.avx2(d), s.x.size());
    EXPECT_LT(s.avx2<SupportPattern::Scattered>(d), s.x.size());
  }
#endif
}

}  // namespace
}  // namespace mink
