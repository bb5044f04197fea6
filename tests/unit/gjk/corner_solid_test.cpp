// A corner of a box against a cone or a cylinder, and a point against a cone, where the answer is
// known exactly by construction: e is a point of the solid's surface (a rim, the apex, a slant, a
// side or a cap) and n a normal of the solid there (in its cone of normals); the box is turned
// so that its support point along -n is a corner whose cone of normals holds -n with room to
// spare, and placed with that corner at e + gap n. The plane through e orthogonal to n has the
// solid on one side and the box `gap` away on the other, so the distance is the gap, the normal n
// and the closest points e and the corner.
//
// The hard case is a rim with n within 1e-7..1e-2 rad of the cap's or base's normal: h, the
// support function of A - B, has a kink at the cap's normal in every direction, and the minimum
// lies that close beside it. Newton's steps stopped short of it; before stop 55 the normal stayed
// 1.4e-6 rad off and the rim point 1.9e-8 of the size off (probe 52 on seed 55, s55_2525, a
// corner of a sum against a cone's base tilted 2e-5 rad).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/check.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Vec3;

enum class Feature { ConeRim, ConeApex, ConeSlant, CylinderRim, CylinderSide, CylinderCap };

const char* name_of(Feature f) {
  switch (f) {
    case Feature::ConeRim:
      return "cone rim";
    case Feature::ConeApex:
      return "cone apex";
    case Feature::ConeSlant:
      return "cone slant";
    case Feature::CylinderRim:
      return "cylinder rim";
    case Feature::CylinderSide:
      return "cylinder side";
    case Feature::CylinderCap:
      return "cylinder cap";
  }
  return "?";
}

struct CornerScene {
  bool cone = true;
  mink::Cone cone_shape;
  mink::Cylinder cylinder;
  mink::Box box;
  Pose pose_solid, pose_box;
  Vec3 on_solid, corner, normal;  // world; normal from the solid towards the box
  double gap = 0, size = 0;
  std::string note;
};

// An angle from the cap's (or base's) normal, most often within 1e-7..1e-2 rad of it, the case
// that Newton's steps cannot settle, else anywhere up to `widest`.
double tilt(oracle::Rng& rng, double widest) {
  return rng.chance(0.7) ? rng.log_uniform(1e-7, 1e-2) : rng.uniform(1e-3, widest - 1e-3);
}

// e and n in the solid's frame, for a solid of `radius` and `half_height`.
void pick_feature(oracle::Rng& rng, Feature f, double r, double h, Vec3& e, Vec3& n) {
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const Vec3 radial(std::cos(phi), std::sin(phi), 0);
  const Vec3 z = Vec3::UnitZ();
  // The cone's outward slant normal at azimuth phi, and its angle from the base's normal -z.
  const Vec3 slant_normal = (2 * h * radial + r * z).normalized();
  const double base_to_slant = oracle::angle(Vec3(-z), slant_normal);
  switch (f) {
    case Feature::ConeRim: {
      e = r * radial - h * z;
      const double a = tilt(rng, base_to_slant);
      n = std::sin(a) * radial - std::cos(a) * z;  // from -z towards the slant's normal
      break;
    }
    case Feature::ConeApex: {
      e = h * z;
      // Within the apex's cone of normals: up to the slant normal's angle from +z.
      const double a = rng.uniform(0, 0.95 * oracle::angle(z, slant_normal));
      n = std::sin(a) * radial + std::cos(a) * z;
      break;
    }
    case Feature::ConeSlant:
      e = h * z + rng.uniform(0.1, 0.9) * (r * radial - 2 * h * z);
      n = slant_normal;
      break;
    case Feature::CylinderRim: {
      const double side = rng.chance(0.5) ? 1 : -1;
      e = r * radial + side * h * z;
      const double a = rng.chance(0.8) ? tilt(rng, std::numbers::pi / 2)
                                       : std::numbers::pi / 2 - rng.log_uniform(1e-7, 1e-2);
      n = std::sin(a) * radial + side * std::cos(a) * z;
      break;
    }
    case Feature::CylinderSide:
      e = r * radial + rng.uniform(-0.9, 0.9) * h * z;
      n = radial;
      break;
    case Feature::CylinderCap:
      e = rng.uniform(0, 0.9) * r * radial + h * z;
      n = z;
      break;
  }
}

