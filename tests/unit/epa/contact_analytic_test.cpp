// contact() against closed-form penetration depths (tests/oracle/penetration.hpp): sphere-sphere,
// sphere-box, box-sphere, sphere-cylinder, capsule-capsule and box-box (separating axes) in random
// poses, mostly penetrating, with touching and separated cases mixed in; sphere-cone against the
// distance to the cone's triangle in the plane through its axis. The depth must match to
// 1e-9 of the size (1e-7 for the cylinder, a curved core), the normal must be optimal
// (h_{A-B}(normal) = depth) and, where it is unique, equal the oracle's; the points must be the
// deepest points along the normal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/mink.hpp"
#include "oracle/analytic.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/curved.hpp"
#include "oracle/penetration.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Vec3;
using oracle::Real;
using oracle::Rng;
using oracle::V3;
using oracle::widen;

/// A signed depth for a random case relative to `size`: mostly penetrating over nine decades,
/// some deep, some near touching of either sign, some apart.
double random_depth(Rng& rng, double size) {
  const double u = rng.uniform(0, 1);
  if (u < 0.45) return size * rng.log_uniform(1e-9, 1);
  if (u < 0.75) return size * rng.uniform(0, 1);
  if (u < 0.85) return size * rng.uniform(-1e-11, 1e-11);
  return -size * rng.log_uniform(1e-9, 0.5);
}

/// The normal equals the oracle's (tolerance 1e-9) when the oracle says it is unique by a clear
/// margin and the geometry does not make it ill-conditioned (`conditioning` > 1e-3 of the size).
void expect_normal(const oracle::Penetration& expected, const mink::ContactResult& got, double size,
                   double conditioning, double& worst) {
  if (!(expected.depth > 1e-9 * size) || !(expected.tie_margin > 1e-6 * size) ||
      !(conditioning > 1e-3 * size))
    return;
  const double err = (got.normal - expected.normal.cast<double>()).norm();
  worst = std::max(worst, err);
  EXPECT_LE(err, 1e-9) << "normal " << got.normal.transpose() << " oracle "
                       << expected.normal.cast<double>().transpose() << " (tolerance 1e-9)";
}

TEST(ContactAnalytic, SphereSphere) {
  const std::uint64_t base = 300000;
  const int n = oracle::sweep_count(2000);
  oracle::DepthWorst worst("contact sphere-sphere");
  double worst_normal = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const double ra = rng.log_uniform(0.01, 3), rb = rng.log_uniform(0.01, 3);
    const double size = ra + rb;
    const Pose pa = rng.pose(10);
    const double depth = std::min(random_depth(rng, size), 0.999 * size);
    const Pose pb = Pose::from(pa.translation + rng.unit() * (size - depth), rng.rotation());
    const mink::Sphere a{ra}, b{rb};
    const V3 ca = widen(pa.translation), cb = widen(pb.translation);
    const auto expected = oracle::sphere_sphere_penetration(ca, ra, cb, rb);
    const auto got = mink::contact(a, pa, b, pb);
    oracle::expect_contact_matches(expected.depth, oracle::sphere_support(ca, ra),
                                   oracle::sphere_support(cb, rb), got, size, pa.translation.norm(),
                                   worst);
    expect_normal(expected, got, size, double((cb - ca).norm()), worst_normal);
  }
  std::printf("[  worst   ] contact sphere-sphere: normal %.3g\n", worst_normal);
}

