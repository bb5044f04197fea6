// Shape::sum() folds a part into a core already there when their sum is again one core (a
// sphere's centre adds nothing; a segment symmetric about the origin lengthens a cylinder or a
// segment along it, or a box along an axis), so that the sum takes that core's closed forms and
// axial paths. Checked: the folded sums have the support values of their parts' sum (each part
// measured on its own), what cannot fold stays a sum of several cores, and coincident sums that
// ended at EPA's cap as several cores (stop 48's probe) answer exactly, against their widths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "mink/mink.hpp"

namespace {

using mink::Pose;
using mink::Quat;
using mink::Shape;
using mink::Vec3;

/// h(d): the support value of a shape, its core's plus its radius.
double support_value(const Shape& s, const Vec3& d) {
  return d.dot(s.support_core(d)) + s.core_radius() * d.norm();
}

struct SumCase {
  std::string name;
  Shape a, b;
  std::size_t cores;  ///< of the sum: 1 when the parts fold
};

std::vector<SumCase> sum_cases() {
  const Vec3 half_x(0.7, 0, 0), half_z(0, 0, 0.4), oblique(0.3, 0.2, 0.1);
  return {
      {"cylinder + sphere", Shape::cylinder(0.5, 0.8).value(), Shape::sphere(0.3).value(), 1},
      {"sphere + box", Shape::sphere(0.3).value(), Shape::box(Vec3(1, 2, 3)).value(), 1},
      {"capsule + cylinder", Shape::capsule(0.55, 0.69).value(), Shape::cylinder(0.1, 0.2).value(),
       1},
      {"cylinder + capsule", Shape::cylinder(0.1, 0.2).value(), Shape::capsule(0.55, 0.69).value(),
       1},
      {"box + segment along x", Shape::box(Vec3(1, 2, 3)).value(),
       Shape::segment(-half_x, half_x).value(), 1},
      {"segment + segment, antiparallel", Shape::segment(-half_z, half_z).value(),
       Shape::segment(Vec3(0, 0, 0.9), Vec3(0, 0, -0.9)).value(), 1},
      {"segment + segment, oblique", Shape::segment(-oblique, oblique).value(),
       Shape::segment(2 * oblique, -2 * oblique).value(), 1},
      {"capsule + capsule", Shape::capsule(0.2, 0.3).value(), Shape::capsule(0.1, 0.6).value(), 1},
      {"capsule + segment along z", Shape::capsule(0.2, 0.3).value(),
       Shape::segment(half_z, -half_z).value(), 1},
      {"box + capsule", Shape::box(Vec3(1, 2, 3)).value(), Shape::capsule(0.2, 0.3).value(), 1},
      {"segment + sphere (a capsule)",
       Shape::segment(Vec3(-0.6, -0.2, 0), Vec3(0.5, -0.4, 0.1)).value(),
       Shape::sphere(0.08).value(), 1},
      // Not one core: a cylinder and a cone; a segment off the cylinder's axis; a box and an
      // oblique segment; a segment off the origin; a point off it.
      {"cylinder + cone", Shape::cylinder(0.5, 0.8).value(), Shape::cone(0.1, 0.1).value(), 2},
      {"cylinder + segment along x", Shape::cylinder(0.5, 0.8).value(),
       Shape::segment(-half_x, half_x).value(), 2},
      {"box + oblique segment", Shape::box(Vec3(1, 2, 3)).value(),
       Shape::segment(-oblique, oblique).value(), 2},
      {"cylinder + segment off the origin", Shape::cylinder(0.5, 0.8).value(),
       Shape::segment(Vec3(0, 0, 0.1), Vec3(0, 0, 0.5)).value(), 2},
      {"capsule + segment along x", Shape::capsule(0.2, 0.3).value(),
       Shape::segment(-half_x, half_x).value(), 2},
      {"box + point off the origin", Shape::box(Vec3(1, 2, 3)).value(),
       Shape::point(Vec3(0.1, 0, 0)).value(), 2},
  };
}

TEST(ShapeSum, FoldedSumsKeepTheSupportOfTheirParts) {
  std::mt19937_64 rng(20261130);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (const SumCase& c : sum_cases()) {
    SCOPED_TRACE(c.name);
    const Shape sum = Shape::sum(c.a, c.b).value();
    EXPECT_EQ(sum.cores().size(), c.cores);
    EXPECT_EQ(sum.core_radius(), c.a.core_radius() + c.b.core_radius());
    const double size = c.a.bounding_radius() + c.b.bounding_radius();
    EXPECT_LE(sum.bounding_radius(), size * (1 + 1e-15));
    std::vector<Vec3> directions = {Vec3::UnitX(),  Vec3::UnitY(), Vec3::UnitZ(),
                                    -Vec3::UnitZ(), Vec3(1, 1, 0), Vec3(0, -1, 1)};
    for (int i = 0; i < 200; ++i) directions.push_back(Vec3(unit(rng), unit(rng), unit(rng)));
    for (const Vec3& d : directions) {
      const double expected = support_value(c.a, d) + support_value(c.b, d);
      EXPECT_NEAR(support_value(sum, d), expected, 1e-15 * size * d.norm()) << d.transpose();
      // The bounding radius still bounds the support point.
      EXPECT_LE(sum.support_core(d).norm(),
                sum.bounding_radius() - sum.core_radius() + 1e-15 * size);
    }
  }
}

// A sphere's core is a Sphere of radius 0 (its centre) and a capsule's a Capsule of radius 0 (the
// segment along z), which take the typed shapes' paths; a sum keeps them, and segments along z
// that fold into a capsule's core, or into each other, make one.
TEST(ShapeSum, SpheresAndSegmentsAlongZKeepTheTypedCores) {
  const Vec3 half_z(0, 0, 0.4);
  const Shape capsule = Shape::capsule(0.2, 0.3).value();
  ASSERT_EQ(capsule.cores().size(), 1u);
  EXPECT_TRUE(std::holds_alternative<mink::Capsule>(capsule.cores()[0]));
  for (const Shape& sphere :
       {Shape::sphere(0.5).value(), Shape::ellipsoid(Vec3(0.5, 0.5, 0.5)).value(),
        Shape::sum(Shape::sphere(0.5).value(), Shape::sphere(0.25).value()).value(),
        Shape::point(Vec3::Zero()).value(), Shape::capsule(0.5, 0).value(),
        Shape::segment(Vec3::Zero(), Vec3::Zero()).value()}) {
    ASSERT_EQ(sphere.cores().size(), 1u);
    const auto* core = std::get_if<mink::Sphere>(&sphere.cores()[0]);
    ASSERT_NE(core, nullptr);
    EXPECT_EQ(core->radius, 0);
  }
  const Shape sums[] = {
      Shape::sum(capsule, Shape::capsule(0.1, 0.6).value()).value(),
      Shape::sum(Shape::segment(half_z, -half_z).value(), capsule).value(),
      Shape::sum(Shape::segment(half_z, -half_z).value(), Shape::segment(-half_z, half_z).value())
          .value(),
      Shape::segment(half_z, -half_z).value(),
      Shape::sum(Shape::point(Vec3::Zero()).value(), Shape::segment(-half_z, half_z).value())
          .value(),
      Shape::segment(-half_z, half_z).value().scaled(2).value()};
  const double half_heights[] = {0.9, 0.7, 0.8, 0.4, 0.4, 0.8};
  for (int i = 0; i < 6; ++i) {
    SCOPED_TRACE(i);
    ASSERT_EQ(sums[i].cores().size(), 1u);
    const auto* core = std::get_if<mink::Capsule>(&sums[i].cores()[0]);
    ASSERT_NE(core, nullptr);
    EXPECT_EQ(core->radius, 0);
    EXPECT_NEAR(core->half_height, half_heights[i], 1e-15);
  }
  // Points off the origin and segments off z keep their cores.
  EXPECT_TRUE(std::holds_alternative<mink::Point>(Shape::point(half_z).value().cores()[0]));
  const Vec3 tilted(0.1, 0, 0.4);
  EXPECT_TRUE(
      std::holds_alternative<mink::Segment>(Shape::segment(-tilted, tilted).value().cores()[0]));
  EXPECT_TRUE(
      std::holds_alternative<mink::Segment>(Shape::segment(-half_z, tilted).value().cores()[0]));
}

TEST(ShapeSum, LengthsThatWouldOverflowStaySeparateCores) {
  const Shape sum = Shape::sum(Shape::cylinder(1, 1e308).value(),
                               Shape::segment(Vec3(0, 0, -1.7e308), Vec3(0, 0, 1.7e308)).value())
                        .value();
  EXPECT_EQ(sum.cores().size(), 2u);
  const Shape capsules =
      Shape::sum(Shape::capsule(1, 1e308).value(),
                 Shape::segment(Vec3(0, 0, -1.7e308), Vec3(0, 0, 1.7e308)).value())
          .value();
  EXPECT_EQ(capsules.cores().size(), 2u);
}

/// A sum against a copy of itself at the same pose: the depth is the least width, 2 min h(n)
/// over n, known in closed form for these. As several cores the pair ran EPA on a circle of
/// equally good normals and ended at its cap (IterationLimit, error bounds to 3e-4).
TEST(ShapeSum, CoincidentSumsAnswerTheirWidth) {
  struct Coincident {
    const char* name;
    Shape sum;
    double width;
  };
  const Coincident cases[] = {
      {"cylinder + sphere",
       Shape::sum(Shape::cylinder(0.5336, 0.827).value(), Shape::sphere(0.2911).value()).value(),
       2 * (0.5336 + 0.2911)},
      {"capsule + thin cylinder",
       Shape::sum(Shape::capsule(0.5504, 0.6892).value(), Shape::cylinder(0.0012, 0.2323).value())
           .value(),
       2 * (0.5504 + 0.0012)},
      {"box + segment along z",
       Shape::sum(Shape::box(Vec3(0.9, 0.8, 0.1)).value(),
                  Shape::segment(Vec3(0, 0, -0.3), Vec3(0, 0, 0.3)).value())
           .value(),
       2 * (0.1 + 0.3)},
  };
  std::mt19937_64 rng(20261131);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (const Coincident& c : cases) {
    for (int i = 0; i < 20; ++i) {
      SCOPED_TRACE(std::string(c.name) + " #" + std::to_string(i));
      const Quat q = Quat(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
      const Vec3 t(unit(rng), unit(rng), unit(rng));
      const Pose pose = Pose::from(t, q);
      // The copy also 1e-12 of the size away along a random direction: the depth drops by no more.
      const Vec3 nudge = 1e-12 * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
      for (const Vec3& shift : {Vec3::Zero().eval(), nudge}) {
        const auto r = mink::contact(c.sum, pose, c.sum, Pose::from(t + shift, q));
        ASSERT_EQ(r.status, mink::Status::Intersecting) << r.error;
        const double size = 2 * c.sum.bounding_radius();
        EXPECT_NEAR(r.depth, c.width, 1e-12 * size + shift.norm());
        EXPECT_NEAR(r.normal.norm(), 1.0, 1e-15);
        EXPECT_LE((r.point_b - r.point_a + r.depth * r.normal).norm(), 1e-12 * size);
      }
    }
  }
}

}  // namespace
