// Pairs far outside unit scale (1e-300 to 1e200), which the queries solve scaled by a power of two
// (query/scale_range.hpp), as run-time Shapes and as typed shapes: answers worked out by hand at
// every scale (a point inside a triangle, cubes apart or overlapping along an axis), and the
// property that scaling every length of a pair scales its answers and keeps its flags, on random
// pairs of every kind (the unit pair's answers are checked against oracles elsewhere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
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

/// Cubes a and b of half side s (run-time Shapes, typed boxes or polytopes), turned alike: B's
/// centre 3 s along A's x axis (faces s apart), shifted across by less than a face, so that the
/// faces face each other, then 1.5 s along it (overlapping by 0.5 s).
template <class Cube>
void expect_cubes_along_an_axis(const Cube& a, const Cube& b, double s) {
  const Quat turn(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  const Pose pa = Pose::from(s * Vec3(5, -1, 2), turn);
  const Pose apart = Pose::from(pa.apply(s * Vec3(3, 0.5, 0.25)), turn);
  const auto d = mink::distance(a, pa, b, apart);
  ASSERT_EQ(d.status, mink::Status::Separated) << s;
  EXPECT_NEAR(d.distance / s, 1, 1e-12) << s;
  EXPECT_LT((d.normal - pa.rotation.col(0)).norm(), 1e-12) << s;
  EXPECT_NEAR(pa.inverse_apply(d.point_a).x() / s, 1, 1e-12) << s;
  EXPECT_NEAR(pa.inverse_apply(d.point_b).x() / s, 2, 1e-12) << s;
  EXPECT_NEAR(((d.point_b - d.point_a) / s).norm(), 1, 1e-12) << s;  // not squared at 1e-300
  EXPECT_FALSE(mink::intersect(a, pa, b, apart).intersect) << s;
  const Pose over = Pose::from(pa.apply(s * Vec3(1.5, 0.5, 0.25)), turn);
  EXPECT_TRUE(mink::intersect(a, pa, b, over).intersect) << s;
  const auto c = mink::contact(a, pa, b, over);
  ASSERT_TRUE(c.intersect) << s;
  EXPECT_NEAR(c.depth / s, 0.5, 1e-12) << s;
  EXPECT_LT((c.normal - pa.rotation.col(0)).norm(), 1e-12) << s;
  EXPECT_NEAR(pa.inverse_apply(c.point_a).x() / s, 1, 1e-12) << s;
  const auto m = mink::manifold(a, pa, b, over);
  ASSERT_EQ(m.count, 4) << s;
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR(m.points[i].depth / s, 0.5, 1e-12) << s;
    EXPECT_NEAR(pa.inverse_apply(m.points[i].point_a).x() / s, 1, 1e-12) << s;
  }
}

TEST(ShapeScale, CubesApartAndOverlappingAlongAnAxis) {
  for (const double s : kScales) expect_cubes_along_an_axis(cube(s), cube(s), s);
}

/// Pair k's poses: B about a unit from A (half that for every third pair), and the same poses
/// with their translations scaled by s.
struct PairPoses {
  Pose a, b, a_scaled, b_scaled;
};

PairPoses pair_poses(int k, double s) {
  std::mt19937_64 rng(1000 + k);
  std::normal_distribution<double> g;
  const Quat qa = Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
  const Quat qb = Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
  const Vec3 ta(g(rng), g(rng), g(rng));
  const Vec3 tb = ta + (k % 3 == 0 ? 0.5 : 1.2) * Vec3(g(rng), g(rng), g(rng));
  return {Pose::from(ta, qa), Pose::from(tb, qb), Pose::from(s * ta, qa), Pose::from(s * tb, qb)};
}

