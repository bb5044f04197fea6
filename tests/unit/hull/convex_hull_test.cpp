// build_convex_hull on random, degenerate and regression inputs, checked without an oracle
// (hull_check.hpp) and, where the answer is known in closed form, against it. The comparison
// with CGAL's exact convex_hull_3 is in tests/hull/cgal_oracle_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
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

struct HullCase {
  std::string name;
  std::vector<Vec3> points;
  HullStatus status;
};

/// Needles from the random nasty sets (tests/hull/cgal_oracle_test.cpp), 17 digits.
std::vector<Vec3> needle(const std::string& name) {
  if (name == "needle_folded")
    return {Vec3(-5292.7218405151098, 236912.34244083398, -6572.806714534483),
            Vec3(-5295.5598155087491, 236912.03400764382, -6571.9159864735429),
            Vec3(-5292.2055897711525, 236912.39854734391, -6572.9687452147109),
            Vec3(-5300.8745642830736, 236911.45639685864, -6570.2478971178707),
            Vec3(-5297.8680076522287, 236911.78315163159, -6571.1915362857253),
            Vec3(-5298.7546196094854, 236911.68679399486, -6570.9132638714791),
            Vec3(-5298.630237864968, 236911.70031189523, -6570.952302380475),
            Vec3(-5300.3736847695327, 236911.5108328108, -6570.4051033814994)};
  if (name == "needle_folded_four_faces")
    return {Vec3(-1911.5615819578625, -1714.1910373839601, 1949.665048892384),
            Vec3(-1911.3116042209167, -1715.9878023059043, 1941.563179042387),
            Vec3(-1911.3325610533902, -1715.8371708883469, 1942.2423976335522),
            Vec3(-1911.3555193577929, -1715.6721534913572, 1942.9864846655521),
            Vec3(-1911.3593837891208, -1715.6443771160252, 1943.1117323105479),
            Vec3(-1911.4541514133687, -1714.9632158857903, 1946.1831856580734),
            Vec3(-1911.3608807633909, -1715.6336173191096, 1943.1602497715394),
            Vec3(-1911.5047790496224, -1714.599319639023, 1947.8240458479547),
            Vec3(-1911.3473971209337, -1715.7305336875029, 1942.7232400151406),
            Vec3(-1911.4392495145466, -1715.0703262626025, 1945.7002096590109),
            Vec3(-1911.6148861343811, -1713.8079029632236, 1951.3926567589269),
            Vec3(-1911.4534106267618, -1714.9685404380855, 1946.1591764943753),
            Vec3(-1911.3665651909628, -1715.5927593596316, 1943.3444841531355),
            Vec3(-1911.3443575399099, -1715.7523812825898, 1942.6247260839848),
            Vec3(-1911.621026727383, -1713.7637662329976, 1951.5916755862927),
            Vec3(-1911.5713516170274, -1714.1208160108899, 1949.9816871037356),
            Vec3(-1911.3444880054149, -1715.7514435371509, 1942.6289545147931),
            Vec3(-1911.5531570138226, -1714.2515933494963, 1949.3919933904492),
            Vec3(-1911.3928646451188, -1715.4037267801207, 1944.1968590708964),
            Vec3(-1911.4100646880283, -1715.2800980316269, 1944.7543187701278),
            Vec3(-1911.3848587720026, -1715.4612705856209, 1943.9373858273893),
            Vec3(-1911.2854960238353, -1716.1754601889654, 1940.7170028235405),
            Vec3(-1911.6169659185355, -1713.7929541029243, 1951.460063306949),
            Vec3(-1911.3876759509146, -1715.441021552469, 1944.0286916142941),
            Vec3(-1911.3136702847048, -1715.972952062071, 1941.6301409125815),
            Vec3(-1911.3011404837928, -1716.0630125104763, 1941.2240454800281),
            Vec3(-1911.2843616257658, -1716.1836139048098, 1940.680236553655),
            Vec3(-1911.3206555774559, -1715.92274387879, 1941.8565367907786),
            Vec3(-1911.3937017243131, -1715.3977101020266, 1944.2239891329418),
            Vec3(-1911.4603109514135, -1714.9189429754251, 1946.3828185375523),
            Vec3(-1911.3274261728129, -1715.8740788669231, 1942.0759742822759),
            Vec3(-1911.357801384909, -1715.6557509668555, 1943.0604459921074),
            Vec3(-1911.4998955535077, -1714.6344207406719, 1947.6657699625277),
            Vec3(-1911.5980871966663, -1713.9286486926321, 1950.8481970074549),
            Vec3(-1911.3693904884917, -1715.5724519695621, 1943.4360530760282),
            Vec3(-1911.4004226261509, -1715.349402278049, 1944.4418160180578),
            Vec3(-1911.4556519531948, -1714.9524304542801, 1946.2318187122003),
            Vec3(-1911.3327480082025, -1715.8358271126269, 1942.2484569093915),
            Vec3(-1911.32312964775, -1715.9049610055165, 1941.9367223071993),
            Vec3(-1911.3387820123219, -1715.7924565029043, 1942.444021191154),
            Vec3(-1911.2849529771197, -1716.1793634457472, 1940.6994024834373),
            Vec3(-1911.5315380855964, -1714.4069837230959, 1948.6913159844194),
            Vec3(-1911.3509819687149, -1715.7047668792561, 1942.8394262376262),
            Vec3(-1911.3967454736355, -1715.3758325474832, 1944.3226381557586),
            Vec3(-1911.3854692077921, -1715.4568829554382, 1943.9571702786961),
            Vec3(-1911.4606269105225, -1714.9166719571836, 1946.3930588832111),
            Vec3(-1911.5689362750263, -1714.1381767618598, 1949.9034049963257),
            Vec3(-1911.4650586990365, -1714.8848175912517, 1946.5366947730727),
            Vec3(-1911.4961361489691, -1714.6614422115733, 1947.5439262919397),
            Vec3(-1911.3938964520371, -1715.3963104600832, 1944.2303003196382),
            Vec3(-1911.3309959733663, -1715.8484202103864, 1942.1916728327981),
            Vec3(-1911.3025306729396, -1716.0530202474497, 1941.2691020206344),
            Vec3(-1911.5028030230408, -1714.6135227217833, 1947.7600021210658),
            Vec3(-1911.3784436545541, -1715.5073805251618, 1943.7294695222015),
            Vec3(-1911.5985255076271, -1713.9254982432317, 1950.8624028349107),
            Vec3(-1911.5514726050963, -1714.2637003802129, 1949.3374010566961),
            Vec3(-1911.5380135668588, -1714.3604399044134, 1948.9011887182971),
            Vec3(-1911.5703526699574, -1714.1279961405535, 1949.9493108698373)};
  if (name == "needle_folded_thicker")
    return {Vec3(-239342.3642449273, -120690.75416246348, -214693.80926571917),
            Vec3(-239342.35375595887, -120690.74256119819, -214693.80770918017),
            Vec3(-239342.26308869701, -120690.64227914948, -214693.79425438488),
            Vec3(-239342.35630844388, -120690.7453843588, -214693.8080879623),
            Vec3(-239342.29157310404, -120690.67378417749, -214693.7984813989),
            Vec3(-239342.28410958085, -120690.66552918234, -214693.79737382467)};
  return {Vec3(-10007.656371174953, 1227.8486381038574, 9968.642576522423),
          Vec3(-16149.669566560324, 1981.4397704634755, 16086.761958188465),
          Vec3(-3143.9665626311735, 385.7117653010456, 3131.6540724044412),
          Vec3(1574.0199126061329, -193.15914626043727, -1567.9783715278463),
          Vec3(-6968.3262299654725, 854.93959840864477, 6941.1361187292814),
          Vec3(14481.237380640008, -1776.8035190227151, -14424.983845097893),
          Vec3(11722.354544066453, -1438.303813983807, -11676.833688815124),
          Vec3(10245.694134172005, -1257.125730710306, -10205.917818204871),
          Vec3(-15131.395572677222, 1856.5031706969276, 15072.44927647732),
          Vec3(-5906.3801224336903, 724.64467039505632, 5883.3212204430329),
          Vec3(-3153.1001111176492, 386.83240349574868, 3140.7520932563052),
          Vec3(13817.268608956769, -1695.3382151368542, -13763.598062473478),
          Vec3(6370.8169900745825, -781.69968102279199, -6346.114820959132),
          Vec3(616.4019442650274, -75.66470345565584, -614.08574969273081),
          Vec3(-10577.583126434965, 1297.7755050903718, 10536.352188999759),
          Vec3(-15261.094316366629, 1872.4164903074111, 15201.643463373357),
          Vec3(7445.2906932282485, -913.53167892450938, -7416.4085805472587),
          Vec3(-15281.672117750781, 1874.9412723800338, 15222.141212988554),
          Vec3(17344.819249621662, -2128.1492158471879, -17277.425735000601),
          Vec3(-3031.6932601180552, 371.93645188661111, 3019.8175363252867),
          Vec3(6365.7196543728378, -781.07426839923369, -6341.0373169779195),
          Vec3(-4762.6448356224364, 584.31465842738839, 4744.035321153412),
          Vec3(-5469.8846962791904, 671.08909197402465, 5448.5238584832869)};
}

