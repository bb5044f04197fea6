// manifold() of sums ("sweeps") with curved parts (cones, ellipsoids, cylinders) against
// primitives, through the run-time Shape. A sum's feature is the sum of its parts' features
// (feature_sum_test.cpp; sampled from its support mapping before stop 53), and a curved part's
// points may lie near the support plane without being on one plane. Checked against support
// functions written here in closed form (independent of the library's support mappings): no
// manifold point of A lies beyond A's support plane along the normal, none of B beyond B's along
// the reverse, and no point is deeper than contact()'s depth, which is itself checked against the
// support function of A - B.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/random.hpp"

// Named, not anonymous: the tests compile in unity batches (tests/CMakeLists.txt), where the
// names of this file's helpers (kinds, cases) would clash with other files' helpers.
namespace manifold_sum_test {

using mink::Pose;
using mink::Shape;
using mink::Vec3;
using oracle::Rng;

/// One part of a sum, with its support function h(n) = max over the part of p . n (local frame).
struct Part {
  enum Kind { kPolytope, kEllipsoid, kCone, kCylinder, kTriangle, kSphere, kBox } kind;
  std::vector<Vec3> points;   // polytope, triangle
  Vec3 radii = Vec3::Zero();  // ellipsoid; box half extents
  double radius = 0, half_height = 0;

  double support(const Vec3& n) const {
    const double planar = std::hypot(n.x(), n.y());
    switch (kind) {
      case kPolytope:
      case kTriangle: {
        double h = -1e300;
        for (const Vec3& p : points) h = std::max(h, p.dot(n));
        return h;
      }
      case kEllipsoid:
        return radii.cwiseProduct(n).norm();
      case kCone:  // apex at +half_height, base disc at -half_height
        return std::max(half_height * n.z(), -half_height * n.z() + radius * planar);
      case kCylinder:
        return half_height * std::abs(n.z()) + radius * planar;
      case kSphere:
        return radius * n.norm();
      case kBox:
        return radii.cwiseProduct(n).cwiseAbs().sum();
    }
    return 0;
  }

  Shape shape() const {
    switch (kind) {
      case kPolytope:
        return Shape::polytope(points).value();
      case kTriangle:
        return Shape::triangle(points[0], points[1], points[2]).value();
      case kEllipsoid:
        return Shape::ellipsoid(radii).value();
      case kCone:
        return Shape::cone(radius, half_height).value();
      case kCylinder:
        return Shape::cylinder(radius, half_height).value();
      case kSphere:
        return Shape::sphere(radius).value();
      case kBox:
        return Shape::box(radii).value();
    }
    return Shape::sphere(1).value();
  }
};

Part random_part(Rng& rng, Part::Kind kind) {
  Part p{kind, {}};
  switch (kind) {
    case Part::kPolytope:
      for (int i = 0; i < 8; ++i) p.points.push_back(rng.in_ball(1));
      break;
    case Part::kTriangle:
      for (int i = 0; i < 3; ++i) p.points.push_back(rng.in_ball(1));
      break;
    case Part::kEllipsoid:  // from nearly flat to round
      p.radii = Vec3(rng.uniform(0.1, 0.6), rng.uniform(0.1, 0.6), rng.uniform(0.05, 0.6));
      break;
    case Part::kCone:
    case Part::kCylinder:
      p.radius = rng.uniform(0.1, 0.8);
      p.half_height = rng.uniform(0.1, 1.5);
      break;
    case Part::kSphere:
      p.radius = rng.uniform(0.1, 0.6);
      break;
    case Part::kBox:
      p.radii = Vec3(rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1));
      break;
  }
  return p;
}

/// World support value of the parts (summed) at pose `pose` along world direction n.
double support(const std::vector<Part>& parts, const Pose& pose, const Vec3& n) {
  const Vec3 local = pose.inverse_rotate(n);
  double h = pose.translation.dot(n);
  for (const Part& part : parts) h += part.support(local);
  return h;
}

