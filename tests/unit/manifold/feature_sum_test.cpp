// Support features of sums ("sweeps") and of run-time Shapes (manifold/feature.hpp). A face of a
// Minkowski sum is the sum of its parts' features along the same direction; checked against a
// brute force over every pair of the parts' points, and through manifold() on scenes whose
// contact is known by construction, in both argument orders.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Shape;
using mink::Vec3;
using oracle::Rng;

std::vector<Vec3> box_corners(const Vec3& half, const mink::Mat3& rotation, const Vec3& centre) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(centre + rotation * Vec3(i & 1 ? half.x() : -half.x(),
                                               i & 2 ? half.y() : -half.y(),
                                               i & 4 ? half.z() : -half.z()));
  return corners;
}

/// Whether planar point p lies in the closed triangle (a, b, c) or on the segment (a, b) when the
/// triangle is flat.
bool in_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double eps) {
  auto cross = [](const Vec3& o, const Vec3& x, const Vec3& y) {
    return (x.x() - o.x()) * (y.y() - o.y()) - (x.y() - o.y()) * (y.x() - o.x());
  };
  const double d1 = cross(a, b, p), d2 = cross(b, c, p), d3 = cross(c, a, p);
  const bool has_neg = d1 < -eps || d2 < -eps || d3 < -eps;
  const bool has_pos = d1 > eps || d2 > eps || d3 > eps;
  if (has_neg && has_pos) return false;
  // Inside or on the boundary of a proper triangle; for a flat one, within the bounding box too.
  const double lo_x = std::min({a.x(), b.x(), c.x()}) - eps,
               hi_x = std::max({a.x(), b.x(), c.x()}) + eps;
  const double lo_y = std::min({a.y(), b.y(), c.y()}) - eps,
               hi_y = std::max({a.y(), b.y(), c.y()}) + eps;
  return p.x() >= lo_x && p.x() <= hi_x && p.y() >= lo_y && p.y() <= hi_y;
}

/// The corners of the convex hull of planar points (z ignored), by brute force: a point is a
/// corner when it lies in no triangle of three other points (distinct to `eps`; on a side to
/// eps times the extent).
std::vector<int> brute_corners(const std::vector<Vec3>& planar, double eps) {
  // Twice a triangle's area is a length times a length: its rounding is eps times the extent.
  double extent = 0;
  for (const Vec3& p : planar) extent = std::max(extent, p.head<2>().norm());
  std::vector<int> distinct;
  for (int i = 0; i < int(planar.size()); ++i) {
    bool repeat = false;
    for (const int j : distinct) repeat = repeat || (planar[i] - planar[j]).head<2>().norm() <= eps;
    if (!repeat) distinct.push_back(i);
  }
  std::vector<int> corners;
  for (const int i : distinct) {
    bool inside = false;
    for (const int a : distinct)
      for (const int b : distinct)
        for (const int c : distinct) {
          if (inside || a == i || b == i || c == i || a >= b || b > c) continue;
          inside = in_triangle(planar[i], planar[a], planar[b], planar[c], eps * extent);
        }
    if (!inside) corners.push_back(i);
  }
  return corners;
}

