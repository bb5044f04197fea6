// Normals of curved pairs (ellipsoids, cylinders, cones, capsules in random poses, apart and
// overlapping) against the independent long-double search of tests/oracle/curved.hpp: GJK and
// EPA stop when the support value is within their tolerance, which on a smooth minimum (or along
// a kink: a capsule or cylinder on its side) leaves the normal off by the square root of it,
// 1e-5 rad; Newton's steps on the support function (gjk/support_newton.hpp) bring it to the
// oracle's own resolution, about 1e-8.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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

TEST(ContactCurvedNormal, LowestPointSunkInAFaceIsExact) {
  // A cylinder's rim, a cone's rim or apex, or an ellipsoid sunk delta into a box's top face well
  // inside it: depth delta along the face's normal, B's point the lowest point, A's delta above it
  // on the face. For the rims EPA closes on that facet of A - B to rounding (epa.hpp, on_facet());
  // its own points, combinations of support points along nearby normals, lay up to 3e-7 of the
  // size off the rim. The ellipsoids' depths are within its inner ball, which proves Newton's
  // answer (inner_ball.hpp). Both orders, typed and run-time shapes, and a third of the pairs 1e3
  // from the origin.
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> unit(-1, 1), tilt(0.2, 1.3), exponent(-4, -2),
      extent(0.3, 0.9), lateral(-0.8, 0.8);
  const mink::Box box{mink::Vec3(2.0, 2.0, 0.5)};
  const double pi = std::acos(-1.0);
  const char* const names[] = {"cylinder", "cone", "ellipsoid"};
  double worst_depth = 0, worst_normal = 0, worst_point = 0;
  for (int i = 0; i < 360; ++i) {
    const int kind = i % 3;
    const bool swap = i % 6 >= 3, typed = i % 12 < 6;
    const double radius = extent(rng), half_height = extent(rng);
    const mink::Vec3 radii(extent(rng), extent(rng), extent(rng));
    const double heading = pi * unit(rng);
    const mink::Mat3 rotation =
        (Eigen::AngleAxisd(tilt(rng), mink::Vec3(std::cos(heading), std::sin(heading), 0)) *
         Eigen::AngleAxisd(pi * unit(rng), mink::Vec3::UnitZ()))
            .toRotationMatrix();
    // The shape's lowest point, from its definition (the oracle's support point along -z in its
    // frame: a cylinder's rim on the cap facing down, a cone's apex when that reaches lower).
    CurvedShape described;
    described.kind = kind == 0   ? CurvedKind::Cylinder
                     : kind == 1 ? CurvedKind::Cone
                                 : CurvedKind::Ellipsoid;
    described.radius = radius;
    described.half_height = half_height;
    described.extents = radii.cast<Real>();
    const mink::Vec3 lowest =
        oracle::local_support_point(described,
                                    V3((rotation.transpose() * mink::Vec3(0, 0, -1)).cast<Real>()))
            .cast<double>();
    const double delta = std::pow(10.0, exponent(rng));
    const mink::Vec3 offset = i % 4 == 0 ? mink::Vec3(1e3, -2e3, 5e2) : mink::Vec3::Zero();
    const mink::Vec3 deepest = mink::Vec3(lateral(rng), lateral(rng), 0.5 - delta) + offset;
    const mink::Pose box_pose = mink::Pose::from_translation(offset);
    mink::Pose shape_pose;
    shape_pose.rotation = rotation;
    shape_pose.translation = deepest - rotation * lowest;
    const auto solve = [&](const auto& box_core, const auto& shape) {
      return swap ? mink::contact(shape, shape_pose, box_core, box_pose)
                  : mink::contact(box_core, box_pose, shape, shape_pose);
    };
    mink::ContactResult r;
    double shape_bound = std::hypot(radius, half_height);
    if (kind == 2) {
      shape_bound = radii.maxCoeff();
      r = typed ? solve(box, mink::Ellipsoid{radii})
                : solve(mink::Shape::box(box.half_extents).value(),
                        mink::Shape::ellipsoid(radii).value());
    } else if (typed) {
      r = kind == 1 ? solve(box, mink::Cone{radius, half_height})
                    : solve(box, mink::Cylinder{radius, half_height});
    } else {
      r = solve(mink::Shape::box(box.half_extents).value(),
                kind == 1 ? mink::Shape::cone(radius, half_height).value()
                          : mink::Shape::cylinder(radius, half_height).value());
    }
    SCOPED_TRACE(std::string(names[kind]) + (swap ? " first" : " second") +
                 (typed ? ", typed #" : ", Shape #") + std::to_string(i));
    ASSERT_EQ(r.status, mink::Status::Intersecting);
    const double size = box.bounding_radius() + shape_bound;
    const mink::Vec3 normal = swap ? mink::Vec3(0, 0, -1) : mink::Vec3(0, 0, 1);
    const mink::Vec3 on_box = deepest + mink::Vec3(0, 0, delta);
    const mink::Vec3& point_box = swap ? r.point_b : r.point_a;
    const mink::Vec3& point_shape = swap ? r.point_a : r.point_b;
    const double rounding = 8 * std::numeric_limits<double>::epsilon() * offset.norm();
    worst_depth = std::max(worst_depth, std::abs(r.depth - delta) / size);
    worst_normal = std::max(worst_normal, (r.normal - normal).norm());
    worst_point = std::max(
        worst_point,
        (std::max((point_box - on_box).norm(), (point_shape - deepest).norm()) - rounding) / size);
    EXPECT_LE(std::abs(r.depth - delta), 1e-13 * size);
    EXPECT_LE((r.normal - normal).norm(), 1e-13);
    EXPECT_LE((point_box - on_box).norm(), 1e-12 * size + rounding);
    EXPECT_LE((point_shape - deepest).norm(), 1e-12 * size + rounding);
  }
  RecordProperty("worst_depth", std::to_string(worst_depth));
  RecordProperty("worst_normal", std::to_string(worst_normal));
  RecordProperty("worst_point", std::to_string(worst_point));
  std::printf("lowest point in a face: worst depth %.2e, normal %.2e, points %.2e of the size\n",
              worst_depth, worst_normal, worst_point);
}

}  // namespace
