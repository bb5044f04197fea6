// Hand-built hard cases for distance() and intersect(): exact contact, parallel features, flat
// and needle polytopes, duplicate points, extreme scales and offsets, coincident shapes,
// degenerate point sets, and curved shapes a hair from touching. Expected values are worked out
// by hand or by the oracles in tests/oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/check.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/penetration.hpp"
#include "oracle/poses.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Box;
using mink::Pose;
using mink::Quat;
using mink::Vec3;

using oracle::at;
using oracle::rotated;

template <class A, class B>
void expect_touching(const A& a, const Pose& pa, const B& b, const Pose& pb, double size) {
  const auto r = mink::distance(a, pa, b, pb);
  const auto i = mink::intersect(a, pa, b, pb);
  EXPECT_FALSE(oracle::has_nan(r));
  EXPECT_TRUE(r.intersect) << "distance " << r.distance;
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_TRUE(i.intersect);
  EXPECT_LE(r.distance, 1e-12 * size);
}

template <class A, class B>
void expect_separated(const A& a, const Pose& pa, const B& b, const Pose& pb, double distance,
                      double tol, const Vec3& normal = Vec3::Zero()) {
  const auto r = mink::distance(a, pa, b, pb);
  const auto i = mink::intersect(a, pa, b, pb);
  EXPECT_FALSE(oracle::has_nan(r));
  EXPECT_EQ(r.status, mink::Status::Separated);
  EXPECT_FALSE(i.intersect);
  EXPECT_NEAR(r.distance, distance, tol);
  if (normal != Vec3::Zero()) {
    EXPECT_LE((r.normal - normal).norm(), 1e-9) << "normal " << r.normal.transpose();
  }
  EXPECT_LE((r.point_b - r.point_a - r.distance * r.normal).norm(), tol);
}

TEST(GjkNasty, BoxesFaceToFaceAtExactContact) {
  const Box a{Vec3(1, 1, 1)}, b{Vec3(1, 1, 1)};
  expect_touching(a, Pose::identity(), b, at(2, 0, 0), 3.5);
  expect_touching(a, Pose::identity(), b, at(2, 0.5, 0.3), 3.5);
  expect_touching(a, Pose::identity(), b, at(0, 0, -2), 3.5);
  expect_touching(a, at(10, 20, 30), b, at(12, 20.25, 30), 3.5);
  // Same rotation for both: contact is exact up to the rounding of the rotated offset.
  const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  expect_touching(a, Pose::from(Vec3::Zero(), q), b, Pose::from(q * Vec3(2, 0.1, 0.2), q), 3.5);
}

TEST(GjkNasty, SphereRestingOnFace) {
  const Box box{Vec3(2, 1, 0.5)};
  expect_touching(mink::Sphere{1}, at(0.3, 0.2, 1.5), box, Pose::identity(), 3.5);
  expect_touching(mink::Sphere{1}, at(2, 1, 1.5), box, Pose::identity(), 3.5);  // above a corner
  expect_separated(mink::Sphere{1}, at(0.3, 0.2, 1.5 + 1e-9), box, Pose::identity(), 1e-9, 1e-15,
                   Vec3(0, 0, -1));
}

TEST(GjkNasty, EdgeOnEdge) {
  // A: unit cube turned 45 degrees about x, so its top is an edge along x at z = sqrt(2).
  // B: the same turned about y, bottom edge along y; placed at z = 2 sqrt(2) the edges cross.
  const Box cube{Vec3(1, 1, 1)};
  const double s2 = std::sqrt(2.0);
  const Pose pa = rotated(Vec3::Zero(), M_PI / 4, Vec3::UnitX());
  expect_touching(cube, pa, cube, rotated(Vec3(0, 0, 2 * s2), M_PI / 4, Vec3::UnitY()), 3.5);
  // Lifted by 1e-6: the distance is the lift, along +z.
  expect_separated(cube, pa, cube, rotated(Vec3(0, 0, 2 * s2 + 1e-6), M_PI / 4, Vec3::UnitY()),
                   1e-6, 1e-14, Vec3::UnitZ());
}

// Capsules whose segments are 1e78 and more long, crossing at right angles 3 lengths apart: the
// closed form multiplies four lengths, which overflowed to NaN; such pairs are solved rescaled.
TEST(GjkNasty, HugeCrossingCapsulesStayFinite) {
  for (double s : {1.0, 1e76, 1e78, 1e120, 1e150}) {
    const mink::Capsule c{0.25 * s, s};
    // B's segment runs along y through (3, 0.5, 0.3) s: the closest points are its point at y = 0
    // and A's at z = 0.3, off both centres.
    const Pose pb =
        Pose::from(Vec3(3, 0.5, 0.3) * s, Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX())));
    const auto r = mink::distance(c, Pose::identity(), c, pb);
    ASSERT_EQ(r.status, mink::Status::Separated) << s;
    EXPECT_NEAR(r.distance / s, 2.5, 1e-14) << s;
    EXPECT_LE((r.point_a / s - Vec3(0.25, 0, 0.3)).norm(), 1e-14) << s;
    EXPECT_LE((r.point_b / s - Vec3(2.75, 0, 0.3)).norm(), 1e-14) << s;
    EXPECT_LE((r.normal - Vec3::UnitX()).norm(), 1e-14) << s;
  }
}