TEST(FeatureSum, SumOfTwoPolytopesIsTheSumOfTheirFeatures) {
  // A and B: boxes given as point sets; the directions are A's face normals and edge bisectors.
  // B is either turned at random (a face of A plus a corner or an edge of B) or turned from A
  // about the direction (two faces: a rectangle or an octagon). The sum's feature must be the
  // outline of the pairwise sums within 1e-9 of the size of the support plane.
  int faces = 0, checked = 0;
  for (int k = 0; k < 60; ++k) {
    Rng rng(910000 + k);
    const mink::Mat3 ra = rng.rotation().toRotationMatrix();
    const Vec3 ha(rng.uniform(0.2, 1), rng.uniform(0.2, 1), rng.uniform(0.2, 1));
    const Vec3 hb(rng.uniform(0.05, 0.8), rng.uniform(0.05, 0.8), rng.uniform(0.05, 0.8));
    const int axis = k % 3;
    const double side = (k / 3) % 2 ? 1.0 : -1.0;
    Vec3 local_n = Vec3::Zero();
    local_n[axis] = side;
    if (k % 5 == 4) local_n[(axis + 1) % 3] = 1;  // an edge of A
    const Vec3 n = (ra * local_n).normalized();
    mink::Mat3 rb;
    if (k % 4 == 0) {
      rb = rng.rotation().toRotationMatrix();
    } else {
      // B turned from A about n: its face along n is parallel to A's.
      rb = Eigen::AngleAxisd(k % 4 == 1 ? 0.0 : rng.uniform(0.1, 1.4), n).toRotationMatrix() * ra;
    }
    const std::vector<Vec3> pa = box_corners(ha, ra, rng.in_ball(0.3));
    const std::vector<Vec3> pb = box_corners(hb, rb, rng.in_ball(0.3));
    const Shape sum = Shape::sum(Shape::polytope(pa).value(), Shape::polytope(pb).value()).value();
    const double size = sum.bounding_radius();
    // Brute force: every pairwise sum, those on the support plane, their outline across n.
    std::vector<Vec3> sums;
    double top = -1e300;
    for (const Vec3& a : pa)
      for (const Vec3& b : pb) {
        sums.push_back(a + b);
        top = std::max(top, (a + b).dot(n));
      }
    Vec3 u = n.unitOrthogonal(), v = n.cross(u);
    std::vector<Vec3> on_plane, planar;
    for (const Vec3& p : sums)
      if (top - p.dot(n) <= 1e-9 * size) {
        on_plane.push_back(p);
        planar.push_back(Vec3(p.dot(u), p.dot(v), 0));
      }
    const std::vector<int> corners = brute_corners(planar, 1e-12 * size);
    mink::SupportFeatureT<double> f;
    mink::support_feature_of(sum, n, 1e-9 * size, f);
    SCOPED_TRACE(testing::Message() << "case " << k << " expected corners " << corners.size());
    ASSERT_EQ(f.count, int(corners.size()));
    faces += f.count >= 3;
    for (const int c : corners) {
      double nearest = 1e300;
      for (int i = 0; i < f.count; ++i)
        nearest = std::min(nearest, (f.points[i] - on_plane[c]).norm());
      EXPECT_LE(nearest, 1e-12 * size);
      ++checked;
    }
    if (f.count >= 3) {
      EXPECT_GT(f.normal.dot(n), 1 - 1e-12);
    }
  }
  EXPECT_GE(faces, 40);
  EXPECT_GT(checked, 150);
}

TEST(FeatureSum, ShapeOfOneCoreKeepsItsFaces) {
  // A polytope or a hull shape paired with a sum runs on Shapes; its feature is still its face:
  // a 12-sided prism's cap has all 12 corners (a feature sampled from 9 support points, before,
  // could not hold them).
  Rng rng(920000);
  for (int k = 0; k < 20; ++k) {
    const mink::Mat3 r = rng.rotation().toRotationMatrix();
    const double radius = rng.uniform(0.1, 2), half_height = rng.uniform(0.1, 2);
    const double phase = rng.uniform(0, 1);
    std::vector<Vec3> corners;
    for (int i = 0; i < 24; ++i) {
      const double angle = 2 * std::numbers::pi * (i % 12 + phase) / 12;
      corners.push_back(r * Vec3(radius * std::cos(angle), radius * std::sin(angle),
                                 i < 12 ? half_height : -half_height));
    }
    const double side = k % 2 ? 1.0 : -1.0;
    const Vec3 n = side * r.col(2);
    for (const bool hull : {false, true}) {
      const Shape shape =
          hull ? Shape::convex_hull(corners).value() : Shape::polytope(corners).value();
      mink::SupportFeatureT<double> f;
      mink::support_feature_of(shape, n, 1e-3 * shape.bounding_radius(), f);
      ASSERT_EQ(f.count, 12) << "case " << k << (hull ? " hull" : " polytope");
      for (int i = 0; i < 12; ++i)
        EXPECT_NEAR(f.points[i].dot(n), half_height, 1e-12 * (radius + half_height))
            << "case " << k;
    }
  }
}

