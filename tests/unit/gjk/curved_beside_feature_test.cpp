// A curved core (an ellipsoid, plain or rounded) just apart from a face, an edge or a corner of a
// box or an 8-point polytope, where the answer is known exactly by construction: the curved
// shape is placed so that its support point along -n lies `gap` beyond a point e of the
// feature along n, with n inside the feature's cone of normals. The plane through e orthogonal
// to n then has the box on one side and the ellipsoid `gap` away on the other, so the distance
// is the gap, the normal n and the closest points e and e + gap n (the ellipsoid is strictly
// convex: its point is the only one). Placed `depth` beyond e the other way, the shapes overlap
// and n gives them a separation of `depth`; that it is the least, so that n is the contact's
// normal, the long-double search of tests/oracle/curved.hpp confirms (else the scene is skipped).
//
// At an edge the support function of A - B has a kink along a circle of directions and the
// minimum lies on it; at a face or corner, on a point where kinks meet. The probe of stop 51
// (tests/slow/probe_stop51, F3) found normals there 5e-7 to 2.4e-6 rad off and points 1.3e-7
// of the size off, in one argument order only: a Newton step that crossed the kink, and a
// kink that lay further from GJK's normal than the secant's straddle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "mink/mink.hpp"
#include "oracle/check.hpp"
#include "oracle/curved.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Mat3;
using mink::Pose;
using mink::Shape;
using mink::Vec3;

enum class BesideFeature { Face, Edge, Corner };

struct BesideScene {
  Shape polyhedral, curved;
  Pose pose_polyhedral, pose_curved;
  Vec3 contact;      // e: on the polyhedral shape, world frame
  Vec3 normal;       // n: from the polyhedral shape towards the curved one
  double gap = 0;    // < 0: the shapes overlap by -gap
  Vec3 half, radii;  // the box's half extents, the ellipsoid's radii (for the oracle)
  BesideFeature feature = BesideFeature::Face;
  double size = 0;
  std::string note;
};

const char* feature_name(BesideFeature f) {
  return f == BesideFeature::Face ? "face" : f == BesideFeature::Edge ? "edge" : "corner";
}

enum class Placement { Apart, Overlapping, Touching };

BesideScene make_scene(std::uint64_t seed, Placement placement) {
  const bool overlapping = placement == Placement::Overlapping;
  oracle::Rng rng(seed);
  BesideScene s;
  const Vec3 half(rng.uniform(0.1, 1.5), rng.uniform(0.1, 1.5), rng.uniform(0.1, 1.5));
  s.half = half;
  const bool as_polytope = rng.chance(0.5);
  if (as_polytope) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
      corners.emplace_back(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(),
                           i & 4 ? half.z() : -half.z());
    s.polyhedral = Shape::polytope(corners).value();
  } else {
    s.polyhedral = Shape::box(half).value();
  }
  const double far = rng.chance(0.2) ? 1e3 : 0;
  s.pose_polyhedral = Pose::from(rng.in_ball(3) + Vec3::Constant(far), rng.rotation());

  // The feature, a point e on it and a normal n in its cone (box frame), from the sign of each
  // axis and which axes are free.
  const auto feature = static_cast<BesideFeature>(rng.integer(0, 2));
  s.feature = feature;
  const int free_axes = feature == BesideFeature::Face ? 2 : feature == BesideFeature::Edge ? 1 : 0;
  const int first = rng.integer(0, 2);
  Vec3 e, n = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const int axis = (first + k) % 3;
    const double sign = rng.chance(0.5) ? 1 : -1;
    if (k < free_axes) {
      e[axis] = rng.uniform(-0.8, 0.8) * half[axis];
    } else {
      e[axis] = sign * half[axis];
      n[axis] = sign * rng.uniform(0.05, 1);
    }
  }
  n.normalize();
  const Mat3& r = s.pose_polyhedral.rotation;
  s.contact = r * e + s.pose_polyhedral.translation;
  s.normal = r * n;

  // An ellipsoid, maybe rounded, whose support point along -n is e + gap n.
  const Vec3 radii(rng.uniform(0.05, 1), rng.uniform(0.05, 1), rng.uniform(0.05, 1));
  s.radii = radii;
  const double margin = !overlapping && rng.chance(0.3) ? rng.uniform(0.001, 0.2) : 0;
  const Shape ellipsoid = Shape::ellipsoid(radii).value();
  s.curved = margin > 0 ? Shape::rounded(ellipsoid, margin).value() : ellipsoid;
  const mink::Quat q = rng.rotation();
  const Vec3 d = q.conjugate() * (-s.normal);  // -n in the ellipsoid's frame
  const Vec3 scaled = radii.cwiseProduct(d);
  const Vec3 local_support = radii.cwiseProduct(scaled) / scaled.norm() + margin * d;
  s.size = half.norm() + radii.maxCoeff() + margin;
  s.gap = placement == Placement::Touching ? s.size * rng.uniform(-1e-13, 1e-13)
          : overlapping                    ? -s.size * rng.log_uniform(1e-9, 1e-2)
                                           : s.size * rng.log_uniform(1e-9, 1e-1);
  const Vec3 target = s.contact + s.gap * s.normal;
  s.pose_curved = Pose::from(target - q * local_support, q);
  s.note = std::string(feature_name(feature)) + (as_polytope ? " of a polytope" : " of a box") +
           (margin > 0 ? ", rounded ellipsoid" : ", ellipsoid") +
           ", gap/size = " + std::to_string(s.gap / s.size) + ", " + oracle::seed_note(seed);
  return s;
}

