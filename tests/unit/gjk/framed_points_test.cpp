// A small polytope B's points moved into A's frame once per query (gjk.hpp, FramedPointsT): the
// support calls of distance() and contact() then scan them along the direction as it is. Checked
// against B's own support mapping turned into A's frame: the same support value to rounding, a
// point of B moved as support() moves it, and the very same point wherever B's farthest point is
// farthest by a clear margin. The queries' answers on these pairs are checked against brute force
// in tests/unit/gjk/brute_force_test.cpp and tests/unit/epa/contact_brute_force_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/random.hpp"

// Named, not anonymous: the tests compile in unity batches (tests/CMakeLists.txt).
namespace framed_points_test {

using mink::Pose;
using mink::Vec3;

// 1 to 9 points: single points, segments, flat sets and duplicates among them.
std::vector<Vec3> random_points(oracle::Rng& rng, int n) {
  std::vector<Vec3> points;
  const bool flat = rng.chance(0.25);
  for (int k = 0; k < n; ++k) {
    if (k > 0 && rng.chance(0.15)) {
      points.push_back(points[rng.integer(0, k - 1)]);  // a duplicate
      continue;
    }
    Vec3 p(rng.uniform(-1, 1), rng.uniform(-1, 1), flat ? 0.0 : rng.uniform(-1, 1));
    points.push_back(p);
  }
  return points;
}

template <class B>
void check_support(const mink::Polytope& a, const B& b, const mink::Polytope& b_points,
                   const Pose& pose_a, const Pose& pose_b, oracle::Rng& rng) {
  using mink::detail::make_core_difference;
  const auto turned = make_core_difference(a, pose_a, b, pose_b);
  auto framed = turned;
  mink::detail::FramedPointsT<double> moved;
  mink::detail::frame_points_of_b(framed, moved);
  ASSERT_EQ(framed.b_points != nullptr, b_points.size() <= moved.kMaxPoints);
  if (!framed.b_points) return;
  // The moved points, as support() moves its answer.
  std::vector<Vec3> in_a;
  for (std::size_t i = 0; i < b_points.size(); ++i)
    in_a.push_back(turned.rotation * b_points.point(i) + turned.translation);
  const double reach = turned.translation.norm() + b_points.bounding_radius();
  const double slack = 16 * std::numeric_limits<double>::epsilon() * reach;
  for (int k = 0; k < 50; ++k) {
    const Vec3 d = rng.unit() * rng.log_uniform(1e-3, 1e3);
    mink::SimplexVertexT<double> plain, fast;
    turned.support(d, plain);
    framed.support(d, fast);
    EXPECT_EQ(fast.a, plain.a);
    EXPECT_EQ(fast.dir, plain.dir);
    // A point of B, moved bit for bit as the turned path moves it.
    bool one_of_them = false;
    for (const Vec3& p : in_a) one_of_them = one_of_them || p == fast.b;
    EXPECT_TRUE(one_of_them) << "framed support " << fast.b.transpose() << " is no moved point";
    // The same reach along -d; the same point when no other comes within the slack.
    const Vec3 u = -d.normalized();
    EXPECT_NEAR(fast.b.dot(u), plain.b.dot(u), slack);
    int near_best = 0;
    for (const Vec3& p : in_a) near_best += p.dot(u) >= plain.b.dot(u) - 4 * slack && p != plain.b;
    if (near_best == 0) EXPECT_EQ(fast.b, plain.b);
    EXPECT_EQ(framed.support_point(d), fast.w);
  }
}

TEST(FramedPoints, SupportMatchesBsOwnTurnedIntoAsFrame) {
  const int n = oracle::sweep_count(400, 100);
  int framed_pairs = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = 951000 + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    const auto a = mink::Polytope::make(random_points(rng, rng.integer(1, 9)));
    const auto b = mink::Polytope::make(random_points(rng, rng.integer(1, 9)));
    ASSERT_TRUE(a && b);
    // Near the origin, and 1e6 from it.
    const double far = rng.chance(0.3) ? 1e6 : 1.0;
    const Pose pose_a = rng.pose(3 * far);
    const Pose pose_b = rng.pose(3 * far);
    check_support(*a, *b, *b, pose_a, pose_b, rng);
    check_support(*a, mink::Rounded<mink::Polytope>{*b, 0.25}, *b, pose_a, pose_b, rng);
    framed_pairs += b->size() <= mink::detail::FramedPointsT<double>::kMaxPoints;
  }
  EXPECT_GT(framed_pairs, n / 2);
}

}  // namespace framed_points_test