/// The pair (a, b) and its copy (as, bs) with every length scaled by s answer alike under all
/// four queries: the same flags, normals and manifold sizes, and lengths and points scaled by s,
/// within 1e-9 of the size. False, and nothing compared, when the unit pair's contact() hit its
/// iteration cap (its answer is then only within its bound).
template <class A, class B>
bool expect_scaled_answers(const A& a, const B& b, const A& as, const B& bs, const PairPoses& p,
                           double s, const std::string& note) {
  const auto c = mink::contact(a, p.a, b, p.b);
  const auto cs = mink::contact(as, p.a_scaled, bs, p.b_scaled);
  if (c.status == mink::Status::IterationLimit) return false;
  const double size = a.bounding_radius() + b.bounding_radius();
  EXPECT_EQ(cs.intersect, c.intersect) << note;
  EXPECT_EQ(mink::intersect(as, p.a_scaled, bs, p.b_scaled).intersect, c.intersect) << note;
  const auto ds = mink::distance(as, p.a_scaled, bs, p.b_scaled);
  EXPECT_EQ(ds.intersect, c.intersect) << note;
  if (!c.intersect) {
    EXPECT_NEAR(ds.distance / s, c.distance, 1e-9 * size) << note;
  }
  const double value = c.intersect ? -c.depth : c.distance;
  const double value_s = cs.intersect ? -cs.depth : cs.distance;
  EXPECT_NEAR(value_s / s, value, 1e-9 * size) << note;
  EXPECT_LT((cs.normal - c.normal).norm(), 1e-9) << note;
  EXPECT_LT((cs.point_a / s - c.point_a).norm(), 1e-9 * size) << note;
  EXPECT_LT((cs.point_b / s - c.point_b).norm(), 1e-9 * size) << note;
  const auto m = mink::manifold(a, p.a, b, p.b);
  const auto ms = mink::manifold(as, p.a_scaled, bs, p.b_scaled);
  EXPECT_EQ(ms.count, m.count) << note;
  for (int i = 0; i < std::min(m.count, ms.count); ++i) {
    EXPECT_NEAR(ms.points[i].depth / s, m.points[i].depth, 1e-9 * size) << note;
    EXPECT_LT((ms.points[i].point_a / s - m.points[i].point_a).norm(), 1e-9 * size) << note;
  }
  return true;
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
      std::mt19937_64 unit_rng(k), scaled_rng(k);
      const Shape a = random_shape(ka, 1, unit_rng), b = random_shape(kb, 1, unit_rng);
      const Shape as = random_shape(ka, s, scaled_rng), bs = random_shape(kb, s, scaled_rng);
      const std::string note = "2^" + std::to_string(exponent) + " pair " + std::to_string(k);
      checked += expect_scaled_answers(a, b, as, bs, pair_poses(k, s), s, note);
    }
    EXPECT_GT(checked, 250) << s;
  }
}

// ---- The templated queries on typed shapes ----

TEST(TypedScale, CubesApartAndOverlappingAlongAnAxis) {
  for (const double s : kScales) {
    SCOPED_TRACE(s);
    const mink::Box box{Vec3(s, s, s)};
    expect_cubes_along_an_axis(box, box, s);
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
      corners.push_back(s * Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    const mink::Polytope cube = mink::Polytope::make(corners).value();
    expect_cubes_along_an_axis(cube, cube, s);
  }
}

/// Draws typed shapes with lengths about `s`: the same draws at every s, so that makers of one
/// seed at two powers of two give the same shapes scaled exactly.
struct TypedMaker {
  double s;
  std::mt19937_64 rng;
  double length() { return s * std::uniform_real_distribution<double>(0.3, 1.0)(rng); }
  Vec3 lengths() { return Vec3(length(), length(), length()); }
  Vec3 point() {
    std::normal_distribution<double> g;
    return s * Vec3(g(rng), g(rng), g(rng));
  }
  std::vector<Vec3> points(int n) {
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i) p.push_back(point());
    return p;
  }
};

/// Scaling every length of a typed pair by 2^e (about 1e-250, 1e-80, 1e80 and 1e150; the hull
/// builder takes coordinates up to 1e100) scales the answers of all four queries and keeps their
/// flags and normals. make_a(maker), make_b(maker) draw the shapes.
template <class MakeA, class MakeB>
void expect_typed_pair_scales(const std::string& name, MakeA make_a, MakeB make_b,
                              std::vector<int> exponents = {-830, -266, 266, 498}) {
  SCOPED_TRACE(name);
  for (const int exponent : exponents) {
    const double s = std::ldexp(1.0, exponent);
    int checked = 0;
    for (int k = 0; k < 30; ++k) {
      TypedMaker unit{1, std::mt19937_64(k)}, scaled{s, std::mt19937_64(k)};
      const auto a = make_a(unit);
      const auto b = make_b(unit);
      const auto as = make_a(scaled);
      const auto bs = make_b(scaled);
      const std::string note = "2^" + std::to_string(exponent) + " pair " + std::to_string(k);
      checked += expect_scaled_answers(a, b, as, bs, pair_poses(k, s), s, note);
    }
    EXPECT_GT(checked, 25) << s;
  }
}

