// intersect() on two boxes a hair from touching, against the Minkowski difference's brute force.
// Its own file: its oracle runs hundreds of brute-force pairs, which want the optimized build of
// the sanitizer run, while the other hand-built cases compile at -O0 there
// (cmake/sanitizers.cmake).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/check.hpp"
#include "oracle/poses.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Box;
using mink::Pose;
using mink::Quat;
using mink::Vec3;
using oracle::rotated;

// intersect() answers most box pairs by the separating axis test alone (query/box_box.hpp) and
// hands the rest to GJK: corner near corner and edge near edge (where the distance exceeds every
// axis's gap), edges parallel to 1e-9 and exactly, faces flush, each moved to a hair inside, at
// and outside touching; the flag must match the Minkowski-difference oracle whenever the gap is
// outside the touching band, and agree with distance() always. Gaps of half and twice the touching
// tolerance (relative * size) must count as touching and as apart: the axis test decides on
// bounds of that tolerance and leaves what lies between them to GJK.
TEST(GjkNasty, BoxBooleanNearTouching) {
  const Box a{Vec3(1, 0.5, 0.25)}, b{Vec3(0.3, 0.7, 0.4)};
  const double size = a.half_extents.norm() + b.half_extents.norm();
  std::vector<Pose> poses;
  for (double tilt : {0.0, 1e-9, 1e-7, 1e-6, 3e-6, 1e-5, 1e-4, 0.3})
    for (const Vec3& axis : {Vec3(1, 1, 1), Vec3(0, 0, 1), Vec3(1, -2, 0.5)})
      poses.push_back(rotated(Vec3::Zero(), tilt, axis));
  // Random turns besides: fewer under the sanitizers, where the long-double oracle runs ten times
  // slower (the structured turns above walk the same code paths).
  oracle::Rng rng(4242);
  const int random_turns = oracle::sweep_count(20, 4);
  for (int i = 0; i < random_turns; ++i) poses.push_back(Pose::from(Vec3::Zero(), rng.rotation()));
  const Pose pa = rotated(Vec3(1e3, -2, 5), 0.7, Vec3(0.2, 1, 0.3));
  int checked = 0, cases = 0;
  for (const Pose& turn : poses) {
    for (const Vec3& dir : {Vec3(1, 1, 1), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(-0.3, 1, 0.2)}) {
      // B along `dir` from A, first clearly apart, then moved back by the distance plus delta.
      Pose pb = Pose::from(pa.translation + pa.rotate(dir.normalized() * 3 * size),
                           Quat(pa.rotation * turn.rotation));
      const auto apart = mink::distance(a, pa, b, pb);
      ASSERT_EQ(apart.status, mink::Status::Separated);
      const double tolerance = mink::Tolerances{}.relative;
      for (double delta : {-1e-6, -1e-11, 0.0, 0.5 * tolerance, 2 * tolerance, 1e-11, 1e-8, 1e-6}) {
        Pose moved = pb;
        moved.translation -= apart.normal * (apart.distance - delta * size);
        const oracle::WorldBox wa{oracle::widen(a.half_extents), oracle::widen(pa.rotation),
                                  oracle::widen(pa.translation)};
        const oracle::WorldBox wb{oracle::widen(b.half_extents), oracle::widen(moved.rotation),
                                  oracle::widen(moved.translation)};
        ++cases;
        const auto expected =
            oracle::polytope_pair(oracle::box_corners(wa), oracle::box_corners(wb));
        const auto got = mink::intersect(a, pa, b, moved);
        const auto dist = mink::distance(a, pa, b, moved);
        ASSERT_NE(got.status, mink::Status::InvalidInput);
        EXPECT_EQ(got.intersect, dist.status == mink::Status::Intersecting)
            << "intersect() and distance() disagree at delta " << delta;
        if (delta == 0.5 * tolerance) EXPECT_TRUE(got.intersect) << "a gap of half the tolerance";
        if (delta == 2 * tolerance) EXPECT_FALSE(got.intersect) << "a gap of twice the tolerance";
        const double gap = static_cast<double>(expected.gap);
        if (std::abs(gap) > oracle::kTouchingBand * size) {
          EXPECT_EQ(got.intersect, gap <= 0) << "gap " << gap << " at delta " << delta;
          ++checked;
        }
      }
    }
  }
  EXPECT_GE(checked, 3 * cases / 8);  // the deltas of -1e-6, 1e-8 and 1e-6 are outside the band
}

}  // namespace
