// Balls inside cylinders and boxes (epa/inner_ball.hpp), which let EPA stop once Newton's normal
// of a cylinder's side is proven. Checked two ways, each against its own definition:
//   - every ball a core offers lies inside it (points of its sphere against the core's
//     inequalities), and near a point of a cylinder's side well away from the caps one of them
//     touches there;
//   - crossing cylinders and a box's edge across a cylinder's side, built with an analytic depth
//     (the side sunk delta into the other shape, both long enough that no other direction is
//     shorter), moved by a random rigid motion: depth, normal and points against the
//     construction, both orders, typed and run-time shapes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "mink/mink.hpp"

namespace inner_ball_test {

using mink::Pose;
using mink::Vec3;

Vec3 ball_test_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  return Vec3(normal(rng), normal(rng), normal(rng)).normalized();
}

template <class Core, class Inside>
void expect_balls_inside(const Core& core, const Vec3& witness, const Vec3& normal,
                         const Inside& inside, std::mt19937_64& rng, int& offered) {
  mink::detail::CoreBall<double> balls[mink::detail::kMaxCoreBalls];
  const int count = mink::detail::InnerBall<Core>::balls(core, witness, witness, normal, balls);
  offered += count;
  for (int i = 0; i < count; ++i) {
    ASSERT_GT(balls[i].radius, 0.0);
    for (int k = 0; k < 64; ++k)
      EXPECT_TRUE(inside(Vec3(balls[i].centre + balls[i].radius * ball_test_unit(rng))))
          << "ball " << i << " of radius " << balls[i].radius << " pokes out";
  }
}

TEST(ContactInnerBall, CylinderAndBoxBallsLieInside) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> unit(-1, 1), extent(0.01, 2.0);
  const double slack = 1e-12;
  int offered = 0, touching = 0, sides = 0;
  for (int i = 0; i < 300; ++i) {
    const mink::Cylinder cylinder{extent(rng), extent(rng)};
    const double r = cylinder.radius, h = cylinder.half_height;
    const auto in_cylinder = [&](const Vec3& p) {
      return std::hypot(p.x(), p.y()) <= r * (1 + slack) && std::abs(p.z()) <= h * (1 + slack);
    };
    const double angle = 3.14159 * unit(rng);
    const Vec3 radial(std::cos(angle), std::sin(angle), 0);
    // A point of the side with its normal; of a cap; of a rim with any normal between the two.
    const double z = h * unit(rng);
    expect_balls_inside(cylinder, Vec3(r * radial + Vec3(0, 0, z)), radial, in_cylinder, rng,
                        offered);
    const Vec3 on_cap = std::abs(unit(rng)) * r * radial + Vec3(0, 0, h);
    expect_balls_inside(cylinder, on_cap, Vec3::UnitZ(), in_cylinder, rng, offered);
    const double mix = std::abs(unit(rng));
    expect_balls_inside(cylinder, Vec3(r * radial + Vec3(0, 0, -h)),
                        Vec3((mix * radial - (1 - mix) * Vec3::UnitZ()).normalized()), in_cylinder,
                        rng, offered);
    // Away from the caps by the radius, a ball touches the side where asked.
    if (h - std::abs(z) >= r) {
      ++sides;
      mink::detail::CoreBall<double> balls[mink::detail::kMaxCoreBalls];
      const Vec3 witness = r * radial + Vec3(0, 0, z);
      const int count =
          mink::detail::InnerBall<mink::Cylinder>::balls(cylinder, witness, witness, radial, balls);
      for (int k = 0; k < count; ++k)
        if (std::abs(balls[k].radius - (witness - balls[k].centre).norm()) <= 1e-12 * (r + h)) {
          ++touching;
          break;
        }
    }

    const mink::Box box{Vec3(extent(rng), extent(rng), extent(rng))};
    const auto in_box = [&](const Vec3& p) {
      return (p.cwiseAbs().array() <= box.half_extents.array() * (1 + slack)).all();
    };
    const int face = i % 3;
    Vec3 witness = box.half_extents.cwiseProduct(Vec3(unit(rng), unit(rng), unit(rng)));
    witness[face] = box.half_extents[face];
    expect_balls_inside(box, witness, Vec3::Unit(face), in_box, rng, offered);
    // A corner with any normal of its cone.
    const Vec3 corner = box.half_extents;
    expect_balls_inside(
        box, corner,
        Vec3(Vec3(std::abs(unit(rng)), std::abs(unit(rng)), std::abs(unit(rng)) + 1e-3)
                 .normalized()),
        in_box, rng, offered);
  }
  EXPECT_GT(offered, 1000);
  EXPECT_EQ(touching, sides);
  EXPECT_GT(sides, 20);
}

