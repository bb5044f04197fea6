// GJK distance and intersect against closed-form answers (tests/oracle/analytic.hpp): sphere,
// capsule, point and box pairs in random poses, including near-touching and overlapping ones.
#include <gtest/gtest.h>

#include "mink/mink.hpp"
#include "oracle/analytic.hpp"
#include "oracle/check.hpp"
#include "oracle/penetration.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Vec3;
using oracle::Real;
using oracle::Rng;
using oracle::V3;
using oracle::widen;

/// A signed gap for a random case relative to `size`: mostly log-uniform separations over eight
/// decades, with overlaps and near-touching cases of both signs mixed in.
double random_gap(Rng& rng, double size) {
  const double u = rng.uniform(0, 1);
  if (u < 0.55) return size * rng.log_uniform(1e-13, 2);
  if (u < 0.75) return -size * rng.log_uniform(1e-13, 0.5);
  return size * rng.uniform(-1, 1);
}

TEST(GjkDistance, SphereSphereMatchesAnalytic) {
  const std::uint64_t base = 1000;
  const int n = oracle::sweep_count(3000);
  oracle::Worst worst("sphere-sphere");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const double ra = rng.log_uniform(0.01, 3), rb = rng.log_uniform(0.01, 3);
    const double size = ra + rb;
    const Pose pa = rng.pose(10);
    const Vec3 dir = rng.unit();
    const Pose pb =
        Pose::from(pa.translation + dir * (size + random_gap(rng, size)), rng.rotation());
    const mink::Sphere a{ra}, b{rb};
    const auto got = mink::distance(a, pa, b, pb);
    const auto got_bool = mink::intersect(a, pa, b, pb);
    const auto expected =
        oracle::sphere_sphere(widen(pa.translation), ra, widen(pb.translation), rb);
    oracle::expect_matches(expected, got, got_bool, size, pa.translation.norm(), true, worst);
  }
}

TEST(GjkDistance, SphereCapsuleMatchesAnalytic) {
  const std::uint64_t base = 2000;
  const int n = oracle::sweep_count(3000);
  oracle::Worst worst("sphere-capsule");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const double rs = rng.log_uniform(0.01, 2);
    const mink::Capsule cap{rng.log_uniform(0.01, 2), rng.log_uniform(0.001, 3)};
    const double size = rs + cap.radius + cap.half_height;
    const Pose pa = rng.pose(5);
    const Pose pb = Pose::from(pa.translation + rng.in_ball(1.5 * size), rng.rotation());
    const auto wc = oracle::make_capsule(cap.radius, cap.half_height, widen(pb.rotation),
                                         widen(pb.translation));
    const auto expected = oracle::sphere_capsule(widen(pa.translation), rs, wc);
    const mink::Sphere s{rs};
    const auto got = mink::distance(s, pa, cap, pb);
    const auto got_bool = mink::intersect(s, pa, cap, pb);
    oracle::expect_matches(expected, got, got_bool, size, pa.translation.norm(), true, worst);
  }
}

TEST(GjkDistance, CapsuleCapsuleMatchesAnalytic) {
  const std::uint64_t base = 3000;
  const int n = oracle::sweep_count(4000);
  oracle::Worst worst("capsule-capsule");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Capsule a{rng.log_uniform(0.01, 1), rng.log_uniform(0.001, 3)};
    const mink::Capsule b{rng.log_uniform(0.01, 1), rng.log_uniform(0.001, 3)};
    const double size = a.radius + a.half_height + b.radius + b.half_height;
    const Pose pa = rng.pose(5);
    // A quarter of the cases have parallel or nearly parallel axes (the classic trap).
    mink::Quat qb = rng.rotation();
    const int kind = rng.integer(0, 7);
    const mink::Quat qa(pa.rotation);
    if (kind == 0) qb = qa;
    if (kind == 1) {
      const double angle = rng.log_uniform(1e-9, 1e-3);  // drawn in sequence: reproducible
      qb = qa * mink::Quat(Eigen::AngleAxisd(angle, rng.unit()));
    }
    const Pose pb = Pose::from(pa.translation + rng.in_ball(1.2 * size), qb);
    const auto wa =
        oracle::make_capsule(a.radius, a.half_height, widen(pa.rotation), widen(pa.translation));
    const auto wb =
        oracle::make_capsule(b.radius, b.half_height, widen(pb.rotation), widen(pb.translation));
    const auto expected = oracle::capsule_capsule(wa, wb);
    // The closest points are unique when the axes are far from parallel.
    const double sin_angle = pa.rotation.col(2).cross(pb.rotation.col(2)).norm();
    const auto got = mink::distance(a, pa, b, pb);
    const auto got_bool = mink::intersect(a, pa, b, pb);
    oracle::expect_matches(expected, got, got_bool, size, pa.translation.norm(), sin_angle > 0.1,
                           worst);
  }
}