CornerScene make_scene(std::uint64_t seed, Feature f) {
  oracle::Rng rng(seed);
  CornerScene s;
  s.cone = f == Feature::ConeRim || f == Feature::ConeApex || f == Feature::ConeSlant;
  const double r = rng.uniform(0.2, 1.5), h = rng.uniform(0.2, 1.5);
  s.cone_shape = mink::Cone{r, h};
  s.cylinder = mink::Cylinder{r, h};
  const double far = rng.chance(0.2) ? 1e3 : 0;
  s.pose_solid = Pose::from(rng.in_ball(3) + Vec3::Constant(far), rng.rotation());
  Vec3 e, n;
  pick_feature(rng, f, r, h, e, n);
  s.on_solid = s.pose_solid.apply(e);
  s.normal = s.pose_solid.rotate(n);
  s.box = mink::Box{Vec3(rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1))};
  s.size = std::hypot(r, h) + s.box.half_extents.norm();
  s.gap = s.size * rng.log_uniform(1e-4, 0.3);
  // A rotation whose corner along -n is at least 0.05 rad inside that corner's cone of normals.
  mink::Quat q = rng.rotation();
  for (int attempt = 0; attempt < 1000; ++attempt) {
    if ((q.conjugate() * (-s.normal)).cwiseAbs().minCoeff() > 0.05) break;
    q = rng.rotation();
  }
  const Vec3 d = q.conjugate() * (-s.normal);
  const Vec3 corner_local(std::copysign(s.box.half_extents.x(), d.x()),
                          std::copysign(s.box.half_extents.y(), d.y()),
                          std::copysign(s.box.half_extents.z(), d.z()));
  s.corner = s.on_solid + s.gap * s.normal;
  s.pose_box = Pose::from(s.corner - q * corner_local, q);
  s.note = std::string("box corner against a ") + name_of(f) + ", gap/size " +
           std::to_string(s.gap / s.size) + ", " + oracle::seed_note(seed);
  return s;
}

// One query in one order: `box_first` puts the box first, which turns the normal round.
template <class Result>
void expect_exact(const CornerScene& s, const Result& r, bool box_first) {
  const double rounding = oracle::world_rounding(s.pose_solid.translation);
  const double tolerance = 1e-9 * s.size + rounding;
  const std::string order = box_first ? " (box first)" : " (box second)";
  ASSERT_EQ(r.status, mink::Status::Separated) << s.note << order;
  EXPECT_NEAR(r.distance, s.gap, tolerance) << s.note << order;
  EXPECT_LE(oracle::angle(r.normal, box_first ? Vec3(-s.normal) : s.normal),
            1e-9 + rounding / s.gap)
      << s.note << order;
  EXPECT_LE((r.point_a - (box_first ? s.corner : s.on_solid)).norm(), tolerance) << s.note << order;
  EXPECT_LE((r.point_b - (box_first ? s.on_solid : s.corner)).norm(), tolerance) << s.note << order;
}

template <class Solid>
void expect_all_queries(const CornerScene& s, const Solid& solid) {
  expect_exact(s, mink::distance(s.box, s.pose_box, solid, s.pose_solid), true);
  expect_exact(s, mink::distance(solid, s.pose_solid, s.box, s.pose_box), false);
  expect_exact(s, mink::contact(s.box, s.pose_box, solid, s.pose_solid), true);
  expect_exact(s, mink::contact(solid, s.pose_solid, s.box, s.pose_box), false);
}

void sweep(Feature f, std::uint64_t first_seed) {
  const int count = oracle::sweep_count(200, 60);
  for (int i = 0; i < count; ++i) {
    const CornerScene s = make_scene(first_seed + i, f);
    if (s.cone)
      expect_all_queries(s, s.cone_shape);
    else
      expect_all_queries(s, s.cylinder);
    if (::testing::Test::HasFailure()) break;  // one scene's messages, not hundreds
  }
}

TEST(CornerSolid, BoxCornerBesideAConeRimNearTheBaseNormal) {
  sweep(Feature::ConeRim, 55000);
}
TEST(CornerSolid, BoxCornerAgainstAConeApex) {
  sweep(Feature::ConeApex, 55300);
}
TEST(CornerSolid, BoxCornerAgainstAConeSlant) {
  sweep(Feature::ConeSlant, 55600);
}
TEST(CornerSolid, BoxCornerBesideACylinderRim) {
  sweep(Feature::CylinderRim, 55900);
}
TEST(CornerSolid, BoxCornerAgainstACylinderSide) {
  sweep(Feature::CylinderSide, 56200);
}
TEST(CornerSolid, BoxCornerAgainstACylinderCap) {
  sweep(Feature::CylinderCap, 56500);
}

