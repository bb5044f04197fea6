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

}  // namespace