TEST(ContactAnalytic, SphereBox) {
  const std::uint64_t base = 310000;
  const int n = oracle::sweep_count(2000);
  oracle::DepthWorst worst("contact sphere-box");
  double worst_normal = 0;
  int inside = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Box box{
        Vec3(rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2))};
    const mink::Sphere sphere{rng.log_uniform(0.01, 2)};
    const double size = box.half_extents.norm() + sphere.radius;
    const Pose pb = rng.pose(5);
    // The centre in the box's frame, within the box grown by the radius on each axis (so mostly
    // penetrating; the corners of that region are apart).
    Vec3 local;
    for (int k = 0; k < 3; ++k) {
      const double reach = box.half_extents[k] + sphere.radius;
      local[k] = rng.uniform(-reach, reach);
    }
    if (rng.chance(0.1)) local[rng.integer(0, 2)] = 0;  // on a symmetry plane of the box
    const Pose pa = Pose::from(pb.apply(local), rng.rotation());
    const oracle::WorldBox wb{widen(box.half_extents), widen(pb.rotation), widen(pb.translation)};
    const V3 c = widen(pa.translation);
    const auto expected = oracle::sphere_box_penetration(c, sphere.radius, wb);
    const auto bp = oracle::point_box(wb, c);
    if (bp.signed_distance < 0) ++inside;
    const auto got = mink::contact(sphere, pa, box, pb);
    oracle::expect_contact_matches(expected.depth, oracle::sphere_support(c, sphere.radius),
                                   oracle::box_support(wb), got, size, pb.translation.norm(),
                                   worst);
    // Outside, the normal is ill-conditioned when the centre is near the box surface.
    const double conditioning = bp.signed_distance < 0 ? size : double(bp.signed_distance);
    expect_normal(expected, got, size, conditioning, worst_normal);
  }
  EXPECT_GT(inside, n / 10) << "the sweep should have centres inside the box";
  std::printf("[  worst   ] contact sphere-box: normal %.3g, %d centres inside\n", worst_normal,
              inside);
}

TEST(ContactAnalytic, BoxSphere) {
  // The same pairs with the roles swapped: the depth is the same and the normal flips.
  const std::uint64_t base = 320000;
  const int n = oracle::sweep_count(1000);
  oracle::DepthWorst worst("contact box-sphere");
  double worst_normal = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Box box{
        Vec3(rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2), rng.log_uniform(0.01, 2))};
    const mink::Sphere sphere{rng.log_uniform(0.01, 2)};
    const double size = box.half_extents.norm() + sphere.radius;
    const Pose pa = rng.pose(5);
    Vec3 local;
    for (int k = 0; k < 3; ++k) {
      const double reach = box.half_extents[k] + sphere.radius;
      local[k] = rng.uniform(-reach, reach);
    }
    const Pose pb = Pose::from(pa.apply(local), rng.rotation());
    const oracle::WorldBox wa{widen(box.half_extents), widen(pa.rotation), widen(pa.translation)};
    const V3 c = widen(pb.translation);
    auto expected = oracle::sphere_box_penetration(c, sphere.radius, wa);
    expected.normal = -expected.normal;
    const auto bp = oracle::point_box(wa, c);
    const auto got = mink::contact(box, pa, sphere, pb);
    oracle::expect_contact_matches(expected.depth, oracle::box_support(wa),
                                   oracle::sphere_support(c, sphere.radius), got, size,
                                   pa.translation.norm(), worst);
    const double conditioning = bp.signed_distance < 0 ? size : double(bp.signed_distance);
    expect_normal(expected, got, size, conditioning, worst_normal);
  }
  std::printf("[  worst   ] contact box-sphere: normal %.3g\n", worst_normal);
}

