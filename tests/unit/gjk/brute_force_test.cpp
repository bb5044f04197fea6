// GJK distance and intersect against brute force (tests/oracle/brute_force.hpp): box pairs by the
// separating-axis test and by the Minkowski difference of their corners, and pairs of small point
// sets (including 1-, 2- and 3-point and flat sets) by the Minkowski difference of their points.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>
#include <vector>

#include "mink/mink.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/check.hpp"
#include "oracle/contact_check.hpp"
#include "oracle/penetration.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Vec3;
using oracle::Real;
using oracle::Rng;
using oracle::V3;
using oracle::widen;

Real max_dot(const std::vector<V3>& points, const V3& n) {
  Real best = -std::numeric_limits<Real>::infinity();
  for (const V3& p : points) best = std::max(best, n.dot(p));
  return best;
}

/// The witnesses lie on the support planes of the two sets along the normal (tolerance 1e-9
/// relative to size + position), which with point_b - point_a = distance * normal pins them to
/// the closest features even when they are not unique.
void expect_witnesses_on_support_planes(const mink::DistanceResult& got,
                                        const std::vector<V3>& a_points,
                                        const std::vector<V3>& b_points, double scale) {
  if (got.status != mink::Status::Separated) return;
  const V3 n = widen(got.normal);
  const double ha = static_cast<double>(max_dot(a_points, n));
  const double hb = static_cast<double>(max_dot(b_points, V3(-n)));
  EXPECT_NEAR(got.normal.dot(got.point_a), ha, 1e-9 * scale)
      << "point_a is not on A's support plane along the normal (tolerance 1e-9 * " << scale << ")";
  EXPECT_NEAR(-got.normal.dot(got.point_b), hb, 1e-9 * scale)
      << "point_b is not on B's support plane along -normal (tolerance 1e-9 * " << scale << ")";
}

TEST(GjkDistance, BoxBoxMatchesBruteForceAndSat) {
  const std::uint64_t base = 10000;
  const int n = oracle::sweep_count(1000, 300);
  oracle::Worst worst("box-box");
  int sat_separated = 0;
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
    const Pose pb = Pose::from(pa.translation + rng.in_ball(1.3 * size), rng.rotation());
    const oracle::WorldBox wa{widen(a.half_extents), widen(pa.rotation), widen(pa.translation)};
    const oracle::WorldBox wb{widen(b.half_extents), widen(pb.rotation), widen(pb.translation)};
    const auto ca = oracle::box_corners(wa), cb = oracle::box_corners(wb);
    const auto expected = oracle::polytope_pair(ca, cb);
    const auto sat = oracle::sat_box_box(wa, wb);
    const double band = oracle::kTouchingBand * size;
    // The two oracles must agree on the flag, and SAT bounds the distance from below.
    if (sat.separation > band) {
      ++sat_separated;
      ASSERT_GT(expected.gap, 0) << "oracles disagree: SAT separation " << (double)sat.separation;
      ASSERT_GE(expected.distance, sat.separation - Real(1e-12) * size);
    } else if (sat.separation < -band) {
      ASSERT_LE(expected.gap, 0) << "oracles disagree: SAT separation " << (double)sat.separation;
    }
    const auto got = mink::distance(a, pa, b, pb);
    const auto got_bool = mink::intersect(a, pa, b, pb);
    oracle::expect_matches(expected, got, got_bool, size, pa.translation.norm(), false, worst);
    if (sat.separation > band) {
      EXPECT_GE(got.distance, double(sat.separation) - 1e-10 * size);
    }
    expect_witnesses_on_support_planes(got, ca, cb, size + pa.translation.norm());
  }
  EXPECT_GT(sat_separated, n / 4) << "the sweep should be mostly separated cases";
}

/// A random small point set in a local frame: 1 to 8 points, sometimes flat, collinear, or with
/// duplicates, of scale about `scale`.
std::vector<Vec3> random_point_set(Rng& rng, double scale) {
  const int count = rng.integer(1, 8);
  const int kind = rng.integer(0, 5);
  std::vector<Vec3> pts;
  const Vec3 u = rng.unit(), v = rng.unit();
  for (int i = 0; i < count; ++i) {
    Vec3 p = rng.in_ball(scale);
    if (kind == 0) p = p - p.dot(u) * u;                // flat: in the plane normal to u
    if (kind == 1) p = rng.uniform(-scale, scale) * v;  // collinear
    if (kind == 2 && i > 0 && rng.chance(0.5)) p = pts[rng.integer(0, i - 1)];  // duplicates
    pts.push_back(p);
  }
  return pts;
}