TEST(TypedScale, ScalingAPairScalesItsAnswers) {
  using mink::Box;
  auto box = [](TypedMaker& m) { return Box{m.lengths()}; };
  auto polytope = [](TypedMaker& m) { return mink::Polytope::make(m.points(8)).value(); };
  auto hull = [](TypedMaker& m) { return mink::ConvexHullShape::make(m.points(12)).value(); };
  auto sphere = [](TypedMaker& m) { return mink::Sphere{m.length()}; };
  auto capsule = [](TypedMaker& m) { return mink::Capsule{m.length(), m.length()}; };
  auto cylinder = [](TypedMaker& m) { return mink::Cylinder{m.length(), m.length()}; };
  auto cone = [](TypedMaker& m) { return mink::Cone{m.length(), m.length()}; };
  auto ellipsoid = [](TypedMaker& m) { return mink::Ellipsoid{m.lengths()}; };
  auto point = [](TypedMaker& m) { return mink::Point{Vec3(0.3 * m.point())}; };
  auto segment = [](TypedMaker& m) { return mink::Segment{m.point(), m.point()}; };
  auto triangle = [](TypedMaker& m) { return mink::Triangle{m.point(), m.point(), m.point()}; };
  auto rounded_box = [](TypedMaker& m) { return mink::Rounded<Box>{Box{m.lengths()}, m.length()}; };
  auto sweep = [](TypedMaker& m) {
    return mink::MinkowskiSum<mink::Segment, Box>{mink::Segment{m.point(), m.point()},
                                                  Box{m.lengths()}};
  };
  auto rounded_cone = [](TypedMaker& m) {
    return mink::Rounded<mink::Cone>{mink::Cone{m.length(), m.length()}, 0.3 * m.length()};
  };
  // One pair for each path of the queries: the boxes' separating axes, the segments' closed form,
  // a point against a solid, a segment against a box, GJK and EPA, the curved refinements.
  expect_typed_pair_scales("box-box", box, box);
  expect_typed_pair_scales("rounded box-box", rounded_box, box);
  expect_typed_pair_scales("polytope-polytope", polytope, polytope);
  expect_typed_pair_scales("hull-box", hull, box, {-830, -266, 266});
  expect_typed_pair_scales("sphere-polytope", sphere, polytope);
  expect_typed_pair_scales("capsule-box", capsule, box);
  expect_typed_pair_scales("capsule-capsule", capsule, capsule);
  expect_typed_pair_scales("cylinder-ellipsoid", cylinder, ellipsoid);
  expect_typed_pair_scales("cone-polytope", cone, polytope);
  expect_typed_pair_scales("point-cylinder", point, cylinder);
  expect_typed_pair_scales("triangle-segment", triangle, segment);
  expect_typed_pair_scales("sweep-rounded cone", sweep, rounded_cone);
}

