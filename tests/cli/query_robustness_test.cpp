// Bad input never crashes, hangs or produces anything but one valid JSON answer per line:
// random byte mutations of valid lines, deep nesting, long lines, extreme but legal magnitudes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "answer_check.hpp"

namespace mink::cli::test {
namespace {

const std::vector<std::string> kSeeds = {
    R"({"id":"s","a":{"type":"sphere","radius":1},"pa":{"t":[0,0,0],"q":[1,0,0,0]},"b":{"type":"box","half_extents":[1,2,3]},"pb":{"t":[3,0.5,-1]},"want":"distance"})",
    R"({"a":{"type":"polytope","points":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]},"b":{"type":"cone","radius":1,"half_height":2},"pb":{"t":[0,0,5],"q":[0,1,0,0]}})",
    R"({"id":3,"a":{"type":"sum","shapes":[{"type":"triangle","points":[[0,0,0],[1,0,0],[0,1,0]]},{"type":"ellipsoid","radii":[1,2,3]}]},"b":{"type":"rounded","shape":{"type":"capsule","radius":0.5,"half_height":1},"radius":0.1},"pb":{"t":[6,0,0]},"want":"intersect"})",
    R"({"a":{"type":"cylinder","radius":1,"half_height":1},"b":{"type":"segment","points":[[0,0,0],[1,1,1]]},"pb":{"t":[3,3,3]}})",
};

void expect_well_formed(const Answer& a, const std::string& line) {
  ASSERT_TRUE(a.valid_json) << line << "\n -> " << a.raw;
  EXPECT_TRUE(a.keys.count("id") && a.keys.count("status")) << a.raw;
  EXPECT_EQ(a.raw.find("nan"), std::string::npos) << a.raw;
  EXPECT_EQ(a.raw.find("inf"), std::string::npos) << a.raw;
  EXPECT_EQ(a.raw.find("null"), std::string::npos) << a.raw;
  if (a.status == "error") {
    EXPECT_FALSE(a.error.empty()) << a.raw;
  }
  if (a.distance) {
    EXPECT_TRUE(std::isfinite(*a.distance) && *a.distance >= 0) << a.raw;
  }
}

TEST(QueryRobustness, RandomMutationsGiveOneValidAnswerPerLine) {
  const unsigned seed = 12345;
  std::mt19937 rng(seed);
  const std::string alphabet = "{}[]\",:0123456789.-+eE \\ntruefalsnul\x01\xff";
  std::string input;
  std::vector<std::string> lines;
  for (int i = 0; i < 4000; ++i) {
    std::string line = kSeeds[rng() % kSeeds.size()];
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits && !line.empty(); ++e) {
      const std::size_t at = rng() % line.size();
      switch (rng() % 3) {
        case 0:
          line[at] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          line.erase(at, 1 + rng() % 8);
          break;
        default:
          line.insert(at, 1, alphabet[rng() % alphabet.size()]);
      }
    }
    // A newline inserted by the mutation would split the line; keep one query per line.
    for (char& c : line)
      if (c == '\n') c = ' ';
    lines.push_back(line);
    input += line + "\n";
  }
  const std::vector<Answer> answers = answer(input);
  std::size_t expected = 0;
  for (const std::string& line : lines)
    if (line.find_first_not_of(" \t\r") != std::string::npos) ++expected;
  ASSERT_EQ(answers.size(), expected) << "seed " << seed;
  for (std::size_t i = 0; i < answers.size(); ++i) expect_well_formed(answers[i], "(mutated)");
}

TEST(QueryRobustness, DeeplyNestedShapesAnswerOrFailCleanly) {
  for (const int depth : {1, 10, 100, 400, 2000}) {
    std::string shape = R"({"type":"sphere","radius":0.001})";
    for (int i = 0; i < depth; ++i)
      shape = R"({"type":"rounded","shape":)" + shape + R"(,"radius":0.001})";
    const Answer a = answer_one(R"({"a":)" + shape +
                                R"(,"b":{"type":"sphere","radius":1},"pb":{"t":[10,0,0]}})");
    expect_well_formed(a, "depth " + std::to_string(depth));
    if (a.status == "ok") {
      EXPECT_NEAR(*a.distance, 9 - 0.001 * (depth + 1), 1e-9);
    }
  }
}

TEST(QueryRobustness, DeeplyNestedArraysAreJsonErrors) {
  const std::string line = std::string(100000, '[') + std::string(100000, ']');
  const Answer a = answer_one(line);
  expect_well_formed(a, "deep arrays");
  EXPECT_EQ(a.status, "error");
}

TEST(QueryRobustness, LongPolytopeLine) {
  // 50 000 points on a sphere of radius 1 around the origin, a point at distance 3.
  std::string points;
  const unsigned seed = 99;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 50000; ++i) {
    Vec3 p(normal(rng), normal(rng), normal(rng));
    p.normalize();
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on long operator+ chains.
    if (i) points += ',';
    points.append("[").append(std::to_string(p.x())).append(",");
    points.append(std::to_string(p.y())).append(",").append(std::to_string(p.z())).append("]");
  }
  const Answer a = answer_one(R"({"a":{"type":"polytope","points":[)" + points +
                              R"(]},"b":{"type":"point","points":[[3,0,0]]}})");
  ASSERT_EQ(a.status, "ok") << a.raw.substr(0, 200);
  // The hull of dense sphere samples lies within 1e-2 of the sphere (tolerance, seed 99).
  EXPECT_NEAR(*a.distance, 2.0, 1e-2);
}

TEST(QueryRobustness, ExtremeLegalMagnitudesStayFinite) {
  // 3e49: the largest number written is 3 * scale, just under kMaxMagnitude (1e50).
  for (const double scale : {1e-300, 1e-100, 1e-10, 1e10, 1e30, 1e45, 3e49}) {
    char line[1024];
    std::snprintf(line, sizeof line,
                  R"({"a":{"type":"box","half_extents":[%.17g,%.17g,%.17g]},)"
                  R"("pa":{"t":[%.17g,0,0],"q":[0.5,0.5,0.5,0.5]},)"
                  R"("b":{"type":"cone","radius":%.17g,"half_height":%.17g},)"
                  R"("pb":{"t":[0,%.17g,%.17g]},"want":"distance"})",
                  scale, 2 * scale, 0.5 * scale, -scale, scale, scale, 3 * scale, -scale);
    const Answer a = answer_one(line);
    expect_well_formed(a, line);
    EXPECT_EQ(a.status, "ok") << a.raw;
  }
}

}  // namespace
}  // namespace mink::cli::test
