// build_convex_hull against CGAL's convex_hull_3 with exact predicates (EPICK), which computes
// the exact convex hull as a triangle mesh:
//   - the same extreme vertices, except points within the tolerance of the hull: a vertex of
//     ours that CGAL does not have must lie within `tolerance` of CGAL's boundary, and a CGAL
//     vertex we do not have must lie within `tolerance` of ours;
//   - the same volume (CGAL's computed exactly, with EPECK), within tolerance times area;
//   - every invariant of hull_check.hpp (containment, Euler, twins, flat and convex faces);
// and the exact orientation predicate against CGAL's on nearly degenerate points.
// Prints one line per input with the worst measurements.
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "mink/hull/convex_hull.hpp"
#include "mink/hull/predicates.hpp"
#include "unit/hull/hull_check.hpp"
#include "unit/hull/hull_inputs.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using mink::ConvexHull;
using mink::HullStatus;
using mink::Vec3;
using Key = std::tuple<double, double, double>;

Exact::Point_3 exact_point(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

Key key(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

struct Plane {
  Vec3 n;
  double d;
};

struct Oracle {
  std::set<Key> vertices;
  std::vector<Plane> planes;  // of its triangles, normals from exactly rounded cross products
  double volume = 0;
  double seconds = 0;
};

Oracle cgal_hull(const std::vector<Vec3>& points) {
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  for (const Vec3& p : points) pts.emplace_back(p.x(), p.y(), p.z());
  Mesh mesh;
  const auto t0 = std::chrono::steady_clock::now();
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
  Oracle o;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Vec3 c = Vec3::Zero();
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const Vec3 x(p.x(), p.y(), p.z());
    o.vertices.insert(key(x));
    c += x;
  }
  c /= static_cast<double>(mesh.number_of_vertices());
  Exact::FT volume = 0;
  for (const auto f : mesh.faces()) {
    std::vector<Vec3> loop;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      const auto& p = mesh.point(v);
      loop.emplace_back(p.x(), p.y(), p.z());
    }
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      double n[3];
      mink::exact::cross_rounded(loop[0].data(), loop[i].data(), loop[i + 1].data(), n);
      const Vec3 nv = Vec3(n[0], n[1], n[2]).normalized();
      o.planes.push_back({nv, nv.dot(loop[0])});
      // Exactly, then rounded: in double, a needle's tetrahedra round to more than its volume.
      volume += CGAL::volume(exact_point(c), exact_point(loop[0]), exact_point(loop[i]),
                             exact_point(loop[i + 1]));
    }
  }
  o.volume = CGAL::to_double(volume);
  return o;
}

struct Row {
  std::string name;
  std::size_t n = 0, v = 0, f = 0, cgal_v = 0, ours_only = 0, cgal_only = 0;
  double worst_outside = 0, worst_flatness = 0, worst_convexity = 0, volume_error = 0, tol = 0;
  double ours_s = 0, cgal_s = 0;
};

std::vector<Row>& table() {
  static std::vector<Row> rows;
  return rows;
}