struct BuiltCrossing {
  Pose pose_a, pose_b;
  Vec3 normal, point_a, point_b;  // world frame; the normal from A to B
  double depth, size;
};

// A rigid motion of the whole construction (given in a local frame where the normal is +y and
// A's deepest point at y = top).
BuiltCrossing crossing_moved(std::mt19937_64& rng, const Pose& local_a, const Pose& local_b,
                             double top, double depth, double size, const Vec3& offset) {
  std::normal_distribution<double> normal;
  const mink::Quat turn =
      mink::Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
  BuiltCrossing b;
  b.pose_a = Pose::from(turn * local_a.translation + offset, turn * mink::Quat(local_a.rotation));
  b.pose_b = Pose::from(turn * local_b.translation + offset, turn * mink::Quat(local_b.rotation));
  b.normal = turn * Vec3::UnitY();
  b.point_a = turn * Vec3(0, top, 0) + offset;
  b.point_b = turn * Vec3(0, top - depth, 0) + offset;
  b.depth = depth;
  b.size = size;
  return b;
}

template <class A, class B>
void expect_crossing_contact(const A& a, const B& b, const BuiltCrossing& built, bool swap,
                             double& worst_depth, double& worst_normal, double& worst_point) {
  const mink::ContactResult r = swap ? mink::contact(b, built.pose_b, a, built.pose_a)
                                     : mink::contact(a, built.pose_a, b, built.pose_b);
  ASSERT_EQ(r.status, mink::Status::Intersecting);
  const double sign = swap ? -1 : 1;
  const Vec3 point_a = swap ? r.point_b : r.point_a, point_b = swap ? r.point_a : r.point_b;
  const double depth_error = std::abs(r.depth - built.depth) / built.size;
  const double normal_error = (sign * r.normal - built.normal).norm();
  const double point_error =
      std::max((point_a - built.point_a).norm(), (point_b - built.point_b).norm()) / built.size;
  worst_depth = std::max(worst_depth, depth_error);
  worst_normal = std::max(worst_normal, normal_error);
  worst_point = std::max(worst_point, point_error);
  EXPECT_LE(depth_error, 1e-12) << "depth " << r.depth << " built " << built.depth;
  EXPECT_LE(normal_error, 1e-7);
  EXPECT_LE(point_error, 1e-9);
}

TEST(ContactInnerBall, CylinderSidesPenetratingAreExact) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> radius(0.2, 1.0), exponent(-6, -0.7), sideways(-1, 1);
  double worst_depth = 0, worst_normal = 0, worst_point = 0;
  for (int i = 0; i < 240; ++i) {
    const bool swap = i % 2 == 1, typed = i % 4 < 2, box_pair = i % 8 >= 4;
    const Vec3 offset = i % 3 == 0 ? Vec3(1e3, -5e2, 2e3) : Vec3::Zero();
    const double ra = radius(rng), rb = radius(rng);
    // Long cylinders (half height 4 radii past the crossing): no shorter way out along an axis.
    const mink::Cylinder cylinder{ra, 4 * (ra + rb)};
    const double delta = std::pow(10.0, exponent(rng)) * std::min(ra, rb);
    // A: the cylinder along z; its side at y = ra faces B. The crossing point slides along A's
    // axis by up to a radius.
    const double slide = ra * sideways(rng);
    const Pose local_a = Pose::from_translation(Vec3(0, 0, slide));
    if (box_pair) {
      // B: a box turned 45 degrees about x, its lowest edge along x at y = ra - delta.
      const double s = rb;
      const mink::Box box{Vec3(4 * (ra + rb), s, s)};
      const Pose local_b =
          Pose::from(Vec3(0, ra - delta + s * std::sqrt(2.0), 0),
                     mink::Quat(Eigen::AngleAxisd(std::acos(-1.0) / 4, Vec3::UnitX())));
      const BuiltCrossing built =
          crossing_moved(rng, local_a, local_b, ra, delta,
                         cylinder.bounding_radius() + box.bounding_radius(), offset);
      if (typed)
        expect_crossing_contact(cylinder, box, built, swap, worst_depth, worst_normal, worst_point);
      else
        expect_crossing_contact(mink::Shape::cylinder(ra, cylinder.half_height).value(),
                                mink::Shape::box(box.half_extents).value(), built, swap,
                                worst_depth, worst_normal, worst_point);
    } else {
      // B: a cylinder along x, its axis at y = ra + rb - delta.
      const mink::Cylinder other{rb, 4 * (ra + rb)};
      const Pose local_b =
          Pose::from(Vec3(0, ra + rb - delta, 0),
                     mink::Quat(Eigen::AngleAxisd(std::acos(-1.0) / 2, Vec3::UnitY())));
      const BuiltCrossing built =
          crossing_moved(rng, local_a, local_b, ra, delta,
                         cylinder.bounding_radius() + other.bounding_radius(), offset);
      if (typed)
        expect_crossing_contact(cylinder, other, built, swap, worst_depth, worst_normal,
                                worst_point);
      else
        expect_crossing_contact(mink::Shape::cylinder(ra, cylinder.half_height).value(),
                                mink::Shape::cylinder(rb, other.half_height).value(), built, swap,
                                worst_depth, worst_normal, worst_point);
    }
  }
  std::printf("cylinder sides: worst depth %.2e, normal %.2e, point %.2e of the size\n",
              worst_depth, worst_normal, worst_point);
}

