// A sphere against an ellipsoid takes the point core's closed form (query/point_solid.hpp): the
// ellipsoid's point nearest to the sphere's centre, inside or outside, by a one-dimensional root.
// Checked against the independent long-double search of tests/oracle/curved.hpp (the least
// support value of A - B over all directions), which knows nothing of that root. GJK and EPA,
// which these pairs took before, were within 1e-10 of the size, took 1 to 70 us, and answered a
// sphere deep inside a nearly round ellipsoid only at EPA's cap (`iteration_limit`).
// Ellipsoids against each other or a box take EPA, which stops once Newton's normal is proven by
// the cores' inner ball (epa/inner_ball.hpp): the ball, and round ellipsoids whose depth is a
// sphere pair's.
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

using mink::Pose;
using mink::Vec3;
using oracle::CurvedKind;
using oracle::CurvedShape;
using oracle::Real;
using oracle::RigidPose;
using oracle::V3;

TEST(ContactEllipsoid, SphereMatchesTheLeastSupportValue) {
  const int count = oracle::sweep_count(80, 24);
  double worst = 0, worst_normal = 0;
  int inside = 0;
  for (int i = 0; i < count; ++i) {
    const std::uint64_t seed = 20261129 + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    oracle::Rng rng(seed);
    Vec3 radii(rng.log_uniform(0.05, 2), rng.log_uniform(0.05, 2), rng.log_uniform(0.05, 2));
    switch (i % 6) {
      case 1:  // a spheroid within 1e-3 of a sphere: EPA's band of nearly equal normals
        radii = Vec3(1, 1, 1 - rng.uniform(1e-6, 1e-3));
        break;
      case 2:  // nearly round, all three different
        radii = Vec3(1, 1 - rng.uniform(0, 1e-3), 1 - rng.uniform(1e-3, 2e-3));
        break;
      case 3:  // flat
        radii.y() *= 1e-3;
        break;
      default:
        break;
    }
    const mink::Ellipsoid ellipsoid{radii};
    const mink::Sphere sphere{rng.log_uniform(0.01, 2)};
    const double size = radii.maxCoeff() + sphere.radius;
    // The centre in the ellipsoid's frame: anywhere within reach, near its centre, or at it;
    // some pairs 1e4 from the origin.
    Vec3 local = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 1.2 * size;
    if (i % 6 == 4) local *= 1e-3;
    if (i % 6 == 5) local.setZero();
    const Pose pb = rng.pose(i % 5 == 0 ? 1e4 : 5);
    const Pose pa = Pose::from(pb.apply(local), rng.rotation());
    CurvedShape ca, cb;
    ca.kind = CurvedKind::Sphere;
    ca.radius = sphere.radius;
    cb.kind = CurvedKind::Ellipsoid;
    cb.extents = radii.cast<Real>();
    const RigidPose wa = oracle::to_oracle_pose(pa), wb = oracle::to_oracle_pose(pb);
    const Real least = oracle::curved_depth(ca, wa, cb, wb).depth;  // minus the distance apart
    if ((local.cwiseQuotient(radii)).squaredNorm() < 1) ++inside;
    for (const bool swap : {false, true}) {
      SCOPED_TRACE(swap ? "ellipsoid first" : "sphere first");
      auto got = swap ? mink::contact(ellipsoid, pb, sphere, pa)
                      : mink::contact(sphere, pa, ellipsoid, pb);
      EXPECT_EQ(got.iterations, 0);  // the closed form, not GJK or EPA
      EXPECT_TRUE(got.status == mink::Status::Intersecting ||
                  got.status == mink::Status::Separated);
      if (swap) {  // as the sphere first: B moves along the normal
        std::swap(got.point_a, got.point_b);
        got.normal = -got.normal;
      }
      const double signed_depth = got.intersect ? got.depth : -got.distance;
      const double err = std::abs(signed_depth - double(least));
      worst = std::max(worst, err / size);
      EXPECT_LE(err, 1e-12 * size) << "mink " << signed_depth << " oracle " << double(least);
      // The normal's own support value is the answer (no direction does better: the oracle).
      const V3 n = got.normal.cast<Real>();
      const Real along = oracle::world_support(ca, wa, n) + oracle::world_support(cb, wb, -n);
      worst_normal = std::max(worst_normal, std::abs(double(along - least)) / size);
      EXPECT_NEAR(double(along), double(least), 1e-12 * size);
      EXPECT_NEAR(double(got.normal.norm()), 1.0, 1e-14);
      // The points are the shapes' extreme points along the normal, to the rounding of their
      // coordinates (some are 1e4 from the origin).
      const double points = 1e-12 * size + 1e-15 * pb.translation.norm();
      EXPECT_NEAR(double(got.point_a.cast<Real>().dot(n)), double(oracle::world_support(ca, wa, n)),
                  points);
      EXPECT_NEAR(double(-got.point_b.cast<Real>().dot(n)),
                  double(oracle::world_support(cb, wb, -n)), points);
      // distance() and intersect() agree with contact().
      const auto d = mink::distance(sphere, pa, ellipsoid, pb);
      EXPECT_EQ(d.intersect, got.intersect);
      if (!d.intersect) {
        EXPECT_NEAR(d.distance, got.distance, 1e-12 * size);
      }
      EXPECT_EQ(mink::intersect(ellipsoid, pb, sphere, pa).intersect, got.intersect);
    }
  }
  EXPECT_GT(inside, count / 4);
  std::printf("[  worst   ] sphere-ellipsoid: depth or distance %.3g, normal's support %.3g\n",
              worst, worst_normal);
}