// One argument order: `flip` puts the curved shape first, which turns the normal round.
template <class Result>
void expect_exact(const BesideScene& s, const Result& r, bool flip, double beside_far_rounding) {
  const double tolerance = 1e-9 * s.size + beside_far_rounding;
  const Vec3 normal = flip ? Vec3(-s.normal) : s.normal;
  const Vec3 on_polyhedral = s.contact, on_curved = s.contact + s.gap * s.normal;
  const Vec3 expected_a = flip ? on_curved : on_polyhedral;
  const Vec3 expected_b = flip ? on_polyhedral : on_curved;
  const std::string order = flip ? " (curved shape first)" : " (polyhedral shape first)";
  if (s.gap > 0) {
    ASSERT_EQ(r.status, mink::Status::Separated) << s.note << order;
    EXPECT_NEAR(r.distance, s.gap, tolerance) << s.note << order;
  } else {
    ASSERT_EQ(r.status, mink::Status::Intersecting) << s.note << order;
    if constexpr (requires { r.depth; }) {
      EXPECT_NEAR(r.depth, -s.gap, tolerance) << s.note << order;
    }
  }
  // The normal's own bound: it turns the points by its angle times their lever, the size.
  EXPECT_LE(oracle::angle(r.normal, normal), 1e-9) << s.note << order;
  EXPECT_LE((r.point_a - expected_a).norm(), tolerance) << s.note << order;
  EXPECT_LE((r.point_b - expected_b).norm(), tolerance) << s.note << order;
}

double beside_far_rounding(const BesideScene& s) {
  return oracle::world_rounding(s.pose_polyhedral.translation);
}

TEST(CurvedBesideFeature, DistanceAndNormalAreExactInBothOrders) {
  const int count = oracle::sweep_count(600, 200);
  for (int i = 0; i < count; ++i) {
    const BesideScene s = make_scene(9100 + i, Placement::Apart);
    const double rounding = beside_far_rounding(s);
    expect_exact(s, mink::distance(s.polyhedral, s.pose_polyhedral, s.curved, s.pose_curved), false,
                 rounding);
    expect_exact(s, mink::distance(s.curved, s.pose_curved, s.polyhedral, s.pose_polyhedral), true,
                 rounding);
    expect_exact(s, mink::contact(s.polyhedral, s.pose_polyhedral, s.curved, s.pose_curved), false,
                 rounding);
    expect_exact(s, mink::contact(s.curved, s.pose_curved, s.polyhedral, s.pose_polyhedral), true,
                 rounding);
    if (::testing::Test::HasFailure()) break;  // one scene's messages, not hundreds
  }
}

TEST(CurvedBesideFeature, DepthAndNormalAreExactInBothOrders) {
  const int count = oracle::sweep_count(200, 40);
  int confirmed = 0;
  for (int i = 0; i < count; ++i) {
    const BesideScene s = make_scene(19100 + i, Placement::Overlapping);
    // The oracle's least separation: n's own is the depth, so n is the normal when no direction
    // does better.
    const oracle::CurvedShape box{oracle::CurvedKind::Box, 0, 0, s.half.cast<oracle::Real>()};
    const oracle::CurvedShape ellipsoid{oracle::CurvedKind::Ellipsoid, 0, 0,
                                        s.radii.cast<oracle::Real>()};
    const auto least = oracle::curved_depth(box,
                                            {s.pose_polyhedral.rotation.cast<oracle::Real>(),
                                             s.pose_polyhedral.translation.cast<oracle::Real>()},
                                            ellipsoid,
                                            {s.pose_curved.rotation.cast<oracle::Real>(),
                                             s.pose_curved.translation.cast<oracle::Real>()});
    if (static_cast<double>(least.depth) < -s.gap - 1e-12 * s.size) continue;
    ++confirmed;
    const double rounding = beside_far_rounding(s);
    expect_exact(s, mink::contact(s.polyhedral, s.pose_polyhedral, s.curved, s.pose_curved), false,
                 rounding);
    expect_exact(s, mink::contact(s.curved, s.pose_curved, s.polyhedral, s.pose_polyhedral), true,
                 rounding);
    if (::testing::Test::HasFailure()) return;
  }
  // Most scenes have n as their normal: the test checks something.
  EXPECT_GE(confirmed, count * 3 / 4);
}

