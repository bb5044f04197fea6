// The penetration oracles (tests/oracle/penetration.hpp) checked against hand-computed cases, each
// other, the distance oracles of brute_force.hpp and sampling, so that a disagreement with mink's
// contact() can be blamed on mink. No mink algorithm is involved here.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "oracle/analytic.hpp"
#include "oracle/brute_force.hpp"
#include "oracle/penetration.hpp"
#include "oracle/random.hpp"

namespace {

using oracle::Real;
using oracle::Rng;
using oracle::V3;
using oracle::widen;

oracle::M3 random_rotation(Rng& rng) {
  return widen(mink::Mat3(rng.rotation().toRotationMatrix()));
}

std::vector<V3> random_points(Rng& rng, int count, double scale, const V3& centre) {
  std::vector<V3> pts;
  for (int i = 0; i < count; ++i) pts.push_back(widen(rng.in_ball(scale)) + centre);
  return pts;
}

TEST(ContactOracle, HandComputedHulls) {
  // Unit corner tetrahedron shifted by -(0.1, 0.1, 0.1): the faces x = -0.1, y = -0.1, z = -0.1
  // are 0.1 from the origin, the slanted one (1 - 0.3) / sqrt(3) = 0.404.
  const V3 s(0.1, 0.1, 0.1);
  const auto tet =
      oracle::hull_depth({V3(0, 0, 0) - s, V3(1, 0, 0) - s, V3(0, 1, 0) - s, V3(0, 0, 1) - s});
  EXPECT_TRUE(tet.full_dimensional);
  EXPECT_NEAR(double(tet.depth), 0.1, 1e-18);
  EXPECT_NEAR(double(oracle::support_of({V3(1, 2, 3), V3(-4, 0, 1)}, V3(0, 0, 1))), 3, 0);
  // Shifted so that the slanted face is nearest: (0.3, 0.3, 0.3) from the corner, the face is
  // (1 - 0.9) / sqrt(3) = 0.0577 away, the others 0.3.
  const V3 t(0.3, 0.3, 0.3);
  const auto tet2 = oracle::hull_depth({V3(0, 0, 0) - t, V3(1, 0, 0) - t, V3(0, 1, 0) - t,
                                        V3(0, 0, 1) - t, V3(0, 0, 0) - t});  // a duplicate
  EXPECT_NEAR(double(tet2.depth), 0.1 / std::sqrt(3.0), 1e-16);
  EXPECT_LE(double((tet2.normal - V3(1, 1, 1).normalized()).norm()), 1e-16);
  // The origin outside: negative.
  const auto outside = oracle::hull_depth({V3(1, 0, 0), V3(2, 0, 0), V3(1, 1, 0), V3(1, 0, 1)});
  EXPECT_LT(outside.depth, 0);
  // A flat square around the origin: no volume, depth 0.
  const auto flat =
      oracle::hull_depth({V3(-1, -1, 0), V3(1, -1, 0), V3(1, 1, 0), V3(-1, 1, 0), V3(0, 0, 0)});
  EXPECT_FALSE(flat.full_dimensional);
  EXPECT_NEAR(double(flat.depth), 0, 1e-18);
  // Two unit cubes overlapping by 0.25 along x (B at x = 1.75): depth 0.25, B moves along +x.
  std::vector<V3> a, b;
  for (int i = 0; i < 8; ++i) {
    const V3 c((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    a.push_back(c);
    b.push_back(c + V3(1.75, 0.5, -0.25));
  }
  const auto cubes = oracle::polytope_penetration(a, b);
  EXPECT_NEAR(double(cubes.depth), 0.25, 1e-18);
  EXPECT_LE(double((cubes.normal - V3(1, 0, 0)).norm()), 1e-18);
  const auto sat =
      oracle::box_box_penetration({V3(1, 1, 1), oracle::M3::Identity(), V3::Zero()},
                                  {V3(1, 1, 1), oracle::M3::Identity(), V3(1.75, 0.5, -0.25)});
  EXPECT_NEAR(double(sat.depth), 0.25, 1e-18);
  EXPECT_LE(double((sat.normal - V3(1, 0, 0)).norm()), 1e-18);
  // Sphere inside a box near its +y face: the box moves along -y.
  const oracle::WorldBox box{V3(2, 1, 3), oracle::M3::Identity(), V3(0, 0, 0)};
  const auto sb = oracle::sphere_box_penetration(V3(0.5, 0.75, 0), 0.5, box);
  EXPECT_NEAR(double(sb.depth), 0.75, 1e-18);
  EXPECT_LE(double((sb.normal - V3(0, -1, 0)).norm()), 1e-18);
  // Crossing capsules: r1 + r2.
  const auto cc = oracle::capsule_capsule_penetration({V3(0, 0, -1), V3(0, 0, 1), 0.3},
                                                      {V3(-1, 0, 0), V3(1, 0, 0), 0.2});
  EXPECT_NEAR(double(cc.depth), 0.5, 1e-18);
  EXPECT_EQ(cc.tie_margin, 0);
}

TEST(ContactOracle, HullDepthMatchesPointBox) {
  const std::uint64_t base = 95000;
  const int n = oracle::sweep_count(300);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const oracle::WorldBox box{V3(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2)),
                               random_rotation(rng), widen(rng.in_ball(2))};
    const V3 x = widen(rng.in_ball(3));
    std::vector<V3> shifted;
    for (const V3& c : oracle::box_corners(box)) shifted.push_back(c - x);
    const auto hull = oracle::hull_depth(shifted);
    const auto bp = oracle::point_box(box, x);
    EXPECT_TRUE(hull.full_dimensional);
    if (bp.signed_distance < 0) {
      // 1e-13: the rotation from a double quaternion is orthonormal only to about 1e-16.
      EXPECT_NEAR(double(hull.depth), double(-bp.signed_distance), 1e-13);
      EXPECT_NEAR(double(oracle::support_of(shifted, hull.normal)), double(hull.depth), 1e-15);
    } else {
      EXPECT_LT(hull.depth, 1e-13);
    }
  }
}

TEST(ContactOracle, PolytopePenetrationMatchesAllTriplesAndHullDistance) {
  const std::uint64_t base = 96000;
  const int n = oracle::sweep_count(300, 100);
  int inside = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    auto a = random_points(rng, rng.integer(4, 8), rng.uniform(0.3, 1.5), widen(rng.in_ball(0.3)));
    auto b = random_points(rng, rng.integer(4, 8), rng.uniform(0.3, 1.5), widen(rng.in_ball(0.3)));
    if (i % 5 == 1) b.push_back(b[0]);  // duplicates
    if (i % 5 == 2)                     // a flat A
      for (V3& p : a) p.z() = 0.1;
    const auto fast = oracle::polytope_penetration(a, b);
    std::vector<V3> diff;
    for (const V3& p : a)
      for (const V3& q : b) diff.push_back(p - q);
    const auto all = oracle::hull_depth(diff);
    const auto reference = oracle::hull_distance(diff);  // side-test enumeration, independent
    ASSERT_EQ(fast.depth > 0, reference.distance == 0) << "inside test disagrees";
    if (reference.distance == 0) {
      ++inside;
      // Inside, the restricted enumeration sees every facet: it matches the full one exactly.
      // (Compared before rounding to double, where one ulp of a depth of 0.1 is 2.8e-17.)
      EXPECT_LE(double(std::abs(fast.depth - all.depth)), 1e-17);
      EXPECT_NEAR(double(fast.depth), double(reference.depth), 1e-15);
      EXPECT_NEAR(double(oracle::support_of(diff, fast.normal)), double(fast.depth), 1e-17);
    }
  }
  EXPECT_GT(inside, n / 4);
}