TEST(ContactInnerBall, BallsProveASideButNotARim) {
  // The certificate itself (inner_ball_proves_depth()) at the exact normal and witness pair: a
  // cylinder along z (A) against a second cylinder along x or a box's edge along x (B), sunk
  // delta into A's side at the point (0, ra, 0), normal +y. The balls about the two sides (or
  // about A's side and B's edge as a point) prove delta to rounding. The same box's edge against
  // A's rim, where no ball touches either core, is not proven.
  using mink::detail::CoreDifference;
  using mink::detail::SupportMinimum;
  const double ra = 0.5, rb = 0.3, half = 3.0;
  const mink::Cylinder a{ra, half};
  const mink::Cylinder b{rb, half};
  const mink::Box box{Vec3(half, rb, rb)};
  const mink::Mat3 along_x =
      Eigen::AngleAxisd(std::acos(-1.0) / 2, Vec3::UnitY()).toRotationMatrix();
  const mink::Mat3 edge_down =
      Eigen::AngleAxisd(std::acos(-1.0) / 4, Vec3::UnitX()).toRotationMatrix();
  const mink::Tolerances tol;
  for (const double delta : {1e-9, 1e-6, 1e-3, 0.1}) {
    SupportMinimum<double> least;
    least.normal = Vec3::UnitY();
    least.value = delta;
    least.vertex.a = Vec3(0, ra, 0);
    least.vertex.b = Vec3(0, ra - delta, 0);
    least.vertex.w = least.vertex.a - least.vertex.b;
    least.vertex.dir = least.normal;
    const double size = a.bounding_radius() + b.bounding_radius();
    int iterations = 0;
    double lower = 0;
    const CoreDifference<mink::Cylinder, mink::Cylinder> crossing{a, b, along_x,
                                                                  Vec3(0, ra + rb - delta, 0)};
    SupportMinimum<double> on_sides = least;
    EXPECT_TRUE(mink::detail::inner_ball_proves_depth(
        crossing, tol.relative * size, tol.relative_depth * size, iterations, on_sides, lower))
        << "delta " << delta;
    EXPECT_NEAR(lower, delta, 1e-14);
    EXPECT_NEAR(on_sides.value, delta, 1e-14);
    const CoreDifference<mink::Cylinder, mink::Box> edge{
        a, box, edge_down, Vec3(0, ra - delta + rb * std::sqrt(2.0), 0)};
    SupportMinimum<double> on_edge = least;
    EXPECT_TRUE(mink::detail::inner_ball_proves_depth(
        edge, tol.relative * size, tol.relative_depth * size, iterations, on_edge, lower))
        << "delta " << delta;
    EXPECT_NEAR(lower, delta, 1e-14);
    // A box's edge along y against A's rim at (ra, 0, half), pressed in by delta along the
    // rim's bisector n = (1, 0, 1) / sqrt 2: no ball touches a rim or an edge, so nothing is
    // proven, whatever the depth.
    const Vec3 bisector = Vec3(1, 0, 1).normalized();
    SupportMinimum<double> at_rim;
    at_rim.normal = bisector;
    at_rim.value = delta;
    at_rim.vertex.a = Vec3(ra, 0, half);
    at_rim.vertex.b = at_rim.vertex.a - delta * bisector;
    at_rim.vertex.w = at_rim.vertex.a - at_rim.vertex.b;
    at_rim.vertex.dir = bisector;
    const mink::Box short_box{Vec3(rb, 0.05, rb)};
    const CoreDifference<mink::Cylinder, mink::Box> rim{a, short_box, mink::Mat3::Identity(),
                                                        Vec3(at_rim.vertex.b + Vec3(rb, 0, rb))};
    EXPECT_FALSE(mink::detail::inner_ball_proves_depth(
        rim, tol.relative * size, tol.relative_depth * size, iterations, at_rim, lower))
        << "delta " << delta;
  }
}

}  // namespace inner_ball_test