// The same corner as a run-time Shape: a sum of a box and a polytope, whose corner is the sum of
// the two corners along -n, against a Shape cone (the dispatch of `mink query`).
TEST(CornerSolid, SumCornerBesideAConeRimAsShapes) {
  const int count = oracle::sweep_count(100, 30);
  for (int i = 0; i < count; ++i) {
    const CornerScene s = make_scene(56800 + i, Feature::ConeRim);
    // The box plus a small tetrahedron whose corner along -n is the origin, its other corners
    // 0.05 or more below it: the sum's corner along -n is the box's.
    oracle::Rng rng(1000000 + 56800 + i);
    const mink::Quat q(s.pose_box.rotation);
    const Vec3 d = q.conjugate() * (-s.normal);
    std::vector<Vec3> tetra = {Vec3::Zero()};
    for (int k = 0; k < 3; ++k) tetra.push_back(0.05 * rng.in_ball(1) - 0.1 * d);
    const auto sum = mink::Shape::sum(mink::Shape::box(s.box.half_extents).value(),
                                      mink::Shape::polytope(tetra).value());
    ASSERT_TRUE(sum.has_value()) << s.note;
    const mink::Shape cone =
        mink::Shape::cone(s.cone_shape.radius, s.cone_shape.half_height).value();
    expect_exact(s, mink::distance(*sum, s.pose_box, cone, s.pose_solid), true);
    expect_exact(s, mink::contact(cone, s.pose_solid, *sum, s.pose_box), false);
    if (::testing::Test::HasFailure()) break;
  }
}

// A box's corner beside an ellipsoid, the box's face turned 1e-9 to 1e-5 rad from facing it, so
// that the face's normal lies that close to the edge of the corner's cone of normals: Newton's
// steps stop beside the kinks there, the face's normal is no answer (the ellipsoid's point lies
// outside the face), and the corner test's disc of 1e-3 rad does not fit. Before stop 75 the
// points stayed Newton's, 8e-8 of the size off (curved probe c12_1155, a rounded box's face
// tilted 4e-7 rad, 2e-9 of the size from an ellipsoid). The box is plain or rounded, given as a
// Shape; e is the ellipsoid's support point along n, and the box's core corner lies at
// e + (gap + margin) n.
TEST(CornerSolid, BoxCornerOfANearlyFacingFaceBesideAnEllipsoid) {
  const int count = oracle::sweep_count(300, 100);
  for (int i = 0; i < count; ++i) {
    const std::uint64_t seed = 75100 + i;
    oracle::Rng rng(seed);
    const Vec3 radii(rng.uniform(0.05, 1), rng.uniform(0.05, 1), rng.uniform(0.05, 1));
    const double far = rng.chance(0.2) ? 1e3 : 0;
    const Pose pose_ellipsoid = Pose::from(rng.in_ball(3) + Vec3::Constant(far), rng.rotation());
    const Vec3 n = rng.in_ball(1).normalized();  // world, from the ellipsoid towards the box
    const Vec3 d = pose_ellipsoid.rotation.transpose() * n;
    const Vec3 scaled = radii.cwiseProduct(d);
    const Vec3 e = pose_ellipsoid.apply(Vec3(radii.cwiseProduct(scaled) / scaled.norm()));
    // In the box's frame, -n is the -y face's normal turned by t1 and t2 towards x and z.
    const Vec3 half(rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1));
    const double t1 = rng.log_uniform(1e-9, 1e-5) * (rng.chance(0.5) ? 1 : -1);
    const double t2 = rng.log_uniform(1e-9, 1e-5) * (rng.chance(0.5) ? 1 : -1);
    const Vec3 toward(t1, -1, t2);
    const mink::Quat spin(Eigen::AngleAxisd(rng.uniform(0, 2 * std::numbers::pi), -n));
    const mink::Quat q = spin * mink::Quat::FromTwoVectors(toward.normalized(), -n);
    const Vec3 corner(std::copysign(half.x(), t1), -half.y(), std::copysign(half.z(), t2));
    const double margin = rng.chance(0.5) ? rng.uniform(0.01, 0.1) : 0;
    const double size = radii.maxCoeff() + half.norm() + margin;
    const double gap = size * rng.log_uniform(1e-9, 1e-1);
    const Pose pose_box = Pose::from(Vec3(e + (gap + margin) * n - q * corner), q.normalized());
    const mink::Shape box = mink::Shape::box(half).value();
    const mink::Shape shape = margin > 0 ? mink::Shape::rounded(box, margin).value() : box;
    const mink::Shape ellipsoid = mink::Shape::ellipsoid(radii).value();
    const double rounding = oracle::world_rounding(pose_ellipsoid.translation);
    const double tolerance = 1e-9 * size + rounding;
    const std::string note = "face turned " + std::to_string(t1) + ", " + std::to_string(t2) +
                             " rad, gap/size " + std::to_string(gap / size) + ", margin " +
                             std::to_string(margin) + ", " + oracle::seed_note(seed);
    const auto check = [&](const auto& r, bool box_first) {
      const std::string order = box_first ? " (box first)" : " (box second)";
      ASSERT_EQ(r.status, mink::Status::Separated) << note << order;
      EXPECT_NEAR(r.distance, gap, tolerance) << note << order;
      // Points a tiny gap apart give their direction only to the rounding over the gap.
      EXPECT_LE(oracle::angle(r.normal, box_first ? Vec3(-n) : n), 1e-9 + rounding / gap)
          << note << order;
      const Vec3 on_box = e + gap * n;
      EXPECT_LE((r.point_a - (box_first ? on_box : e)).norm(), tolerance) << note << order;
      EXPECT_LE((r.point_b - (box_first ? e : on_box)).norm(), tolerance) << note << order;
    };
    check(mink::distance(ellipsoid, pose_ellipsoid, shape, pose_box), false);
    check(mink::distance(shape, pose_box, ellipsoid, pose_ellipsoid), true);
    check(mink::contact(ellipsoid, pose_ellipsoid, shape, pose_box), false);
    check(mink::contact(shape, pose_box, ellipsoid, pose_ellipsoid), true);
    if (::testing::Test::HasFailure()) break;
  }
}