TEST(FeatureSum, ARimOfASumAgainstAFaceIsOnePoint) {
  // Found by probe 51's cone sums (line c360): a cone plus a capsule whose base rim touches a
  // face along a normal 54 degrees from the cone's axis. The rim point is the sum's only point
  // on its support plane. The sampled feature took three rim points 0.1 rad apart as a sliver
  // "face" of the base and pushed them out along the base's normal by the capsule's radius: two
  // more manifold points 0.09 shallower, and which points the reduction kept depended on the
  // order of the shapes. Known answer: one point, the rim point pushed out along the normal.
  const double cone_r = 0.1287662986645218, cone_h = 0.281707470792881;
  const double cap_r = 0.22270037580770574, cap_h = 0.43648641837150026;
  const Shape a =
      Shape::sum(Shape::cone(cone_r, cone_h).value(), Shape::capsule(cap_r, cap_h).value()).value();
  const Shape b = Shape::box(Vec3(2, 2, 0.5)).value();
  for (int k = 0; k < 20; ++k) {
    Rng rng(930000 + k);
    const double tilt = rng.uniform(0.5, 1.1), turn = rng.uniform(0, 2 * std::numbers::pi);
    // Deep enough in half the cases for the sliver's points (0.09 shallower) to be kept.
    const double depth = k % 2 ? rng.uniform(0.1, 0.3) : rng.log_uniform(1e-6, 0.05);
    // In A's frame: the normal, the sum's deepest point along it, B's face depth below it.
    const Vec3 n(std::sin(tilt) * std::cos(turn), std::sin(tilt) * std::sin(turn), -std::cos(tilt));
    const Vec3 rim(cone_r * std::cos(turn), cone_r * std::sin(turn), -cone_h);
    const Vec3 deepest = rim + Vec3(0, 0, -cap_h) + cap_r * n;
    // B's top face (outward normal -n) through deepest - depth n, its centre 0.5 behind it.
    const mink::Mat3 face_down =
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), Vec3(-n)).toRotationMatrix();
    Pose local_b;
    local_b.rotation = face_down;
    local_b.translation = deepest - depth * n + 0.5 * n;
    const Pose motion = rng.pose(3);
    const Pose pose_a = motion;
    const Pose pose_b = Pose{motion.rotation * local_b.rotation, motion.apply(local_b.translation)};
    const double size = a.bounding_radius() + b.bounding_radius();
    const Vec3 world_n = motion.rotate(n), world_deepest = motion.apply(deepest);
    for (const bool swap : {false, true}) {
      SCOPED_TRACE(testing::Message() << "case " << k << (swap ? " B, A" : " A, B"));
      const mink::ManifoldResult m =
          swap ? mink::manifold(b, pose_b, a, pose_a) : mink::manifold(a, pose_a, b, pose_b);
      ASSERT_EQ(m.status, mink::Status::Intersecting);
      ASSERT_EQ(m.count, 1);
      const Vec3 on_sum = swap ? m.points[0].point_b : m.points[0].point_a;
      EXPECT_LE((on_sum - world_deepest).norm(), 1e-9 * size);
      EXPECT_NEAR(m.points[0].depth, depth, 1e-9 * size);
      EXPECT_LE((m.normal - (swap ? -world_n : world_n)).norm(), 1e-9);
    }
  }
}

TEST(FeatureSum, ARoundedBoxSumRestsOnAHullWithItsFourCorners) {
  // A box plus a ball (a sum of two cores) face down on a large box given as a hull shape or a
  // polytope: four points, the sum's bottom corners, at the overlap's depth, in both orders.
  const Vec3 half(0.4, 0.3, 0.2);
  const double ball = 0.1;
  const Shape a = Shape::sum(Shape::box(half).value(), Shape::sphere(ball).value()).value();
  const std::vector<Vec3> table =
      box_corners(Vec3(2, 2, 0.5), mink::Mat3::Identity(), Vec3::Zero());
  for (int k = 0; k < 12; ++k) {
    Rng rng(940000 + k);
    const Shape b = k % 2 ? Shape::convex_hull(table).value() : Shape::polytope(table).value();
    const double depth = rng.log_uniform(1e-6, 0.05), spin = rng.uniform(0, 2 * std::numbers::pi);
    Pose local_a;
    local_a.rotation = Eigen::AngleAxisd(spin, Vec3::UnitZ()).toRotationMatrix();
    local_a.translation =
        Vec3(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), 0.5 + half.z() + ball - depth);
    const Pose motion = rng.pose(3);
    const Pose pose_b = motion;
    const Pose pose_a = Pose{motion.rotation * local_a.rotation, motion.apply(local_a.translation)};
    const double size = a.bounding_radius() + b.bounding_radius();
    for (const bool swap : {false, true}) {
      SCOPED_TRACE(testing::Message() << "case " << k << (swap ? " B, A" : " A, B"));
      const mink::ManifoldResult m =
          swap ? mink::manifold(b, pose_b, a, pose_a) : mink::manifold(a, pose_a, b, pose_b);
      ASSERT_EQ(m.status, mink::Status::Intersecting);
      ASSERT_EQ(m.count, 4);
      for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.points[i].depth, depth, 1e-9 * size);
        const Vec3 on_a = local_a.inverse_apply(
            motion.inverse_apply(swap ? m.points[i].point_b : m.points[i].point_a));
        // A bottom corner of the sum: (+-hx, +-hy, -hz - ball) in A's frame.
        EXPECT_NEAR(std::abs(on_a.x()), half.x(), 1e-9 * size) << "point " << i;
        EXPECT_NEAR(std::abs(on_a.y()), half.y(), 1e-9 * size) << "point " << i;
        EXPECT_NEAR(on_a.z(), -half.z() - ball, 1e-9 * size) << "point " << i;
      }
    }
  }
}

}  // namespace
