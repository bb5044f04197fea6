// Capsules and segments against boxes, whose cores' closest points are a closed form
// (query/segment_box.hpp), against a golden-section search in long double over the core segment
// (oracle::capsule_box()): random poses, needles, segments parallel to a face, far from the
// origin, both orders, and the needle pair on which GJK stalled.
#include <gtest/gtest.h>

#include <cmath>

#include "mink/mink.hpp"
#include "oracle/analytic.hpp"
#include "oracle/check.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Quat;
using mink::Vec3;
using oracle::Real;
using oracle::Rng;
using oracle::widen;

struct Case {
  mink::Capsule capsule;
  Pose pose_capsule;
  mink::Box box;
  Pose pose_box;
};

/// A capsule near a box: anywhere around it, or lying along one of its axes (parallel to a face,
/// the flat minimum) or tilted from one by 1e-12 to 1e-2 rad; sometimes both needles.
Case random_case(Rng& rng, double far) {
  Case c;
  const bool needles = rng.chance(0.2);
  const double thin = needles ? 1e-6 : 1.0;
  c.box.half_extents = Vec3(thin * rng.log_uniform(0.01, 2), thin * rng.log_uniform(0.01, 2),
                            rng.log_uniform(0.01, 2));
  c.capsule = mink::Capsule{thin * rng.log_uniform(0.001, 1), rng.log_uniform(0.01, 2)};
  c.pose_box = rng.pose(far);
  const double reach = c.box.half_extents.norm() + c.capsule.half_height + c.capsule.radius;
  Vec3 offset = rng.in_ball(1.5 * reach);
  Quat turn = Quat(rng.rotation());
  if (rng.chance(0.5)) {
    // Along a box axis (the capsule's z onto the box's axis k), beside a face, maybe tilted.
    const int k = static_cast<int>(rng.uniform(0, 3)) % 3;
    turn = Quat::FromTwoVectors(Vec3::UnitZ(), Vec3::Unit(k));
    if (rng.chance(0.6))
      turn = Quat(Eigen::AngleAxisd(rng.log_uniform(1e-12, 1e-2), rng.unit())) * turn;
    const int side = (k + 1 + static_cast<int>(rng.uniform(0, 2)) % 2) % 3;
    const double sign = rng.chance(0.5) ? 1 : -1;
    offset[side] = sign * (c.box.half_extents[side] + c.capsule.radius +
                           c.box.half_extents.norm() * rng.uniform(-0.01, 0.3));
  }
  c.pose_capsule = Pose{c.pose_box.rotation * turn.toRotationMatrix(), c.pose_box.apply(offset)};
  return c;
}

oracle::Answer expected_of(const Case& c) {
  const oracle::WorldCapsule capsule =
      oracle::make_capsule(c.capsule.radius, c.capsule.half_height, widen(c.pose_capsule.rotation),
                           widen(c.pose_capsule.translation));
  const oracle::WorldBox box{widen(c.box.half_extents), widen(c.pose_box.rotation),
                             widen(c.pose_box.translation)};
  return oracle::capsule_box(capsule, box);
}

TEST(SegmentBox, CapsuleBoxMatchesTheConvexMinimum) {
  const std::uint64_t base = 490000;
  const int n = oracle::sweep_count(3000, 600);
  oracle::Worst worst("capsule-box"), swapped("box-capsule");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const Case c = random_case(rng, rng.chance(0.2) ? 1e5 : 5);
    const double size = c.capsule.bounding_radius() + c.box.bounding_radius();
    const double far = c.pose_box.translation.norm();
    const oracle::Answer expected = expected_of(c);
    // The closest points are unique unless the segment is parallel to a face or an edge.
    const Vec3 axis = c.pose_box.rotation.transpose() * c.pose_capsule.rotation.col(2);
    const bool unique = axis.cwiseAbs().minCoeff() > 1e-3;
    const auto got = mink::distance(c.capsule, c.pose_capsule, c.box, c.pose_box);
    oracle::expect_matches(expected, got,
                           mink::intersect(c.capsule, c.pose_capsule, c.box, c.pose_box), size, far,
                           unique, worst);
    // Swapped: the same distance, the normal flipped.
    oracle::Answer flipped = expected;
    std::swap(flipped.point_a, flipped.point_b);
    flipped.normal = -expected.normal;
    oracle::expect_matches(flipped, mink::distance(c.box, c.pose_box, c.capsule, c.pose_capsule),
                           mink::intersect(c.box, c.pose_box, c.capsule, c.pose_capsule), size, far,
                           unique, swapped);
    // contact(): the same answer apart; where the cores are apart but the radius reaches, the
    // depth is the radius minus the core distance.
    const auto r = mink::contact(c.capsule, c.pose_capsule, c.box, c.pose_box);
    ASSERT_NE(r.status, mink::Status::InvalidInput) << r.error;
    const double gap = static_cast<double>(expected.gap);
    if (std::abs(gap) <= oracle::kTouchingBand * size) continue;
    EXPECT_EQ(r.intersect, gap < 0);
    if (gap > 0) {
      EXPECT_NEAR(r.distance, gap, 1e-12 * size + 1e-15 * far);
    } else if (gap > -c.capsule.radius + oracle::kTouchingBand * size) {
      // The cores apart (the segment does not cross the box): the radius minus their distance.
      EXPECT_EQ(r.status, mink::Status::Intersecting);
      EXPECT_NEAR(r.depth, -gap, 1e-12 * size + 1e-15 * far);
    }
    const double sign = r.intersect ? -r.depth : r.distance;
    EXPECT_LE((r.point_b - r.point_a - sign * r.normal).norm(), 1e-12 * size + 1e-15 * far);
  }
}

