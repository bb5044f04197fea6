// ConvexHullShape's climbing support against brute force: the maximum dot product over the input
// points (every point, hull vertex or not) and the vectorised scan over the hull's vertices, on
// random directions, cold (random start vertex) and warm (the previous answer, directions turning
// slowly), for hulls of 4 to 100,000 vertices and degenerate sets. Then GJK distance and contact
// on hull shapes against the same queries on plain (scanned) polytopes of the same points.
//
// Default: 1e6 directions in all (half cold, half warm); DISABLED_HeavySweep checks 1.8e6 more on
// hulls of 20,000 to 100,000 vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "mink/mink.hpp"
#include "mink/shapes/hull_shape.hpp"

namespace {

using mink::ConvexHull;
using mink::ConvexHullShape;
using mink::HullStatus;
using mink::Vec3;

constexpr double kEps = std::numeric_limits<double>::epsilon();

Vec3 unit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  for (;;) {
    const Vec3 v(n(g), n(g), n(g));
    if (v.norm() > 1e-3) return v.normalized();
  }
}

std::vector<Vec3> sphere(int n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back(unit(g));
  return p;
}

/// Points on the surface of [-1, 1]^3 plus its corners: faces full of exactly coplanar points.
std::vector<Vec3> cube_surface(int n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  for (int i = 0; i < n; ++i) {
    Vec3 v(u(g), u(g), u(g));
    const int f = int(g() % 6);
    v[f / 2] = f % 2 ? 1 : -1;
    p.push_back(v);
  }
  return p;
}

/// The integer points of a ball of radius k: a hull of many faces full of coplanar points and
/// exact ties.
std::vector<Vec3> lattice(int k) {
  std::vector<Vec3> p;
  for (int i = -k; i <= k; ++i)
    for (int j = -k; j <= k; ++j)
      for (int l = -k; l <= k; ++l)
        if (i * i + j * j + l * l <= k * k) p.emplace_back(i, j, l);
  return p;
}

mink::Quat rotation(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  for (;;) {
    const mink::Quat q(n(g), n(g), n(g), n(g));
    if (q.norm() > 1e-3) return q.normalized();
  }
}

/// A disc of random points in a tilted plane through (3, -2, 5).
std::vector<Vec3> flat(int n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 a = Vec3(1, 2, 0.5).normalized(), b = a.cross(Vec3(0, 0, 1)).normalized();
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back(Vec3(3, -2, 5) + u(g) * a + u(g) * b);
  return p;
}

std::vector<Vec3> segment(int n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back(Vec3(1, 1, 1) + u(g) * Vec3(0.25, 2, -1));
  return p;
}

/// A long thin cylinder of points: 1000 long, 1e-3 across.
std::vector<Vec3> needle(int n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-500, 500), a(0, 6.283185307179586);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double t = a(g);
    p.emplace_back(u(g), 1e-3 * std::cos(t), 1e-3 * std::sin(t));
  }
  return p;
}

/// Points in the unit disk, `thickness` apart at most across it: a solid so thin that the
/// dihedral angle at its rim is about thickness / spacing, so a face-plane tolerance reaches far
/// beyond the rim (hull_faces.cpp keeps the rim's corners for that).
std::vector<Vec3> thin_disk(int n, unsigned seed, double thickness) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p;
  while (int(p.size()) < n) {
    const double x = u(g), y = u(g);
    if (x * x + y * y <= 1) p.emplace_back(x, y, 0.5 * thickness * u(g));
  }
  return p;
}

/// Two circles of radius 1 at z = +-0.5 with every coordinate moved by up to `noise`.
std::vector<Vec3> noisy_rims(int n, unsigned seed, double noise) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1), a(0, 6.283185307179586);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double t = a(g);
    p.emplace_back(std::cos(t) + noise * u(g), std::sin(t) + noise * u(g),
                   (i % 2 ? 0.5 : -0.5) + noise * u(g));
  }
  return p;
}

/// A cone over a regular n-gon: the apex has n neighbours, more than a vertex record holds inline
/// (hull_shape.hpp), so its climb steps read the edge list.
std::vector<Vec3> cone(int n) {
  std::vector<Vec3> p{Vec3(0.1, -0.2, 1.5)};
  for (int i = 0; i < n; ++i) {
    const double t = 6.283185307179586 * i / n;
    p.emplace_back(std::cos(t), std::sin(t), 0);
  }
  return p;
}