void compare(const std::string& name, const std::vector<Vec3>& points) {
  SCOPED_TRACE(name);
  const auto t0 = std::chrono::steady_clock::now();
  const auto built = mink::build_convex_hull(points);
  const double ours_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(built.has_value()) << built.error();
  const ConvexHull& h = *built;
  ASSERT_EQ(h.status, HullStatus::Full);
  const auto report = hull_check::check_hull(points, h);
  const Oracle o = cgal_hull(points);
  const double tol = h.tolerance;
  const double slack = hull_check::rounding_slack(hull_check::magnitude(points));

  Row row;
  row.name = name;
  row.n = points.size();
  row.v = h.vertices.size();
  row.f = h.faces.size();
  row.cgal_v = o.vertices.size();
  row.tol = tol;
  row.ours_s = ours_s;
  row.cgal_s = o.seconds;
  row.worst_outside = report.worst_outside;
  row.worst_flatness = report.worst_flatness;
  row.worst_convexity = report.worst_convexity;

  std::set<Key> ours;
  for (const auto& v : h.vertices) ours.insert(key(v.position));
  // Ours, not CGAL's: must be within tol of CGAL's boundary (and inside it, as an input point).
  for (const auto& v : h.vertices) {
    if (o.vertices.count(key(v.position))) continue;
    ++row.ours_only;
    double nearest = -HUGE_VAL;
    for (const Plane& p : o.planes) nearest = std::max(nearest, p.n.dot(v.position) - p.d);
    EXPECT_GE(nearest, -tol - slack) << "vertex " << v.input_index << " is deep inside";
  }
  // CGAL's, not ours: must be within tol of our boundary.
  for (const Key& k : o.vertices) {
    if (ours.count(k)) continue;
    ++row.cgal_only;
    const Vec3 w(std::get<0>(k), std::get<1>(k), std::get<2>(k));
    double depth = HUGE_VAL;
    for (const auto& f : h.faces) depth = std::min(depth, f.offset - f.normal.dot(w));
    EXPECT_LE(depth, tol + slack) << "an extreme point was lost";
  }
  row.volume_error = std::fabs(h.volume - o.volume);
  // Points within tol of the faces may be dropped: what is lost is a shell tol thick over the
  // faces and, on a needle as thin as tol, tubes of radius tol along the edges (the tol^2 term of
  // Steiner's formula, pi tol^2 per unit of edge length at most).
  double edges = 0;
  for (const auto& face : h.faces) {
    for (std::uint32_t k = 0; k < face.count; ++k) {
      const Vec3& a = h.vertices[h.half_edges[face.first + k].vertex].position;
      const Vec3& b = h.vertices[h.half_edges[face.first + (k + 1) % face.count].vertex].position;
      edges += (b - a).norm() / 2;
    }
  }
  EXPECT_LE(row.volume_error, 2 * tol * h.area + 3.2 * tol * tol * edges + 1e-13 * o.volume)
      << "volume " << h.volume << " vs " << o.volume;
  table().push_back(row);
}

TEST(HullOracle, RandomDistributions) {
  using namespace hull_inputs;
  compare("ball 2e4", in_ball(20000, 1));
  compare("cube 2e4", in_cube(20000, 2));
  compare("sphere 5e3", on_sphere(5000, 3));
  {
    auto p = in_ball(5000, 4);
    for (Vec3& v : p) v += Vec3(1e6, 2e6, -1e6);
    compare("ball at 1e6", p);
  }
  {
    auto p = in_ball(5000, 5);
    for (Vec3& v : p) v *= 1e-6;
    compare("ball x 1e-6", p);
  }
  {
    auto p = on_sphere(3000, 6);
    for (Vec3& v : p) v = 1e-6 * v + Vec3(1, 1, 1);
    compare("sphere 1e-6 at 1", p);
  }
}

TEST(HullOracle, CoplanarAndNearlyDegenerate) {
  using namespace hull_inputs;
  compare("cube surface", on_cube_surface(5000, 11, false));
  compare("cube surface + corners", on_cube_surface(5000, 12, true));
  compare("rotated cube surface", rotated(on_cube_surface(5000, 13, false), 13));
  compare("rotated cube + corners", rotated(on_cube_surface(5000, 14, true), 14));
  compare("fuzzy cube 1e-13", on_cube_surface(3000, 15, true, 1e-13));
  compare("fuzzy cube 1e-11", on_cube_surface(3000, 16, true, 1e-11));
  compare("lattice 10^3", lattice(10, false));
  compare("lattice M3,4,5", lattice(10, true));
  compare("rotated lattice", rotated(lattice(8, false), 17));
  compare("near pairs 1e-13", near_pairs(2000, 1e-13, 18));
  compare("near pairs 1e-10", near_pairs(2000, 1e-10, 19));
  compare("near pairs 1e-7", near_pairs(2000, 1e-7, 20));
  compare("lens L1e5", lens(3000, 1e5, 21));
  compare("lens L1e7", lens(3000, 1e7, 22));
  compare("cocircular cone 1e-13", cocircular_cone(1000, 1e-13, 23));
  compare("cocircular cone 0", cocircular_cone(1000, 0, 24));
  {
    auto p = in_ball(3000, 25);
    auto g = rng(25);
    std::uniform_real_distribution<double> u(-1, 1);
    for (Vec3& v : p) v[2] = 1e-9 * u(g);
    compare("near flat 1e-9", p);
  }
  {
    auto p = on_sphere(2000, 26);
    const auto q = p;
    p.insert(p.end(), q.begin(), q.end());
    compare("sphere, every point twice", p);
  }
}

TEST(HullOracle, RegressionInputs) {
  for (const auto& r : hull_inputs::regressions()) {
    if (r.name == "jolt_quad" || r.name == "jolt_triangle") continue;  // flat
    compare(r.name, r.points);
  }
}