TEST(ContactAnalytic, SphereCylinder) {
  // A closed form (query/point_solid.hpp), inside the cylinder or not: exact to rounding, with
  // the tolerance of polytopes and no IterationLimit (EPA's, which this pair used to take, needed
  // 1e-7 and the cap). Half of the centres are inside the cylinder; the cylinder is A or B.
  const std::uint64_t base = 315000;
  const int n = oracle::sweep_count(2000);
  oracle::DepthWorst worst("contact sphere-cylinder");
  double worst_normal = 0;
  int inside = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Cylinder cyl{rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2)};
    const mink::Sphere sphere{rng.log_uniform(0.01, 2)};
    const double size = std::hypot(cyl.radius, cyl.half_height) + sphere.radius;
    const Pose pb = rng.pose(5);
    // The centre in the cylinder's frame: inside it, or within the radius of its surface.
    const bool in = rng.chance(0.5);
    const double reach_r = cyl.radius + (in ? 0.0 : sphere.radius);
    const double reach_z = cyl.half_height + (in ? 0.0 : sphere.radius);
    const double rho = reach_r * std::sqrt(rng.uniform(0, 1)), phi = rng.uniform(0, 2 * M_PI);
    const Vec3 local(rho * std::cos(phi), rho * std::sin(phi), rng.uniform(-reach_z, reach_z));
    const Pose pa = Pose::from(pb.apply(local), rng.rotation());
    const oracle::WorldCylinder wc{cyl.radius, cyl.half_height, widen(pb.rotation),
                                   widen(pb.translation)};
    const V3 c = widen(pa.translation);
    const auto expected = oracle::sphere_cylinder_penetration(c, sphere.radius, wc);
    const V3 lc = wc.rotation.transpose() * (c - wc.center);
    const bool centre_inside = std::hypot(double(lc.x()), double(lc.y())) < cyl.radius &&
                               std::abs(double(lc.z())) < cyl.half_height;
    if (centre_inside) ++inside;
    const bool swap = i % 2 == 1;
    auto got = swap ? mink::contact(cyl, pb, sphere, pa) : mink::contact(sphere, pa, cyl, pb);
    EXPECT_EQ(got.iterations, 0);
    if (swap) {  // as the sphere first: B moves along the normal
      std::swap(got.point_a, got.point_b);
      got.normal = -got.normal;
    }
    oracle::expect_contact_matches(expected.depth, oracle::sphere_support(c, sphere.radius),
                                   oracle::cylinder_support(wc), got, size, pb.translation.norm(),
                                   worst, oracle::kDepthTolerance, false);
    // Outside, the normal is ill-conditioned when the centre is near the surface.
    const double conditioning =
        centre_inside ? size : double(sphere.radius - expected.depth);  // the core distance
    if (expected.depth > 1e-6 * size) {
      // The normal is computed, not searched: exact to its conditioning.
      if (expected.tie_margin > 1e-3 * size && conditioning > 1e-3 * size) {
        const double err = (got.normal - expected.normal.cast<double>()).norm();
        worst_normal = std::max(worst_normal, err);
        EXPECT_LE(err, 1e-9) << "normal " << got.normal.transpose() << " oracle "
                             << expected.normal.cast<double>().transpose() << " (tolerance 1e-9)";
      }
    }
  }
  EXPECT_GT(inside, n / 4);
  std::printf("[  worst   ] contact sphere-cylinder: normal %.3g, %d centres inside\n",
              worst_normal, inside);
}

/// Signed distance (negative inside) from q, in the frame of a cone of base radius r at z = -h
/// and apex at z = h, to the cone, in long double: in the plane through the axis and q the cone
/// is the triangle (0, h), (-r, -h), (r, -h), and the distance is the least over its three edges
/// (as segments), negative when q is on the inner side of all three.
Real cone_signed_distance(Real r, Real h, const V3& q) {
  using P = Eigen::Matrix<Real, 2, 1>;
  const P p(std::hypot(q.x(), q.y()), q.z());
  const P corners[3] = {P(0, h), P(-r, -h), P(r, -h)};  // counter-clockwise
  Real least = std::numeric_limits<Real>::infinity();
  bool inside = true;
  for (int i = 0; i < 3; ++i) {
    const P& a = corners[i];
    const P& b = corners[(i + 1) % 3];
    const P ab = b - a, ap = p - a;
    const Real t = std::clamp(ap.dot(ab) / ab.squaredNorm(), Real(0), Real(1));
    least = std::min(least, (ap - t * ab).norm());
    inside = inside && ab.x() * ap.y() - ab.y() * ap.x() >= 0;
  }
  return inside ? -least : least;
}