struct SupportCase {
  std::string name;
  std::vector<Vec3> points;
  int directions;
};

double dot(const Vec3& p, const Vec3& d) {
  return p.x() * d.x() + p.y() * d.y() + p.z() * d.z();
}

/// Checks `directions` random directions cold and warm on one point set; `worst` gets the largest
/// shortfall of the climb below the input points' maximum, in units of eps R |d|.
void check_case(const SupportCase& c, unsigned seed, double& worst) {
  SCOPED_TRACE(c.name);
  worst = 0;
  const auto hull = mink::build_convex_hull(c.points);
  ASSERT_TRUE(hull.has_value()) << hull.error();
  const auto shape = ConvexHullShape::make(*hull);
  ASSERT_TRUE(shape.has_value()) << shape.error();
  const std::uint32_t n = std::uint32_t(shape->size());
  double radius = 0;
  for (const Vec3& p : c.points) radius = std::max(radius, p.norm());
  // Rounding of two dot products of |p| <= radius (4 eps R |d| each), plus the hull's flatness:
  // see hull_shape.hpp, "Accuracy".
  const double rounding = 8 * kEps * radius;

  std::mt19937_64 g(seed);
  std::vector<double> xs, ys, zs;
  for (const Vec3& p : c.points) {
    xs.push_back(p.x());
    ys.push_back(p.y());
    zs.push_back(p.z());
  }
  // Brute force over every input point, and over the vertices (the scan), on some directions;
  // the scan alone on the rest (it is exact over the vertices: tests/unit/shapes).
  const int input_checks = std::max(1, int(1e7 / double(c.points.size() + 1)));
  Vec3 warm_d = unit(g);
  std::uint32_t warm_start = 0;
  for (int k = 0; k < c.directions; ++k) {
    // Cold: a random direction from a random vertex.
    const Vec3 d = unit(g) * std::ldexp(1.0, int(g() % 21) - 10);
    const std::uint32_t start = std::uint32_t(g() % n);
    const std::uint32_t cold = shape->climb_index(d, start);
    // Warm: a direction a small random turn from the previous one, from the previous answer.
    warm_d = (warm_d + 0.05 * unit(g)).normalized();
    const std::uint32_t warm = shape->climb_index(warm_d, warm_start);
    warm_start = warm;
    // The public path (hint and direction table) must give the climb's answer.
    ASSERT_EQ(shape->support_index(k % 2 ? d : warm_d), k % 2 ? cold : warm);
    // support_core() reads the point from the vertex's record, not the scan's arrays: the same.
    ASSERT_EQ(shape->support_core(k % 2 ? d : warm_d), shape->point(k % 2 ? cold : warm));

    for (const auto& [dir, got] : {std::pair{d, cold}, std::pair{warm_d, warm}}) {
      ASSERT_LT(got, n);
      const double value = dot(shape->point(got), dir);
      const double vertex_max = dot(shape->point(shape->scan_index(dir)), dir);
      const double slack = (hull->tolerance + rounding) * dir.norm();
      ASSERT_GE(value, vertex_max - slack) << "direction " << k << " start " << start;
      ASSERT_LE(value, vertex_max + rounding * dir.norm());
      if (k < input_checks) {
        const double input_max =
            dot(c.points[mink::detail::support_index(xs.data(), ys.data(), zs.data(), xs.size(),
                                                     dir.x(), dir.y(), dir.z())],
                dir);
        ASSERT_GE(value, input_max - slack) << "direction " << k;
        ASSERT_LE(value, input_max);  // a vertex is an input point: never above their maximum
        worst = std::max(worst, (input_max - value) / (kEps * radius * dir.norm()));
      }
    }
  }
}