TEST(HullOracle, SmallDegenerateSetsMatchCgal) {
  // Many small sets on integer grids (massively coplanar and collinear), some rotated in
  // double (coplanar only to rounding), some on a few planes with tiny offsets.
  auto g = hull_inputs::rng(123);
  int full = 0, differing = 0;
  for (int it = 0; it < 3000; ++it) {
    std::uniform_int_distribution<int> count(4, 60), coord(0, 1 + it % 4);
    std::vector<Vec3> p;
    const int n = count(g);
    for (int i = 0; i < n; ++i) p.emplace_back(coord(g), coord(g), coord(g));
    if (it % 3 == 1) p = hull_inputs::rotated(p, static_cast<unsigned>(it));
    if (it % 3 == 2) {
      std::uniform_real_distribution<double> u(-1, 1);
      for (Vec3& v : p) v += 1e-12 * Vec3(u(g), u(g), u(g));
    }
    const auto built = mink::build_convex_hull(p);
    ASSERT_TRUE(built.has_value()) << built.error();
    hull_check::check_hull(p, *built);
    if (built->status != HullStatus::Full) continue;
    ++full;
    const std::size_t before = table().size();
    compare("small set " + std::to_string(it), p);
    if (::testing::Test::HasFailure()) {
      for (const Vec3& v : p) std::printf("{%.17g, %.17g, %.17g},\n", v.x(), v.y(), v.z());
      return;
    }
    if (table().back().ours_only + table().back().cgal_only > 0) {
      ++differing;
      if (it % 3 == 0) ADD_FAILURE() << "an exact integer set differs from CGAL";
    }
    table().resize(before);  // keep the printed table short
  }
  RecordProperty("full", full);
  RecordProperty("differing_within_tolerance", differing);
  std::printf(
      "small sets: %d solids compared with CGAL, %d with vertex sets differing within "
      "tolerance\n",
      full, differing);
}

TEST(HullOracle, RandomNastySetsMatchCgal) {
  // Random small sets of the kinds that break hull builders, each moved by a random rotation,
  // scale and offset: points on a few planes (coplanar to rounding only), near-duplicates 1e-15
  // to 1e-6 apart, layered cocircular rings, a few far points with a dense cluster (scale ratios
  // to 1e9), and needles (all points near a line). MINK_TEST_SWEEP_SCALE multiplies the count.
  const char* env = std::getenv("MINK_TEST_SWEEP_SCALE");
  const int count = 400 * (env ? std::max(1, std::atoi(env)) : 1);
  auto g = hull_inputs::rng(20261126);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  auto power = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * unit(g)); };
  int full = 0;
  for (int it = 0; it < count; ++it) {
    std::vector<Vec3> p;
    const int kind = it % 5;
    const int n = 4 + static_cast<int>(unit(g) * 60);
    if (kind == 0) {  // on 2 to 5 random planes, and a point off them
      const int planes = 2 + it % 4;
      Vec3 normals[5];
      double offsets[5];
      for (int k = 0; k < planes; ++k) {
        normals[k] = hull_inputs::unit_vector(g);
        offsets[k] = u(g);
      }
      for (int i = 0; i < n; ++i) {
        const int k = i % planes;
        const Vec3 e1 = normals[k].unitOrthogonal(), e2 = normals[k].cross(e1);
        p.push_back(offsets[k] * normals[k] + u(g) * e1 + u(g) * e2);
      }
      p.push_back(hull_inputs::unit_vector(g));
    } else if (kind == 1) {  // near-duplicates
      const double gap = power(-15, -6);
      for (int i = 0; i < n; ++i) {
        const Vec3 x = hull_inputs::unit_vector(g) * std::cbrt(unit(g));
        p.push_back(x);
        p.push_back(x + gap * Vec3(u(g), u(g), u(g)));
      }
    } else if (kind == 2) {  // cocircular rings stacked along z
      const int rings = 2 + it % 3, per = 3 + static_cast<int>(unit(g) * 12);
      for (int r = 0; r < rings; ++r) {
        const double z = u(g), radius = 0.2 + unit(g), phase = unit(g) * 6.283185307179586;
        for (int k = 0; k < per; ++k) {
          const double a = phase + 6.283185307179586 * k / per;
          p.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
        }
      }
    } else if (kind == 3) {  // a dense cluster and a few far points
      const double spread = power(-9, -3);
      for (int i = 0; i < n; ++i) p.push_back(spread * Vec3(u(g), u(g), u(g)));
      for (int i = 0; i < 4; ++i) p.push_back(hull_inputs::unit_vector(g));
    } else {  // a needle: points near a segment
      const double width = power(-12, -4);
      const Vec3 axis = hull_inputs::unit_vector(g);
      for (int i = 0; i < n; ++i) p.push_back(u(g) * axis + width * Vec3(u(g), u(g), u(g)));
    }
    p = hull_inputs::rotated(p, static_cast<unsigned>(it));
    const double scale = power(-6, 6);
    const Vec3 offset = power(-3, 6) * hull_inputs::unit_vector(g);
    for (Vec3& v : p) v = scale * v + offset * (it % 2 ? scale : 1.0);
    SCOPED_TRACE("set " + std::to_string(it) + ", kind " + std::to_string(kind));
    const auto built = mink::build_convex_hull(p);
    ASSERT_TRUE(built.has_value()) << built.error();
    hull_check::check_hull(p, *built);
    if (built->status == HullStatus::Full) {
      ++full;
      const std::size_t before = table().size();
      compare("nasty set " + std::to_string(it), p);
      table().resize(before);  // keep the printed table short
    }
    if (::testing::Test::HasFailure()) {
      for (const Vec3& v : p) std::printf("{%.17g, %.17g, %.17g},\n", v.x(), v.y(), v.z());
      return;
    }
  }
  std::printf("nasty sets: %d of %d solids compared with CGAL\n", full, count);
}