// Boxes, points and segments whose size squared overflows or underflows: their bounding radius
// scales every tolerance, and a plain norm() made it inf above 1e154 (every pair then touched:
// boxes 8 sizes apart intersected, at distance 0) or 0 below 1e-154.
TEST(GjkNasty, HugeAndTinyBoxesKeepTheirTolerances) {
  for (double s : {1e-200, 1e-160, 1.0, 1e160, 1e200}) {
    const Box a{Vec3(1, 1, 1) * s}, b{Vec3(1, 2, 1) * s};
    EXPECT_NEAR(a.bounding_radius() / s, std::sqrt(3.0), 1e-15) << s;
    const Pose apart = Pose::from_translation(Vec3(10, 0, 0) * s);
    const auto hit = mink::intersect(a, Pose::identity(), b, apart);
    EXPECT_EQ(hit.status, mink::Status::Separated) << s;
    const auto d = mink::distance(a, Pose::identity(), b, apart);
    ASSERT_EQ(d.status, mink::Status::Separated) << s;
    EXPECT_NEAR(d.distance / s, 8, 1e-14) << s;
    const Pose flush = Pose::from_translation(Vec3(2, 0.5, 0) * s);  // faces touching exactly
    EXPECT_TRUE(mink::intersect(a, Pose::identity(), b, flush).intersect) << s;
    const auto c =
        mink::contact(a, Pose::identity(), b, Pose::from_translation(Vec3(1.5, 0.1, 0) * s));
    ASSERT_EQ(c.status, mink::Status::Intersecting) << s;
    EXPECT_NEAR(c.depth / s, 0.5, 1e-14) << s;
    const mink::Point p{Vec3(3, 4, 0) * s};
    EXPECT_NEAR(p.bounding_radius() / s, 5, 1e-15) << s;
    const mink::Segment seg{Vec3(0, 0, 0), Vec3(0, 3, 4) * s};
    EXPECT_NEAR(seg.bounding_radius() / s, 5, 1e-15) << s;
    const auto pd = mink::distance(p, Pose::identity(), a, Pose::identity());
    ASSERT_EQ(pd.status, mink::Status::Separated) << s;
    EXPECT_NEAR(pd.distance / s, std::sqrt(2.0 * 2 + 3.0 * 3), 1e-14) << s;
  }
}

// A rotation orthonormal only to 7e-7 (pose_error() accepts 1e-6): B is 1.15e-6 from A. The
// common-point proof of box_box_verdict() once checked A's point in B's frame by r's transpose,
// which is not its inverse here, and called the boxes intersecting while distance() did not.
TEST(GjkNasty, BoxesUnderANearlyOrthonormalRotationAgree) {
  const Box a{Vec3(0x1.9be6cdd0d1495p-4, 0, 0x1.a9fb2e4bc6a34p-6)};
  const Box b{Vec3(0x1.f5850458e49dfp+1, 0x1.48b0485c1e311p+2, 0x1.8e8fe02f6332ep+0)};
  Pose pb;
  pb.rotation << 0x1.5c76910a57127p-18, -0x1.6dfbf6f873a44p-22, -0x1.000001f0309c5p+0,
      0x1.fffffbbcb26fp-1, 0x1.898f99439afep-20, 0x1.5d245892c0d19p-18, 0x1.8d106516590d3p-20,
      -0x1.fffff9cf507fap-1, 0x1.dbe995d7fc05p-27;
  pb.translation = Vec3(-0x1.0ea02a34cd79ep-26, 0x1.a683ec2be8cbcp-34, 0x1.4a5a446142608p+2);
  ASSERT_EQ(mink::pose_error(pb), nullptr);
  const auto d = mink::distance(a, Pose::identity(), b, pb);
  ASSERT_EQ(d.status, mink::Status::Separated);
  EXPECT_NEAR(d.distance, 1.146e-6, 1e-9);
  EXPECT_FALSE(mink::intersect(a, Pose::identity(), b, pb).intersect);
}

