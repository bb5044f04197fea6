// Small point sets whose Minkowski difference is thin, at or near touching: a segment beside a
// needle triangle, two needles, nearly parallel (query/point_set_pair.hpp). The answer is known
// by construction: both sets lie in planes orthogonal to v, `offset` apart along v, and their
// shadows along v cross, so the cores' signed distance is the offset (with the radii taken off)
// and v is the normal. Checked in long double against the input points: the value, the normal by
// the gap it proves, and both points on their shapes, to 1e-9 of the size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/random.hpp"

// Named, not anonymous: the tests compile as unity builds, several files to a unit.
namespace point_set_pair_test {

using mink::Mat3;
using mink::Pose;
using mink::Vec3;
using oracle::Real;
using oracle::V3;
using oracle::widen;

std::vector<V3> widened(const std::vector<Vec3>& points) {
  std::vector<V3> out;
  for (const Vec3& p : points) out.push_back(widen(p));
  return out;
}

// The gap of B beyond A along the unit n (long double): the least of B's heights less the
// largest of A's.
Real gap_along(const std::vector<V3>& a, const std::vector<V3>& b, const Vec3& normal) {
  const V3 n = widen(normal);
  Real top_a = -std::numeric_limits<Real>::infinity(),
       low_b = std::numeric_limits<Real>::infinity();
  for (const V3& p : a) top_a = std::max(top_a, n.dot(p));
  for (const V3& q : b) low_b = std::min(low_b, n.dot(q));
  return low_b - top_a;
}

// Distance from x to the hull of a flat set of up to four points: the least over its segments
// and triangles (the sets here lie in one plane, so these cover the hull).
Real distance_to_set(const std::vector<V3>& set, const Vec3& point) {
  const V3 x = widen(point);
  Real best = std::numeric_limits<Real>::infinity();
  const std::size_t n = set.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j) {
      best = std::min(best, (oracle::closest_on_segment(set[i], set[j], x).point - x).norm());
      for (std::size_t k = j + 1; k < n; ++k) {
        const V3 cross = (set[j] - set[i]).cross(set[k] - set[i]);
        if (!(cross.norm() > Real(1e-30))) continue;
        best = std::min(best, (oracle::closest_on_triangle(x, set[i], set[j], set[k]) - x).norm());
      }
    }
  return best;
}

struct Scene {
  std::vector<Vec3> a, b;  // world points; A is a segment when it has two
  double offset = 0;       // B's plane beyond A's along v: the cores' signed distance
  double radius = 0;       // of each shape (0: the point sets themselves)
  double size = 0;
};

// A signed offset: `scale` times 0, 1e-14, 1e-12, 1e-10 or 1e-8, either way.
double draw_offset(oracle::Rng& rng, double scale) {
  const double offsets[] = {0, 1e-14, 1e-12, 1e-10, 1e-8};
  const double offset = offsets[rng.integer(0, 4)] * scale;
  return rng.chance(0.5) ? -offset : offset;
}

// Seen along v, A runs along u through `centre` and B along a direction `tilt` from u, through
// a point of A; each is a segment or a needle (its copy moved within the plane by `width`).
Scene make_scene(oracle::Rng& rng, bool needles) {
  const Mat3 frame = rng.rotation().toRotationMatrix();
  const Vec3 u = frame.col(0), w = frame.col(1), v = frame.col(2);
  const double scale = rng.log_uniform(0.1, 10);
  const double tilt = rng.log_uniform(1e-13, 1e-7);
  const double offset = draw_offset(rng, scale);
  const double half_a = scale * rng.uniform(0.3, 1);
  const double half_b = scale * rng.uniform(0.3, 1);
  const Vec3 centre = rng.in_ball(scale);
  const Vec3 along_b = std::cos(tilt) * u + std::sin(tilt) * w;
  const Vec3 centre_b = centre + offset * v + rng.uniform(-0.2, 0.2) * std::min(half_a, half_b) * u;
  Scene s;
  s.offset = offset;
  const double width_a = scale * rng.log_uniform(1e-12, 1e-6);
  const double width_b = scale * rng.log_uniform(1e-12, 1e-3);
  s.a = {centre - half_a * u, centre + half_a * u};
  if (needles) {
    // The copy within the plane, on either side of the line.
    const Vec3 side = (rng.chance(0.5) ? 1.0 : -1.0) * width_a * w;
    s.a.push_back(s.a[0] + side);
    s.a.push_back(s.a[1] + side);
    const Vec3 side_b = (rng.chance(0.5) ? 1.0 : -1.0) * std::min(width_b, 1e-6 * scale) * w;
    s.b = {centre_b - half_b * along_b, centre_b + half_b * along_b};
    s.b.push_back(s.b[0] + side_b);
    s.b.push_back(s.b[1] + side_b);
  } else {
    // A triangle 1e-12 to 1e-3 of the size wide: the third corner beside its long edge's middle.
    s.b = {centre_b - half_b * along_b, centre_b + half_b * along_b, centre_b + width_b * w};
  }
  s.size = 2 * (centre.norm() + 2 * scale);
  return s;
}