TEST(ContactEllipsoid, CentreOnTheShortestAxesPlaneLeavesIt) {
  // A centre inside, on the plane z = 0 across the shortest axis and near the centre: the
  // nearest point lies off that plane, at +z or -z alike, either is the answer, and the normal is
  // marked as chosen. Ellipsoid (2, 1, 0.5), centre (0.3, 0.2, 0): by the Lagrange condition
  // x_i = r_i^2 p_i / (r_i^2 - 0.25) for x and y, and z from the surface's equation.
  const mink::Ellipsoid ellipsoid{Vec3(2, 1, 0.5)};
  const mink::Sphere sphere{0.1};
  const Vec3 centre(0.3, 0.2, 0);
  const double x = 4 * 0.3 / 3.75, y = 0.2 / 0.75;
  const double z = 0.5 * std::sqrt(1 - x * x / 4 - y * y);
  const double depth = std::sqrt((x - 0.3) * (x - 0.3) + (y - 0.2) * (y - 0.2) + z * z) + 0.1;
  const auto got =
      mink::contact(ellipsoid, Pose{}, sphere, Pose::from(centre, mink::Quat::Identity()));
  EXPECT_EQ(got.status, mink::Status::Intersecting);
  EXPECT_NEAR(got.depth, depth, 1e-15);
  EXPECT_TRUE(got.normal_chosen);
  EXPECT_NEAR(std::abs(got.point_a.z()), z, 1e-15);
  // At the centre: out along the shortest axis, chosen.
  const auto at_centre = mink::contact(sphere, Pose{}, ellipsoid, Pose{});
  EXPECT_EQ(at_centre.status, mink::Status::Intersecting);
  EXPECT_DOUBLE_EQ(at_centre.depth, 0.6);
  EXPECT_NEAR(std::abs(at_centre.normal.z()), 1.0, 1e-15);
  EXPECT_TRUE(at_centre.normal_chosen);
  // Off the plane by a little: the nearest point is unique, on the centre's side.
  const auto above = mink::contact(ellipsoid, Pose{}, sphere,
                                   Pose::from(Vec3(0.3, 0.2, 1e-9), mink::Quat::Identity()));
  EXPECT_FALSE(above.normal_chosen);
  EXPECT_GT(above.point_a.z(), 0);
  EXPECT_NEAR(above.depth, depth, 1e-9);
}