TEST(GjkNasty, ParallelFacesAndEdges) {
  const Box a{Vec3(1, 1, 1)}, b{Vec3(0.5, 2, 0.25)};
  expect_separated(a, Pose::identity(), b, at(2.0, 0.3, 0.1), 0.5, 1e-15, Vec3::UnitX());
  // Parallel capsules: segments overlap along z, so the points are not unique.
  const mink::Capsule c{0.25, 1};
  expect_separated(c, Pose::identity(), c, at(3, 0, 0.5), 2.5, 1e-15, Vec3::UnitX());
  // Parallel segments offset in y.
  const mink::Segment s{Vec3(-1, 0, 0), Vec3(1, 0, 0)};
  expect_separated(s, Pose::identity(), s, at(0.5, 2, 0), 2.0, 1e-15, Vec3::UnitY());
  // Collinear segments with a gap.
  expect_separated(s, Pose::identity(), s, at(2.5, 0, 0), 0.5, 1e-15, Vec3::UnitX());
}

TEST(GjkNasty, FlatAndNeedlePolytopes) {
  const std::vector<Vec3> square{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0),
                                 Vec3(0, 0, 0)};
  const auto flat = mink::Polytope::make(square);
  ASSERT_TRUE(flat);
  expect_separated(mink::Sphere{0.5}, at(0.2, 0.3, 1.5), *flat, Pose::identity(), 1.0, 1e-15,
                   Vec3(0, 0, -1));
  expect_separated(mink::Sphere{0.5}, at(3, 0, 0), *flat, Pose::identity(), 1.5, 1e-15,
                   Vec3(-1, 0, 0));
  expect_touching(mink::Sphere{0.5}, at(0.2, 0.3, 0.5), *flat, Pose::identity(), 2);
  // A needle: points along x with 1e-9 jitter across it.
  std::vector<Vec3> needle;
  for (int i = 0; i <= 10; ++i)
    needle.push_back(Vec3(i * 0.2 - 1, 1e-9 * (i % 3), -1e-9 * (i % 2)));
  const auto n = mink::Polytope::make(needle);
  ASSERT_TRUE(n);
  std::vector<oracle::V3> world;
  for (const Vec3& p : needle) world.push_back(oracle::widen(p));
  const Vec3 x(0.3, 0.7, 0.4);
  const auto expected = oracle::polytope_pair({oracle::widen(x)}, world);
  expect_separated(mink::Point{}, at(x.x(), x.y(), x.z()), *n, Pose::identity(),
                   double(expected.distance), 1e-14);
}

TEST(GjkNasty, DuplicatePoints) {
  std::vector<Vec3> pts;
  for (int rep = 0; rep < 10; ++rep)
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
      pts.push_back(p);
  const auto tet = mink::Polytope::make(pts);
  ASSERT_TRUE(tet);
  // The face x + y + z = 1 faces the point (1, 1, 1): distance (3 - 1) / sqrt(3).
  expect_separated(*tet, Pose::identity(), mink::Point{Vec3(1, 1, 1)}, Pose::identity(),
                   2 / std::sqrt(3.0), 1e-15, Vec3(1, 1, 1).normalized());
  expect_separated(*tet, Pose::identity(), Box{Vec3(0.5, 0.5, 0.5)}, at(-1, 0.2, 0.2), 0.5, 1e-15,
                   Vec3(-1, 0, 0));
}

TEST(GjkNasty, ExtremeScaleRatios) {
  // A 1e-6 sphere near a 1e6 box face; tolerance 1e-10 of the size (1.7e6): 2e-4 absolute.
  const Box big{Vec3(1e6, 1e6, 1e6)};
  const double size_big = std::sqrt(3.0) * 1e6;
  expect_separated(mink::Sphere{1e-6}, at(0.5, 0.25, 1e6 + 2e-6 + 1), big, Pose::identity(),
                   1 + 1e-6, 1e-10 * size_big, Vec3(0, 0, -1));
  expect_touching(mink::Sphere{1e-6}, at(0.5, 0.25, 1e6 + 1e-6), big, Pose::identity(), size_big);
  // Both tiny: relative accuracy holds at 1e-6 scale.
  const Box tiny{Vec3(1e-6, 1e-6, 1e-6)};
  expect_separated(tiny, Pose::identity(), tiny, at(3e-6, 0, 0), 1e-6, 1e-10 * 3.5e-6,
                   Vec3::UnitX());
  // Huge pair at distance 1e6.
  expect_separated(big, Pose::identity(), big, at(3e6, 0, 5e5), 1e6, 1e-10 * 2 * size_big,
                   Vec3::UnitX());
}

