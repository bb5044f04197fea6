// build_convex_hull on random, degenerate and regression inputs, checked without an oracle
// (hull_check.hpp) and, where the answer is known in closed form, against it. The comparison
// with CGAL's exact convex_hull_3 is in tests/hull/cgal_oracle_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include "mink/hull/convex_hull.hpp"
#include "unit/hull/hull_check.hpp"
#include "unit/hull/hull_inputs.hpp"

namespace {

using mink::build_convex_hull;
using mink::ConvexHull;
using mink::HullOptions;
using mink::HullStatus;
using mink::Vec3;

ConvexHull build(const std::vector<Vec3>& p, const HullOptions& o = {}) {
  auto r = build_convex_hull(p, o);
  EXPECT_TRUE(r.has_value()) << r.error();
  if (!r) return {};
  return std::move(r).value();
}

TEST(ConvexHull, Tetrahedron) {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const ConvexHull h = build(p);
  EXPECT_EQ(h.status, HullStatus::Full);
  EXPECT_EQ(h.vertices.size(), 4u);
  EXPECT_EQ(h.faces.size(), 4u);
  EXPECT_NEAR(h.volume, 1.0 / 6, 1e-15);
  EXPECT_NEAR(h.area, 1.5 + std::sqrt(3.0) / 2, 1e-14);
  hull_check::check_hull(p, h);
}

TEST(ConvexHull, CubeWithInteriorAndFacePointsIsSixQuads) {
  std::vector<Vec3> p = hull_inputs::on_cube_surface(2000, 1, true);
  for (const Vec3& v : hull_inputs::in_cube(500, 2)) p.push_back(0.9 * v);
  const ConvexHull h = build(p);
  EXPECT_EQ(h.vertices.size(), 8u);
  ASSERT_EQ(h.faces.size(), 6u);
  for (const auto& f : h.faces) {
    EXPECT_EQ(f.count, 4u);
    EXPECT_EQ(f.normal.cwiseAbs().maxCoeff(), 1.0);
    EXPECT_NEAR(f.offset, 1.0, 1e-15);
  }
  EXPECT_NEAR(h.volume, 8, 1e-13);
  EXPECT_NEAR(h.area, 24, 1e-13);
  for (std::size_t v = 0; v < 8; ++v)
    EXPECT_EQ(h.neighbor_offsets[v + 1] - h.neighbor_offsets[v], 3u);
  hull_check::check_hull(p, h);
}

TEST(ConvexHull, LatticeIsACube) {
  for (const bool rotated : {false, true}) {
    const auto p = hull_inputs::lattice(10, rotated);
    const ConvexHull h = build(p);
    EXPECT_EQ(h.vertices.size(), 8u);
    EXPECT_EQ(h.faces.size(), 6u);
    EXPECT_NEAR(h.volume, rotated ? 729.0 * 125 : 729.0, 1e-9);
    hull_check::check_hull(p, h);
  }
}

TEST(ConvexHull, RoundedRotationsMergeBackIntoSixFaces) {
  // Corners plus face points, rotated in double: faces are coplanar only to rounding.
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto p = hull_inputs::rotated(hull_inputs::on_cube_surface(1000, seed, true), seed);
    const ConvexHull h = build(p);
    EXPECT_EQ(h.vertices.size(), 8u) << seed;
    EXPECT_EQ(h.faces.size(), 6u) << seed;
    EXPECT_NEAR(h.volume, 8, 1e-12);
    hull_check::check_hull(p, h);
  }
}

TEST(ConvexHull, FuzzyCubeSurface) {
  // rbox W1e-13 with the corners: points within 1e-13 of the faces. The exact hull keeps
  // many of them as vertices; the tolerance (3.5e-10 here) merges them back.
  const auto p = hull_inputs::on_cube_surface(1000, 7, true, 1e-13);
  const ConvexHull h = build(p);
  hull_check::check_hull(p, h);
  EXPECT_EQ(h.faces.size(), 6u);
  EXPECT_EQ(h.vertices.size(), 8u);
  // With a tolerance below the fuzz, the bumps are real geometry again.
  HullOptions tight;
  tight.relative_tolerance = 0;
  const ConvexHull t = build(p, tight);
  hull_check::check_hull(p, t);
  EXPECT_GT(t.vertices.size(), 8u);
}

struct Case {
  std::string name;
  std::vector<Vec3> points;
  HullStatus status;
};