std::vector<SupportCase> default_cases() {
  std::vector<SupportCase> cases;
  // Spheres: every point is a vertex; directions spread so that the run stays short.
  for (int n : {4, 5, 8, 16, 31, 32, 33, 64, 100, 256, 1000, 4096, 10000, 100000})
    cases.push_back(
        {"sphere " + std::to_string(n), sphere(n, 1000u + unsigned(n)), n <= 4096 ? 32000 : 4000});
  cases.push_back({"cube surface", cube_surface(20000, 7), 32000});
  cases.push_back({"lattice 12", lattice(12), 32000});
  cases.push_back({"flat 5000", flat(5000, 8), 32000});
  cases.push_back({"segment", segment(1000, 9), 10000});
  cases.push_back({"point", std::vector<Vec3>(10, Vec3(0.5, -1, 2)), 1000});
  cases.push_back({"needle", needle(3000, 10), 32000});
  cases.push_back({"cone over a 200-gon", cone(200), 32000});
  for (const auto& [thickness, name] : {std::pair{1e-9, "1e-9"}, {1e-7, "1e-7"}, {1e-5, "1e-5"}})
    for (int n : {64, 2000})
      cases.push_back({"thin disk " + std::to_string(n) + " " + name,
                       thin_disk(n, 11u + unsigned(n), thickness), 16000});
  for (const auto& [noise, name] : {std::pair{1e-11, "1e-11"}, {1e-9, "1e-9"}})
    cases.push_back({std::string("noisy rims ") + name, noisy_rims(400, 14, noise), 16000});
  return cases;
}

TEST(HullSupport, ClimbEqualsBruteForceColdAndWarm) {
  int total = 0;
  for (const SupportCase& c : default_cases()) {
    double worst = 0;
    check_case(c, 77, worst);
    if (HasFatalFailure()) return;
    total += 2 * c.directions;
    // Points in general position and exact lattices: no face is merged across a non-zero angle,
    // so the climb is exact up to the rounding of the dot products.
    if (c.name.rfind("sphere", 0) == 0 || c.name == "lattice 12" || c.name == "cube surface") {
      EXPECT_LE(worst, 8.0) << c.name;
    }
  }
  EXPECT_GE(total, 1000000);
}

TEST(HullSupport, DISABLED_HeavySweep) {
  for (int n : {20000, 50000, 100000}) {
    double worst = 0;
    check_case({"sphere", sphere(n, 5u + unsigned(n)), 300000}, 3, worst);
    EXPECT_LE(worst, 8.0);
  }
}

TEST(HullSupport, StatusesAndSizes) {
  struct Expect {
    std::vector<Vec3> points;
    HullStatus status;
  };
  const std::vector<Expect> expects = {
      {sphere(3000, 1), HullStatus::Full},
      {flat(3000, 2), HullStatus::Flat},
      {segment(50, 3), HullStatus::Segment},
      {std::vector<Vec3>(3, Vec3(1, 2, 3)), HullStatus::Point},
  };
  for (const auto& e : expects) {
    const auto s = ConvexHullShape::make(std::span<const Vec3>(e.points));
    ASSERT_TRUE(s.has_value()) << s.error();
    EXPECT_EQ(s->status(), e.status);
    EXPECT_EQ(s->climbs(), s->size() >= mink::kHullClimbMinVertices);
  }
  const auto big = ConvexHullShape::make(std::span<const Vec3>(sphere(20000, 1)));
  EXPECT_EQ(big->size(), 20000u);  // every point of a sphere is a vertex
  EXPECT_TRUE(big->climbs());
}

TEST(HullSupport, TiesGiveTheScansAnswerFromEveryStart) {
  // The answer depends on the direction only: from every start vertex, directions facing a face
  // or an edge give the lowest index of the tied vertices, which is the scan's rule.
  for (const auto& pts : {cube_surface(2000, 11), lattice(9), flat(300, 12)}) {
    const auto s = ConvexHullShape::make(std::span<const Vec3>(pts));
    ASSERT_TRUE(s.has_value());
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(1, 1, 0),
                          Vec3(-1, 0, 1), Vec3(1, 2, 0), Vec3(0, 0, 0)}) {
      const std::size_t want = s->scan_index(d);
      for (std::uint32_t start = 0; start < s->size(); ++start)
        ASSERT_EQ(s->climb_index(d, start), want) << d.transpose() << " start " << start;
      EXPECT_EQ(s->support_index(d), want);
    }
  }
}