std::vector<HullCase> cases() {
  using namespace hull_inputs;
  std::vector<HullCase> c;
  c.push_back({"ball", in_ball(5000, 11), HullStatus::Full});
  c.push_back({"cube", in_cube(5000, 12), HullStatus::Full});
  c.push_back({"sphere", on_sphere(3000, 13), HullStatus::Full});
  c.push_back({"cube_surface", on_cube_surface(3000, 14, false), HullStatus::Full});
  c.push_back({"rotated_cube_surface", hull_inputs::rotated(on_cube_surface(3000, 15, false), 15),
               HullStatus::Full});
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
    auto p = hull_inputs::rotated(in_ball(1000, 25), 25);
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
  // Needles found by the random nasty sets against CGAL (tests/hull/): about as thin as the
  // tolerance across their length, they were folded onto 3 faces, or 4 with two of them meeting
  // along both sides (volume -3.5e-20); one within the tolerance of a plane but tilted to the
  // coordinate axes got a polygon 1.03 tolerances non-convex.
  for (const auto& [name, status] : {std::pair{"needle_folded", HullStatus::Full},
                                     std::pair{"needle_folded_thicker", HullStatus::Full},
                                     std::pair{"needle_folded_four_faces", HullStatus::Full},
                                     std::pair{"needle_flat", HullStatus::Flat}})
    c.push_back({name, needle(name), status});
  for (auto& r : regressions()) {
    HullStatus s = HullStatus::Full;
    // The Jolt disc is flat only to 1e-5 (float y coordinates): a thin solid here.
    if (r.name == "jolt_quad" || r.name == "jolt_triangle") s = HullStatus::Flat;
    c.push_back({r.name, r.points, s});
  }
  return c;
}

TEST(ConvexHull, AllCasesHoldTheInvariants) {
  for (const HullCase& c : cases()) {
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

TEST(ConvexHull, NeedleVolumesAreExact) {
  // Exact volumes of the hulls (CGAL, exact constructions): a needle's tetrahedra round to more
  // than its volume in plain double products; the hull sums them exactly rounded.
  const std::pair<const char*, double> expected[] = {
      {"needle_folded", 3.8006790891929871e-17},
      {"needle_folded_thicker", 5.6558507132250883e-19},
      {"needle_folded_four_faces", 7.9898390190579349e-18}};
  for (const auto& [name, volume] : expected) {
    SCOPED_TRACE(name);
    const ConvexHull h = build(needle(name));
    ASSERT_EQ(h.status, HullStatus::Full);
    EXPECT_GE(h.faces.size(), 4u);
    EXPECT_NEAR(h.volume, volume, 1e-9 * volume);
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
  const std::vector<std::vector<Vec3>> inputs{
      on_sphere(1500, 1),
      in_ball(1500, 2),
      on_cube_surface(1000, 3, true, 1e-6),
      hull_inputs::rotated(on_cube_surface(1000, 4, false), 4),
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