TEST(GjkDistance, PointBoxMatchesAnalytic) {
  const std::uint64_t base = 4000;
  const int n = oracle::sweep_count(3000);
  oracle::Worst worst("point-box");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Box box{
        Vec3(rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2))};
    const double size = box.half_extents.norm();
    const Pose pb = rng.pose(5);
    // The point either sits in a pose (point at its local origin) or is offset in its own frame.
    const Vec3 x = pb.translation + rng.in_ball(2.0 * size);
    const bool use_pose = rng.chance(0.5);
    const mink::Point point{use_pose ? Vec3::Zero() : Vec3(x - pb.translation)};
    const Pose pa =
        use_pose ? Pose::from(x, rng.rotation()) : Pose::from_translation(pb.translation);
    const oracle::WorldBox wb{widen(box.half_extents), widen(pb.rotation), widen(pb.translation)};
    const auto expected = oracle::point_box_answer(widen(x), wb);
    const auto got = mink::distance(point, pa, box, pb);
    const auto got_bool = mink::intersect(point, pa, box, pb);
    oracle::expect_matches(expected, got, got_bool, size, pb.translation.norm(), true, worst);
  }
}

TEST(GjkDistance, SphereBoxMatchesAnalytic) {
  const std::uint64_t base = 5000;
  const int n = oracle::sweep_count(3000);
  oracle::Worst worst("sphere-box");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Box box{
        Vec3(rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2))};
    const mink::Sphere sphere{rng.log_uniform(0.01, 2)};
    const double size = box.half_extents.norm() + sphere.radius;
    const Pose pb = rng.pose(5);
    const Pose pa = Pose::from(pb.translation + rng.in_ball(1.5 * size), rng.rotation());
    const oracle::WorldBox wb{widen(box.half_extents), widen(pb.rotation), widen(pb.translation)};
    const auto expected = oracle::sphere_box(widen(pa.translation), sphere.radius, wb);
    const auto got = mink::distance(sphere, pa, box, pb);
    const auto got_bool = mink::intersect(sphere, pa, box, pb);
    oracle::expect_matches(expected, got, got_bool, size, pb.translation.norm(), true, worst);
  }
}

TEST(GjkDistance, SphereCylinderMatchesAnalytic) {
  // A closed form (query/point_solid.hpp): centres all around the cylinder, some inside it and
  // some on its axis, the cylinder A or B.
  const std::uint64_t base = 6000;
  const int n = oracle::sweep_count(3000);
  oracle::Worst worst("sphere-cylinder");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Cylinder cyl{rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2)};
    const mink::Sphere sphere{rng.log_uniform(0.01, 2)};
    const double size = std::hypot(cyl.radius, cyl.half_height) + sphere.radius;
    const Pose pb = rng.pose(5);
    Vec3 offset = rng.in_ball(1.5 * size);
    if (i % 5 == 0) offset = Vec3(0, 0, offset.z());  // on the axis
    const Pose pa = Pose::from(pb.apply(offset), rng.rotation());
    const oracle::WorldCylinder wc{cyl.radius, cyl.half_height, widen(pb.rotation),
                                   widen(pb.translation)};
    const V3 c = widen(pa.translation);
    const auto pen = oracle::sphere_cylinder_penetration(c, sphere.radius, wc);
    oracle::Answer expected;
    expected.gap = -pen.depth;
    expected.distance = std::max(Real(0), expected.gap);
    if (expected.gap > 0) {  // the centre is outside: normal from it to the nearest point
      expected.normal = pen.normal;
      expected.point_a = c + Real(sphere.radius) * pen.normal;
      expected.point_b = c + (Real(sphere.radius) + expected.gap) * pen.normal;
    }
    const auto got = mink::distance(sphere, pa, cyl, pb);
    const auto got_bool = mink::intersect(sphere, pa, cyl, pb);
    EXPECT_EQ(got.iterations, 0);
    oracle::expect_matches(expected, got, got_bool, size, pb.translation.norm(), true, worst);
    // Swapped: the same distance, the normal and points swapped.
    const auto swapped = mink::distance(cyl, pb, sphere, pa);
    EXPECT_EQ(swapped.intersect, got.intersect);
    EXPECT_NEAR(swapped.distance, got.distance, 1e-15 * size);
    if (!got.intersect) {
      EXPECT_LE((swapped.normal + got.normal).norm(), 1e-12);
      EXPECT_LE((swapped.point_a - got.point_b).norm(), 1e-14 * (size + pb.translation.norm()));
    }
  }
}