TEST(CurvedBesideFeature, TouchingPointsAreTheContact) {
  // Touching to 1e-13 of the size: GJK's closest points, combinations of support points from
  // several directions, lay a chord of the ellipsoid off the contact (4e-7 of the size, probe
  // 52's W-face). Both points must be e; beside a face the normal is its normal (at an edge or a
  // corner any normal of its cone is right: there the minimum is flat to the gap).
  const int count = oracle::sweep_count(300, 100);
  for (int i = 0; i < count; ++i) {
    const BesideScene s = make_scene(29100 + i, Placement::Touching);
    const double tolerance = 1e-9 * s.size + beside_far_rounding(s);
    for (const bool flip : {false, true}) {
      const std::string order = flip ? " (curved shape first)" : " (polyhedral shape first)";
      const mink::ContactResult r =
          flip ? mink::contact(s.curved, s.pose_curved, s.polyhedral, s.pose_polyhedral)
               : mink::contact(s.polyhedral, s.pose_polyhedral, s.curved, s.pose_curved);
      ASSERT_TRUE(r.intersect) << s.note << order;
      EXPECT_LE(r.depth, tolerance) << s.note << order;
      EXPECT_LE((r.point_a - s.contact).norm(), tolerance) << s.note << order;
      EXPECT_LE((r.point_b - s.contact).norm(), tolerance) << s.note << order;
      if (s.feature == BesideFeature::Face) {
        EXPECT_LE(oracle::angle(r.normal, flip ? Vec3(-s.normal) : s.normal), 1e-9)
            << s.note << order;
      }
    }
    if (::testing::Test::HasFailure()) break;
  }
}

// A line on each shape's surface, the two crossing: a cone's or a cylinder's side line (A) across
// a box's edge or another cylinder's or cone's side line (B). Each line is given in its shape's
// frame by a point on it, its direction and the outward normal there (a normal of the surface
// all along the line). A sits at the origin with its line through P, direction d and normal n;
// B is turned so that its line runs through P along e (d turned by psi about n) with outward
// normal -n, and then pushed `depth` along -n. The plane through P orthogonal to n holds both
// lines and has A and B on either side (touching), or B's line `depth` below it: h of A - B has
// kinks across both lines at n, so n is the normal, the depth is `depth`, and the points are P
// on A and P - depth n on B. Both cores show an edge on their support planes, so neither has a
// single point there: GJK's points, combinations of the edges' ends, lay 1.4e-9 of the size off
// the box (the slow oracle sweep's DistanceMatchesOracle, scale 80: a cone touching a box's edge,
// axes parallel), and EPA's, with its normal 1e-9 rad off, up to 1.3e-5 of the size.
struct SideLine {
  Shape shape;
  Vec3 point, direction, normal;  // in the shape's frame; direction and normal unit, orthogonal
  double size = 0;                // bounding radius
  std::string note;
};

SideLine make_side_line(oracle::Rng& rng, int kind) {
  SideLine l;
  const double phi = rng.uniform(-std::numbers::pi, std::numbers::pi);
  const Vec3 radial(std::cos(phi), std::sin(phi), 0);
  if (kind == 0) {  // a box's edge along y, between its +x and +z faces
    const Vec3 half(rng.uniform(0.1, 1.5), rng.uniform(0.1, 1.5), rng.uniform(0.1, 1.5));
    const double alpha = rng.uniform(0.25, std::numbers::pi / 2 - 0.25);
    l.shape = Shape::box(half).value();
    l.point = Vec3(half.x(), rng.uniform(-0.7, 0.7) * half.y(), half.z());
    l.direction = Vec3::UnitY();
    l.normal = Vec3(std::cos(alpha), 0, std::sin(alpha));
    l.size = half.norm();
    l.note = "box edge";
  } else if (kind == 1) {  // a cylinder's side line
    const double r = rng.uniform(0.1, 1.5), h = rng.uniform(0.1, 1.5);
    l.shape = Shape::cylinder(r, h).value();
    l.point = r * radial + Vec3(0, 0, rng.uniform(-0.7, 0.7) * h);
    l.direction = Vec3::UnitZ();
    l.normal = radial;
    l.size = std::hypot(r, h);
    l.note = "cylinder side";
  } else {  // a cone's side line, apex to rim
    const double r = rng.uniform(0.1, 2), h = rng.uniform(0.1, 1.5);
    const Vec3 apex(0, 0, h), rim = r * radial - Vec3(0, 0, h);
    l.shape = Shape::cone(r, h).value();
    l.point = apex + rng.uniform(0.15, 0.85) * (rim - apex);
    l.direction = (rim - apex).normalized();
    l.normal = (2 * h * radial + Vec3(0, 0, r)).normalized();
    l.size = std::hypot(r, h);
    l.note = "cone side";
  }
  return l;
}