// A point against a cone in closed form (query/point_solid.hpp): the same constructions with a
// sphere's centre in place of the corner. The sphere's radius is taken off the gap.
TEST(CornerSolid, SphereAgainstAConeInClosedForm) {
  const int count = oracle::sweep_count(300, 100);
  const Feature features[] = {Feature::ConeRim, Feature::ConeApex, Feature::ConeSlant};
  for (int i = 0; i < count; ++i) {
    const CornerScene s = make_scene(57000 + i, features[i % 3]);
    const double radius = 0.5 * s.gap;
    const mink::Sphere sphere{radius};
    const Pose pose_sphere = Pose::from(s.corner, mink::Quat(1, 0, 0, 0));
    const double rounding = oracle::world_rounding(s.pose_solid.translation);
    const double tolerance = 1e-9 * s.size + rounding;
    const auto r = mink::distance(s.cone_shape, s.pose_solid, sphere, pose_sphere);
    ASSERT_EQ(r.status, mink::Status::Separated) << s.note;
    EXPECT_EQ(r.iterations, 0) << s.note << ": the closed form, no GJK";
    EXPECT_NEAR(r.distance, s.gap - radius, tolerance) << s.note;
    EXPECT_LE(oracle::angle(r.normal, s.normal), 1e-9 + rounding / s.gap) << s.note;
    EXPECT_LE((r.point_a - s.on_solid).norm(), tolerance) << s.note;
    EXPECT_LE((r.point_b - (s.corner - radius * s.normal)).norm(), tolerance) << s.note;
    // contact() in the other order, and a sphere twice the gap in radius, which overlaps the
    // cone by the gap along the same normal.
    const auto c = mink::contact(sphere, pose_sphere, s.cone_shape, s.pose_solid);
    EXPECT_FALSE(c.intersect) << s.note;
    EXPECT_NEAR(c.distance, s.gap - radius, tolerance) << s.note;
    EXPECT_LE(oracle::angle(c.normal, Vec3(-s.normal)), 1e-9 + rounding / s.gap) << s.note;
    const mink::Sphere big{2 * s.gap};
    const auto deep = mink::contact(big, pose_sphere, s.cone_shape, s.pose_solid);
    EXPECT_TRUE(deep.intersect) << s.note;
    EXPECT_NEAR(deep.depth, s.gap, tolerance) << s.note;
    EXPECT_LE(oracle::angle(deep.normal, Vec3(-s.normal)), 1e-9 + rounding / s.gap) << s.note;
    EXPECT_LE((deep.point_b - s.on_solid).norm(), tolerance) << s.note;
    if (::testing::Test::HasFailure()) break;
  }
}