std::vector<Case> cases() {
  using namespace hull_inputs;
  std::vector<Case> c;
  c.push_back({"ball", in_ball(5000, 11), HullStatus::Full});
  c.push_back({"cube", in_cube(5000, 12), HullStatus::Full});
  c.push_back({"sphere", on_sphere(3000, 13), HullStatus::Full});
  c.push_back({"cube_surface", on_cube_surface(3000, 14, false), HullStatus::Full});
  c.push_back(
      {"rotated_cube_surface", rotated(on_cube_surface(3000, 15, false), 15), HullStatus::Full});
  c.push_back({"near_pairs_1e-13", near_pairs(1000, 1e-13, 16), HullStatus::Full});
  c.push_back({"near_pairs_1e-9", near_pairs(1000, 1e-9, 17), HullStatus::Full});
  c.push_back({"lens", lens(2000, 1e5, 18), HullStatus::Full});
  c.push_back({"cocircular_cone", cocircular_cone(1000, 1e-13, 19), HullStatus::Full});
  {
    auto p = in_ball(3000, 20);
    for (Vec3& v : p) v += Vec3(1e6, -1e6, 1e6);
    c.push_back({"far_1e6", p, HullStatus::Full});
  }
  {
    auto p = in_ball(3000, 21);
    for (Vec3& v : p) v *= 1e-6;
    c.push_back({"tiny_1e-6", p, HullStatus::Full});
  }
  {
    auto p = in_ball(2000, 22);
    for (Vec3& v : p) v = Vec3(1, 1, 0.5) + 1e-20 * v;
    c.push_back({"cluster_1e-20_at_1", p, HullStatus::Point});
  }
  {
    auto p = in_ball(2000, 23);
    for (Vec3& v : p) v *= 1e-20;
    c.push_back({"tiny_1e-20_at_origin", p, HullStatus::Full});
  }
  {
    auto p = in_ball(1000, 24);
    for (Vec3& v : p) v[2] = 0;
    c.push_back({"flat", p, HullStatus::Flat});
  }
  {
    auto p = rotated(in_ball(1000, 25), 25);
    for (Vec3& v : p) v[1] = 0.25 * v[0] - 0.5 * v[2] + 3;
    c.push_back({"flat_tilted_rounded", p, HullStatus::Flat});
  }
  {
    auto p = in_ball(1000, 26);
    auto g = rng(26);
    std::uniform_real_distribution<double> u(-1, 1);
    for (Vec3& v : p) v[2] = 1e-9 * u(g);
    c.push_back({"near_flat_1e-9", p, HullStatus::Full});
    for (Vec3& v : p) v[2] *= 1e-4;
    c.push_back({"near_flat_1e-13", p, HullStatus::Flat});
  }
  {
    std::vector<Vec3> p;
    for (int i = 0; i < 1000; ++i) {
      const double t = 0.001 * i - 0.3;
      p.emplace_back(t, 2 * t, 3 * t);
    }
    c.push_back({"collinear", p, HullStatus::Segment});
  }
  c.push_back({"identical", std::vector<Vec3>(1000, Vec3(0.1, -2, 3e5)), HullStatus::Point});
  c.push_back({"single", {Vec3(1, 2, 3)}, HullStatus::Point});
  c.push_back({"two", {Vec3(1, 2, 3), Vec3(1, 2, 4)}, HullStatus::Segment});
  c.push_back({"three", {Vec3(1, 2, 3), Vec3(1, 2, 4), Vec3(0, 0, 0)}, HullStatus::Flat});
  {
    auto p = on_sphere(500, 27);
    auto q = p;
    p.insert(p.end(), q.begin(), q.end());
    c.push_back({"sphere_duplicated", p, HullStatus::Full});
  }
  for (auto& r : regressions()) {
    HullStatus s = HullStatus::Full;
    // The Jolt disc is flat only to 1e-5 (float y coordinates): a thin solid here.
    if (r.name == "jolt_quad" || r.name == "jolt_triangle") s = HullStatus::Flat;
    c.push_back({r.name, r.points, s});
  }
  return c;
}

TEST(ConvexHull, AllCasesHoldTheInvariants) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const ConvexHull h = build(c.points);
    EXPECT_EQ(h.status, c.status) << mink::to_string(h.status);
    EXPECT_TRUE(h.complete);
    const auto r = hull_check::check_hull(c.points, h);
    RecordProperty(
        c.name, std::to_string(h.vertices.size()) + " v, " + std::to_string(h.faces.size()) + " f");
    if (::testing::Test::HasFailure()) {
      std::printf("%s: %zu v %zu f outside %.3g flat %.3g convex %.3g tol %.3g\n", c.name.c_str(),
                  h.vertices.size(), h.faces.size(), r.worst_outside, r.worst_flatness,
                  r.worst_convexity, h.tolerance);
    }
  }
}