TEST(ContactAnalytic, SphereCone) {
  // A closed form (query/point_solid.hpp) since stop 55, inside the cone or not, against the
  // distance to the cone's triangle in the plane through its axis (cone_signed_distance(), long
  // double); the normal's optimality and the points from the cone's support function in
  // tests/oracle/curved.hpp. Half of the centres are inside the cone (half of those within 1e-3
  // of its size of the axis, where every direction round the axis is nearly as good); the cone
  // is A or B.
  const std::uint64_t base = 555000;
  const int n = oracle::sweep_count(200, 40);
  oracle::DepthWorst worst("contact sphere-cone");
  int inside = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Cone cone{rng.log_uniform(0.05, 2), rng.log_uniform(0.05, 2)};
    const mink::Sphere sphere{rng.log_uniform(0.01, 1)};
    const double size = std::hypot(cone.radius, cone.half_height) + sphere.radius;
    const Pose pb = rng.pose(5);
    // The centre in the cone's frame: inside it (its radius at height z is r (h - z) / 2h), or
    // within the sphere's radius of its surface.
    const bool in = rng.chance(0.5);
    const double z = rng.uniform(-cone.half_height, cone.half_height);
    const double radius_at_z = cone.radius * (cone.half_height - z) / (2 * cone.half_height);
    const double rho =
        in ? radius_at_z * (rng.chance(0.5) ? rng.uniform(0, 1e-3) : rng.uniform(0, 1))
           : rng.uniform(0, radius_at_z + sphere.radius);
    const double phi = rng.uniform(0, 2 * M_PI);
    const double z_out = in ? z : z + rng.uniform(-sphere.radius, sphere.radius);
    const Vec3 local(rho * std::cos(phi), rho * std::sin(phi), z_out);
    const Pose pa = Pose::from(pb.apply(local), rng.rotation());
    if (in) ++inside;
    const oracle::CurvedShape oc{oracle::CurvedKind::Cone, cone.radius, cone.half_height,
                                 V3::Zero()};
    const oracle::RigidPose opb{widen(pb.rotation), widen(pb.translation)};
    const V3 centre_in_cone = opb.rotation.transpose() * (widen(pa.translation) - opb.translation);
    const Real expected =
        Real(sphere.radius) - cone_signed_distance(cone.radius, cone.half_height, centre_in_cone);
    const bool swap = i % 2 == 1;
    auto got = swap ? mink::contact(cone, pb, sphere, pa) : mink::contact(sphere, pa, cone, pb);
    EXPECT_EQ(got.iterations, 0) << "the closed form, no GJK or EPA";
    if (swap) {  // as the sphere first: B moves along the normal
      std::swap(got.point_a, got.point_b);
      got.normal = -got.normal;
    }
    oracle::expect_contact_matches(
        expected, oracle::sphere_support(widen(pa.translation), sphere.radius),
        [&](const V3& u) { return oracle::world_support(oc, opb, u); }, got, size,
        pb.translation.norm(), worst, oracle::kDepthTolerance, false);
  }
  EXPECT_GT(inside, n / 4);
}

TEST(ContactAnalytic, CapsuleCapsule) {
  const std::uint64_t base = 330000;
  const int n = oracle::sweep_count(3000);
  oracle::DepthWorst worst("contact capsule-capsule");
  double worst_normal = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Capsule a{rng.log_uniform(0.01, 1), rng.log_uniform(0.001, 3)};
    const mink::Capsule b{rng.log_uniform(0.01, 1), rng.log_uniform(0.001, 3)};
    const double size = a.radius + a.half_height + b.radius + b.half_height;
    const Pose pa = rng.pose(5);
    // A quarter of the cases have parallel or nearly parallel axes.
    mink::Quat qb = rng.rotation();
    const int kind = rng.integer(0, 7);
    const mink::Quat qa(pa.rotation);
    if (kind == 0) qb = qa;
    if (kind == 1) qb = qa * mink::Quat(Eigen::AngleAxisd(rng.log_uniform(1e-9, 1e-3), rng.unit()));
    // B's centre near a point of A's axis, within about the sum of the radii plus B's half height.
    const Vec3 along = pa.rotation.col(2) * rng.uniform(-a.half_height, a.half_height);
    const Vec3 offset = rng.in_ball(1.2 * (a.radius + b.radius) + 0.5 * b.half_height);
    const Pose pb = Pose::from(pa.translation + along + offset, qb);
    const auto wa =
        oracle::make_capsule(a.radius, a.half_height, widen(pa.rotation), widen(pa.translation));
    const auto wb =
        oracle::make_capsule(b.radius, b.half_height, widen(pb.rotation), widen(pb.translation));
    const auto expected = oracle::capsule_capsule_penetration(wa, wb);
    const auto got = mink::contact(a, pa, b, pb);
    oracle::expect_contact_matches(expected.depth, oracle::capsule_support(wa),
                                   oracle::capsule_support(wb), got, size, pa.translation.norm(),
                                   worst);
    const Real core = a.radius + b.radius - expected.depth;  // distance of the segments
    expect_normal(expected, got, size, double(core), worst_normal);
  }
  std::printf("[  worst   ] contact capsule-capsule: normal %.3g\n", worst_normal);
}