TEST(ManifoldSum, CurvedPartsKeepThePointsOnTheShapes) {
  const Part::Kind curved[] = {Part::kEllipsoid, Part::kCone, Part::kCylinder};
  const Part::Kind flat[] = {Part::kPolytope, Part::kTriangle};
  const Part::Kind others[] = {Part::kSphere, Part::kCylinder, Part::kBox, Part::kCone,
                               Part::kEllipsoid};
  const int count = oracle::sweep_count(1500, 300);
  int penetrating = 0, multi = 0;
  double worst_beyond = 0, worst_deeper = 0, worst_contact = 0, worst_shallower = 0;
  for (int k = 0; k < count; ++k) {
    Rng rng(620000 + k);
    const std::vector<Part> a = {random_part(rng, flat[k % 2]), random_part(rng, curved[k % 3])};
    const std::vector<Part> b = {random_part(rng, others[(k / 6) % 5])};
    const Shape sa = Shape::sum(a[0].shape(), a[1].shape()).value();
    const Shape sb = b[0].shape();
    const Pose pa = rng.pose(2);
    Pose pb = rng.pose(0);
    pb.translation = pa.translation + rng.in_ball(1.2);
    const mink::ContactResult c = mink::contact(sa, pa, sb, pb);
    if (!c.intersect || c.status != mink::Status::Intersecting) continue;
    const double size = sa.bounding_radius() + sb.bounding_radius();  // the bar's size
    const Vec3& n = c.normal;
    const double h_a = support(a, pa, n), h_b = support(b, pb, -n);
    // contact()'s depth is the support function of A - B along its normal (EPA's bound).
    worst_contact = std::max(worst_contact, std::abs(h_a + h_b - c.depth) / size);
    const mink::ManifoldResult m = mink::manifold(sa, pa, sb, pb);
    ASSERT_GE(m.count, 1) << oracle::seed_note(k);
    // The deepest point comes first, and it is the contact's depth.
    const double shallower = (c.depth - m.points[0].depth) / size;
    worst_shallower = std::max(worst_shallower, shallower);
    EXPECT_LE(shallower, 1e-9) << oracle::seed_note(k) << " the deepest point is missing";
    ++penetrating;
    multi += m.count > 1;
    for (int i = 0; i < m.count; ++i) {
      const mink::ManifoldPoint& p = m.points[i];
      const double beyond_a = (p.point_a.dot(m.normal) - support(a, pa, m.normal)) / size;
      const double beyond_b = (-p.point_b.dot(m.normal) - support(b, pb, -m.normal)) / size;
      const double deeper = (p.depth - c.depth) / size;
      worst_beyond = std::max({worst_beyond, beyond_a, beyond_b});
      worst_deeper = std::max(worst_deeper, deeper);
      EXPECT_LE(beyond_a, 1e-9) << oracle::seed_note(k) << " point " << i << " outside A";
      EXPECT_LE(beyond_b, 1e-9) << oracle::seed_note(k) << " point " << i << " outside B";
      EXPECT_LE(deeper, 1e-9) << oracle::seed_note(k) << " point " << i << " deeper than contact";
    }
  }
  EXPECT_GT(penetrating, count / 3);
  EXPECT_LE(worst_contact, 1e-6);
  std::printf(
      "[manifold sum] %d penetrating pairs (%d with several points); worst / size: beyond a "
      "support plane %.1e, deeper than contact %.1e, deepest shallower than contact %.1e, contact "
      "depth vs support function %.1e\n",
      penetrating, multi, worst_beyond, worst_deeper, worst_shallower, worst_contact);
}