TEST(GjkNasty, FarFromOrigin) {
  // The pair of the smoke test, moved 1e6 away: the answer must not lose the 1e-10 bar.
  const Box a{Vec3(1, 1, 1)};
  const mink::Sphere s{0.5};
  const Vec3 far(1e6, -2e6, 3e6);
  const Quat q(Eigen::AngleAxisd(0.3, Vec3(0, 0, 1)));
  expect_separated(a, Pose::from(far, q), s, Pose::from_translation(far + q * Vec3(2.5, 0.2, 0.1)),
                   1.0, 1e-10 * 3, q * Vec3::UnitX());
  const mink::Capsule c{0.25, 1};
  expect_separated(c, at(1e6, 1e6, 1e6), c, at(1e6 + 1, 1e6, 1e6 + 0.5), 0.5, 1e-10 * 2.5,
                   Vec3::UnitX());
}

TEST(GjkNasty, CoincidentShapes) {
  const Box box{Vec3(1, 2, 3)};
  const Pose p = rotated(Vec3(1, 2, 3), 0.4, Vec3(1, 1, 0));
  expect_touching(box, p, box, p, 8);
  expect_touching(mink::Sphere{1}, p, mink::Sphere{1}, p, 2);
  expect_touching(mink::Point{Vec3(1, 2, 3)}, p, mink::Point{Vec3(1, 2, 3)}, p, 8);
  expect_touching(mink::Segment{Vec3(0, 0, 0), Vec3(1, 0, 0)}, p,
                  mink::Segment{Vec3(0, 0, 0), Vec3(1, 0, 0)}, p, 2);
  const auto tri = mink::Triangle{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  expect_touching(tri, p, tri, p, 2);
  const mink::Ellipsoid e{Vec3(1, 0.5, 0.25)};
  expect_touching(e, p, e, p, 2);
  const auto poly = mink::Polytope::make(
      std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)});
  ASSERT_TRUE(poly);
  expect_touching(*poly, p, *poly, p, 2);
}

TEST(GjkNasty, DegeneratePointSets) {
  // 1, 2 and 3 points against a box, compared with the brute-force oracle.
  const Box box{Vec3(0.5, 0.5, 0.5)};
  const Pose pb = rotated(Vec3(0.1, -0.2, 0.3), 0.9, Vec3(1, -2, 0.5));
  const oracle::WorldBox wb{oracle::V3(0.5, 0.5, 0.5), oracle::widen(pb.rotation),
                            oracle::widen(pb.translation)};
  const std::vector<std::vector<Vec3>> sets{
      {Vec3(2, 1, 0.5)},
      {Vec3(2, 1, 0.5), Vec3(-1, 2, 0.3)},
      {Vec3(2, 1, 0.5), Vec3(-1, 2, 0.3), Vec3(0.5, 1.5, 2)},
      {Vec3(2, 1, 0.5), Vec3(2, 1, 0.5), Vec3(2, 1, 0.5)},    // one point thrice
      {Vec3(2, 1, 0.5), Vec3(3, 1.5, 0.5), Vec3(4, 2, 0.5)},  // collinear
  };
  for (const auto& set : sets) {
    SCOPED_TRACE(testing::Message() << "set of " << set.size() << " points");
    const auto poly = mink::Polytope::make(set);
    ASSERT_TRUE(poly);
    std::vector<oracle::V3> world;
    for (const Vec3& p : set) world.push_back(oracle::widen(p));
    const auto expected = oracle::polytope_pair(world, oracle::box_corners(wb));
    ASSERT_GT(expected.gap, 0);
    expect_separated(*poly, Pose::identity(), box, pb, double(expected.distance), 1e-14,
                     expected.normal.cast<double>());
  }
}