TEST(ContactAnalytic, BoxBox) {
  const std::uint64_t base = 340000;
  const int n = oracle::sweep_count(2000);
  oracle::DepthWorst worst("contact box-box");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const mink::Box a{
        Vec3(rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2))};
    const mink::Box b{
        Vec3(rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2), rng.log_uniform(0.02, 2))};
    const double size = a.half_extents.norm() + b.half_extents.norm();
    const Pose pa = rng.pose(5);
    // Some pairs share a rotation or an axis (parallel edges: the cross-product axes vanish).
    mink::Quat qb = rng.rotation();
    const int kind = rng.integer(0, 9);
    if (kind == 0) qb = mink::Quat(pa.rotation);
    if (kind == 1)
      qb = mink::Quat(pa.rotation) *
           mink::Quat(Eigen::AngleAxisd(rng.uniform(0, 6.3), Vec3::UnitZ()));
    const Pose pb = Pose::from(pa.translation + rng.in_ball(0.8 * size), qb);
    const oracle::WorldBox wa{widen(a.half_extents), widen(pa.rotation), widen(pa.translation)};
    const oracle::WorldBox wb{widen(b.half_extents), widen(pb.rotation), widen(pb.translation)};
    const auto expected = oracle::box_box_penetration(wa, wb);
    const auto got = mink::contact(a, pa, b, pb);
    // Optimality (h_{A-B}(normal) = depth) rather than equality with one of tied axes.
    oracle::expect_contact_matches(expected.depth, oracle::box_support(wa), oracle::box_support(wb),
                                   got, size, pa.translation.norm(), worst);
  }
}