TEST(ManifoldSum, TheDeepestPointIsTheContacts) {
  // Found by an adversarial probe (stop 50): a rounded cylinder deep in a sum of a polytope and a
  // segment. The features clipped gave one point 0.1 shallower than the depth (3 % of the size);
  // with A and B swapped, the full depth. The contact's own pair joins the clipped points then.
  const Shape a = Shape::rounded(Shape::cylinder(0.8425582345519447, 0.20929915373453292).value(),
                                 0.13550819092243838)
                      .value();
  const std::vector<Vec3> points = {
      Vec3(0.9202457298151492, -0.13149034064279133, -0.9648531707964445),
      Vec3(0.4142971661257362, -0.8853347449641352, -1.3506525929482345),
      Vec3(0.7005284316003463, 0.2847261745009616, 0.7615575059520874),
      Vec3(0.04068493039609787, 0.5456006582446793, 0.9259879364991043),
      Vec3(-0.06602794771528918, -0.33830673461308913, 0.9368533843942811),
      Vec3(-0.14617999283806313, 0.346377137607276, 0.938370890720888)};
  const Shape b =
      Shape::sum(Shape::polytope(points).value(),
                 Shape::segment(Vec3(0.2269767199509014, 0.2147354548415225, -0.12656325634220725),
                                Vec3(-0.3285492024338373, -0.2330279696206798, 0.2669226135717763))
                     .value())
          .value();
  const Pose pa = Pose::from(Vec3(-0.3560689047383339, -0.032739524348275637, -0.2418026236866008),
                             mink::Quat(0.038413656385672804, 0.3326545093283456,
                                        -0.938341837068599, -0.08590672402861269));
  const Pose pb = Pose::from(Vec3(-0.42761108298821804, 0.05254812299357969, -0.06686840146103662),
                             mink::Quat(0.2285356606814353, -0.7958781110071856, 0.5020473746360795,
                                        -0.24959550844827674));
  const double size = a.bounding_radius() + b.bounding_radius();
  for (const bool swap : {false, true}) {
    SCOPED_TRACE(swap ? "B, A" : "A, B");
    const auto c = swap ? mink::contact(b, pb, a, pa) : mink::contact(a, pa, b, pb);
    const auto m = swap ? mink::manifold(b, pb, a, pa) : mink::manifold(a, pa, b, pb);
    ASSERT_EQ(c.status, mink::Status::Intersecting);
    ASSERT_GE(m.count, 1);
    EXPECT_NEAR(m.points[0].depth, c.depth, 1e-9 * size);
    EXPECT_LE((m.points[0].point_b - m.points[0].point_a + m.points[0].depth * m.normal).norm(),
              1e-12 * size);
    for (int i = 1; i < m.count; ++i) EXPECT_LE(m.points[i].depth, m.points[0].depth);
  }
}

/// Least of h(u) - u . x over unit u near-uniformly spread (a Fibonacci sphere of `count`): for a
/// point x inside the shape, its distance to the surface (to the grid's resolution), 0 on it.
double depth_below_surface(const std::vector<Part>& parts, const Vec3& x, int count) {
  double least = 1e300;
  for (int i = 0; i < count; ++i) {
    const double z = 1 - (2 * i + 1.0) / count, rho = std::sqrt(1 - z * z);
    const double phi = i * 2.399963229728653;  // the golden angle
    const Vec3 u(rho * std::cos(phi), rho * std::sin(phi), z);
    double h = 0;
    for (const Part& part : parts) h += part.support(u);
    least = std::min(least, h - u.dot(x));
  }
  return least;
}

TEST(ManifoldSum, FeaturePointsMetTwiceAreOnePoint) {
  // Found by an adversarial probe (stop 51): the sampled feature of a sum of a cone and a capsule
  // met one rim point twice, 5e-17 apart, and the zero-length "edge" between them, rounded by the
  // capsule's radius across its arbitrary direction, gave a second manifold point 0.037 inside
  // the sum (2 % of the size); with A and B swapped, one point. Now one point in both orders, on
  // the sum's surface.
  Part cone{Part::kCone, {}};
  cone.radius = 0.27929207438715264;
  cone.half_height = 0.12005018703143604;
  Part segment_ball{Part::kSphere, {}};  // the capsule: a segment along z plus a ball
  segment_ball.radius = 0.26176657686917576;
  Part segment{Part::kPolytope, {Vec3(0, 0, -0.07115001927781), Vec3(0, 0, 0.07115001927781)}};
  const std::vector<Part> parts = {cone, segment, segment_ball};
  const Shape a =
      Shape::sum(cone.shape(), Shape::capsule(segment_ball.radius, 0.07115001927781).value())
          .value();
  const Shape b =
      Shape::box(Vec3(0.7833605824174813, 0.9749068926375872, 0.22447661981650574)).value();
  const Pose pa = Pose::from(Vec3(0.23957369349692192, -1.2174944605303515, -0.9668749207368029),
                             mink::Quat(-0.3631257519344581, -0.19591232632971742,
                                        0.8795393691120739, -0.23699904399817287));
  const Pose pb = Pose::from(Vec3(0.970931414440291, -1.1569108120042166, -0.9129253186246323),
                             mink::Quat(0.6261940196733234, -0.11067732055555357,
                                        0.7384199628133894, -0.22442713507657872));
  const double size = a.bounding_radius() + b.bounding_radius();
  int counts[2];
  for (const bool swap : {false, true}) {
    SCOPED_TRACE(swap ? "B, A" : "A, B");
    const auto m = swap ? mink::manifold(b, pb, a, pa) : mink::manifold(a, pa, b, pb);
    ASSERT_EQ(m.status, mink::Status::Intersecting);
    counts[swap] = m.count;
    for (int i = 0; i < m.count; ++i) {
      const Vec3& on_sum = swap ? m.points[i].point_b : m.points[i].point_a;
      // On the surface to the grid's resolution (0.04 rad: about 2e-4 of this size).
      EXPECT_LT(depth_below_surface(parts, pa.inverse_apply(on_sum), 20000), 1e-3 * size)
          << "point " << i;
    }
  }
  EXPECT_EQ(counts[0], counts[1]);
}

