// An ellipsoid against a cone's slant or a cylinder's rim, where the answer is known exactly by
// construction: the ellipsoid is placed so that its support point along -n lies `gap` beyond a
// point e of the feature along n, with n the feature's normal there. The plane through e
// orthogonal to n has the cone or cylinder on one side and the ellipsoid `gap` away on the
// other, so the distance is the gap, the normal n and the closest points e and e + gap n (the
// ellipsoid is strictly convex, and the cone's or cylinder's support along n is e's feature).
//
// - A cone's slant: its support along n is the segment from the apex to a rim point, and the
//   support function of A - B has a kink along the small circle of such normals; the minimum
//   lies on it, sharp across it and curved along it. Touching to 1e-13 of the size, no Newton
//   step ran before stop 54 (the normal was taken to be ill-conditioned at touching): GJK's
//   normal stayed 1.6e-6 rad off and the points 5e-7 of the size off (probe 52, s11_525).
// - A cylinder's rim seen from close to its axis: its support point moves round the rim r / sin
//   of the angle to the axis as fast as the direction turns, faster than a core of the size's
//   curvature, and Newton's step took it for a kink and stopped at EPA's 1e-5 rad (s11_342).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "mink/mink.hpp"
#include "oracle/check.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Shape;
using mink::Vec3;

struct KinkScene {
  Shape solid, ellipsoid;
  Pose pose_solid, pose_ellipsoid;
  Vec3 contact;    // e: on the cone or cylinder, world frame
  Vec3 normal;     // n: from the cone or cylinder towards the ellipsoid
  double gap = 0;  // < 0: the shapes overlap by -gap
  double size = 0;
  std::string note;
};

// Places an ellipsoid of random radii and orientation with its support point along -normal at
// contact + gap * normal.
void place_ellipsoid(oracle::Rng& rng, KinkScene& s) {
  const Vec3 radii(rng.uniform(0.05, 1), rng.uniform(0.05, 1), rng.uniform(0.05, 1));
  s.ellipsoid = Shape::ellipsoid(radii).value();
  const mink::Quat q = rng.rotation();
  const Vec3 d = q.conjugate() * (-s.normal);
  const Vec3 scaled = radii.cwiseProduct(d);
  const Vec3 local_support = radii.cwiseProduct(scaled) / scaled.norm();
  s.size += radii.maxCoeff();
  const Vec3 target = s.contact + s.gap * s.normal;
  s.pose_ellipsoid = Pose::from(target - q * local_support, q);
}

// A cone's or cylinder's size (random), its pose (sometimes 1e3 from the origin), and e and n
// from its frame to the world.
struct Solid {
  double radius, half_height;
  Pose pose;
};

Solid random_solid(oracle::Rng& rng) {
  Solid solid{rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5), Pose::identity()};
  const double far = rng.chance(0.2) ? 1e3 : 0;
  solid.pose = Pose::from(rng.in_ball(3) + Vec3::Constant(far), rng.rotation());
  return solid;
}

void set_contact(const Solid& solid, const Vec3& e, const Vec3& n, KinkScene& s) {
  s.pose_solid = solid.pose;
  s.contact = solid.pose.apply(e);
  s.normal = solid.pose.rotate(n);
  s.size = std::hypot(solid.radius, solid.half_height);
}

KinkScene slant_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  KinkScene s;
  const Solid solid = random_solid(rng);
  const double radius = solid.radius, half_height = solid.half_height;
  s.solid = Shape::cone(radius, half_height).value();
  // The slant at azimuth phi runs from the apex (0, 0, h) to the rim point (r cos, r sin, -h);
  // (2h cos, 2h sin, r) is orthogonal to it, outwards.
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const Vec3 apex(0, 0, half_height);
  const Vec3 rim(radius * std::cos(phi), radius * std::sin(phi), -half_height);
  const Vec3 e = apex + rng.uniform(0.2, 0.8) * (rim - apex);
  const Vec3 n =
      Vec3(2 * half_height * std::cos(phi), 2 * half_height * std::sin(phi), radius).normalized();
  set_contact(solid, e, n, s);
  s.gap = s.size * rng.uniform(-1e-13, 1e-13);
  place_ellipsoid(rng, s);
  s.note =
      "cone slant, gap/size = " + std::to_string(s.gap / s.size) + ", " + oracle::seed_note(seed);
  return s;
}