// The four checks of one answer (signed: the distance when apart, minus the depth when not).
void expect_exact(const Scene& s, bool swapped, double signed_value, const Vec3& normal,
                  const Vec3& point_a, const Vec3& point_b) {
  const std::vector<V3> a = widened(swapped ? s.b : s.a), b = widened(swapped ? s.a : s.b);
  const double expected = std::abs(s.offset) - 2 * s.radius;
  const double bar = 1e-9 * s.size;
  EXPECT_NEAR(signed_value, expected, bar);
  // The normal proves a gap within the bar of the least, whichever way the cores lie.
  EXPECT_GE(double(gap_along(a, b, normal)) - 2 * s.radius, expected - bar);
  EXPECT_NEAR(double(distance_to_set(a, point_a)), s.radius, bar);
  EXPECT_NEAR(double(distance_to_set(b, point_b)), s.radius, bar);
  EXPECT_LE((point_b - point_a - signed_value * normal).norm(), bar);
}

// `pose_a` places A (whose world points are s.a); B stays at the origin.
template <class A, class B>
void check_pair(const Scene& s, const A& a, const B& b, const Pose& pose_a = Pose{}) {
  for (const bool swapped : {false, true}) {
    SCOPED_TRACE(swapped ? "B, A" : "A, B");
    const auto c =
        swapped ? mink::contact(b, Pose{}, a, pose_a) : mink::contact(a, pose_a, b, Pose{});
    ASSERT_TRUE(c.status == mink::Status::Separated || c.status == mink::Status::Intersecting)
        << oracle::describe(c);
    expect_exact(s, swapped, c.intersect ? -c.depth : c.distance, c.normal, c.point_a, c.point_b);
    const auto d =
        swapped ? mink::distance(b, Pose{}, a, pose_a) : mink::distance(a, pose_a, b, Pose{});
    ASSERT_TRUE(d.status == mink::Status::Separated || d.status == mink::Status::Intersecting);
    // Touching and intersecting pairs answer the flag alone; apart, everything.
    if (!d.intersect) expect_exact(s, swapped, d.distance, d.normal, d.point_a, d.point_b);
    EXPECT_EQ(d.intersect, c.intersect);
    const auto i =
        swapped ? mink::intersect(b, Pose{}, a, pose_a) : mink::intersect(a, pose_a, b, Pose{});
    EXPECT_NE(i.status, mink::Status::IterationLimit);
    EXPECT_EQ(i.intersect, c.intersect);
  }
}

mink::Polytope polytope(const std::vector<Vec3>& points) {
  return mink::Polytope::make(points).value();
}

TEST(PointSetPair, SegmentBesideNeedleTriangleNearlyParallel) {
  // Stop 62's exact probe: of 7,200 such lines, 126 failed before point_set_pair(), most with
  // GJK at its cap and the normal 1e-9 to 3e-7 of the size off in support value.
  oracle::Rng rng(6601);
  for (int n = 0; n < 1500; ++n) {
    Scene s = make_scene(rng, false);
    const bool rounded = rng.chance(0.3);
    SCOPED_TRACE(testing::Message()
                 << "case " << n << ", offset " << s.offset << ", rounded " << rounded);
    const mink::Segment a{s.a[0], s.a[1]};
    const mink::Triangle b{s.b[0], s.b[1], s.b[2]};
    if (!rounded) {
      check_pair(s, a, b);
      continue;
    }
    s.radius = 1e-3 * s.size;
    check_pair(s, mink::Rounded<mink::Segment>{a, s.radius},
               mink::Rounded<mink::Triangle>{b, s.radius});
  }
}

// check_pair() of A at `pose` against the scene's triangle B rounded by s.radius: both typed, or
// both as Shapes (`typed` picks).
template <class A>
void check_against_triangle(const Scene& s, const Pose& pose, bool typed, const A& typed_a,
                            const mink::Shape& shape_a) {
  const mink::Triangle b{s.b[0], s.b[1], s.b[2]};
  if (typed)
    check_pair(s, typed_a, mink::Rounded<mink::Triangle>{b, s.radius}, pose);
  else
    check_pair(s, shape_a,
               mink::Shape::rounded(mink::Shape::triangle(b.a, b.b, b.c).value(), s.radius).value(),
               pose);
}

