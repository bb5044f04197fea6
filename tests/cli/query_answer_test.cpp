// Answers checked against independent, hand-computed values (sphere-sphere |c| - r1 - r2,
// axis-aligned box gaps, point-box corner distances, capsule axes), and the fields each `want`
// writes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>

#include "answer_check.hpp"
#include "json_writer.hpp"

namespace mink::cli::test {
namespace {

std::string num(double x) {
  std::string out;
  append_number(out, x);
  return out;
}

std::string vec(const Vec3& v) {
  std::string out;
  append_vec3(out, v);
  return out;
}

/// Every separated answer satisfies point_b - point_a = distance * normal, |normal| = 1.
void expect_consistent(const Answer& a, double tolerance) {
  ASSERT_TRUE(a.normal && a.point_a && a.point_b) << a.raw;
  EXPECT_NEAR(a.normal->norm(), 1.0, 1e-12) << a.raw;
  EXPECT_LE((*a.point_b - *a.point_a - *a.distance * *a.normal).norm(), tolerance) << a.raw;
}

TEST(QueryAnswer, SphereSphereMatchesAnalytic) {
  const unsigned seed = 7;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coordinate(-10, 10), radius(0.01, 2);
  for (int i = 0; i < 500; ++i) {
    const Vec3 ca(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3 cb(coordinate(rng), coordinate(rng), coordinate(rng));
    const double ra = radius(rng), rb = radius(rng);
    const double expected = (cb - ca).norm() - ra - rb;
    const Answer a = answer_one(R"({"a":{"type":"sphere","radius":)" + num(ra) + R"(},"pa":{"t":)" +
                                vec(ca) + R"(},"b":{"type":"sphere","radius":)" + num(rb) +
                                R"(},"pb":{"t":)" + vec(cb) + "}}");
    // Tolerance: a few ulps of the coordinates (|c| <= 20).
    const double tolerance = 1e-13 * 20;
    if (expected > tolerance) {
      ASSERT_EQ(a.status, "ok") << a.raw << " (seed " << seed << ")";
      EXPECT_EQ(a.intersect, false);
      EXPECT_NEAR(*a.distance, expected, tolerance) << a.raw;
      EXPECT_EQ(a.depth, 0.0);
      expect_consistent(*&a, tolerance);
      const Vec3 n = (cb - ca).normalized();
      EXPECT_LE((*a.normal - n).norm(), 1e-12) << a.raw;
      EXPECT_LE((*a.point_a - (ca + ra * n)).norm(), tolerance) << a.raw;
      EXPECT_LE((*a.point_b - (cb - rb * n)).norm(), tolerance) << a.raw;
    } else if (expected < -tolerance) {
      // Penetrating: depth r_a + r_b - |cb - ca|, normal along the line of centres (B moves
      // away from A), deepest points on each sphere along it.
      ASSERT_EQ(a.status, "ok") << a.raw;
      EXPECT_EQ(a.intersect, true);
      EXPECT_EQ(a.distance, 0.0);
      EXPECT_NEAR(*a.depth, -expected, tolerance) << a.raw;
      if ((cb - ca).norm() > 1e-6) {
        const Vec3 n = (cb - ca).normalized();
        EXPECT_LE((*a.normal - n).norm(), 1e-9) << a.raw;
        EXPECT_LE((*a.point_a - (ca + ra * n)).norm(), tolerance) << a.raw;
        EXPECT_LE((*a.point_b - (cb - rb * n)).norm(), tolerance) << a.raw;
      }
    }
  }
}

TEST(QueryAnswer, AxisAlignedBoxGaps) {
  // Box A half extents (1,2,3) at the origin; box B half extents (0.5,0.5,0.5) shifted along each
  // axis so that the gap is exactly 0.25 (all values are exact in binary).
  const std::string a = R"({"type":"box","half_extents":[1,2,3]})";
  const std::string b = R"({"type":"box","half_extents":[0.5,0.5,0.5]})";
  const Vec3 half_a(1, 2, 3);
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {1.0, -1.0}) {
      Vec3 t = Vec3::Zero();
      t[axis] = sign * (half_a[axis] + 0.5 + 0.25);
      const Answer r = answer_one(R"({"a":)" + a + R"(,"b":)" + b + R"(,"pb":{"t":)" + vec(t) +
                                  R"(},"want":"distance"})");
      ASSERT_EQ(r.status, "ok") << r.raw;
      EXPECT_EQ(r.distance, 0.25) << r.raw;
      Vec3 n = Vec3::Zero();
      n[axis] = sign;
      EXPECT_LE((*r.normal - n).norm(), 1e-15) << r.raw;
      EXPECT_NEAR((*r.point_a)[axis], sign * half_a[axis], 1e-15) << r.raw;
      EXPECT_FALSE(r.depth.has_value()) << "want distance has no depth: " << r.raw;
      expect_consistent(r, 1e-15);
    }
  }
}

TEST(QueryAnswer, RotatedBoxSwapsItsExtents) {
  // B (half extents 3,0.5,0.5) turned 90 degrees about z reaches 3 along y and 0.5 along x.
  const double h = std::sqrt(0.5);
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string chains.
  std::string q = "[";
  q.append(num(h)).append(",0,0,").append(num(h)).append("]");
  const Answer r = answer_one(
      R"({"a":{"type":"box","half_extents":[1,1,1]},"b":{"type":"box","half_extents":[3,0.5,0.5]},)"
      R"("pb":{"t":[2,0,0],"q":)" +
      q + "}}");
  ASSERT_EQ(r.status, "ok") << r.raw;
  EXPECT_NEAR(*r.distance, 0.5, 1e-15) << r.raw;
}

TEST(QueryAnswer, PointToBoxCorner) {
  // The closest point of the box [-1,1]^3 to (2,3,4) is its corner (1,1,1): distance sqrt(14).
  const Answer r = answer_one(
      R"({"a":{"type":"box","half_extents":[1,1,1]},"b":{"type":"point","points":[[2,3,4]]}})");
  ASSERT_EQ(r.status, "ok") << r.raw;
  EXPECT_NEAR(*r.distance, std::sqrt(14.0), 1e-15);
  EXPECT_LE((*r.point_a - Vec3(1, 1, 1)).norm(), 1e-15) << r.raw;
  EXPECT_LE((*r.point_b - Vec3(2, 3, 4)).norm(), 1e-15) << r.raw;
}

TEST(QueryAnswer, CapsuleTurnedOntoTheXAxis) {
  // A capsule (radius 0.5, half height 2) turned 90 degrees about y lies along x from -2 to 2;
  // a unit sphere at (5,0,0) is 5 - 2 - 0.5 - 1 = 1.5 away, and one at (0,0,4) 4 - 0.5 - 1.
  const double h = std::sqrt(0.5);
  const std::string capsule = R"("a":{"type":"capsule","radius":0.5,"half_height":2},"pa":{"q":[)" +
                              num(h) + ",0," + num(h) + ",0]}";
  const std::string sphere = R"("b":{"type":"sphere","radius":1})";
  EXPECT_NEAR(*answer_one("{" + capsule + "," + sphere + R"(,"pb":{"t":[5,0,0]}})").distance, 1.5,
              1e-14);
  EXPECT_NEAR(*answer_one("{" + capsule + "," + sphere + R"(,"pb":{"t":[0,0,4]}})").distance, 2.5,
              1e-14);
}

TEST(QueryAnswer, SumOfSegmentAndSphereIsACapsule) {
  const std::string b = R"("b":{"type":"sphere","radius":1},"pb":{"t":[0,3,0.5]})";
  const Answer sum =
      answer_one(R"({"a":{"type":"sum","shapes":[{"type":"segment","points":[[0,0,-1],[0,0,1]]},)"
                 R"({"type":"sphere","radius":0.5}]},)" +
                 b + "}");
  const Answer capsule =
      answer_one(R"({"a":{"type":"capsule","radius":0.5,"half_height":1},)" + b + "}");
  ASSERT_EQ(sum.status, "ok") << sum.raw;
  EXPECT_NEAR(*sum.distance, 1.5, 1e-14);
  EXPECT_NEAR(*sum.distance, *capsule.distance, 1e-14);
}

TEST(QueryAnswer, RoundedBoxAddsItsRadius) {
  const Answer r = answer_one(
      R"({"a":{"type":"rounded","shape":{"type":"box","half_extents":[1,1,1]},"radius":0.25},)"
      R"("b":{"type":"point","points":[[3,0,0]]}})");
  ASSERT_EQ(r.status, "ok") << r.raw;
  EXPECT_NEAR(*r.distance, 1.75, 1e-15);
}

TEST(QueryAnswer, TouchingSpheresIntersect) {
  const Answer r = answer_one(R"({"a":{"type":"sphere","radius":1},"b":{"type":"sphere",)"
                              R"("radius":1},"pb":{"t":[2,0,0]},"want":"distance"})");
  EXPECT_EQ(r.status, "ok") << r.raw;
  EXPECT_EQ(r.intersect, true);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_FALSE(r.normal.has_value()) << r.raw;
}

TEST(QueryAnswer, FieldsOfEachWant) {
  const std::string apart = R"({"a":{"type":"box","half_extents":[1,1,1]},"b":{"type":"box",)"
                            R"("half_extents":[1,1,1]},"pb":{"t":[3,0,0]})";
  const std::string overlapping = R"({"a":{"type":"box","half_extents":[1,1,1]},"b":{"type":)"
                                  R"("box","half_extents":[1,1,1]},"pb":{"t":[1.5,0,0]})";
  using Keys = std::set<std::string>;
  const Keys separated_distance = {"id",     "status",  "intersect", "distance",
                                   "normal", "point_a", "point_b",   "iterations"};
  Keys separated_contact = separated_distance;
  separated_contact.insert("depth");

  EXPECT_EQ(answer_one(apart + R"(,"want":"intersect"})").keys,
            (Keys{"id", "status", "intersect", "iterations"}));
  EXPECT_EQ(answer_one(apart + R"(,"want":"distance"})").keys, separated_distance);
  EXPECT_EQ(answer_one(apart + R"(,"want":"contact"})").keys, separated_contact);
  EXPECT_EQ(answer_one(apart + "}").keys, separated_contact) << "contact is the default";
  EXPECT_EQ(answer_one(apart + "}").depth, 0.0);
  const Answer concentric = answer_one(R"({"a":{"type":"sphere","radius":1},"b":{"type":)"
                                       R"("sphere","radius":2}})");
  EXPECT_EQ(concentric.status, "ok") << concentric.raw;
  EXPECT_EQ(concentric.depth, 3.0) << concentric.raw;
  EXPECT_NE(concentric.raw.find("\"normal_chosen\":true"), std::string::npos) << concentric.raw;

  const Answer hit = answer_one(overlapping + R"(,"want":"intersect"})");
  EXPECT_EQ(hit.status, "ok");
  EXPECT_EQ(hit.intersect, true);
  EXPECT_EQ(*hit.iterations, 0) << "two boxes: the separating axis test decides, no GJK";
  const Answer hit_distance = answer_one(overlapping + R"(,"want":"distance"})");
  EXPECT_EQ(hit_distance.keys, (Keys{"id", "status", "intersect", "distance", "iterations"}));
  EXPECT_EQ(hit_distance.distance, 0.0);
  const Answer hit_contact = answer_one(overlapping + "}");
  EXPECT_EQ(hit_contact.status, "ok");
  EXPECT_EQ(hit_contact.intersect, true);
  EXPECT_EQ(hit_contact.distance, 0.0);
  EXPECT_EQ(hit_contact.depth, 0.5) << hit_contact.raw;
  EXPECT_EQ(*hit_contact.normal, Vec3(1, 0, 0)) << hit_contact.raw;
  EXPECT_EQ(hit_contact.keys, separated_contact);
}

TEST(QueryAnswer, ManifoldOfABoxOnATable) {
  // A 1 x 1 box pushed 0.25 into a 4 x 4 table: four points at the box's bottom corners
  // (x, y = +-0.5, z = 0.75 on B, 1 on A; position the midpoint 0.875), each 0.25 deep.
  const Answer r = answer_one(R"({"a":{"type":"box","half_extents":[2,2,1]},"b":{"type":"box",)"
                              R"("half_extents":[0.5,0.5,0.5]},"pb":{"t":[0,0,1.25]},)"
                              R"("want":"manifold"})");
  EXPECT_EQ(r.status, "ok") << r.raw;
  EXPECT_EQ(r.depth, 0.25) << r.raw;
  EXPECT_EQ(*r.normal, Vec3(0, 0, 1)) << r.raw;
  EXPECT_TRUE(r.keys.count("manifold")) << r.raw;
  for (const char* corner :
       {"[0.5,0.5,0.875]", "[-0.5,0.5,0.875]", "[0.5,-0.5,0.875]", "[-0.5,-0.5,0.875]"})
    EXPECT_NE(r.raw.find(std::string("{\"position\":") + corner + ",\"depth\":0.25,"),
              std::string::npos)
        << corner << " in " << r.raw;
  std::size_t points = 0;
  for (std::size_t at = r.raw.find("\"position\""); at != std::string::npos;
       at = r.raw.find("\"position\"", at + 1))
    ++points;
  EXPECT_EQ(points, 4u) << r.raw;
  // Apart: no points.
  const Answer apart = answer_one(R"({"a":{"type":"sphere","radius":1},"b":{"type":"sphere",)"
                                  R"("radius":1},"pb":{"t":[3,0,0]},"want":"manifold"})");
  EXPECT_EQ(apart.status, "ok") << apart.raw;
  EXPECT_NE(apart.raw.find("\"points\":[]"), std::string::npos) << apart.raw;
}

TEST(QueryAnswer, ManifoldMarginGivesSpeculativePoints) {
  // A 1 x 1 box 0.05 above a 2 x 2 one: with a margin of 0.1, its four bottom corners with depth
  // -0.05 (point_a on A's top face z = 1, point_b on B's bottom z = 1.05); with 0.01, none.
  const std::string boxes = R"({"a":{"type":"box","half_extents":[1,1,1]},"b":{"type":"box",)"
                            R"("half_extents":[0.5,0.5,0.5]},"pb":{"t":[0,0,1.55]},)"
                            R"("want":"manifold")";
  const double gap = 1.55 - 0.5 - 1;
  const Answer within = answer_one(boxes + R"(,"margin":0.1})");
  EXPECT_EQ(within.status, "ok") << within.raw;
  EXPECT_EQ(within.intersect, false);
  EXPECT_NEAR(*within.distance, gap, 1e-15);
  EXPECT_EQ(within.depth, 0.0);
  EXPECT_EQ(*within.normal, Vec3(0, 0, 1)) << within.raw;
  EXPECT_EQ(*within.manifold_normal, Vec3(0, 0, 1)) << within.raw;
  ASSERT_EQ(within.manifold_points.size(), 4u) << within.raw;
  std::set<std::pair<double, double>> corners;
  for (const ManifoldPointAnswer& p : within.manifold_points) {
    EXPECT_NEAR(p.depth, -gap, 1e-15) << within.raw;
    EXPECT_NEAR(std::abs(p.position.x()), 0.5, 1e-15);
    EXPECT_NEAR(std::abs(p.position.y()), 0.5, 1e-15);
    EXPECT_NEAR(p.position.z(), 1 + gap / 2, 1e-15);
    EXPECT_NEAR(p.point_a.z(), 1, 1e-15);
    EXPECT_NEAR(p.point_b.z(), 1 + gap, 1e-15);
    EXPECT_LE((p.point_b - p.point_a + p.depth * Vec3(0, 0, 1)).norm(), 1e-15);
    corners.emplace(p.position.x(), p.position.y());
  }
  EXPECT_EQ(corners.size(), 4u) << within.raw;
  // point_a and point_b: the deepest manifold point's.
  EXPECT_EQ(*within.point_a, within.manifold_points[0].point_a);
  EXPECT_EQ(*within.point_b, within.manifold_points[0].point_b);

  for (const std::string margin : {",\"margin\":0.01", ",\"margin\":0", ""}) {
    const Answer beyond = answer_one(boxes + margin + "}");
    EXPECT_EQ(beyond.status, "ok") << beyond.raw;
    EXPECT_TRUE(beyond.manifold_points.empty()) << beyond.raw;
    EXPECT_FALSE(beyond.point_a || beyond.point_b) << beyond.raw;
    EXPECT_NE(beyond.raw.find("\"points\":[]"), std::string::npos) << beyond.raw;
  }

  // A margin also keeps the corners of a penetrating box that are just above the surface: a
  // unit box turned about x by 5e-4 rad (its bottom still a face: within the feature tolerance,
  // 1e-3 of its bounding radius), its lower bottom edge 1e-4 deep, the upper one sin(5e-4)
  // higher, so about 4e-4 above.
  const double angle = 5e-4, s = std::sin(angle), c = std::cos(angle), deep = 1e-4;
  const std::string tilted = R"({"a":{"type":"box","half_extents":[2,2,1]},"b":{"type":"box",)"
                             R"("half_extents":[0.5,0.5,0.5]},"pb":{"t":[0,0,)" +
                             num(1 - deep + 0.5 * c + 0.5 * s) + R"(],"q":[)" +
                             num(std::cos(angle / 2)) + "," + num(std::sin(angle / 2)) +
                             R"(,0,0]},"want":"manifold")";
  const Answer tight = answer_one(tilted + "}");
  const Answer loose = answer_one(tilted + R"(,"margin":1e-3})");
  EXPECT_EQ(tight.status, "ok") << tight.raw;
  EXPECT_EQ(loose.status, "ok") << loose.raw;
  EXPECT_NEAR(*tight.depth, deep, 1e-12) << tight.raw;
  ASSERT_EQ(tight.manifold_points.size(), 2u) << tight.raw;
  for (const ManifoldPointAnswer& p : tight.manifold_points) EXPECT_NEAR(p.depth, deep, 1e-12);
  ASSERT_EQ(loose.manifold_points.size(), 4u) << loose.raw;
  std::multiset<double> depths;
  for (const ManifoldPointAnswer& p : loose.manifold_points) depths.insert(p.depth);
  EXPECT_NEAR(*depths.begin(), deep - s, 1e-12) << loose.raw;
  EXPECT_NEAR(*std::next(depths.begin()), deep - s, 1e-12) << loose.raw;
  EXPECT_NEAR(*depths.rbegin(), deep, 1e-12) << loose.raw;
}

TEST(QueryAnswer, TimingAddsMicroseconds) {
  const std::string line = R"({"a":{"type":"sphere","radius":1},"b":{"type":"box",)"
                           R"("half_extents":[1,1,1]},"pb":{"t":[3,0,0]})";
  for (const char* want : {"intersect", "distance", "contact"}) {
    const auto answers = answer(line + R"(,"want":")" + want + "\"}", true);
    ASSERT_EQ(answers.size(), 1u);
    ASSERT_TRUE(answers[0].us.has_value()) << answers[0].raw;
    EXPECT_GE(*answers[0].us, 0.0);
    EXPECT_TRUE(std::isfinite(*answers[0].us));
  }
  EXPECT_FALSE(answer(line + "}", false)[0].us.has_value());
  // Error lines carry no time.
  EXPECT_FALSE(answer("{}", true)[0].us.has_value());
}

TEST(QueryAnswer, NumbersInAnswersReadBackToTheSameDouble) {
  // 1/3-ish inputs give distances with all 17 digits; the text must parse back bit for bit to
  // what the writer was given, which the JSON reader (simdjson) and the writer agree on.
  const Answer r = answer_one(R"({"a":{"type":"sphere","radius":0.3333333333333333},)"
                              R"("b":{"type":"sphere","radius":0.1},"pb":{"t":[1,1,1]}})");
  ASSERT_EQ(r.status, "ok");
  const std::size_t at = r.raw.find("\"distance\":") + 11;
  const std::string text = r.raw.substr(at, r.raw.find(',', at) - at);
  EXPECT_EQ(std::strtod(text.c_str(), nullptr), *r.distance) << text;
  EXPECT_NEAR(*r.distance, std::sqrt(3.0) - 0.3333333333333333 - 0.1, 1e-15);
  EXPECT_GE(text.size(), 15u) << "not rounded to a few digits";
}

}  // namespace
}  // namespace mink::cli::test