TEST(CurvedBesideFeature, CrossingSideLinesMeetAtTheCrossing) {
  const int count = oracle::sweep_count(40, 10);
  int cases = 0, within_close = 0;
  for (const int kind_a : {1, 2}) {
    for (const int kind_b : {0, 1, 2}) {
      for (int i = 0; i < count; ++i) {
        const std::uint64_t seed = 29900 + 1000 * (3 * kind_a + kind_b) + i;
        oracle::Rng rng(seed);
        const SideLine a = make_side_line(rng, kind_a), b = make_side_line(rng, kind_b);
        const double psi = rng.uniform(0.35, std::numbers::pi - 0.35);
        const Vec3 e = std::cos(psi) * a.direction + std::sin(psi) * a.normal.cross(a.direction);
        // B's frame: its (normal, direction) onto (-n, e).
        Mat3 from, to;
        from << b.normal, b.direction, b.normal.cross(b.direction);
        to << -a.normal, e, (-a.normal).cross(e);
        const Mat3 turn = to * from.transpose();
        const double size = a.size + b.size;
        // Touching, penetrating, or apart (a negative depth: the gap).
        const double pick = rng.uniform(0, 1);
        const double depth = pick < 0.2   ? 0
                             : pick < 0.6 ? size * rng.log_uniform(1e-9, 1e-2)
                                          : -size * rng.log_uniform(1e-9, 1e-1);
        const Vec3 centre_b = a.point - turn * b.point - depth * a.normal;
        // The whole scene moved rigidly, sometimes far from the origin.
        const Pose motion =
            Pose::from(rng.in_ball(3) + Vec3::Constant(rng.chance(0.2) ? 1e3 : 0), rng.rotation());
        const Pose pose_a = motion;
        const Pose pose_b =
            Pose::from(motion.apply(centre_b), mink::Quat(Mat3(motion.rotation * turn)));
        const Vec3 on_a = motion.apply(a.point),
                   on_b = motion.apply(Vec3(a.point - depth * a.normal));
        const Vec3 normal = motion.rotate(a.normal);
        const double tolerance = 1e-9 * size + oracle::world_rounding(motion.translation);
        // What the crossing gives (1e-15 of the size; apart, GJK's bracket on the distance
        // leaves up to 2.3e-13), against 1.4e-9 to 1.3e-5 before.
        const double close = 1e-12 * size + oracle::world_rounding(motion.translation);
        const std::string note = a.note + " across " + b.note + ", depth/size " +
                                 std::to_string(depth / size) + ", " + oracle::seed_note(seed);
        for (const bool flip : {false, true}) {
          const std::string order = flip ? " (B first)" : " (A first)";
          const mink::ContactResult c = flip ? mink::contact(b.shape, pose_b, a.shape, pose_a)
                                             : mink::contact(a.shape, pose_a, b.shape, pose_b);
          const mink::DistanceResult d = flip ? mink::distance(b.shape, pose_b, a.shape, pose_a)
                                              : mink::distance(a.shape, pose_a, b.shape, pose_b);
          ASSERT_EQ(c.intersect, depth >= 0) << note << order;
          ASSERT_EQ(d.intersect, depth >= 0) << note << order;
          EXPECT_NEAR(c.depth - c.distance, depth, tolerance) << note << order;
          EXPECT_LE(oracle::angle(c.normal, flip ? Vec3(-normal) : normal), 1e-9) << note << order;
          const Vec3 expected_a = flip ? on_b : on_a, expected_b = flip ? on_a : on_b;
          auto off = [&](const auto& r) {
            return std::max((r.point_a - expected_a).norm(), (r.point_b - expected_b).norm());
          };
          EXPECT_LE(off(c), tolerance) << note << order;
          ++cases;
          if (off(c) <= close) ++within_close;
          if (depth < 0) {
            EXPECT_NEAR(d.distance, -depth, tolerance) << note << order;
            EXPECT_LE(oracle::angle(d.normal, flip ? Vec3(-normal) : normal), 1e-9)
                << note << order;
            EXPECT_LE(off(d), tolerance) << note << order;
            ++cases;
            if (off(d) <= close) ++within_close;
          }
        }
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
  // Every answer is the crossing to 1e-12 of the size, not merely within the bar.
  EXPECT_EQ(within_close, cases);
}

}  // namespace
