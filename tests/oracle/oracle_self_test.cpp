// The oracles checked against each other and against dense sampling, so that a disagreement with
// mink can be blamed on mink. No mink algorithm is involved here.
#include <gtest/gtest.h>

#include <vector>

#include "oracle/analytic.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/random.hpp"

namespace {

using oracle::Real;
using oracle::Rng;
using oracle::V3;
using oracle::widen;

TEST(Oracle, SegmentSegmentMatchesSampling) {
  const std::uint64_t base = 90000;
  const int n = oracle::sweep_count(150);
  constexpr int kGrid = 100;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const V3 p1 = widen(rng.in_ball(1)), q1 = widen(rng.in_ball(1));
    V3 p2 = widen(rng.in_ball(1)), q2 = widen(rng.in_ball(1));
    if (i % 3 == 0) q2 = p2 + (q1 - p1) * Real(rng.uniform(-1.5, 1.5));  // parallel
    if (i % 7 == 0) q2 = p2;                                             // degenerate
    const auto s = oracle::closest_segment_segment(p1, q1, p2, q2);
    // The answer is a real pair of points on the segments at the stated distance.
    EXPECT_NEAR(double((s.on_second - s.on_first).norm()), double(s.distance), 1e-15);
    EXPECT_LE(
        double(oracle::closest_on_segment(p1, q1, s.on_first).point.norm() - s.on_first.norm()),
        1e-15);
    Real sampled = std::numeric_limits<Real>::infinity();
    for (int a = 0; a <= kGrid; ++a)
      for (int b = 0; b <= kGrid; ++b) {
        const V3 x = p1 + (q1 - p1) * (Real(a) / kGrid), y = p2 + (q2 - p2) * (Real(b) / kGrid);
        sampled = std::min(sampled, (y - x).norm());
      }
    // The minimum is never above a sample, and the grid is within half a cell of the minimum.
    const double cell = double(((q1 - p1).norm() + (q2 - p2).norm()) / kGrid);
    EXPECT_LE(double(s.distance), double(sampled) + 1e-15);
    EXPECT_GE(double(s.distance), double(sampled) - cell);
  }
}

TEST(Oracle, SegmentSegmentNearlyParallelCrossingAtKnownDistance) {
  // Two segments 2 long in the planes z = 0 and z = gap, crossing over each other's middle at an
  // angle of 1e-12 to 1e-6 rad: the common perpendicular is the z axis, so the distance is the
  // gap. Moved anywhere. The interior solve of the parameter square (the oracle's candidate before)
  // is noise here: for 1e-9 rad and a gap of 1e-8 it was 1 % off.
  Rng rng(92000);
  for (int i = 0; i < 2000; ++i) {
    SCOPED_TRACE(testing::Message() << "case " << i);
    const Real angle = rng.log_uniform(1e-12, 1e-6), gap = rng.log_uniform(1e-10, 1e-3);
    const oracle::M3 frame = widen(mink::Mat3(rng.rotation().toRotationMatrix()));
    const V3 centre = widen(rng.in_ball(3));
    auto world = [&](const V3& x) { return V3(frame * x + centre); };
    const V3 along(std::cos(angle), std::sin(angle), 0);
    const auto s = oracle::closest_segment_segment(world(V3(-1, 0, 0)), world(V3(1, 0, 0)),
                                                   world(V3(V3(0, 0, gap) - along)),
                                                   world(V3(V3(0, 0, gap) + along)));
    EXPECT_NEAR(double(s.distance), double(gap), 1e-15) << "angle " << double(angle);
  }
}

TEST(Oracle, HullDistanceMatchesPointBox) {
  const std::uint64_t base = 91000;
  const int n = oracle::sweep_count(400);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const oracle::WorldBox box{V3(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2)),
                               widen(mink::Mat3(rng.rotation().toRotationMatrix())),
                               widen(rng.in_ball(2))};
    const V3 x = widen(rng.in_ball(4));
    std::vector<V3> shifted;
    for (const V3& c : oracle::box_corners(box)) shifted.push_back(c - x);
    const auto hull = oracle::hull_distance(shifted);
    const auto bp = oracle::point_box(box, x);
    EXPECT_TRUE(hull.full_dimensional);
    EXPECT_GE(hull.facets, 12);  // 6 faces of 4 coplanar corners: at least 2 triples each
    if (bp.signed_distance > 0) {
      // 1e-13: the rotation from a double quaternion is orthonormal only to about 1e-16.
      EXPECT_NEAR(double(hull.distance), double(bp.signed_distance), 1e-13);
    } else {
      EXPECT_EQ(hull.distance, 0);
      EXPECT_NEAR(double(hull.depth), double(-bp.signed_distance), 1e-13);
    }
  }
}

TEST(Oracle, HullDistanceOfDegenerateSets) {
  // One point, two points (a segment), three collinear points and a flat square.
  EXPECT_EQ(oracle::hull_distance({V3(3, 4, 0)}).distance, 5);
  EXPECT_NEAR(double(oracle::hull_distance({V3(1, -1, 2), V3(1, 1, 2)}).distance), std::sqrt(5.0),
              1e-15);
  EXPECT_NEAR(double(oracle::hull_distance({V3(-1, 1, 1), V3(0, 1, 1), V3(2, 1, 1)}).distance),
              std::sqrt(2.0), 1e-15);
  const std::vector<V3> square{V3(-1, -1, 0.5), V3(1, -1, 0.5), V3(1, 1, 0.5), V3(-1, 1, 0.5)};
  const auto flat = oracle::hull_distance(square);
  EXPECT_FALSE(flat.full_dimensional);
  EXPECT_NEAR(double(flat.distance), 0.5, 1e-15);
  const std::vector<V3> through{V3(-1, -1, 0), V3(1, -1, 0), V3(1, 1, 0), V3(-1, 1, 0)};
  EXPECT_NEAR(double(oracle::hull_distance(through).distance), 0, 1e-18);
}

}  // namespace