// The same scenes with A a capsule (its core the segment), typed and as a Shape, which holds a
// Capsule core: without the point sets of a capsule's core, 137 of these 1,500 ended at GJK's
// cap as Shapes (a rounded segment: none).
TEST(PointSetPair, CapsuleBesideNeedleTriangleNearlyParallel) {
  oracle::Rng rng(6601);
  for (int n = 0; n < 1500; ++n) {
    Scene s = make_scene(rng, false);
    (void)rng.chance(0.3);  // as above: the same scenes
    SCOPED_TRACE(testing::Message() << "case " << n << ", offset " << s.offset);
    s.radius = 1e-3 * s.size;
    const Vec3 along = s.a[1] - s.a[0];
    const double half = 0.5 * along.norm();
    Pose pose;
    pose.translation = 0.5 * (s.a[0] + s.a[1]);
    pose.rotation =
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), along).normalized().toRotationMatrix();
    // The capsule's ends, as the pose places them, are the scene's A.
    s.a = {pose.translation - half * pose.rotation.col(2),
           pose.translation + half * pose.rotation.col(2)};
    check_against_triangle(s, pose, n % 2 == 0, mink::Capsule{s.radius, half},
                           mink::Shape::capsule(s.radius, half).value());
  }
}

// A sphere whose centre lies `offset` off a needle triangle's plane, its shadow inside the
// triangle near the long edge: the distance is |offset| less the radius. Typed and as a Shape
// (a Sphere core): as a Shape, 192 of 3,000 ended at GJK's cap before a sphere's core had its
// point set (a rounded point: none).
TEST(PointSetPair, SphereOverNeedleTriangle) {
  oracle::Rng rng(777);
  for (int n = 0; n < 3000; ++n) {
    const Mat3 frame = rng.rotation().toRotationMatrix();
    const Vec3 u = frame.col(0), w = frame.col(1), v = frame.col(2);
    const double scale = rng.log_uniform(0.1, 10);
    const double half = scale * rng.uniform(0.3, 1);
    const Vec3 centre = rng.in_ball(scale);
    const double width = scale * rng.log_uniform(1e-12, 1e-3);
    const double offset = draw_offset(rng, scale);
    Scene s;
    s.offset = offset;
    s.size = 2 * (centre.norm() + 2 * scale);
    s.radius = 1e-3 * s.size;
    Pose pose;
    pose.translation = centre + rng.uniform(-0.5, 0.5) * half * u + 0.01 * width * w + offset * v;
    s.a = {pose.translation};
    s.b = {centre - half * u, centre + half * u, centre + width * w};
    SCOPED_TRACE(testing::Message() << "case " << n << ", offset " << offset);
    check_against_triangle(s, pose, n % 2 == 0, mink::Sphere{s.radius},
                           mink::Shape::sphere(s.radius).value());
  }
}

TEST(PointSetPair, NeedlesNearlyParallel) {
  oracle::Rng rng(6602);
  for (int n = 0; n < 1500; ++n) {
    Scene s = make_scene(rng, true);
    SCOPED_TRACE(testing::Message() << "case " << n << ", offset " << s.offset);
    check_pair(s, polytope(s.a), polytope(s.b));
  }
}

TEST(PointSetPair, SegmentBesideTwinSegmentsHasItsPairAlongTheNormal) {
  // Stop 62's exact probe (gen2.py, seed 32): a segment against two copies of a segment
  // 1e-13 apart (a 4-point needle), 1e-7 rad from parallel, 3.7944707610329096e-08 apart
  // (exact rational arithmetic). The closest pair met the needle's 1e-13 end edge inside, and
  // its direction, made orthogonal to that edge, came out 0.4 rad off: point_b - point_a lay
  // 1.9e-9 of the size off distance x normal.
  const std::vector<Vec3> a = {{-2.6336989316703496, -0.1159524004059812, 1.2356741968842602},
                               {-1.4835790661293247, 1.8618605751287731, 1.1121038436991368}};
  const std::vector<Vec3> b = {{-3.6527044612797606, -1.8682934958165247, 1.3451576191388908},
                               {-1.9956312896388666, 0.9813057601749743, 1.167119229758487},
                               {-3.6527044612797344, -1.8682934958165265, 1.3451576191389738},
                               {-1.9956312896386248, 0.9813057601750913, 1.1671192297585589}};
  Scene s;
  s.a = a;
  s.b = b;
  s.offset = 3.7944707610329096e-08;
  s.size = 7.229141935323582;  // the probe's: the sum of the bounding radii about the origin
  check_pair(s, mink::Segment{a[0], a[1]}, polytope(b));
}