/// Distance from a rotated curved shape's lowest point to a box's top face (z = 0), when the
/// shape's centre is at height `z`: z - h(-e_z), where h is the shape's support value (its own
/// formula here, not mink's).
TEST(GjkNasty, CurvedShapesNearTouching) {
  const Box floor{Vec3(10, 10, 1)};
  const Pose pf = at(0, 0, -1);  // top face at z = 0
  const Quat q(Eigen::AngleAxisd(0.6, Vec3(1, 2, 0.5).normalized()));
  const Eigen::Vector3d down = q.conjugate() * Vec3(0, 0, -1);  // -e_z in the shape's frame
  const double rho = std::hypot(down.x(), down.y());
  const mink::Ellipsoid ell{Vec3(1, 0.5, 0.3)};
  const mink::Cylinder cyl{0.7, 0.4};
  const mink::Cone cone{0.6, 0.9};
  const double h_ell = ell.radii.cwiseProduct(down).norm();
  const double h_cyl = cyl.radius * rho + cyl.half_height * std::abs(down.z());
  const double h_cone =
      std::max(cone.half_height * down.z(), cone.radius * rho - cone.half_height * down.z());
  const double size = Vec3(10, 10, 1).norm() + 1.2;
  for (const double gap : {1e-3, 1e-6, 1e-9}) {
    SCOPED_TRACE(testing::Message() << "gap " << gap);
    expect_separated(ell, Pose::from(Vec3(0.3, 0.2, h_ell + gap), q), floor, pf, gap, 1e-10 * size,
                     Vec3(0, 0, -1));
    expect_separated(cyl, Pose::from(Vec3(0.3, 0.2, h_cyl + gap), q), floor, pf, gap, 1e-10 * size,
                     Vec3(0, 0, -1));
    expect_separated(cone, Pose::from(Vec3(0.3, 0.2, h_cone + gap), q), floor, pf, gap,
                     1e-10 * size, Vec3(0, 0, -1));
    // Sunk by the same amount: intersecting.
    EXPECT_TRUE(
        mink::intersect(ell, Pose::from(Vec3(0.3, 0.2, h_ell - gap), q), floor, pf).intersect);
    EXPECT_TRUE(
        mink::intersect(cyl, Pose::from(Vec3(0.3, 0.2, h_cyl - gap), q), floor, pf).intersect);
    EXPECT_TRUE(
        mink::intersect(cone, Pose::from(Vec3(0.3, 0.2, h_cone - gap), q), floor, pf).intersect);
    EXPECT_TRUE(
        mink::distance(ell, Pose::from(Vec3(0.3, 0.2, h_ell - gap), q), floor, pf).intersect);
  }
  // Two ellipsoids nearly touching at their tips along x: gap 1e-9.
  const mink::Ellipsoid e2{Vec3(2, 0.3, 0.3)};
  expect_separated(e2, Pose::identity(), e2, at(4 + 1e-9, 0, 0), 1e-9, 1e-10 * 4, Vec3::UnitX());
}

// Stacked boxes turned by 1e-6..1e-4 about the stacking axis, under a general orientation: their
// edges are nearly parallel, where an identity of exact rotations would misjudge the edge axes
// by the rotation's rounding over the axis length (1e-7 in float). Overlapping by 2 % of the
// height: intersect() must say so, contact() must give that depth, in double and in float.
template <class S>
void expect_stacked_boxes_overlap() {
  using V = mink::Vec3T<S>;
  using Q = Eigen::Quaternion<S>;
  const mink::BoxT<S> a{V(1, 1, S(0.5))}, b{V(1, 1, S(0.5))};
  const double tolerance = std::is_same_v<S, float> ? 1e-5 : 1e-12;
  oracle::Rng rng(77);
  for (int i = 0; i < 20; ++i) {
    const Quat q = rng.rotation();
    const Q base(S(q.w()), S(q.x()), S(q.y()), S(q.z()));
    for (double turn : {1e-6, 2e-6, 1e-5, 1e-4}) {
      const mink::PoseT<S> pa = mink::PoseT<S>::from(V(3, -1, 2), base);
      const Q twist(Eigen::AngleAxis<S>(S(turn), V::UnitZ()));
      const mink::PoseT<S> pb = mink::PoseT<S>::from(pa.apply(V(0, 0, S(0.98))), base * twist);
      const auto hit = mink::intersect(a, pa, b, pb);
      EXPECT_TRUE(hit.intersect) << "turn " << turn;
      const auto c = mink::contact(a, pa, b, pb);
      EXPECT_TRUE(c.intersect) << "turn " << turn;
      EXPECT_NEAR(double(c.depth), 0.02, tolerance) << "turn " << turn;
    }
  }
}

TEST(GjkNasty, StackedBoxesTurnedSlightly) {
  expect_stacked_boxes_overlap<double>();
  expect_stacked_boxes_overlap<float>();
}

// Equal boxes stacked flush and shifted by 3e-8 sideways: contact()'s witness points lie on the
// boxes (no side-plane slack), 1e-12 of the size.
TEST(GjkNasty, FlushBoxesWitnessesOnTheSurfaces) {
  const Box box{Vec3(1, 1, 1)};
  const Pose pa = Pose::identity();
  const Pose pb = at(3e-8, 0, 1.999);
  const auto c = mink::contact(box, pa, box, pb);
  ASSERT_TRUE(c.intersect);
  EXPECT_NEAR(c.depth, 1e-3, 1e-12);
  const Vec3 la = pa.inverse_apply(c.point_a), lb = pb.inverse_apply(c.point_b);
  EXPECT_LE(la.cwiseAbs().maxCoeff(), 1 + 1e-12) << la.transpose();
  EXPECT_LE(lb.cwiseAbs().maxCoeff(), 1 + 1e-12) << lb.transpose();
  EXPECT_LE((c.point_b - c.point_a + c.depth * c.normal).norm(), 1e-12);
}

}  // namespace