TEST(ContactEllipsoid, InnerBallFitsInside) {
  // The ball of InnerBall's radius touching an ellipsoid at a boundary point from inside lies in
  // it: points of the ball's sphere in 64 directions, in the ellipsoid's implicit form. And it is
  // the largest: 1 % larger, it pokes out beside the ends of the longest axis.
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> unit(-1, 1), extent(0.05, 2.0);
  for (int i = 0; i < 200; ++i) {
    const mink::Ellipsoid e{Vec3(extent(rng), extent(rng), extent(rng))};
    const double ball = mink::detail::InnerBall<mink::Ellipsoid>::radius(e);
    ASSERT_GT(ball, 0.0);
    const auto implicit = [&](const Vec3& p) { return p.cwiseQuotient(e.radii).squaredNorm(); };
    for (int j = 0; j < 20; ++j) {
      const Vec3 d = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
      const Vec3 touch = e.support_core(d);
      // The outward normal there: the gradient of the implicit form.
      const Vec3 n = touch.cwiseQuotient(e.radii.cwiseProduct(e.radii)).normalized();
      const Vec3 centre = touch - ball * n;
      for (int k = 0; k < 64; ++k) {
        const Vec3 u = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
        EXPECT_LE(implicit(centre + ball * u), 1 + 1e-12) << "ellipsoid " << i;
      }
    }
    // Near the tip, in the plane of the longest and shortest axes, where the surface curves most.
    int longest = 0, shortest = 0;
    e.radii.maxCoeff(&longest);
    e.radii.minCoeff(&shortest);
    if (longest == shortest) continue;  // a sphere: every ball of its radius fits exactly
    const double larger = 1.01 * ball;
    Vec3 centre = Vec3::Zero();
    centre[longest] = e.radii[longest] - larger;
    double most = 0;
    for (int k = 1; k <= 400; ++k) {
      Vec3 u = Vec3::Zero();
      u[longest] = std::cos(1e-3 * k);
      u[shortest] = std::sin(1e-3 * k);
      most = std::max(most, implicit(centre + larger * u));
    }
    EXPECT_GT(most, 1.0) << "ellipsoid " << i;
  }
}

TEST(ContactEllipsoid, RoundEllipsoidsOverlapLikeSpheres) {
  // Ellipsoids with three equal radii, turned at random, overlapping: EPA on their cores (not the
  // spheres' closed form), the depth rA + rB - |cB - cA| along the line of centres, the points
  // that far along it from each centre. Within the inner balls (every depth here), the ball
  // proves Newton's answer; both orders, and every fourth pair 1e3 from the origin.
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> unit(-1, 1), extent(0.2, 1.5), overlap(1e-4, 0.9);
  double worst = 0;
  for (int i = 0; i < 300; ++i) {
    const double ra = extent(rng), rb = extent(rng);
    const Vec3 offset = i % 4 == 0 ? Vec3(1e3, 5e2, -2e3) : Vec3::Zero();
    const Vec3 along = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    const double depth = overlap(rng) * std::min(ra, rb);
    const auto turn = [&] {
      return mink::Quat(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    };
    const Pose pa = Pose::from(offset, turn());
    const Pose pb = Pose::from(offset + (ra + rb - depth) * along, turn());
    const mink::Ellipsoid a{Vec3(ra, ra, ra)}, b{Vec3(rb, rb, rb)};
    const bool swap = i % 2 == 1;
    const auto r = swap ? mink::contact(b, pb, a, pa) : mink::contact(a, pa, b, pb);
    SCOPED_TRACE("pair " + std::to_string(i));
    ASSERT_EQ(r.status, mink::Status::Intersecting);
    const double size = ra + rb;
    const Vec3 normal = swap ? Vec3(-along) : along;
    const Vec3 on_a = offset + ra * along, on_b = pb.translation - rb * along;
    const double rounding = 8 * std::numeric_limits<double>::epsilon() * offset.norm();
    worst = std::max({worst, std::abs(r.depth - depth) / size, (r.normal - normal).norm()});
    EXPECT_LE(std::abs(r.depth - depth), 1e-13 * size + rounding);
    EXPECT_LE((r.normal - normal).norm(), 1e-13 + rounding / size);
    EXPECT_LE(((swap ? r.point_b : r.point_a) - on_a).norm(), 1e-12 * size + rounding);
    EXPECT_LE(((swap ? r.point_a : r.point_b) - on_b).norm(), 1e-12 * size + rounding);
  }
  std::printf("round ellipsoids: worst depth or normal %.2e\n", worst);
}

}  // namespace