// Pairs whose closest points lie on the line of centres, where intersect()'s first test (the line
// of centres as a separating axis) decides: capsules side by side, end to end and crossing, and a
// sphere beside a capsule, with their surfaces a quarter of the touching tolerance apart (they
// count as intersecting) or four times it (separated). The gap is built into the placement, so
// the answer is known exactly; the poses stay within the size of the shapes, where rounding
// (1e-15 of the size) is far below the tolerance (1e-12 of it).
TEST(GjkIntersect, LineOfCentresAtTouching) {
  const std::uint64_t base = 9000;
  const int n = oracle::sweep_count(2000);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Capsule a{rng.log_uniform(0.01, 1), rng.log_uniform(0.001, 3)};
    const mink::Capsule b{rng.log_uniform(0.01, 1), rng.log_uniform(0.001, 3)};
    const int kind = i % 4;
    // The sum of the bounding radii, which scales the touching tolerance (B's is its radius when
    // it is a sphere).
    const double size = a.radius + a.half_height + b.radius + (kind == 3 ? 0 : b.half_height);
    const double touch = mink::Tolerances{}.relative * size;
    const Pose pa = Pose::from(rng.in_ball(size), rng.rotation());
    const Vec3 axis = pa.rotation.col(2);
    const Vec3 across = axis.cross(rng.unit()).normalized();  // orthogonal to A's axis
    const bool apart = (i / 4) % 2 == 1;
    const double gap = apart ? 4 * touch : 0.25 * touch;
    const double radii = a.radius + b.radius;
    mink::Pose pb;
    if (kind == 0) {  // side by side, parallel (either way round)
      const mink::Quat qb = rng.uniform(0, 1) < 0.5
                                ? mink::Quat(pa.rotation)
                                : mink::Quat(pa.rotation) * mink::Quat(0, 1, 0, 0);
      pb = Pose::from(pa.translation + (radii + gap) * across, qb);
    } else if (kind == 1) {  // end to end, on one line
      pb = Pose::from(pa.translation + (a.half_height + b.half_height + radii + gap) * axis,
                      mink::Quat(pa.rotation));
    } else if (kind == 2) {  // crossing: B's axis orthogonal to A's and to the line of centres
      const Vec3 b_axis = axis.cross(across);
      const mink::Quat qb = mink::Quat::FromTwoVectors(Vec3::UnitZ(), b_axis);
      pb = Pose::from(pa.translation + (radii + gap) * across, qb);
    } else {  // B is a sphere beside A's side
      const mink::Sphere sphere{b.radius};
      const Pose ps = Pose::from(pa.translation + (radii + gap) * across, rng.rotation());
      EXPECT_EQ(mink::intersect(a, pa, sphere, ps).intersect, !apart);
      EXPECT_EQ(mink::intersect(sphere, ps, a, pa).intersect, !apart);
      EXPECT_EQ(mink::distance(a, pa, sphere, ps).intersect, !apart);
      continue;
    }
    EXPECT_EQ(mink::intersect(a, pa, b, pb).intersect, !apart) << "kind " << kind;
    EXPECT_EQ(mink::intersect(b, pb, a, pa).intersect, !apart) << "kind " << kind;
    EXPECT_EQ(mink::distance(a, pa, b, pb).intersect, !apart) << "kind " << kind;
  }
}

}  // namespace
