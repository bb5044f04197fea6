// Warm start: a GjkCache carried along a moving pair must give the same answers as a cold start
// (checked against the brute-force oracle), save iterations on coherent motion, and stay correct
// when the cache is stale or belongs to another pair.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Vec3;

TEST(GjkWarmStart, CoherentMotionMatchesOracleAndSavesIterations) {
  const std::uint64_t seed = 7100;
  SCOPED_TRACE(oracle::seed_note(seed));
  oracle::Rng rng(seed);
  std::vector<Vec3> pa, pb;
  for (int i = 0; i < 8; ++i) pa.push_back(rng.in_ball(1.0));
  for (int i = 0; i < 8; ++i) pb.push_back(rng.in_ball(0.7));
  const mink::Polytope a = *mink::Polytope::make(pa), b = *mink::Polytope::make(pb);

  mink::GjkCache cache;
  int warm_iterations = 0, cold_iterations = 0;
  const mink::Quat spin(Eigen::AngleAxisd(0.04, Vec3(0.3, 1, 0.2).normalized()));
  mink::Quat qb = rng.rotation();
  for (int frame = 0; frame < 150; ++frame) {
    qb = (spin * qb).normalized();
    // The pair approaches, overlaps and separates again.
    const Pose pose_a = Pose::identity();
    const Pose pose_b = Pose::from(Vec3(2.5 - 0.024 * frame, 0.2, -0.1), qb);
    const auto warm = mink::distance(a, pose_a, b, pose_b, mink::Tolerances{}, &cache);
    const auto cold = mink::distance(a, pose_a, b, pose_b);
    const auto expected =
        oracle::polytope_pair(oracle::world_points(pa, pose_a), oracle::world_points(pb, pose_b));
    const double expected_distance = double(expected.distance);
    ASSERT_EQ(warm.intersect, cold.intersect) << "frame " << frame;
    if (expected_distance > 1e-9) {
      ASSERT_EQ(warm.status, mink::Status::Separated) << "frame " << frame;
      EXPECT_NEAR(warm.distance, expected_distance, 1e-12) << "frame " << frame;
      EXPECT_NEAR(warm.distance, cold.distance, 1e-12) << "frame " << frame;
    } else if (expected_distance == 0) {
      EXPECT_TRUE(warm.intersect) << "frame " << frame;
    }
    warm_iterations += warm.iterations;
    cold_iterations += cold.iterations;
  }
  EXPECT_LT(warm_iterations, cold_iterations);
}

TEST(GjkWarmStart, StaleOrForeignCacheIsOnlyAHint) {
  const std::uint64_t base = 7200;
  for (int i = 0; i < 300; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    const mink::Box box{Vec3(rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1))};
    const mink::Capsule capsule{rng.uniform(0.05, 0.5), rng.uniform(0.0, 1.0)};
    // A cache full of unrelated directions, including repeated and opposite ones.
    mink::GjkCache cache;
    cache.size = 4;
    cache.directions[0] = rng.unit();
    cache.directions[1] = cache.directions[0];
    cache.directions[2] = -cache.directions[0];
    cache.directions[3] = rng.unit();
    const Pose pose_a = rng.pose(2), pose_b = rng.pose(2);
    const auto warm = mink::distance(box, pose_a, mink::Rounded{capsule, 0.0}, pose_b,
                                     mink::Tolerances{}, &cache);
    const auto cold = mink::distance(box, pose_a, mink::Rounded{capsule, 0.0}, pose_b);
    ASSERT_EQ(warm.intersect, cold.intersect);
    EXPECT_NEAR(warm.distance, cold.distance, 1e-12);
    const auto warm_bool = mink::intersect(box, pose_a, mink::Rounded{capsule, 0.0}, pose_b,
                                           mink::Tolerances{}, &cache);
    EXPECT_EQ(warm_bool.intersect, cold.intersect);
  }
}

TEST(GjkWarmStart, GarbageCacheIsIgnored) {
  const mink::Box box{Vec3(1, 1, 1)};
  const Pose apart = Pose::from_translation(Vec3(3, 0, 0));
  for (int size : {-3, 0, 2, 5, 1000}) {
    mink::GjkCache cache;
    cache.size = size;
    for (auto& d : cache.directions) d = Vec3(std::nan(""), 1, 0);
    const auto r = mink::distance(box, Pose::identity(), box, apart, mink::Tolerances{}, &cache);
    ASSERT_EQ(r.status, mink::Status::Separated) << "cache size " << size;
    EXPECT_NEAR(r.distance, 1.0, 1e-15);
    EXPECT_GE(cache.size, 1);  // the cache now holds this query's simplex
    EXPECT_LE(cache.size, 4);
  }
}

}  // namespace