TEST(ContactOracle, BoxBoxSatMatchesMinkowskiDifference) {
  const std::uint64_t base = 97000;
  const int n = oracle::sweep_count(300);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const oracle::WorldBox a{V3(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2)),
                             random_rotation(rng), widen(rng.in_ball(1))};
    const oracle::WorldBox b{V3(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2)),
                             random_rotation(rng), widen(rng.in_ball(2))};
    const auto sat = oracle::box_box_penetration(a, b);
    const auto ca = oracle::box_corners(a), cb = oracle::box_corners(b);
    const auto mink_diff = oracle::polytope_penetration(ca, cb);
    EXPECT_EQ(sat.depth > 0, mink_diff.depth > 0);
    if (sat.depth > 0) {
      EXPECT_NEAR(double(sat.depth), double(mink_diff.depth), 1e-13);
      EXPECT_NEAR(double(oracle::support_of_difference(ca, cb, sat.normal)), double(sat.depth),
                  1e-13);
    }
  }
}

TEST(ContactOracle, SphereBoxMatchesMinkowskiDifference) {
  // A sphere is its centre grown by r: depth = r + min_u h_{c - box}(u), which is the hull depth
  // of c - corners when c is inside the box and minus its distance otherwise.
  const std::uint64_t base = 98000;
  const int n = oracle::sweep_count(300);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const oracle::WorldBox box{V3(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2)),
                               random_rotation(rng), widen(rng.in_ball(1))};
    const V3 c = widen(rng.in_ball(2.5));
    const Real r = rng.uniform(0.05, 1.5);
    const auto got = oracle::sphere_box_penetration(c, r, box);
    std::vector<V3> diff;
    for (const V3& q : oracle::box_corners(box)) diff.push_back(c - q);
    const auto dist = oracle::hull_distance(diff);
    const Real core = dist.distance > 0 ? -dist.distance : oracle::hull_depth(diff).depth;
    EXPECT_NEAR(double(got.depth), double(r + core), 1e-13);
    // The normal of a centre just outside the box is the direction of a short vector, known to
    // the rounding of its ends (1e-16, the rotation's orthonormality) over its length, and tilting
    // it tilts the face's support by the face's size: compare it when the length is at least 1e-3,
    // to 1e-12.
    if (!(dist.distance > 0 && dist.distance < 1e-3)) {
      EXPECT_NEAR(double(oracle::support_of(diff, got.normal) + r), double(got.depth), 1e-12);
    }
  }
}