TEST(SegmentBox, SegmentsAndRoundedBoxesTakeTheSamePath) {
  // A segment is a capsule of radius 0; a rounded box adds its radius to the gap.
  Rng rng(4901);
  for (int i = 0; i < 200; ++i) {
    const Case c = random_case(rng, 5);
    const Vec3 half = c.capsule.half_height * Vec3::UnitZ();
    const mink::Segment segment{-half, half};
    const double rounding = 0.01;
    const mink::Rounded<mink::Box> rounded{c.box, rounding};
    const double size = c.capsule.bounding_radius() + c.box.bounding_radius() + rounding;
    oracle::Answer expected = expected_of(c);
    const Real core_gap = expected.gap + c.capsule.radius;
    const auto got = mink::distance(segment, c.pose_capsule, rounded, c.pose_box);
    if (core_gap - rounding > 1e-9 * size) {
      EXPECT_EQ(got.status, mink::Status::Separated);
      EXPECT_NEAR(got.distance, static_cast<double>(core_gap) - rounding, 1e-12 * size);
    } else if (core_gap - rounding < -1e-9 * size) {
      EXPECT_TRUE(got.intersect);
    }
  }
}

TEST(SegmentBox, NeedleCapsuleBesideANeedleBox) {
  // Found by an adversarial probe (tests/slow/probe_stop48/status_iteration_limit.jsonl): a
  // capsule of radius 2.8e-9 beside a box 1.4e-6 by 3.3e-6 by 2.9, nearly parallel. GJK's
  // simplices on the two needles stalled: IterationLimit, apart by 2.77e-9 with a bound as large.
  // They overlap by 2e-12 (the oracle), within the touching tolerance: intersecting.
  const mink::Capsule capsule{2.7696032868291136e-09, 0.5682104624090566};
  const mink::Box box{Vec3(6.758770544631009e-07, 1.642845843953395e-06, 1.4512273052983704)};
  const Pose pa = Pose::from(
      Vec3(-0.2537969901039814, -1.4893801669237168, 0.15728811734681747),
      Quat(0.018932336348535746, 0.746844733794272, -0.015969199240145594, 0.6645370530826535)
          .normalized());
  const Pose pb = Pose::from(
      Vec3(-1.1297560093864587, -1.44566629323329, 0.25977537808703427),
      Quat(0.01893233660421975, 0.7468447348861024, -0.015969199686443364, 0.664537051837583)
          .normalized());
  const double size = capsule.bounding_radius() + box.bounding_radius();
  const oracle::Answer expected = expected_of({capsule, pa, box, pb});
  EXPECT_LT(static_cast<double>(expected.gap), 0.0);
  EXPECT_GT(static_cast<double>(expected.gap), -1e-11);
  for (const bool swap : {false, true}) {
    const auto d =
        swap ? mink::distance(box, pb, capsule, pa) : mink::distance(capsule, pa, box, pb);
    EXPECT_EQ(d.status, mink::Status::Intersecting);
    const auto r = swap ? mink::contact(box, pb, capsule, pa) : mink::contact(capsule, pa, box, pb);
    EXPECT_EQ(r.status, mink::Status::Intersecting);
    EXPECT_NEAR(r.depth, -static_cast<double>(expected.gap), 1e-12 * size);
    EXPECT_TRUE(swap ? mink::intersect(box, pb, capsule, pa).intersect
                     : mink::intersect(capsule, pa, box, pb).intersect);
  }
}

TEST(SegmentBox, CapsuleLyingBesideAFaceTakesTheMiddleOfTheStretch) {
  // Parallel to the top face, 0.5 above it, hanging over its +x edge: every point of the
  // stretch over the face is as near; the middle one is taken, for points that do not jump.
  const mink::Box box{Vec3(1, 1, 1)};
  const mink::Capsule capsule{0.25, 1};
  const Pose pb{};
  const Pose pa =
      Pose::from(Vec3(1.5, 0.2, 1.75), Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY())));
  const auto r = mink::contact(capsule, pa, box, pb);
  EXPECT_EQ(r.status, mink::Status::Separated);
  EXPECT_NEAR(r.distance, 0.5, 1e-15);
  EXPECT_NEAR(r.normal.z(), -1, 1e-15);
  // The segment covers x in [0.5, 2.5]; over the face, [0.5, 1]: the middle is 0.75.
  EXPECT_NEAR(r.point_a.x(), 0.75, 1e-15);
  EXPECT_NEAR(r.point_b.x(), 0.75, 1e-15);
  EXPECT_NEAR(r.point_b.z(), 1, 1e-15);
  EXPECT_NEAR(r.point_a.z(), 1.5, 1e-15);
}

TEST(SegmentBox, FloatAgreesWithDouble) {
  Rng rng(4902);
  for (int i = 0; i < 100; ++i) {
    const Case c = random_case(rng, 2);
    const auto d = mink::distance(c.capsule, c.pose_capsule, c.box, c.pose_box);
    const mink::CapsuleT<float> capsule{static_cast<float>(c.capsule.radius),
                                        static_cast<float>(c.capsule.half_height)};
    const mink::BoxT<float> box{c.box.half_extents.cast<float>()};
    const mink::PoseT<float> pa{c.pose_capsule.rotation.cast<float>(),
                                c.pose_capsule.translation.cast<float>()};
    const mink::PoseT<float> pb{c.pose_box.rotation.cast<float>(),
                                c.pose_box.translation.cast<float>()};
    const auto f = mink::distance(capsule, pa, box, pb);
    const double size = c.capsule.bounding_radius() + c.box.bounding_radius();
    if (d.distance > 1e-4 * size) {
      EXPECT_NEAR(f.distance, d.distance, 1e-5 * size);
    }
  }
}

}  // namespace