TEST(HullSupport, BadInput) {
  EXPECT_FALSE(ConvexHullShape::make(std::span<const Vec3>()).has_value());
  const std::vector<Vec3> nan = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, std::nan(""), 0)};
  EXPECT_FALSE(ConvexHullShape::make(std::span<const Vec3>(nan)).has_value());
  ConvexHull broken;
  EXPECT_FALSE(ConvexHullShape::make(broken).has_value());
  broken.vertices.push_back({Vec3(0, 0, 0), 0});
  broken.neighbor_offsets = {0, 1};
  broken.neighbors = {5};  // out of range
  EXPECT_FALSE(ConvexHullShape::make(broken).has_value());
  // A NaN direction gives a valid vertex.
  const auto s = ConvexHullShape::make(std::span<const Vec3>(sphere(500, 4)));
  EXPECT_LT(s->support_index(Vec3(std::nan(""), 0, 1)), s->size());
}

TEST(HullSupport, FloatShape) {
  const auto pts = sphere(2000, 13);
  std::vector<mink::Vec3T<float>> fp;
  for (const Vec3& p : pts) fp.push_back(p.cast<float>());
  const auto s = mink::ConvexHullShapeT<float>::make(std::span<const mink::Vec3T<float>>(fp));
  ASSERT_TRUE(s.has_value()) << s.error();
  std::mt19937_64 g(14);
  for (int k = 0; k < 2000; ++k) {
    const mink::Vec3T<float> d = unit(g).cast<float>();
    const float got = s->point(s->support_index(d)).dot(d);
    const float want = s->point(s->scan_index(d)).dot(d);
    // float rounding of the hull vertices' dot products (the hull is built on the exact points).
    ASSERT_GE(got, want - 1e-5f);
  }
}

// GJK and EPA on hull shapes against the same queries on scanned polytopes of the same points:
// the support values agree (up to ties), so distances and depths must agree to GJK's tolerance.
TEST(HullSupport, QueriesMatchPlainPolytopes) {
  std::mt19937_64 g(99);
  std::uniform_real_distribution<double> u(-1, 1);
  int separated = 0, penetrating = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int na = 40 + int(g() % 1000), nb = 40 + int(g() % 1000);
    const auto pa =
        trial % 3 == 0 ? cube_surface(na, unsigned(trial)) : sphere(na, unsigned(trial));
    const auto pb = sphere(nb, 5000u + unsigned(trial));
    const auto ha = ConvexHullShape::make(std::span<const Vec3>(pa));
    const auto hb = ConvexHullShape::make(std::span<const Vec3>(pb));
    const auto qa = mink::Polytope::make(pa);
    const auto qb = mink::Polytope::make(pb);
    ASSERT_TRUE(ha && hb && qa && qb);
    const mink::Pose pose_a = mink::Pose::from(Vec3(u(g), u(g), u(g)), rotation(g));
    const mink::Pose pose_b = mink::Pose::from(Vec3(u(g), u(g), u(g)) * 2.5, rotation(g));
    const double size =
        ha->bounding_radius() + hb->bounding_radius() + 2 * pose_b.translation.norm();

    const auto dh = mink::distance(*ha, pose_a, *hb, pose_b);
    const auto dp = mink::distance(*qa, pose_a, *qb, pose_b);
    ASSERT_EQ(dh.status, dp.status);
    ASSERT_NEAR(dh.distance, dp.distance, 1e-10 * size) << "trial " << trial;
    const auto ch = mink::contact(*ha, pose_a, *hb, pose_b);
    const auto cp = mink::contact(*qa, pose_a, *qb, pose_b);
    ASSERT_EQ(ch.intersect, cp.intersect);
    ASSERT_NEAR(ch.depth, cp.depth, 1e-8 * size) << "trial " << trial;
    (ch.intersect ? penetrating : separated)++;

    // The run-time Shape path: a hull core against a polytope core, and two hull cores.
    const auto sa = mink::Shape::polytope(pa);
    const auto sb = mink::Shape::convex_hull(pb);
    const auto sh = mink::Shape::convex_hull(pa);
    ASSERT_TRUE(sa && sb);
    ASSERT_TRUE(sh.has_value());
    const auto ds = mink::distance(*sa, pose_a, *sb, pose_b);
    ASSERT_NEAR(ds.distance, dp.distance, 1e-10 * size) << "trial " << trial;
    const auto dss = mink::distance(*sh, pose_a, *sb, pose_b);
    ASSERT_NEAR(dss.distance, dp.distance, 1e-10 * size) << "trial " << trial;
  }
  EXPECT_GT(separated, 20);
  EXPECT_GT(penetrating, 20);
}

