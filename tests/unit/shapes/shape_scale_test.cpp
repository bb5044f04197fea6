// Run-time Shape pairs far outside unit scale (1e-300 to 1e200), which the queries solve scaled by
// a power of two (src/shape_dispatch.hpp, solve_in_range()): answers worked out by hand at every
// scale (a point inside a triangle, cubes apart or overlapping along an axis), and the property
// that scaling every length of a pair scales its answers and keeps its flags, on random pairs of
// every kind (the unit pair's answers are checked against oracles elsewhere).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mink/mink.hpp"

namespace {

using mink::Pose;
using mink::Quat;
using mink::Shape;
using mink::Vec3;

constexpr double kScales[] = {1e-300, 1e-200, 1e-100, 1e-60, 1, 1e60, 1e100, 1e200};

Shape cube(double s) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(s * Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  return Shape::polytope(corners).value();
}

TEST(ShapeScale, APointInsideATriangleAtAnyScale) {
  for (const double s : kScales) {
    const Shape triangle =
        Shape::triangle(s * Vec3(-1, -1, 0), s * Vec3(1, -1, 0), s * Vec3(0, 1, 0)).value();
    const Shape point = Shape::point(s * Vec3(0.1, 0.05, 0)).value();
    const Pose at = Pose::from(Vec3(s, -2 * s, 0.5 * s), Quat(0.6, 0.8, 0, 0));
    EXPECT_TRUE(mink::intersect(triangle, at, point, at).intersect) << s;
    EXPECT_TRUE(mink::distance(triangle, at, point, at).intersect) << s;
    EXPECT_TRUE(mink::contact(triangle, at, point, at).intersect) << s;
    EXPECT_TRUE(mink::intersect(triangle, at, triangle, at).intersect) << s;  // coincident
  }
}

TEST(ShapeScale, CubesApartAndOverlappingAlongAnAxis) {
  for (const double s : kScales) {
    const Shape a = cube(s), b = cube(s);
    const Quat turn(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
    const Pose pa = Pose::from(s * Vec3(5, -1, 2), turn);
    // B's centre 3 s along A's x (faces 1 s apart), shifted across by less than the face: the
    // faces face each other, so the distance is s and the normal A's x axis.
    const Pose apart = Pose::from(pa.apply(s * Vec3(3, 0.5, 0.25)), turn);
    const auto d = mink::distance(a, pa, b, apart);
    ASSERT_EQ(d.status, mink::Status::Separated) << s;
    EXPECT_NEAR(d.distance / s, 1, 1e-12) << s;
    EXPECT_LT((d.normal - pa.rotation.col(0)).norm(), 1e-12) << s;
    EXPECT_NEAR(((d.point_b - d.point_a) / s).norm(), 1, 1e-12) << s;  // not squared at 1e-300
    EXPECT_NEAR(pa.inverse_apply(d.point_a).x() / s, 1, 1e-12) << s;
    EXPECT_FALSE(mink::intersect(a, pa, b, apart).intersect) << s;
    // 1.5 s along x: overlapping by 0.5 s.
    const Pose over = Pose::from(pa.apply(s * Vec3(1.5, 0.5, 0.25)), turn);
    const auto c = mink::contact(a, pa, b, over);
    ASSERT_TRUE(c.intersect) << s;
    EXPECT_NEAR(c.depth / s, 0.5, 1e-12) << s;
    EXPECT_LT((c.normal - pa.rotation.col(0)).norm(), 1e-12) << s;
    EXPECT_NEAR((c.point_a - c.point_b).dot(c.normal) / s, 0.5, 1e-12) << s;
    const auto m = mink::manifold(a, pa, b, over);
    ASSERT_EQ(m.count, 4) << s;  // B's face on A's: four corners
    for (int i = 0; i < m.count; ++i) EXPECT_NEAR(m.points[i].depth / s, 0.5, 1e-12) << s;
  }
}

/// A shape of kind `kind` with lengths about `s`, from `rng`.
Shape random_shape(int kind, double s, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.3, 1.0);
  std::normal_distribution<double> g;
  auto lengths = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  auto point = [&] { return Vec3(g(rng), g(rng), g(rng)); };
  switch (kind) {
    case 0:
      return Shape::sphere(s * u(rng)).value();
    case 1:
      return Shape::box(s * lengths()).value();
    case 2:
      return Shape::capsule(s * u(rng), s * u(rng)).value();
    case 3:
      return Shape::cylinder(s * u(rng), s * u(rng)).value();
    case 4:
      return Shape::cone(s * u(rng), s * u(rng)).value();
    case 5:
      return Shape::ellipsoid(s * lengths()).value();
    case 6:
      return Shape::triangle(s * point(), s * point(), s * point()).value();
    case 7: {
      std::vector<Vec3> points;
      for (int i = 0; i < 8; ++i) points.push_back(s * point());
      return Shape::polytope(points).value();
    }
    case 8:
      return Shape::rounded(Shape::box(s * lengths()).value(), 0.2 * s * u(rng)).value();
    default:
      return Shape::sum(Shape::cone(s * u(rng), s * u(rng)).value(),
                        Shape::box(s * lengths()).value())
          .value();
  }
}

TEST(ShapeScale, ScalingAPairScalesItsAnswers) {
  constexpr int kKinds = 10;
  // Powers of two (about 1e-250, 1e-80, 1e80 and 1e150): the scaled pair is the unit pair to the
  // last bit, and so, up to a power of two, is the copy the queries solve.
  for (const int exponent : {-830, -266, 266, 498}) {
    const double s = std::ldexp(1.0, exponent);
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
      const int ka = k % kKinds, kb = (k / kKinds) % kKinds;
      std::mt19937_64 unit_rng(k), scaled_rng(k), pose_rng(1000 + k);
      std::normal_distribution<double> g;
      const Shape a = random_shape(ka, 1, unit_rng), b = random_shape(kb, 1, unit_rng);
      const Shape as = random_shape(ka, s, scaled_rng), bs = random_shape(kb, s, scaled_rng);
      const Quat qa = Quat(g(pose_rng), g(pose_rng), g(pose_rng), g(pose_rng)).normalized();
      const Quat qb = Quat(g(pose_rng), g(pose_rng), g(pose_rng), g(pose_rng)).normalized();
      const Vec3 ta(g(pose_rng), g(pose_rng), g(pose_rng));
      const Vec3 tb = ta + (k % 3 == 0 ? 0.5 : 1.2) * Vec3(g(pose_rng), g(pose_rng), g(pose_rng));
      const Pose pa = Pose::from(ta, qa), pb = Pose::from(tb, qb);
      const Pose pas = Pose::from(s * ta, qa), pbs = Pose::from(s * tb, qb);
      const auto c = mink::contact(a, pa, b, pb), cs = mink::contact(as, pas, bs, pbs);
      if (c.status == mink::Status::IterationLimit) continue;  // compared within its bound only
      ++checked;
      const double size = a.bounding_radius() + b.bounding_radius();
      ASSERT_EQ(cs.intersect, c.intersect) << s << " pair " << k;
      EXPECT_EQ(mink::intersect(as, pas, bs, pbs).intersect, c.intersect) << s << " pair " << k;
      EXPECT_EQ(mink::distance(as, pas, bs, pbs).intersect, c.intersect) << s << " pair " << k;
      const double value = c.intersect ? -c.depth : c.distance;
      const double value_s = cs.intersect ? -cs.depth : cs.distance;
      EXPECT_NEAR(value_s / s, value, 1e-9 * size) << s << " pair " << k;
      EXPECT_LT((cs.normal - c.normal).norm(), 1e-9) << s << " pair " << k;
      EXPECT_LT((cs.point_a / s - c.point_a).norm(), 1e-9 * size) << s << " pair " << k;
    }
    EXPECT_GT(checked, 250) << s;
  }
}

}  // namespace