// A segment or triangle lying 3e-10 to 3e-7 rad from a box's top face, its lowest corner
// `offset` above the face (or below it), every corner's shadow on the face at least a tenth of
// the face's half width inside it. The answer is exact by construction: the signed distance is
// the offset, along the face's normal, between the lowest corner and its shadow on the face (a
// single pair: the other corners stand higher). Stop 66's probe (gen4.py, BOXSEG=hair): a triangle
// 8e-9 rad from a face ran GJK to its cap, segments 5e-9 rad from a face got normals 1.8e-9 of the
// size off.
TEST(PointSetPair, SetNearlyParallelToABoxFace) {
  oracle::Rng rng(6701);
  for (int n = 0; n < 1500; ++n) {
    const double scale = rng.log_uniform(0.1, 10);
    const Vec3 half(scale * rng.uniform(0.2, 1), scale * rng.uniform(0.2, 1),
                    scale * rng.uniform(0.2, 1));
    const double offset = draw_offset(rng, scale);
    const double tilt = rng.log_uniform(3e-10, 3e-7);
    const int corners = rng.chance(0.5) ? 2 : 3;
    // The corners' shadows, and their heights: the first lowest, the others up the tilt.
    std::vector<Vec3> local;
    for (int k = 0; k < corners; ++k) {
      const Vec3 shadow(rng.uniform(-0.9, 0.9) * half.x(), rng.uniform(-0.9, 0.9) * half.y(), 0);
      const double rise = k == 0 ? 0 : tilt * (shadow - Vec3(local[0].x(), local[0].y(), 0)).norm();
      local.push_back(shadow + Vec3(0, 0, half.z() + offset + rise));
    }
    const Pose pose = Pose::from(rng.in_ball(scale), rng.rotation());
    std::vector<Vec3> world;
    for (const Vec3& p : local) world.push_back(pose.apply(p));
    const mink::Box box{half};
    const double size = 2 * (pose.translation.norm() + 2 * (half.norm() + scale));
    SCOPED_TRACE(testing::Message() << "case " << n << ", offset " << offset << ", tilt " << tilt
                                    << ", corners " << corners);
    const Vec3 lowest = world[0], shadow = pose.apply(Vec3(local[0].x(), local[0].y(), half.z()));
    const Vec3 up = pose.rotation.col(2);
    // The world corners carry their rounding (1e-16 of the translation): within the bar.
    auto expect_answer = [&](bool swapped, double value, const Vec3& normal, const Vec3& on_box,
                             const Vec3& on_set) {
      const double bar = 1e-9 * size;
      EXPECT_NEAR(value, offset, bar);
      EXPECT_LE((normal - (swapped ? -up : up)).norm() * size, bar) << "normal " << normal;
      EXPECT_LE((on_box - shadow).norm(), bar);
      EXPECT_LE((on_set - lowest).norm(), bar);
    };
    for (const bool swapped : {false, true}) {
      SCOPED_TRACE(swapped ? "set, box" : "box, set");
      auto check = [&](const auto& set) {
        const auto c =
            swapped ? mink::contact(set, Pose{}, box, pose) : mink::contact(box, pose, set, Pose{});
        ASSERT_TRUE(c.status == mink::Status::Separated || c.status == mink::Status::Intersecting)
            << oracle::describe(c);
        expect_answer(swapped, c.intersect ? -c.depth : c.distance, c.normal,
                      swapped ? c.point_b : c.point_a, swapped ? c.point_a : c.point_b);
        const auto d = swapped ? mink::distance(set, Pose{}, box, pose)
                               : mink::distance(box, pose, set, Pose{});
        ASSERT_TRUE(d.status == mink::Status::Separated || d.status == mink::Status::Intersecting);
        EXPECT_EQ(d.intersect, c.intersect);
        if (!d.intersect)
          expect_answer(swapped, d.distance, d.normal, swapped ? d.point_b : d.point_a,
                        swapped ? d.point_a : d.point_b);
        const auto i = swapped ? mink::intersect(set, Pose{}, box, pose)
                               : mink::intersect(box, pose, set, Pose{});
        EXPECT_NE(i.status, mink::Status::IterationLimit);
        EXPECT_EQ(i.intersect, c.intersect);
      };
      if (corners == 2)
        check(mink::Segment{world[0], world[1]});
      else
        check(mink::Triangle{world[0], world[1], world[2]});
    }
  }
}

}  // namespace point_set_pair_test