// A large polytope scans for its first kPolytopeHullAfterSupports queries (exactly the scan's
// answers), then builds its hull and climbs: answers are then input points whose support value is
// the maximum within the hull's tolerance. Small polytopes never switch.
TEST(HullSupport, PolytopeSwitchesToItsHullAfterManyQueries) {
  std::vector<SupportCase> cases;
  auto ball = sphere(500, 31);
  for (int i = 0; i < 300; ++i) ball.push_back(0.5 * ball[std::size_t(i)]);  // interior
  for (int i = 0; i < 50; ++i) ball.push_back(ball[std::size_t(i)]);         // duplicates
  cases.push_back({"sphere, interior, duplicates", ball, 20000});
  cases.push_back({"cube surface", cube_surface(2000, 32), 20000});
  cases.push_back({"lattice 6", lattice(6), 20000});
  cases.push_back({"flat 300", flat(300, 33), 20000});
  cases.push_back({"segment 200", segment(200, 34), 20000});
  cases.push_back({"needle 300", needle(300, 35), 20000});
  for (const SupportCase& c : cases) {
    SCOPED_TRACE(c.name);
    const auto polytope = mink::Polytope::make(c.points);
    ASSERT_TRUE(polytope.has_value());
    std::mt19937_64 g(36);
    for (std::uint32_t k = 0; k < mink::kPolytopeHullAfterSupports; ++k) {
      ASSERT_FALSE(polytope->climbs()) << k;
      const Vec3 d = unit(g);
      ASSERT_EQ(polytope->support_index(d), polytope->scan_index(d));
    }
    ASSERT_TRUE(polytope->climbs());
    const double tolerance = polytope->hull()->tolerance();
    double radius = 0;
    for (const Vec3& p : c.points) radius = std::max(radius, p.norm());
    for (int k = 0; k < c.directions; ++k) {
      const Vec3 d = unit(g) * std::ldexp(1.0, int(g() % 21) - 10);
      const std::size_t got = polytope->support_index(d);
      ASSERT_LT(got, c.points.size());
      // The climb's position (hull_shape.hpp): the polytope's own point, to the bit.
      ASSERT_EQ(polytope->support_core(d), c.points[got]) << k;
      const double value = dot(c.points[got], d), best = dot(c.points[polytope->scan_index(d)], d);
      ASSERT_GE(value, best - (tolerance + 8 * kEps * radius) * d.norm()) << k;
      ASSERT_LE(value, best) << k;
    }
  }
  const auto small = mink::Polytope::make(sphere(int(mink::kHullClimbMinVertices) - 1, 37));
  ASSERT_TRUE(small.has_value());
  std::mt19937_64 g(38);
  for (std::uint32_t k = 0; k < 2 * mink::kPolytopeHullAfterSupports; ++k) {
    const Vec3 d = unit(g);
    ASSERT_EQ(small->support_index(d), small->scan_index(d));
  }
  EXPECT_FALSE(small->climbs());
}

// Threads sharing one polytope through its switch: one of them builds the hull while the others
// go on scanning, and every answer stays a farthest point.
TEST(HullSupport, PolytopeSwitchesSafelyUnderThreads) {
  const auto points = sphere(2000, 39);
  const auto polytope = mink::Polytope::make(points);
  ASSERT_TRUE(polytope.has_value());
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      std::mt19937_64 g(40 + t);
      for (int k = 0; k < 4000; ++k) {
        const Vec3 d = unit(g);
        const std::size_t got = polytope->support_index(d);
        const double best = dot(points[polytope->scan_index(d)], d);
        if (!(got < points.size()) || dot(points[got], d) < best - 1e-9) ++wrong;
      }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_TRUE(polytope->climbs());
}

}  // namespace