/// The pairs at the edges of the range test that the typed queries run first (in_scale_range()):
/// shapes of size 0, tiny shapes far apart, subnormal lengths, and invalid input that the test
/// turns away, each with its answer worked out by hand.
TEST(TypedScale, EdgesOfTheRangeTest) {
  const mink::Point origin{Vec3::Zero()};
  const Pose here = Pose::identity();
  // Two points at one place: nothing to scale, and they touch.
  const auto same = mink::contact(origin, here, origin, here);
  EXPECT_EQ(same.status, mink::Status::Intersecting);
  EXPECT_EQ(same.depth, 0.0);
  EXPECT_TRUE(mink::intersect(origin, here, origin, here).intersect);
  // Two points 5 * 2^-700 apart: scaled up, the 3-4-5 triangle is exact.
  const double unit = std::ldexp(1.0, -700);
  const Pose there = Pose::from(Vec3(3 * unit, 4 * unit, 0), Quat::Identity());
  const auto apart = mink::distance(origin, here, origin, there);
  ASSERT_EQ(apart.status, mink::Status::Separated);
  EXPECT_NEAR(apart.distance / unit, 5, 1e-12);
  EXPECT_LT((apart.normal - Vec3(0.6, 0.8, 0)).norm(), 1e-12);
  EXPECT_NEAR(apart.point_b.y() / unit, 4, 1e-12);
  // Spheres of radius 1e-200 a unit apart: the offset is in the range, and they are solved as
  // they are.
  const mink::Sphere speck{1e-200};
  const Pose unit_x = Pose::from(Vec3(1, 0, 0), Quat::Identity());
  const auto specks = mink::contact(speck, here, speck, unit_x);
  ASSERT_EQ(specks.status, mink::Status::Separated);
  EXPECT_EQ(specks.distance, 1.0);  // 1 - 2e-200, rounded
  EXPECT_LT((specks.normal - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_EQ(specks.point_b.x(), 1.0);
  // Subnormal spheres: radius 2 * 2^-1074 with centres 10 * 2^-1074 apart, 6 * 2^-1074 between
  // them (every length a whole multiple of the smallest subnormal: exact).
  const double tiniest = std::numeric_limits<double>::denorm_min();
  const mink::Sphere dust{2 * tiniest};
  const Pose dust_at = Pose::from(Vec3(0, 0, 10 * tiniest), Quat::Identity());
  const auto grains = mink::distance(dust, here, dust, dust_at);
  ASSERT_EQ(grains.status, mink::Status::Separated);
  EXPECT_EQ(grains.distance, 6 * tiniest);
  EXPECT_EQ(grains.normal, Vec3::UnitZ());
  EXPECT_FALSE(mink::intersect(dust, here, dust, dust_at).intersect);
  const Pose dust_touching = Pose::from(Vec3(0, 0, 3 * tiniest), Quat::Identity());
  const auto overlap = mink::contact(dust, here, dust, dust_touching);
  ASSERT_EQ(overlap.status, mink::Status::Intersecting);
  EXPECT_EQ(overlap.depth, tiniest);
  // Invalid input that the range test turns away is reported as such, never scaled.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto bad_sphere = mink::contact(mink::Sphere{nan}, here, speck, unit_x);
  EXPECT_EQ(bad_sphere.status, mink::Status::InvalidInput);
  ASSERT_NE(bad_sphere.error, nullptr);
  EXPECT_NE(std::string(bad_sphere.error).find("sphere radius"), std::string::npos);
  const auto bad_box = mink::manifold(mink::Box{Vec3(1, nan, 1)}, here, speck, unit_x);
  EXPECT_EQ(bad_box.status, mink::Status::InvalidInput);
  ASSERT_NE(bad_box.error, nullptr);
  EXPECT_NE(std::string(bad_box.error).find("box half_extents"), std::string::npos);
  const double inf = std::numeric_limits<double>::infinity();
  const auto huge = mink::intersect(mink::Box{Vec3(1, 1, inf)}, here, speck, unit_x);
  EXPECT_EQ(huge.status, mink::Status::InvalidInput);
  // A pair out of the range whose scaled copy would be valid: a negative half height of 2e-148
  // beside a capsule 1e300 long rounds to -0 when scaled by 2^-996 (fuzz/corpus).
  const mink::Capsule long_one{1, 1e300}, inside_out{432, -2.1408691866764404e-148};
  const auto flipped = mink::contact(long_one, here, inside_out, unit_x);
  EXPECT_EQ(flipped.status, mink::Status::InvalidInput);
  ASSERT_NE(flipped.error, nullptr);
  EXPECT_NE(std::string(flipped.error).find("capsule half_height"), std::string::npos);
  EXPECT_EQ(mink::intersect(long_one, here, inside_out, unit_x).status, mink::Status::InvalidInput);
  const Pose nowhere = Pose::from(Vec3(nan, 0, 0), Quat::Identity());
  const auto lost = mink::distance(dust, here, dust, nowhere);
  EXPECT_EQ(lost.status, mink::Status::InvalidInput);
  ASSERT_NE(lost.error, nullptr);
  EXPECT_NE(std::string(lost.error).find("pose of B"), std::string::npos);
}

}  // namespace