namespace {

/// Cores at tiny and subnormal distances (found by fuzz/fuzz_queries.cpp): the squared distance
/// underflows, so a root of it is off by up to 1e-3 and a reciprocal of a subnormal length
/// overflows. The distance must still be the gap, the normal unit, and the verdict right.
/// `closest` is B's translation minus A's closest point, which the gap runs along (computed in
/// long double, whose exponent range has room for these squares).
void expect_tiny_gap(const mink::Shape& a, const mink::Shape& b, const Vec3& translation_b,
                     const Vec3& closest_on_a) {
  SCOPED_TRACE(testing::Message() << "B at (" << translation_b.x() << ", " << translation_b.y()
                                  << ", " << translation_b.z() << ")");
  const Pose pa = Pose::identity(), pb = Pose::from_translation(translation_b);
  long double sq = 0;
  for (int i = 0; i < 3; ++i) {
    const long double g = static_cast<long double>(translation_b[i]) - closest_on_a[i];
    sq += g * g;
  }
  const double expected = static_cast<double>(std::sqrt(sq));
  // A subnormal gap carries an absolute rounding of 5e-324 per coordinate.
  const double tolerance = 1e-12 * expected + 2e-323;
  const auto d = mink::distance(a, pa, b, pb);
  ASSERT_EQ(d.status, mink::Status::Separated) << d.error;
  EXPECT_NEAR(d.distance, expected, tolerance);
  EXPECT_NEAR(d.normal.norm(), 1.0, 1e-12);
  const auto c = mink::contact(a, pa, b, pb);
  EXPECT_FALSE(c.intersect);
  EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
  EXPECT_NEAR(c.distance, expected, tolerance);
  EXPECT_FALSE(mink::intersect(a, pa, b, pb).intersect);
}

TEST(GjkNasty, TinyAndSubnormalGapsGiveUnitNormals) {
  const auto point = mink::Shape::point(Vec3::Zero()).value();
  const auto dot = mink::Shape::sphere(0).value();
  const double h = 1e-170;
  const auto tiny_box = mink::Shape::box(Vec3(h, h, h)).value();
  const auto tiny_capsule = mink::Shape::capsule(0, h).value();
  for (const double length : {1e-150, 3.4e-161, 1e-200, 1e-310, 1.5e-323, 4.9e-324}) {
    for (const Vec3& direction : {Vec3(1, 0, 0), Vec3(0, 0, -1), Vec3(1, 1, 0), Vec3(1, -2, 3)}) {
      const Vec3 gap = direction * length;
      if (gap == Vec3::Zero()) continue;
      expect_tiny_gap(point, dot, gap, Vec3::Zero());
      // Past a box or a capsule of 1e-170 along x, by a gap that 1e-170 can resolve (1.2e-321,
      // the square of 3.4e-161, is subnormal): the nearest point is on the face x = h, or on the
      // capsule's axis.
      if (length < 1e-185) continue;
      const Vec3 beyond(h + std::abs(gap.x()) + length, gap.y(), gap.z());
      if (std::abs(beyond.y()) <= h && std::abs(beyond.z()) <= h)
        expect_tiny_gap(tiny_box, dot, beyond, Vec3(h, beyond.y(), beyond.z()));
      expect_tiny_gap(tiny_capsule, dot, beyond, Vec3(0, 0, std::clamp(beyond.z(), -h, h)));
    }
  }
}

TEST(GjkNasty, TinySegmentBesideAHugeOneKeepsItsNormal) {
  // Found by fuzzing: a segment of 1e-160 some 1.5e5 past the end of a segment 1.4e11 long. Solved
  // rescaled, the tiny one was a point at its centre, and its "interior" parameter made the normal
  // orthogonal to it: 90 degrees off. The closest point is the long segment's end, worked out
  // here: P lies beyond it (P - end has a negative component along the segment).
  oracle::Rng rng(381000);
  for (int k = 0; k < 200; ++k) {
    const Vec3 u = rng.unit();
    const Vec3 end = rng.in_ball(1e6);
    const double length = rng.log_uniform(1e3, 1e12);
    const Vec3 v = rng.unit();
    const Vec3 off = (v - v.dot(u) * u).normalized();
    const double gap = rng.log_uniform(1, 1e6);
    const Vec3 p = end + gap * off - rng.uniform(0, 0.1) * gap * u;
    // Squares from subnormal (the found case: 4e-161) to just below the rescaling threshold.
    const double tiny = rng.log_uniform(1e-165, 1e-150);
    // The tiny segment along the gap (the worst case: orthogonal to it is 90 degrees off) or
    // along a random direction.
    const Vec3 along = k % 2 ? Vec3((p - end).normalized()) : rng.unit();
    const auto long_segment = mink::Shape::segment(end, end + length * u).value();
    const auto small = mink::Shape::segment(-tiny * along, tiny * along).value();
    const auto rounded = mink::Shape::rounded(small, 1e-300).value();
    const Vec3 normal = (p - end).normalized();
    const double distance = (p - end).norm();
    // Placed by its pose: a segment of 1e-160 needs coordinates near 0 to have any length.
    const Pose at_p = Pose::from_translation(p);
    // The long segment's end is rebuilt from its centre and half vector: rounding of a few eps
    // of its length (1e-4 at 1e12), which bounds the distance's error and tilts the normal by
    // that over the gap.
    const double tol =
        1e-12 * distance + 8 * std::numeric_limits<double>::epsilon() * (end.norm() + length);
    for (const mink::Shape* b : {&small, &rounded}) {
      for (const bool swapped : {false, true}) {
        const auto r = swapped ? mink::distance(*b, at_p, long_segment, Pose::identity())
                               : mink::distance(long_segment, Pose::identity(), *b, at_p);
        ASSERT_EQ(r.status, mink::Status::Separated) << oracle::seed_note(381000) << " case " << k;
        EXPECT_NEAR(r.distance, distance, tol) << "case " << k;
        EXPECT_LE((r.normal - (swapped ? -normal : normal)).norm(), 1e-12 + tol / distance)
            << "case " << k << ": " << r.normal.transpose();
      }
    }
  }
}

TEST(GjkNasty, BoxInANeedleAgreesWithDistance) {
  // A box 1e-6 across sunk 3.3e-9 into a needle polytope 1e-8 thick and 0.83 long (found by an
  // adversarial sweep). The boolean loop stalls on the needle's thin simplices and hands over to
  // the distance loop, whose own Separated is not a proof: intersect() answered Separated, a
  // definite wrong status, where distance() says IterationLimit. Now both follow distance()'s
  // rule: IterationLimit, undecided (distance 1.9e-9 within an error bound of 1.9e-9), and
  // contact(), whose EPA decides what GJK's bounds cannot, finds the depth of the facet oracle.
  const Box box{Vec3(0x1.423973685ebeap-21, 0x1.8ca8f37c9f2c9p-21, 0x1.cc34c1ea11c12p-22)};
  const std::vector<Vec3> needle = {
      {-0x1.7109ae84d7314p-3, -0x1.afa25fd2bac68p-28, -0x1.c13a9420c5d99p-28},
      {-0x1.77ed8141ee4e4p-1, -0x1.efd0fc2485ec7p-29, 0x1.8632001a13b37p-28},
      {-0x1.3add35af7186fp-8, -0x1.291151d2f4164p-28, 0x1.a4658940facb2p-34},
      {0x1.4cbf8bb839284p-2, -0x1.a966dbee31ee9p-28, -0x1.52c6c53abb4b5p-28},
      {-0x1.aa29dea33f4ebp-1, -0x1.aacfd9d3214cp-29, -0x1.7f3e7c79c30b6p-30},
      {0x1.d516ea3d00dap-2, 0x1.a7b1772a50bbcp-32, -0x1.f6bfdb7b749fap-32},
      {0x1.81d3aeafb1b8bp-2, -0x1.193ec3030e267p-28, 0x1.ab480838dc137p-28}};
  const auto polytope = mink::Polytope::make(needle);
  ASSERT_TRUE(polytope.has_value());
  const double ra[9] = {
      0x1p+0, -0x1.024ffbdac3febp-42, -0x1.5908cc3903962p-39, 0x1.024ffbdad0d93p-42,
      0x1p+0, 0x1.312ce79c7968fp-40,  0x1.5908cc39036fap-39,  -0x1.312ce79c7a171p-40,
      0x1p+0};
  const double rb[9] = {0x1.ce20d4591f0cp-6,  0x1.fec3a292241d4p-1, 0x1.03e470c0c4f3ep-4,
                        0x1.b05444d169df4p-1, -0x1.d916e6dfe154p-5, 0x1.10b14937bf7e2p-1,
                        0x1.11e9125e30d13p-1, 0x1.3bd650783212p-5,  -0x1.b01ea2eadaa74p-1};
  Pose pa, pb;
  for (int i = 0; i < 9; ++i) {
    pa.rotation(i / 3, i % 3) = ra[i];
    pb.rotation(i / 3, i % 3) = rb[i];
  }
  pa.translation = Vec3(0x1.01a31496fc98p-7, -0x1.1e5d61bbc2a68p-4, 0x1.53e3d77b5528ep-5);
  pb.translation = Vec3(0x1.42650cfce1094p-7, -0x1.5fbc1caab935ep-7, 0x1.438647b1bb896p-4);
  const double size = box.bounding_radius() + polytope->bounding_radius();

  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(i & 1 ? box.half_extents.x() : -box.half_extents.x(),
                         i & 2 ? box.half_extents.y() : -box.half_extents.y(),
                         i & 4 ? box.half_extents.z() : -box.half_extents.z());
  const double depth = double(oracle::polytope_penetration(oracle::world_points(corners, pa),
                                                           oracle::world_points(needle, pb))
                                  .depth);
  ASSERT_GT(depth, 1e-9 * size);  // penetrating, well beyond the touching tolerance

  const auto i = mink::intersect(box, pa, *polytope, pb);
  const auto d = mink::distance(box, pa, *polytope, pb);
  EXPECT_NE(i.status, mink::Status::Separated);
  EXPECT_EQ(i.status, d.status);
  EXPECT_EQ(i.intersect, d.intersect);
  const auto c = mink::contact(box, pa, *polytope, pb);
  EXPECT_TRUE(c.intersect);
  EXPECT_NEAR(c.depth, depth, 1e-12 * size + c.error_bound);
}

TEST(GjkNasty, BoxesFarApartForTheirSizeAreNotCrossingEdges) {
  // Boxes whose edges are shorter than 1e-77 of their distance (found by fuzzing): the segments'
  // solve treats such edges as points, and their closest points, taken for crossing edges along an
  // edge axis, left the axis. The normal was 1.5e-3 rad and 18 degrees off, the distance 1e-6 and
  // 5 % short. Against boxes this small for their distance, the distance is that of their centres
  // to 1e-100 of itself, and the normal is the line between them.
  struct Case {
    Vec3 ha, hb, ta, tb;
    double ra[9], rb[9];
  };
  const Case cases[] = {
      {Vec3(0, 1e-300, 1e-300),
       Vec3(4.9406564584124654e-324, 1e-300, 1e-300),
       Vec3(4.6566128730773926e-10, -54.3671875, 1e-300),
       Vec3(2.8421709430404007e-14, -0.08776092529296875, -0.07872772216796875),
       {0.99221789883268308, -0.12451361867704269, 5.9372720087548586e-08, 0.12451361867704269,
        0.99221789883268485, 3.7107950054717866e-09, -5.9372720087548586e-08,
        3.7107950054717866e-09, 0.99999999999999822},
       {0, 0, 1, 1, 0, 0, 0, 1, 0}},
      {Vec3(1, 512, 1.4796387404203415e-07),
       Vec3(1, 1, 1),
       Vec3(-0.1990966796875, 0, 1.2151717632445912e+120),
       Vec3(4.0354991326765202e+119, 1e-300, -3.8556754589080811e-06),
       {0.99999999446781629, -6.4709126766666226e-11, 0.00010518729657638202, 3.5605296390443e-11,
        -0.99999999999954525, -9.5367431453342077e-07, 0.0001051872965763959,
        9.5367431300274414e-07, -0.99999999446736165},
       {1, 0, 0, 0, 1, 0, 0, 0, 1}},
  };
  for (const Case& c : cases) {
    Pose pa, pb;
    for (int i = 0; i < 9; ++i) {
      pa.rotation(i / 3, i % 3) = c.ra[i];
      pb.rotation(i / 3, i % 3) = c.rb[i];
    }
    pa.translation = c.ta;
    pb.translation = c.tb;
    const Vec3 between = c.tb - c.ta;
    const double distance = between.norm();
    const Vec3 normal = between / distance;
    const double tol = 1e-12 * distance;
    expect_separated(Box{c.ha}, pa, Box{c.hb}, pb, distance, tol, normal);
    const auto a = mink::Shape::box(c.ha), b = mink::Shape::box(c.hb);
    ASSERT_TRUE(a && b);
    const auto ab = mink::distance(a.value(), pa, b.value(), pb);
    const auto ba = mink::distance(b.value(), pb, a.value(), pa);
    EXPECT_NEAR(ab.distance, distance, tol);
    EXPECT_NEAR(ba.distance, distance, tol);
    EXPECT_LE((ab.normal - normal).norm(), 1e-12) << ab.normal.transpose();
    EXPECT_LE((ba.normal + normal).norm(), 1e-12) << ba.normal.transpose();
    const auto contact = mink::contact(a.value(), pa, b.value(), pb);
    EXPECT_FALSE(contact.intersect);
    EXPECT_NEAR(contact.distance, distance, tol);
    EXPECT_LE((contact.normal - normal).norm(), 1e-12) << contact.normal.transpose();
    EXPECT_LE((contact.point_b - contact.point_a - distance * normal).norm(), tol);
  }
}

}  // namespace