TEST(ContactOracle, CapsuleDepthIsTheLeastSupportValue) {
  // depth = min over unit u of h_{A-B}(u): the normal attains it, and no sampled direction is
  // below it.
  const std::uint64_t base = 99000;
  const int n = oracle::sweep_count(100);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const oracle::WorldCapsule a{widen(rng.in_ball(1)), widen(rng.in_ball(1)), rng.uniform(0.1, 1)};
    const oracle::WorldCapsule b{widen(rng.in_ball(1)), widen(rng.in_ball(1)), rng.uniform(0.1, 1)};
    const auto got = oracle::capsule_capsule_penetration(a, b);
    auto h = [&](const V3& u) {
      return std::max(a.p.dot(u), a.q.dot(u)) + std::max(-b.p.dot(u), -b.q.dot(u)) + a.radius +
             b.radius;
    };
    if (got.tie_margin > 0) {
      EXPECT_NEAR(double(h(got.normal)), double(got.depth), 1e-15);
    }
    for (int k = 0; k < 2000; ++k) {
      const V3 u = widen(rng.unit());
      ASSERT_GE(h(u), got.depth - Real(1e-15)) << "direction " << u.transpose();
    }
  }
}

TEST(ContactOracle, LeastSupportMatchesClosedForms) {
  // Segment cores (A - B is a parallelogram: always the outside branch) against the closed-form
  // capsule depth, and a point against box corners (both branches) against point_box.
  const std::uint64_t base = 99500;
  const int n = oracle::sweep_count(200);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const oracle::WorldCapsule a{widen(rng.in_ball(1)), widen(rng.in_ball(1)), 0.3};
    const oracle::WorldCapsule b{widen(rng.in_ball(1)), widen(rng.in_ball(1)), 0.2};
    const Real least = oracle::least_support_of_difference({a.p, a.q}, {b.p, b.q});
    EXPECT_NEAR(double(least + a.radius + b.radius),
                double(oracle::capsule_capsule_penetration(a, b).depth), 1e-15);
    const oracle::WorldBox box{V3(rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2)),
                               random_rotation(rng), widen(rng.in_ball(1))};
    const V3 x = widen(rng.in_ball(2.5));
    const Real point = oracle::least_support_of_difference({x}, oracle::box_corners(box));
    EXPECT_NEAR(double(point), double(-oracle::point_box(box, x).signed_distance), 1e-13);
  }
}

TEST(ContactOracle, SphereCylinderDepthIsTheLeastSupportValue) {
  const std::uint64_t base = 99800;
  const int n = oracle::sweep_count(100);
  for (int i = 0; i < n; ++i) {
    const std::uint64_t seed = base + i;
    SCOPED_TRACE(oracle::seed_note(seed));
    Rng rng(seed);
    const oracle::WorldCylinder cyl{rng.uniform(0.1, 1), rng.uniform(0.1, 1), random_rotation(rng),
                                    widen(rng.in_ball(1))};
    const V3 c = cyl.center + widen(rng.in_ball(1.2));
    const Real r = rng.uniform(0.05, 1);
    const auto got = oracle::sphere_cylinder_penetration(c, r, cyl);
    auto h = [&](const V3& u) {  // h_{A-B}(u) for unit u
      const V3 l = cyl.rotation.transpose() * (-u);
      return c.dot(u) + r - cyl.center.dot(u) + cyl.radius * std::hypot(l.x(), l.y()) +
             cyl.half_height * std::abs(l.z());
    };
    // 1e-11: the rotation from a double quaternion is orthonormal only to about 1e-16, and the
    // radial direction of a centre near the axis amplifies that (3.6e-12 seen with clang).
    EXPECT_NEAR(double(h(got.normal)), double(got.depth), 1e-11);
    for (int k = 0; k < 2000; ++k) {
      const V3 u = widen(rng.unit());
      ASSERT_GE(h(u), got.depth - Real(1e-12)) << "direction " << u.transpose();
    }
  }
}

}  // namespace