TEST(GjkDistance, PolytopePairMatchesBruteForce) {
  const std::uint64_t base = 20000;
  const int n = oracle::sweep_count(3000, 1000);
  oracle::Worst worst("polytope-polytope");
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const double sa = rng.log_uniform(0.05, 2), sb = rng.log_uniform(0.05, 2);
    const auto la = random_point_set(rng, sa), lb = random_point_set(rng, sb);
    const auto a = mink::Polytope::make(la), b = mink::Polytope::make(lb);
    ASSERT_TRUE(a && b);
    const double size = a->bounding_radius() + b->bounding_radius() + 1e-3;
    const Pose pa = rng.pose(5);
    const Pose pb = Pose::from(pa.translation + rng.in_ball(1.0 * (sa + sb)), rng.rotation());
    std::vector<V3> wa, wb;
    for (const Vec3& p : la) wa.push_back(widen(pa.rotation) * widen(p) + widen(pa.translation));
    for (const Vec3& p : lb) wb.push_back(widen(pb.rotation) * widen(p) + widen(pb.translation));
    const auto expected = oracle::polytope_pair(wa, wb);
    const auto got = mink::distance(*a, pa, *b, pb);
    const auto got_bool = mink::intersect(*a, pa, *b, pb);
    oracle::expect_matches(expected, got, got_bool, size, pa.translation.norm(), false, worst);
    expect_witnesses_on_support_planes(got, wa, wb, size + pa.translation.norm());
  }
}