// A point on a cone's slant or a tiny gap above it (0 to 1e-8 of the size): the closed form's
// normal is the slant's own. From the gap to the foot it took the direction of the gap's
// rounding: 2.6e-7 rad off at 2.6e-9 of the size, and any direction at all for a point on the
// slant to rounding (0.6 rad off, its support value 1.1 of the size above the depth 0).
TEST(CornerSolid, PointOnOrJustAboveAConeSlant) {
  const int count = oracle::sweep_count(300, 100);
  for (int i = 0; i < count; ++i) {
    CornerScene s = make_scene(58000 + i, Feature::ConeSlant);
    s.gap = i % 4 == 0 ? 0 : s.size * oracle::Rng(58000 + i).log_uniform(1e-15, 1e-8);
    s.note = "point " + std::to_string(s.gap / s.size) + " of the size above a cone's slant, " +
             oracle::seed_note(58000 + i);
    const mink::Point point{Vec3::Zero()};
    const Pose pose_point = Pose::from(s.on_solid + s.gap * s.normal, mink::Quat(1, 0, 0, 0));
    const double rounding = oracle::world_rounding(s.pose_solid.translation);
    const double tolerance = 1e-9 * s.size + rounding;
    const auto c = mink::contact(s.cone_shape, s.pose_solid, point, pose_point);
    ASSERT_NE(c.status, mink::Status::InvalidInput) << s.note;
    EXPECT_NEAR(c.distance - c.depth, s.gap, tolerance) << s.note;
    EXPECT_LE(oracle::angle(c.normal, s.normal), 1e-9) << s.note;
    EXPECT_LE((c.point_a - s.on_solid).norm(), tolerance) << s.note;
    const auto d = mink::distance(point, pose_point, s.cone_shape, s.pose_solid);
    if (d.status == mink::Status::Separated) {
      EXPECT_LE(oracle::angle(d.normal, Vec3(-s.normal)), 1e-9) << s.note;
    }
    if (::testing::Test::HasFailure()) break;
  }
}

// A cone and spheres at 1e200, where r (h - z) and 2h rho overflow: the closed form works with
// their ratios to the cone's size. One sphere beyond the rim, one inside above the base.
TEST(CornerSolid, SphereAgainstAConeAt1e200) {
  const double scale = 1e200;
  const mink::Cone cone{scale, scale};
  const mink::Sphere outside_sphere{0.1 * scale}, inside_sphere{0.2 * scale};
  // In units of the scale: the centre (3, 0, 0) is nearest the rim (1, 0, -1), sqrt(5) away.
  const auto apart = mink::distance(cone, Pose::identity(), outside_sphere,
                                    Pose::from(Vec3(3 * scale, 0, 0), mink::Quat(1, 0, 0, 0)));
  ASSERT_EQ(apart.status, mink::Status::Separated) << apart.error;
  EXPECT_NEAR(apart.distance / scale, std::sqrt(5.0) - 0.1, 1e-14);
  EXPECT_LE(oracle::angle(apart.normal, Vec3(2, 0, 1).normalized()), 1e-14);
  // The centre (0, 0, -0.5) is 0.5 above the base and 1.5 / sqrt(5) inside the slant.
  const auto deep = mink::contact(cone, Pose::identity(), inside_sphere,
                                  Pose::from(Vec3(0, 0, -0.5 * scale), mink::Quat(1, 0, 0, 0)));
  ASSERT_EQ(deep.status, mink::Status::Intersecting) << deep.error;
  EXPECT_NEAR(deep.depth / scale, 0.7, 1e-14);
  EXPECT_LE(oracle::angle(deep.normal, Vec3(0, 0, -1)), 1e-14);
}

}  // namespace
