// Normals of curved pairs (ellipsoids, cylinders, cones, capsules in random poses, apart and
// overlapping) against the independent long-double search of tests/oracle/curved.hpp: GJK and
// EPA stop when the support value is within their tolerance, which on a smooth minimum (or along
// a kink: a capsule or cylinder on its side) leaves the normal off by the square root of it,
// 1e-5 rad; Newton's steps on the support function (gjk/support_newton.hpp) bring it to the
// oracle's own resolution, about 1e-8.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "mink/mink.hpp"
#include "oracle/curved.hpp"
#include "oracle/curved_to_mink.hpp"
#include "oracle/random.hpp"

namespace {

using oracle::CurvedKind;
using oracle::CurvedShape;
using oracle::Real;
using oracle::RigidPose;
using oracle::V3;

TEST(ContactCurvedNormal, NormalsMatchTheLeastSupportValue) {
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> unit(-1, 1), extent(0.2, 1.5);
  auto rotation = [&] {
    return Eigen::Quaternion<Real>(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
  };
  const CurvedKind kinds[] = {CurvedKind::Ellipsoid, CurvedKind::Cylinder, CurvedKind::Cone,
                              CurvedKind::Capsule};
  const int per_pair = oracle::sweep_count(4, 1);
  double worst = 0, worst_cone = 0;
  for (const CurvedKind ka : kinds) {
    for (const CurvedKind kb : kinds) {
      for (int i = 0; i < per_pair; ++i) {
        auto make = [&](CurvedKind kind) {
          CurvedShape s;
          s.kind = kind;
          s.radius = extent(rng);
          s.half_height = extent(rng);
          s.extents = V3(extent(rng), extent(rng), extent(rng));
          return s;
        };
        const CurvedShape a = make(ka), b = make(kb);
        const RigidPose pa = RigidPose::from(V3::Zero(), rotation());
        const V3 offset =
            V3(unit(rng), unit(rng), unit(rng)).normalized() * Real(1.5 * extent(rng));
        const RigidPose pb = RigidPose::from(offset, rotation());
        SCOPED_TRACE(std::string(oracle::kind_name(ka)) + "-" + oracle::kind_name(kb) + " #" +
                     std::to_string(i));
        const auto expected = oracle::curved_depth(a, pa, b, pb);
        const mink::Pose ma{pa.rotation.cast<double>(), pa.translation.cast<double>()};
        const mink::Pose mb{pb.rotation.cast<double>(), pb.translation.cast<double>()};
        const auto r = mink::contact(oracle::to_mink_shape(a), ma, oracle::to_mink_shape(b), mb);
        ASSERT_NE(r.status, mink::Status::InvalidInput) << r.error;
        const double size =
            static_cast<double>(oracle::bounding_radius(a) + oracle::bounding_radius(b));
        const double depth = static_cast<double>(expected.depth);
        if (std::abs(depth) < 1e-6 * size) continue;  // touching: the normal is not unique
        EXPECT_NEAR(r.intersect ? r.depth : -r.distance, depth, 1e-9 * size);
        const double angle = (r.normal - expected.normal.cast<double>()).norm();
        // A cone's kink is a small circle (apex and rim tie at a fixed angle to the axis), which
        // the secant along a great circle follows only to about 1e-6.
        const bool cone = ka == CurvedKind::Cone || kb == CurvedKind::Cone;
        (cone ? worst_cone : worst) = std::max(cone ? worst_cone : worst, angle);
        EXPECT_LE(angle, cone ? 3e-6 : 1e-7);
        const double signed_gap = r.intersect ? -r.depth : r.distance;
        EXPECT_LE((r.point_b - r.point_a - signed_gap * r.normal).norm(), 1e-12 * size);
      }
    }
  }
  testing::Test::RecordProperty("worst_normal_error", std::to_string(worst));
  testing::Test::RecordProperty("worst_normal_error_cone", std::to_string(worst_cone));
  std::printf("[  worst   ] normal %.3g rad, with a cone %.3g rad\n", worst, worst_cone);
}

TEST(ContactCurvedNormal, RefinementCanBeTurnedOff) {
  // Tolerances::refine_curved_normals = false: GJK's and EPA's own normal, the same depth and
  // distance to EPA's tolerance, and fewer support calls where the shapes penetrate. Apart, the
  // refinement's Newton steps close GJK's bracket in place of its last iterations (gjk_apart()),
  // and may take fewer.
  const mink::Ellipsoid a{mink::Vec3(1.0, 0.7, 0.5)};
  const mink::Cylinder b{0.6, 0.9};
  mink::Tolerances plain;
  plain.refine_curved_normals = false;
  const mink::Pose pa =
      mink::Pose::from(mink::Vec3::Zero(), mink::Quat(0.9, 0.1, -0.3, 0.2).normalized());
  for (const double offset : {0.8, 2.5}) {
    const mink::Pose pb = mink::Pose::from(mink::Vec3(offset, 0.4, 0.3),
                                           mink::Quat(0.3, 0.8, 0.1, -0.5).normalized());
    const auto refined = mink::contact(a, pa, b, pb);
    const auto unrefined = mink::contact(a, pa, b, pb, plain);
    ASSERT_EQ(refined.intersect, unrefined.intersect);
    if (refined.intersect) EXPECT_LT(unrefined.iterations, refined.iterations);
    EXPECT_NEAR(refined.depth, unrefined.depth, 1e-9);
    EXPECT_NEAR(refined.distance, unrefined.distance, 1e-9);
    EXPECT_LT((refined.normal - unrefined.normal).norm(), 1e-4);
  }
}

}  // namespace