/// Box pairs where the closest features are a vertex or a face over a face, or two crossing
/// edges, which distance() and contact() answer from the separating axis in closed form
/// (box_box_closest()), against brute force over the corners: generic poses, boxes turned by
/// multiples of 90 degrees (exact and rounded ties), faces stacked parallel with a twist about
/// their normal, flat and needle boxes, 1e3 scale ratios, 1e6 from the origin, and rounded boxes.
TEST(GjkDistance, BoxBoxClosedFormMatchesBruteForce) {
  const std::uint64_t base = 90000;
  const int n = oracle::sweep_count(1500, 250);
  oracle::Worst worst("box-box closed form");
  oracle::DepthWorst contact_worst("contact box-box closed form");
  int closed_form[5] = {}, separated[5] = {};
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const int kind = i % 5;
    auto extents = [&rng](double scale) {
      Vec3 h(rng.log_uniform(0.05, 1), rng.log_uniform(0.05, 1), rng.log_uniform(0.05, 1));
      for (int k = 0; k < 3; ++k)
        if (rng.chance(0.1)) h[k] = 0;  // flat, needle or point boxes
      return Vec3(scale * h);
    };
    const double ratio = rng.chance(0.2) ? (rng.chance(0.5) ? 1e-3 : 1e3) : 1.0;
    const mink::Box a{extents(1.0)}, b{extents(ratio)};
    const double radius_a = rng.chance(0.2) ? rng.uniform(0, 0.1) : 0.0;
    const double radius_b = rng.chance(0.2) ? rng.uniform(0, 0.1) * ratio : 0.0;
    const double size = a.half_extents.norm() + b.half_extents.norm() + radius_a + radius_b + 1e-3;
    const double far = rng.chance(0.2) ? 1e6 : 5;
    Pose pa = rng.pose(far);
    Pose pb;
    // Rotations by multiples of 90 degrees about the axes, as quaternions (their matrices carry
    // 1e-16 where the exact ones have 0) or as exact matrices.
    auto quarter_turns = [&rng](bool exact) {
      mink::Quat q = mink::Quat::Identity();
      for (int k = 0; k < 3; ++k)
        q = q *
            mink::Quat(Eigen::AngleAxisd(rng.integer(0, 3) * std::numbers::pi / 2, Vec3::Unit(k)));
      mink::Mat3 r = q.toRotationMatrix();
      if (exact) r = r.array().round().matrix();
      return r;
    };
    switch (kind) {
      case 0:  // generic
        pb = Pose::from(pa.translation + rng.in_ball(1.5 * size), rng.rotation());
        break;
      case 1:  // axis-aligned boxes, turned by exact or rounded quarter turns
        pa.rotation = quarter_turns(rng.chance(0.5));
        pb.rotation = quarter_turns(rng.chance(0.5));
        pb.translation = pa.translation + rng.in_ball(1.5 * size);
        break;
      case 2:  // B stacked over one of A's faces, twisted about the face's normal
      case 3: {
        const int axis = rng.integer(0, 2);
        const double side = rng.chance(0.5) ? 1 : -1;
        Vec3 offset = rng.in_cube(1.0).cwiseProduct(a.half_extents + b.half_extents);
        // Apart, or pushed in (the deepest points then come from the same closed form).
        const double gap = (rng.chance(0.7) ? 1 : -0.1) * rng.log_uniform(1e-9, 0.5) * size;
        offset[axis] =
            side * (a.half_extents[axis] + b.half_extents[axis] + radius_a + radius_b + gap);
        const double twist = kind == 2 ? rng.uniform(-std::numbers::pi, std::numbers::pi) : 0.0;
        pb.rotation = pa.rotation * Eigen::AngleAxisd(twist, Vec3::Unit(axis)).toRotationMatrix();
        pb.translation = pa.translation + pa.rotation * offset;
        break;
      }
      default:  // crossing edges: B's edge over A's edge, turned about the line joining them
        pb = Pose::from(pa.translation + rng.in_ball(1.5 * size), rng.rotation());
        pb.translation =
            pa.translation +
            pa.rotation * (a.half_extents + b.half_extents)
                              .cwiseProduct(Vec3(rng.uniform(0.6, 1.4), rng.uniform(0.6, 1.4), 0)) +
            pa.rotation * Vec3(0, 0, rng.uniform(-0.5, 0.5) * size);
        break;
    }
    const oracle::WorldBox wa{widen(a.half_extents), widen(pa.rotation), widen(pa.translation)};
    const oracle::WorldBox wb{widen(b.half_extents), widen(pb.rotation), widen(pb.translation)};
    const auto ca = oracle::box_corners(wa), cb = oracle::box_corners(wb);
    auto expected = oracle::polytope_pair(ca, cb);
    expected.gap -= radius_a + radius_b;
    expected.distance = std::max(Real(0), expected.distance - radius_a - radius_b);
    expected.point_a += Real(radius_a) * expected.normal;
    expected.point_b -= Real(radius_b) * expected.normal;
    const mink::Rounded<mink::Box> ra{a, radius_a}, rb{b, radius_b};
    const auto got = mink::distance(ra, pa, rb, pb);
    const auto got_bool = mink::intersect(ra, pa, rb, pb);
    oracle::expect_matches(expected, got, got_bool, size, pa.translation.norm(), false, worst);
    const auto got_contact = mink::contact(ra, pa, rb, pb);
    const oracle::SupportFn support_a = [&](const V3& u) {
      return oracle::box_support(wa)(u) + Real(radius_a) * u.norm();
    };
    const oracle::SupportFn support_b = [&](const V3& u) {
      return oracle::box_support(wb)(u) + Real(radius_b) * u.norm();
    };
    // The depth by facet enumeration over the 64 corner differences only where the pair may
    // overlap: for separated convex sets the least support of A - B over unit directions is minus
    // their distance (the separating direction attains it), which brute force has just given.
    // The enumeration was two thirds of this test's time.
    const double gap = static_cast<double>(expected.gap);
    const Real expected_depth =
        gap > 2 * oracle::kTouchingBand * size
            ? -expected.gap
            : oracle::least_support_of_difference(ca, cb) + Real(radius_a + radius_b);
    oracle::expect_contact_matches(expected_depth, support_a, support_b, got_contact, size,
                                   pa.translation.norm(), contact_worst);
    if (gap > oracle::kTouchingBand * size) {
      ++separated[kind];
      if (got.iterations == 0) ++closed_form[kind];
      ASSERT_EQ(got_contact.status, mink::Status::Separated);
      EXPECT_LE(std::abs(got_contact.distance - got.distance), 1e-12 * size);
      EXPECT_LE(
          (got_contact.point_b - got_contact.point_a - got_contact.distance * got_contact.normal)
              .norm(),
          1e-10 * (size + pa.translation.norm()));
      if (radius_a == 0 && radius_b == 0)
        expect_witnesses_on_support_planes(got, ca, cb, size + pa.translation.norm());
    }
  }
  // The closed form must carry its share of each kind (else it has gone dead). The rest are
  // pairs whose closest features are a vertex and a vertex or an edge, or two parallel edges
  // (most of the diagonal offsets of quarter-turned boxes), whose direction is none of the 15
  // axes: GJK's.
  const char* names[5] = {"generic", "quarter turns", "stacked, twisted", "stacked", "edges"};
  const double least_share[5] = {0.3, 0.25, 0.6, 0.9, 0.5};
  for (int kind = 0; kind < 5; ++kind) {
    std::printf("[  boxes   ] %s: %d of %d separated pairs in closed form\n", names[kind],
                closed_form[kind], separated[kind]);
    EXPECT_GE(closed_form[kind], least_share[kind] * separated[kind]) << names[kind];
  }
}

}  // namespace