TEST(ConvexHull, RandomDegenerateSets) {
  // Small sets on tiny integer grids (a third of them in a plane), some rotated in double:
  // every status appears, and every result holds the invariants.
  auto g = hull_inputs::rng(5);
  int counts[4] = {};
  for (int it = 0; it < 6000; ++it) {
    std::uniform_int_distribution<int> count(1, 40), coord(0, 1 + it % 4);
    std::vector<Vec3> p;
    const int n = count(g);
    for (int i = 0; i < n; ++i) p.emplace_back(coord(g), coord(g), it % 3 == 0 ? 0 : coord(g));
    if (it % 5 == 0) p = hull_inputs::rotated(p, static_cast<unsigned>(it));
    const ConvexHull h = build(p);
    ++counts[static_cast<int>(h.status)];
    hull_check::check_hull(p, h);
    if (HasFailure()) {
      for (const Vec3& v : p) std::printf("{%.17g, %.17g, %.17g},\n", v.x(), v.y(), v.z());
      return;
    }
  }
  for (const int c : counts) EXPECT_GT(c, 100);
}

TEST(ConvexHull, InvariantsHoldAtEveryTolerance) {
  // Large tolerances merge more (greedily, so not always as much as they could), and the
  // result stays flat within the tolerance, convex and closed.
  using namespace hull_inputs;
  const std::vector<std::vector<Vec3>> inputs{on_sphere(1500, 1),
                                              in_ball(1500, 2),
                                              on_cube_surface(1000, 3, true, 1e-6),
                                              rotated(on_cube_surface(1000, 4, false), 4),
                                              lens(1000, 1e3, 5),
                                              near_pairs(500, 1e-5, 6)};
  for (const auto& p : inputs) {
    for (const double rel : {0.0, 1e-12, 1e-8, 1e-5, 1e-3, 1e-2}) {
      HullOptions o;
      o.relative_tolerance = rel;
      const ConvexHull h = build(p, o);
      SCOPED_TRACE(rel);
      hull_check::check_hull(p, h);
    }
  }
}

TEST(ConvexHull, SphereKeepsEveryPoint) {
  const auto p = hull_inputs::on_sphere(20000, 31);
  const ConvexHull h = build(p);
  EXPECT_EQ(h.vertices.size(), p.size());
  EXPECT_EQ(h.faces.size(), 2 * p.size() - 4);
  EXPECT_NEAR(h.volume, 4 * M_PI / 3, 4e-3);
}

TEST(ConvexHull, FlatResultIsTwoOppositeFaces) {
  std::vector<Vec3> p;
  for (int i = 0; i < 12; ++i) {
    const double a = 2 * M_PI * i / 12;
    p.emplace_back(std::cos(a), std::sin(a), 2);
    p.emplace_back(0.5 * std::cos(a), 0.5 * std::sin(a), 2);
  }
  const ConvexHull h = build(p);
  ASSERT_EQ(h.status, HullStatus::Flat);
  ASSERT_EQ(h.faces.size(), 2u);
  EXPECT_EQ(h.faces[0].count, 12u);
  // Either side may come first; the two are opposite.
  const double side = h.faces[0].normal.z();
  EXPECT_NEAR(std::fabs(side), 1, 1e-15);
  EXPECT_NEAR(h.faces[1].normal.z(), -side, 1e-15);
  EXPECT_NEAR(h.faces[0].offset, 2 * side, 1e-14);
  EXPECT_NEAR(h.faces[1].offset, -2 * side, 1e-14);
  EXPECT_NEAR(h.area, 2 * 3.0, 1e-13);  // both sides of a dodecagon of circumradius 1
  for (std::size_t v = 0; v < h.vertices.size(); ++v) {
    EXPECT_EQ(h.vertices[v].position.head<2>().norm() > 0.9, true);
    EXPECT_EQ(h.neighbor_offsets[v + 1] - h.neighbor_offsets[v], 2u);
  }
  hull_check::check_hull(p, h);
}

TEST(ConvexHull, SegmentEndsAreTheExtremes) {
  std::vector<Vec3> p{{0.5, 1, 1.5}, {-1, -2, -3}, {2, 4, 6}, {0, 0, 0}};
  const ConvexHull h = build(p);
  ASSERT_EQ(h.status, HullStatus::Segment);
  std::set<std::uint32_t> ends{h.vertices[0].input_index, h.vertices[1].input_index};
  EXPECT_EQ(ends, (std::set<std::uint32_t>{1, 2}));
  EXPECT_EQ(h.neighbors, (std::vector<std::uint32_t>{1, 0}));
}

TEST(ConvexHull, BadInputIsAnError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(build_convex_hull(std::vector<Vec3>{}));
  for (const Vec3& bad : {Vec3(nan, 0, 0), Vec3(0, inf, 0), Vec3(0, 0, -inf)}) {
    std::vector<Vec3> p = hull_inputs::in_ball(10, 1);
    p[5] = bad;
    const auto r = build_convex_hull(p);
    EXPECT_FALSE(r);
    EXPECT_NE(r.error().find("point 5 is not finite"), std::string::npos) << r.error();
  }
  EXPECT_FALSE(build_convex_hull(std::vector<Vec3>{Vec3(1e200, 0, 0)}));
  HullOptions o;
  o.relative_tolerance = -1;
  EXPECT_FALSE(build_convex_hull(hull_inputs::in_ball(10, 1), o));
  o.relative_tolerance = nan;
  EXPECT_FALSE(build_convex_hull(hull_inputs::in_ball(10, 1), o));
  o = {};
  o.max_vertices = 3;
  EXPECT_FALSE(build_convex_hull(hull_inputs::in_ball(10, 1), o));
}