TEST(ManifoldSum, ATiltedRimGivesWayToTheContactsDeepestPoint) {
  // Found by an adversarial probe (stop 51): a cylinder standing on a box, tilted 1.3e-6 rad. Its
  // cap is a polygon of 16 rim points, whose deepest lies between two of them, 3.9e-9 short of the
  // contact's depth; the reduction then took another point within 1e-9 of the size of that one
  // first: 7.8e-9 (2e-9 of the size) short. The contact's pair now joins whenever it is deeper by
  // more than the touching tolerance, and goes first. Tilts from 1e-9 to 1e-4 rad (the cap is a
  // face to the feature tolerance), turned about the axis at random, both argument orders.
  const mink::Box box{Vec3(2.8724961845230395, 2.1954972695984405, 0.20781325037962217)};
  const mink::Cylinder cylinder{0.22332737961564125, 0.28291263095932806};
  Rng rng(5105);
  const double size = box.bounding_radius() + cylinder.bounding_radius();
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    const double tilt = std::pow(10.0, rng.uniform(-9, -4));
    const Vec3 axis = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0).normalized();
    const mink::Quat turn(Eigen::AngleAxisd(rng.uniform(0, 6.3), Vec3::UnitZ()));
    const mink::Quat lean(Eigen::AngleAxisd(tilt, axis));
    const double sunk = 2e-5;  // the cap's centre below the box's top face
    const Pose pa = Pose::identity();
    const Pose pb = Pose::from(Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                    box.half_extents.z() + cylinder.half_height - sunk),
                               lean * turn);
    for (const bool swap : {false, true}) {
      const auto c =
          swap ? mink::contact(cylinder, pb, box, pa) : mink::contact(box, pa, cylinder, pb);
      const auto m =
          swap ? mink::manifold(cylinder, pb, box, pa) : mink::manifold(box, pa, cylinder, pb);
      ASSERT_EQ(c.status, mink::Status::Intersecting);
      ASSERT_GE(m.count, 3);
      // The deepest point agrees with the contact's depth; the first is within the reduction's
      // tie tolerance (1e-9 of the size) of the deepest.
      double deepest = m.points[0].depth;
      for (int k = 1; k < m.count; ++k) deepest = std::max(deepest, m.points[k].depth);
      worst = std::max(worst, std::abs(deepest - c.depth) / size);
      EXPECT_GE(m.points[0].depth, deepest - 1e-9 * size);
    }
  }
  EXPECT_LE(worst, 1e-9);
}

TEST(ManifoldFeature, PointsApartByRoundingAreOne) {
  const Vec3 n = Vec3::UnitZ();
  // Two samples of one point, 5e-17 apart: a point, not an edge.
  Vec3 twice[2] = {Vec3(-0.20698390214970763, -0.18751460494147934, -0.19120020630924606),
                   Vec3(-0.20698390214970758, -0.18751460494147934, -0.19120020630924606)};
  mink::SupportFeatureT<double> out;
  mink::detail::feature_from_points(twice, 2, n, out);
  EXPECT_EQ(out.count, 1);
  // A triangle with one corner met twice, 1e-17 apart: three corners.
  Vec3 triangle[4] = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(1e-17, 1, 1)};
  mink::detail::feature_from_points(triangle, 4, n, out);
  EXPECT_EQ(out.count, 3);
  // Corners 1e-9 apart on a unit feature are kept: a short edge is an edge.
  Vec3 short_edge[2] = {Vec3(0.5, 0.5, 1), Vec3(0.5 + 1e-9, 0.5, 1)};
  mink::detail::feature_from_points(short_edge, 2, n, out);
  EXPECT_EQ(out.count, 2);
}

}  // namespace manifold_sum_test