TEST(HullOracle, OrientationMatchesCgal) {
  // Nearly coplanar quadruples in general position (rounded combinations), where double
  // evaluation is unreliable.
  auto g = hull_inputs::rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  int zero = 0;
  for (int it = 0; it < 200000; ++it) {
    const Vec3 a(u(g), u(g), u(g)), b(u(g), u(g), u(g)), c(u(g), u(g), u(g));
    const double s = u(g), t = u(g);
    Vec3 d = a + s * (b - a) + t * (c - a);
    if (it % 4 == 0) d = a + std::ldexp(s, -20) * (b - a);  // nearly collinear too
    if (it % 7 == 0) d = 1e6 * d;                           // and far away
    const int ours = mink::exact::orient3d(a.data(), b.data(), c.data(), d.data());
    const auto o =
        CGAL::orientation(K::Point_3(a.x(), a.y(), a.z()), K::Point_3(b.x(), b.y(), b.z()),
                          K::Point_3(c.x(), c.y(), c.z()), K::Point_3(d.x(), d.y(), d.z()));
    const int theirs = o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0);
    zero += theirs == 0;
    ASSERT_EQ(ours, theirs) << it;
  }
  // CGAL's convention agrees with ours on a positive tetrahedron.
  const double p0[3] = {0, 0, 0}, p1[3] = {1, 0, 0}, p2[3] = {0, 1, 0}, p3[3] = {0, 0, 1};
  EXPECT_EQ(mink::exact::orient3d(p0, p1, p2, p3), 1);
  EXPECT_EQ(CGAL::orientation(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0),
                              K::Point_3(0, 0, 1)),
            CGAL::POSITIVE);
  RecordProperty("exactly_coplanar", zero);
}

class Environment : public ::testing::Environment {
 public:
  void TearDown() override {
    if (table().empty()) return;
    std::printf("\n%-28s %7s %7s %7s %7s %5s %5s %9s %9s %9s %9s %9s %8s %8s\n", "input", "n", "V",
                "F", "cgal V", "ours+", "cgal+", "outside", "flatness", "convexity", "vol err",
                "tol", "ours ms", "cgal ms");
    for (const Row& r : table()) {
      std::printf("%-28s %7zu %7zu %7zu %7zu %5zu %5zu %9.2e %9.2e %9.2e %9.2e %9.2e %8.2f %8.2f\n",
                  r.name.c_str(), r.n, r.v, r.f, r.cgal_v, r.ours_only, r.cgal_only,
                  r.worst_outside, r.worst_flatness, r.worst_convexity, r.volume_error, r.tol,
                  1e3 * r.ours_s, 1e3 * r.cgal_s);
    }
  }
};

const auto* const environment = ::testing::AddGlobalTestEnvironment(new Environment);

}  // namespace