/// Point cores (Point, Rounded<Sphere>) against box cores (Box, Rounded<Box>) in either order:
/// intersect(), distance() and contact() take the closed form (0 iterations) and agree with the
/// clamped point of the box (oracle::point_box) with the radii added; swapping A and B flips the
/// normal and keeps depth and distance. Boxes from 1e-6 to 1, and 1e6 from the origin; centres
/// inside, outside and on symmetry planes and the surface.
TEST(ContactAnalytic, PointCoreBoxClosedForm) {
  const std::uint64_t base = 330000;
  const int n = oracle::sweep_count(2000);
  oracle::DepthWorst worst("contact point core-box core");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const double scale = rng.chance(0.2) ? 1e-4 : 1.0;
    const mink::Box core{
        scale * Vec3(rng.log_uniform(0.01, 1), rng.log_uniform(0.01, 1), rng.log_uniform(0.01, 1))};
    const double box_margin = rng.chance(0.3) ? scale * rng.uniform(0, 0.2) : 0.0;
    const double point_radius = rng.chance(0.7) ? scale * rng.uniform(0, 0.5) : 0.0;
    const mink::Rounded<mink::Box> box{core, box_margin};
    const mink::Point point{scale * rng.in_ball(0.5)};
    const mink::Rounded<mink::Point> ball{point, point_radius};
    const double size = box.bounding_radius() + ball.bounding_radius();
    // Far from the origin only at scale 1: there the oracle's own support values carry 1e-13.
    const Pose pb = rng.pose(scale == 1.0 && rng.chance(0.2) ? 1e6 : 5);
    Vec3 local;
    for (int k = 0; k < 3; ++k) {
      const double reach = core.half_extents[k] + box_margin + point_radius;
      local[k] = rng.uniform(-1.2 * reach, 1.2 * reach);
    }
    if (rng.chance(0.1)) local[rng.integer(0, 2)] = 0;  // on a symmetry plane
    if (rng.chance(0.1)) {
      const int k = rng.integer(0, 2);
      local[k] = core.half_extents[k];  // on the core's surface, or its plane
    }
    // The point core lands at `local` in the box's frame.
    const mink::Quat turn = rng.rotation();
    const Pose pa = Pose::from(pb.apply(local) - turn * point.position, turn);
    const oracle::WorldBox wb{widen(core.half_extents), widen(pb.rotation), widen(pb.translation)};
    // The centre as mink sees it (the pose rounds it at 1e6 from the origin), in long double.
    const V3 centre = widen(pa.rotation) * widen(point.position) + widen(pa.translation);
    const auto clamped = oracle::point_box(wb, centre);
    const Real radii = Real(box_margin + point_radius);
    const Real depth = radii - clamped.signed_distance;
    const auto ball_support = oracle::sphere_support(centre, point_radius);
    const oracle::SupportFn box_support = [&](const V3& u) {
      return oracle::box_support(wb)(u) + Real(box_margin) * u.norm();
    };
    const auto ab = mink::contact(ball, pa, box, pb);
    const auto ba = mink::contact(box, pb, ball, pa);
    oracle::expect_contact_matches(depth, ball_support, box_support, ab, size,
                                   pb.translation.norm(), worst);
    oracle::expect_contact_matches(depth, box_support, ball_support, ba, size,
                                   pb.translation.norm(), worst);
    EXPECT_EQ(ab.iterations, 0);
    EXPECT_EQ(ba.iterations, 0);
    EXPECT_EQ(ab.intersect, ba.intersect);
    EXPECT_NEAR(ab.depth, ba.depth, 1e-12 * size);
    EXPECT_LE((ab.normal + ba.normal).norm(), 1e-12) << "swapping A and B must flip the normal";
    const auto d = mink::distance(ball, pa, box, pb);
    const auto in = mink::intersect(box, pb, ball, pa);
    EXPECT_EQ(d.iterations, 0);
    EXPECT_EQ(in.iterations, 0);
    const double tol = 1e-9 * size + 1e-15 * pb.translation.norm();
    if (depth < -tol) {
      EXPECT_EQ(d.status, mink::Status::Separated);
      EXPECT_NEAR(d.distance, double(-depth), tol);
      EXPECT_LE((d.point_b - d.point_a - d.distance * d.normal).norm(), tol);
      EXPECT_FALSE(in.intersect);
    } else if (depth > tol) {
      EXPECT_TRUE(d.intersect);
      EXPECT_TRUE(in.intersect);
    }
  }
}

/// A point core as deep below two or three faces (a cube's centre, a diagonal) leaves through one
/// of them: contact() says the normal was chosen. One face nearest: it was not.
TEST(ContactAnalytic, PointCoreBoxTies) {
  const mink::Box cube{Vec3(1, 1, 1)}, slab{Vec3(2, 1, 0.5)};
  const mink::Sphere ball{0.25};
  struct Case {
    const mink::Box* box;
    Vec3 centre;
    bool chosen;
    double depth;
  };
  const Case cases[] = {{&cube, Vec3(0, 0, 0), true, 1.25},
                        {&cube, Vec3(0.5, 0.5, 0.1), true, 0.75},
                        {&cube, Vec3(0.5, 0.4, 0.1), false, 0.75},
                        {&slab, Vec3(0.3, 0.2, 0), true, 0.75},
                        {&slab, Vec3(0.3, 0.2, 0.1), false, 0.65}};
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "centre " << c.centre.transpose());
    const auto got =
        mink::contact(ball, Pose::from_translation(c.centre), *c.box, Pose::identity());
    EXPECT_EQ(got.status, mink::Status::Intersecting);
    EXPECT_EQ(got.normal_chosen, c.chosen);
    EXPECT_DOUBLE_EQ(got.depth, c.depth);
    EXPECT_DOUBLE_EQ(got.normal.norm(), 1.0);
    EXPECT_LE((got.point_b - got.point_a + got.depth * got.normal).norm(), 1e-15);
  }
}

}  // namespace
