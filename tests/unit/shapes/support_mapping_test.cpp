// Support mappings of the curved shapes at any direction: a support point depends on the
// direction's orientation only, so d and s * d must give the same finite point for every scale s
// a double holds, and directions one component short of an axis (a component of 1e-316 beside 1)
// must not overflow. The answers are checked against the shapes' own equations, not against the
// code: the point lies on the surface and no sampled point of the shape reaches farther along d.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "mink/mink.hpp"

namespace mink {
namespace {

// Directions near the axes with a subnormal component, and ordinary ones.
std::vector<Vec3> awkward_directions() {
  std::vector<Vec3> out = {Vec3(3.3e-316, 0, 1),     Vec3(3.3e-316, 0, -1), Vec3(0, -5e-324, 1),
                           Vec3(1e-300, 1e-300, -1), Vec3(1, 0, 0),         Vec3(0, 1e-310, 0),
                           Vec3(1, -2, 3),           Vec3(-0.3, 0.1, -2)};
  std::mt19937 rng(20261126);
  std::normal_distribution<double> g;
  for (int i = 0; i < 40; ++i) out.emplace_back(g(rng), g(rng), g(rng));
  return out;
}

// The scales a direction may come at: GJK's v near touching is as short as the gap.
constexpr double kScales[] = {5e-324, 1e-310, 1e-200, 1e-160, 1, 1e150, 1e300};

// Points of the solid shape (its surface sampled finely), to check that none reaches farther.
std::vector<Vec3> samples(const std::function<Vec3(double, double)>& surface) {
  std::vector<Vec3> out;
  constexpr int kSteps = 60;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j < kSteps; ++j)
      out.push_back(surface(double(i) / kSteps, 2 * std::numbers::pi * j / kSteps));
  return out;
}

template <class Shape>
void expect_support(const Shape& shape, const std::vector<Vec3>& points,
                    const std::function<double(const Vec3&)>& off_surface) {
  for (const Vec3& d : awkward_directions()) {
    const Vec3 unit = d.normalized().allFinite() && d.squaredNorm() > 0 ? d.normalized() : d;
    const Vec3 reference = shape.support_core(unit);
    ASSERT_TRUE(reference.allFinite()) << d.transpose();
    EXPECT_LE(off_surface(reference), 1e-12) << d.transpose();
    // No point of the shape is farther along d (to rounding).
    double farthest = -std::numeric_limits<double>::infinity();
    for (const Vec3& p : points) farthest = std::max(farthest, p.dot(unit));
    EXPECT_GE(reference.dot(unit), farthest - 1e-12) << d.transpose();
    for (const double scale : kScales) {
      const Vec3 scaled = d * scale;
      if (scaled.isZero(0) || !scaled.allFinite()) continue;
      const Vec3 s = shape.support_core(scaled);
      ASSERT_TRUE(s.allFinite()) << d.transpose() << " * " << scale;
      // The direction as it is after rounding (5e-324 * d keeps one or two bits of each
      // component), brought back to unit length exactly by a power of two.
      const int exponent = std::ilogb(scaled.cwiseAbs().maxCoeff());
      const Vec3 exact(std::ldexp(scaled.x(), -exponent), std::ldexp(scaled.y(), -exponent),
                       std::ldexp(scaled.z(), -exponent));
      const Vec3 u = exact.normalized();
      // The same point, or one as far along d (a tie: every rim point of a cylinder along its
      // axis).
      EXPECT_NEAR(s.dot(u), shape.support_core(u).dot(u), 1e-12) << d.transpose() << " * " << scale;
      EXPECT_LE(off_surface(s), 1e-12) << d.transpose() << " * " << scale;
    }
  }
}

TEST(SupportMapping, CylinderAtAnyDirectionScale) {
  const Cylinder cylinder{3.40380859375, 0.75};
  const double r = cylinder.radius, h = cylinder.half_height;
  const auto points = samples([&](double t, double phi) {
    return Vec3(r * std::cos(phi), r * std::sin(phi), -h + 2 * h * t);
  });
  // Outside the solid by: the larger of the radial and the axial excess.
  expect_support(cylinder, points, [&](const Vec3& p) {
    return std::max(std::hypot(p.x(), p.y()) - r, std::abs(p.z()) - h);
  });
}

TEST(SupportMapping, ConeAtAnyDirectionScale) {
  const Cone cone{1.5, 0.5};
  const double r = cone.radius, h = cone.half_height;
  std::vector<Vec3> points = samples([&](double t, double phi) {
    return Vec3(t * r * std::cos(phi), t * r * std::sin(phi), h - 2 * h * t);
  });
  // The cone's support points are its apex and the points of its base (the whole base along -z,
  // its rim otherwise): off by the distance to them.
  expect_support(cone, points, [&](const Vec3& p) {
    const double apex = (p - Vec3(0, 0, h)).norm();
    const double base = std::max(std::abs(p.z() + h), std::hypot(p.x(), p.y()) - r);
    return std::min(apex, base);
  });
}

TEST(SupportMapping, EllipsoidAtAnyDirectionScale) {
  const Ellipsoid ellipsoid{Vec3(2.0, 0.5, 1.25)};
  const Vec3 radii = ellipsoid.radii;
  const auto points = samples([&](double t, double phi) {
    const double theta = std::numbers::pi * t;
    return Vec3(radii.x() * std::sin(theta) * std::cos(phi),
                radii.y() * std::sin(theta) * std::sin(phi), radii.z() * std::cos(theta));
  });
  expect_support(ellipsoid, points,
                 [&](const Vec3& p) { return std::abs(p.cwiseQuotient(radii).norm() - 1); });
}

TEST(SupportMapping, SphereTouchingAFlatCylinderOffItsAxisBy1e300) {
  // Found by fuzzing (fuzz/corpus/queries/sphere-cylinder-subnormal-rho.bin): GJK's direction
  // was (3e-316, 0, 1), the cylinder's radius / rho overflowed and its support point was NaN;
  // contact() then answered iteration_limit with the normal upside down.
  const auto sphere = Shape::sphere(1).value();
  const double h = 7.4505805969238281e-09;
  const auto disk = Shape::cylinder(3.40380859375, h).value();
  for (const double offset : {0.0, 1e-300, 5e-324, 1e-10}) {
    Pose pose_b;
    pose_b.translation = Vec3(offset, -1, -1);
    const auto c = contact(sphere, Pose{}, disk, pose_b);
    ASSERT_EQ(c.status, Status::Intersecting) << offset;
    // The sphere's bottom (z = -1) sinks h into the disk's top face (z = -1 + h).
    EXPECT_NEAR(c.depth, h, 1e-15) << offset;
    EXPECT_NEAR((c.normal - Vec3(0, 0, -1)).norm(), 0, 1e-12) << offset;
    EXPECT_NEAR((c.point_b - c.point_a + c.depth * c.normal).norm(), 0, 1e-15) << offset;
    const auto d = distance(sphere, Pose{}, disk, pose_b);
    EXPECT_EQ(d.status, Status::Intersecting) << offset;
  }
}

}  // namespace
}  // namespace mink