KinkScene rim_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  KinkScene s;
  const Solid solid = random_solid(rng);
  const double radius = solid.radius, half_height = solid.half_height;
  s.solid = Shape::cylinder(radius, half_height).value();
  // The top rim at azimuth phi; a normal tilted from the axis towards it by alpha is in the
  // rim's cone of normals, and its support point is that rim point alone.
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const double alpha = rng.log_uniform(0.005, 0.3);
  const Vec3 e(radius * std::cos(phi), radius * std::sin(phi), half_height);
  const Vec3 n(std::sin(alpha) * std::cos(phi), std::sin(alpha) * std::sin(phi), std::cos(alpha));
  set_contact(solid, e, n, s);
  s.gap = s.size * rng.log_uniform(1e-6, 1e-1);
  place_ellipsoid(rng, s);
  s.note = "cylinder rim, " + std::to_string(alpha) +
           " rad from the axis, gap/size = " + std::to_string(s.gap / s.size) + ", " +
           oracle::seed_note(seed);
  return s;
}

double kink_far_rounding(const KinkScene& s) {
  return oracle::world_rounding(s.pose_solid.translation);
}

// One argument order: `flip` puts the ellipsoid first, which turns the normal round. Touching
// pairs answer both points at the contact.
template <class Result>
void expect_exact(const KinkScene& s, const Result& r, bool flip, bool touching) {
  const double tolerance = 1e-9 * s.size + kink_far_rounding(s);
  const std::string order = flip ? " (ellipsoid first)" : " (ellipsoid second)";
  const Vec3 on_solid = s.contact;
  const Vec3 on_ellipsoid = touching ? s.contact : Vec3(s.contact + s.gap * s.normal);
  if (touching) {
    ASSERT_TRUE(r.intersect) << s.note << order;
  } else {
    ASSERT_EQ(r.status, mink::Status::Separated) << s.note << order;
    EXPECT_NEAR(r.distance, s.gap, tolerance) << s.note << order;
  }
  EXPECT_LE(oracle::angle(r.normal, flip ? Vec3(-s.normal) : s.normal), 1e-9) << s.note << order;
  EXPECT_LE((r.point_a - (flip ? on_ellipsoid : on_solid)).norm(), tolerance) << s.note << order;
  EXPECT_LE((r.point_b - (flip ? on_solid : on_ellipsoid)).norm(), tolerance) << s.note << order;
}

TEST(CurvedKink, EllipsoidTouchingAConeSlant) {
  const int count = oracle::sweep_count(300, 100);
  for (int i = 0; i < count; ++i) {
    const KinkScene s = slant_scene(54100 + i);
    expect_exact(s, mink::contact(s.solid, s.pose_solid, s.ellipsoid, s.pose_ellipsoid), false,
                 true);
    expect_exact(s, mink::contact(s.ellipsoid, s.pose_ellipsoid, s.solid, s.pose_solid), true,
                 true);
    if (::testing::Test::HasFailure()) break;  // one scene's messages, not hundreds
  }
}

TEST(CurvedKink, EllipsoidBesideACylinderRimNearItsAxis) {
  const int count = oracle::sweep_count(300, 100);
  for (int i = 0; i < count; ++i) {
    const KinkScene s = rim_scene(54500 + i);
    expect_exact(s, mink::distance(s.solid, s.pose_solid, s.ellipsoid, s.pose_ellipsoid), false,
                 false);
    expect_exact(s, mink::distance(s.ellipsoid, s.pose_ellipsoid, s.solid, s.pose_solid), true,
                 false);
    expect_exact(s, mink::contact(s.solid, s.pose_solid, s.ellipsoid, s.pose_ellipsoid), false,
                 false);
    expect_exact(s, mink::contact(s.ellipsoid, s.pose_ellipsoid, s.solid, s.pose_solid), true,
                 false);
    if (::testing::Test::HasFailure()) break;
  }
}

}  // namespace