TEST(ConvexHull, MaxVerticesIsFurthestFirst) {
  const auto p = hull_inputs::in_ball(20000, 41);
  const ConvexHull full = build(p);
  double previous = HUGE_VAL;
  for (const std::size_t m : {4, 8, 16, 32, 64, 128, 256}) {
    HullOptions o;
    o.max_vertices = m;
    const ConvexHull h = build(p, o);
    SCOPED_TRACE(m);
    EXPECT_EQ(h.status, HullStatus::Full);
    EXPECT_FALSE(h.complete);
    EXPECT_LE(h.vertices.size(), m);
    EXPECT_GE(h.vertices.size(), std::min<std::size_t>(m, 4));
    // The structure is that of a complete hull of its vertices.
    hull_check::check_hull(p, h);
    // The true worst distance outside, by brute force; the reported one is a lower bound of it.
    double worst = 0;
    for (const Vec3& x : p) {
      double out = -HUGE_VAL;
      for (const auto& f : h.faces) out = std::max(out, f.normal.dot(x) - f.offset);
      worst = std::max(worst, out);
    }
    EXPECT_GT(h.max_outside, 0);
    EXPECT_LE(h.max_outside, worst + 1e-12);
    EXPECT_LT(worst, previous);
    previous = worst;
    EXPECT_LT(h.volume, full.volume);
  }
  HullOptions big;
  big.max_vertices = full.vertices.size() + 10;
  const ConvexHull h = build(p, big);
  EXPECT_TRUE(h.complete);
  EXPECT_EQ(h.vertices.size(), full.vertices.size());
}

TEST(ConvexHull, MaxVerticesOnAFlatPolygon) {
  std::vector<Vec3> p;
  for (int i = 0; i < 100; ++i) {
    const double a = 2 * M_PI * i / 100;
    p.emplace_back(std::cos(a), std::sin(a), 0);
  }
  HullOptions o;
  o.max_vertices = 10;
  const ConvexHull h = build(p, o);
  EXPECT_EQ(h.status, HullStatus::Flat);
  EXPECT_FALSE(h.complete);
  EXPECT_EQ(h.vertices.size(), 10u);
  EXPECT_GT(h.max_outside, 0);
  EXPECT_LT(h.max_outside, 0.1);
}

TEST(ConvexHull, ResultDoesNotDependOnScaleByPowersOfTwo) {
  // Scaling by 2^k is exact and so is the local frame, so every decision is the same from
  // 2^-990 (coordinates near 1e-298) to 2^330 (near 2e99).
  const auto p = hull_inputs::on_cube_surface(2000, 61, true, 1e-12);
  const ConvexHull ref = build(p);
  std::set<std::uint32_t> ref_ids;
  for (const auto& v : ref.vertices) ref_ids.insert(v.input_index);
  for (const int k : {-990, -500, -100, -1, 1, 100, 330}) {
    auto q = p;
    for (Vec3& v : q) v = Vec3(std::ldexp(v.x(), k), std::ldexp(v.y(), k), std::ldexp(v.z(), k));
    const ConvexHull h = build(q);
    SCOPED_TRACE(k);
    EXPECT_EQ(h.faces.size(), ref.faces.size());
    std::set<std::uint32_t> ids;
    for (const auto& v : h.vertices) ids.insert(v.input_index);
    EXPECT_EQ(ids, ref_ids);
    EXPECT_EQ(h.tolerance, std::ldexp(ref.tolerance, k));
    if (k >= -100) {
      hull_check::check_hull(q, h);
      EXPECT_NEAR(h.volume, std::ldexp(ref.volume, 3 * k), 1e-12 * std::ldexp(ref.volume, 3 * k));
    }
  }
}

TEST(ConvexHull, ResultDoesNotDependOnTranslationByPowersOfTwo) {
  // The local frame is exact, so shifting by a value that keeps the subtraction exact gives
  // the same combinatorial hull.
  const auto p = hull_inputs::in_ball(3000, 51);
  auto q = p;
  for (Vec3& v : q) v += Vec3(1024, 2048, -4096);
  const ConvexHull a = build(p), b = build(q);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  std::set<std::uint32_t> ia, ib;
  for (const auto& v : a.vertices) ia.insert(v.input_index);
  for (const auto& v : b.vertices) ib.insert(v.input_index);
  EXPECT_EQ(ia, ib);
}

}  // namespace
