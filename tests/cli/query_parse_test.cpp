// Reading query lines: every shape type of protocol.md parses and answers, every malformed line
// gets an error line that says what and where, and the next line is still answered.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "answer_check.hpp"

namespace mink::cli::test {
namespace {

const std::string kUnitSphere = R"({"type":"sphere","radius":1})";

std::string line_with_a(const std::string& a, const std::string& extra = "") {
  return R"({"a":)" + a + R"(,"b":)" + kUnitSphere + R"(,"pb":{"t":[10,0,0]})" + extra + "}";
}

TEST(QueryParse, EveryShapeTypeParsesAndAnswers) {
  const std::vector<std::string> shapes = {
      R"({"type":"sphere","radius":0.5})",
      R"({"type":"box","half_extents":[1,2,3]})",
      R"({"type":"capsule","radius":0.5,"half_height":1})",
      R"({"type":"cylinder","radius":0.5,"half_height":1})",
      R"({"type":"cone","radius":0.5,"half_height":1})",
      R"({"type":"ellipsoid","radii":[1,2,3]})",
      R"({"type":"polytope","points":[[0,0,0],[1,0,0],[0,1,0],[0,0,1],[0.1,0.1,0.1]]})",
      R"({"type":"sum","shapes":[{"type":"segment","points":[[0,0,-1],[0,0,1]]},)"
      R"({"type":"sphere","radius":0.5}]})",
      R"({"type":"rounded","shape":{"type":"box","half_extents":[1,1,1]},"radius":0.1})",
      R"({"type":"point","points":[[1,2,3]]})",
      R"({"type":"segment","points":[[0,0,0],[1,1,1]]})",
      R"({"type":"triangle","points":[[0,0,0],[1,0,0],[0,1,0]]})",
  };
  for (const std::string& shape : shapes) {
    const Answer a = answer_one(line_with_a(shape));
    ASSERT_TRUE(a.valid_json) << shape;
    EXPECT_EQ(a.status, "ok") << shape << " -> " << a.raw;
    EXPECT_EQ(a.intersect, false) << shape;
    ASSERT_TRUE(a.distance.has_value()) << shape;
    EXPECT_GT(*a.distance, 0) << shape;
    // The same shape as b.
    const Answer b =
        answer_one(R"({"a":)" + kUnitSphere + R"(,"b":)" + shape + R"(,"pb":{"t":[10,0,0]}})");
    EXPECT_EQ(b.status, "ok") << shape << " -> " << b.raw;
  }
}

struct MalformedCase {
  std::string line;
  std::string reason;  ///< a substring the error must contain
};

TEST(QueryParse, MalformedLinesGetErrorsAndTheNextLineStillAnswers) {
  const std::string sphere_b = R"(,"b":)" + kUnitSphere;
  const std::vector<MalformedCase> cases = {
      {"not json at all", "invalid JSON"},
      {R"({"a":)", "invalid JSON"},
      {R"({"a":{"type":"sphere","radius":1}} trailing)", "invalid JSON"},
      {R"({"a":{"type":"sphere","radius":NaN})" + sphere_b + "}", "invalid JSON"},
      {R"({"a":{"type":"sphere","radius":Infinity})" + sphere_b + "}", "invalid JSON"},
      {R"({"a":{"type":"sphere","radius":1e400})" + sphere_b + "}", "out of range"},
      {R"({"a":{"type":"sphere","radius":1e60})" + sphere_b + "}", "a.radius is out of range"},
      {R"([1,2,3])", "must be a JSON object"},
      {R"("just a string")", "must be a JSON object"},
      {R"({"b":)" + kUnitSphere + "}", "a is missing"},
      {R"({"a":)" + kUnitSphere + "}", "b is missing"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"colour":"red"})", "unknown field 'colour'"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"a":{"type":"sphere","radius":2}})",
       "duplicate field 'a'"},
      {R"({"a":{"type":"sphere","radius":-1})" + sphere_b + "}", "a.radius must be >= 0"},
      {R"({"a":{"type":"sphere"})" + sphere_b + "}", "a.radius is missing"},
      {R"({"a":{"radius":1})" + sphere_b + "}", "a.type is missing"},
      {R"({"a":{"type":7,"radius":1})" + sphere_b + "}", "a.type must be a string"},
      {R"({"a":{"type":"blob"})" + sphere_b + "}", "a.type 'blob' is not a shape type"},
      {R"({"a":{"type":"sphere","radius":"1"})" + sphere_b + "}", "a.radius must be a number"},
      {R"({"a":{"type":"sphere","radius":1,"colour":2})" + sphere_b + "}",
       "a has an unknown field 'colour'"},
      {R"({"a":{"type":"sphere","radius":1,"radius":2})" + sphere_b + "}",
       "a.radius appears twice"},
      {R"({"a":[1,2])" + sphere_b + "}", "a must be an object"},
      {R"({"a":{"type":"box","half_extents":[1,1]})" + sphere_b + "}",
       "a.half_extents must be an array of 3 numbers"},
      {R"({"a":{"type":"box","half_extents":[1,1,1,1]})" + sphere_b + "}",
       "a.half_extents must be an array of 3 numbers"},
      {R"({"a":{"type":"box","half_extents":[1,-1,1]})" + sphere_b + "}",
       "a.half_extents[1] must be >= 0"},
      {R"({"a":{"type":"box","half_extents":[1,null,1]})" + sphere_b + "}",
       "a.half_extents[1] must be a number"},
      {R"({"a":{"type":"capsule","radius":1,"half_height":-2})" + sphere_b + "}",
       "a.half_height must be >= 0"},
      {R"({"a":{"type":"cylinder","radius":-1,"half_height":2})" + sphere_b + "}",
       "a.radius must be >= 0"},
      {R"({"a":{"type":"cone","radius":1})" + sphere_b + "}", "a.half_height is missing"},
      {R"({"a":{"type":"ellipsoid","radii":[1,2,-3]})" + sphere_b + "}", "a.radii[2] must be >= 0"},
      {R"({"a":{"type":"polytope","points":[]})" + sphere_b + "}",
       "a.points must hold at least one point"},
      {R"({"a":{"type":"polytope","points":[[0,0,0],[1,1]]})" + sphere_b + "}",
       "a.points[1] must be an array of 3 numbers"},
      {R"({"a":{"type":"polytope","points":{"x":1}})" + sphere_b + "}",
       "a.points must be an array"},
      {R"({"a":{"type":"point","points":[]})" + sphere_b + "}",
       "a.points must hold exactly 1 point"},
      {R"({"a":{"type":"segment","points":[[0,0,0]]})" + sphere_b + "}",
       "a.points must hold exactly 2 points"},
      {R"({"a":{"type":"triangle","points":[[0,0,0],[1,0,0]]})" + sphere_b + "}",
       "a.points must hold exactly 3 points"},
      {R"({"a":{"type":"sum","shapes":[{"type":"sphere","radius":1}]})" + sphere_b + "}",
       "a.shapes must be an array of 2 shapes"},
      {R"({"a":{"type":"sum","shapes":[{"type":"sphere","radius":1},)"
       R"({"type":"box","half_extents":[1,1,-1]}]})" +
           sphere_b + "}",
       "a.shapes[1].half_extents[2] must be >= 0"},
      {R"({"a":{"type":"rounded","shape":{"type":"sphere","radius":1},"radius":-0.1})" + sphere_b +
           "}",
       "a.radius must be >= 0"},
      {R"({"a":{"type":"rounded","shape":{"type":"blob"},"radius":0.1})" + sphere_b + "}",
       "a.shape.type 'blob' is not a shape type"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"pa":[0,0,0]})", "pa must be an object"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"pa":{"t":[0,0]}})",
       "pa.t must be an array of 3 numbers"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"pb":{"t":[0,0,0],"x":1}})",
       "pb has an unknown field 'x'"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"pb":{"q":[1,0,0]}})",
       "pb.q must be an array of 4 numbers"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"pb":{"q":[1,0,0,0.01]}})",
       "pb.q: quaternion is not unit length"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"pb":{"q":[0,0,0,0]}})",
       "pb.q: quaternion is not unit length"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"pb":{"t":[1,2,1e51]}})",
       "pb.t[2] is out of range"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":"everything"})",
       "want 'everything' is unknown"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":3})", "want must be a string"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":"manifold","margin":-1})",
       "margin must be >= 0"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":"manifold","margin":"0.1"})",
       "margin must be a number"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":"manifold","margin":1e60})",
       "margin is out of range"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":"manifold","margin":1e400})",
       "invalid JSON"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"margin":0.1})",
       "margin is only for want manifold"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":"contact","margin":0.1})",
       "margin is only for want manifold"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"want":"manifold","margin":1,"margin":2})",
       "duplicate field 'margin'"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"id":[1]})", "id must be a string or a number"},
      {R"({"a":)" + kUnitSphere + sphere_b + R"(,"id":null})", "id must be a string or a number"},
      {"{\"a\":\"\xff\xfe\"" + sphere_b + "}", "invalid JSON"},
  };
  std::string input;
  for (const MalformedCase& c : cases) {
    input += c.line + "\n";
    input += R"({"id":"next","a":)" + kUnitSphere + sphere_b + R"(,"pb":{"t":[3,0,0]}})" + "\n";
  }
  const std::vector<Answer> answers = answer(input);
  ASSERT_EQ(answers.size(), 2 * cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Answer& bad = answers[2 * i];
    const Answer& next = answers[2 * i + 1];
    ASSERT_TRUE(bad.valid_json) << cases[i].line;
    EXPECT_EQ(bad.status, "error") << cases[i].line;
    EXPECT_NE(bad.error.find(cases[i].reason), std::string::npos)
        << cases[i].line << "\n  error: " << bad.error << "\n  expected: " << cases[i].reason;
    EXPECT_EQ(bad.keys, (std::set<std::string>{"id", "status", "error"})) << bad.raw;
    // Lines without a (valid) id are answered with their line number.
    if (cases[i].line.find("\"id\"") == std::string::npos) {
      EXPECT_EQ(bad.id, std::to_string(2 * i + 1)) << cases[i].line;
    }
    EXPECT_EQ(next.status, "ok") << "after " << cases[i].line;
    EXPECT_EQ(next.id, "\"next\"");
    EXPECT_EQ(next.distance, 1.0);
  }
}

TEST(QueryParse, ErrorLinesCarryTheIdEvenWhenItComesLast) {
  const Answer a =
      answer_one(R"({"a":{"type":"sphere","radius":-1},"b":)" + kUnitSphere + R"(,"id":"late"})");
  EXPECT_EQ(a.status, "error");
  EXPECT_EQ(a.id, "\"late\"");
  const Answer b =
      answer_one(R"({"a":)" + kUnitSphere + R"(,"b":)" + kUnitSphere + R"(,"extra":1,"id":42})");
  EXPECT_EQ(b.status, "error");
  EXPECT_EQ(b.id, "42");
}

TEST(QueryParse, IdsAreEchoed) {
  const std::string rest = R"("a":)" + kUnitSphere + R"(,"b":)" + kUnitSphere +
                           R"(,"pb":{"t":[3,0,0]},"want":"intersect"})";
  struct IdCase {
    std::string id_json;  ///< as written in the query
    std::string echoed;   ///< as simdjson re-serialises the echoed id
  };
  const std::vector<IdCase> cases = {
      {R"("plain")", R"("plain")"},
      {R"("quote \" backslash \\ newline \n tab \t")",
       R"("quote \" backslash \\ newline \n tab \t")"},
      {R"("\u00e9t\u00e9 \ud83d\ude00")", "\"\xc3\xa9t\xc3\xa9 \xf0\x9f\x98\x80\""},
      {R"("")", R"("")"},
      {"0", "0"},
      {"-17", "-17"},
      {"18446744073709551615", "18446744073709551615"},
      {"2.5", "2.5"},
      {"-1e-300", "-1e-300"},
  };
  for (const IdCase& c : cases) {
    const Answer a = answer_one(R"({"id":)" + c.id_json + "," + rest);
    ASSERT_TRUE(a.valid_json) << c.id_json << " -> " << a.raw;
    EXPECT_EQ(a.status, "ok") << a.raw;
    EXPECT_EQ(a.id, c.echoed) << a.raw;
  }
}

TEST(QueryParse, MissingIdsAreLineNumbersCountingBlankLines) {
  const std::string line =
      R"({"a":)" + kUnitSphere + R"(,"b":)" + kUnitSphere + R"(,"pb":{"t":[3,0,0]}})";
  const std::string input = line + "\n\n   \n" + line + "\r\n\t\r\n" + line;  // no final newline
  const std::vector<Answer> answers = answer(input);
  ASSERT_EQ(answers.size(), 3u);
  EXPECT_EQ(answers[0].id, "1");
  EXPECT_EQ(answers[1].id, "4");
  EXPECT_EQ(answers[2].id, "6");
  for (const Answer& a : answers) EXPECT_EQ(a.status, "ok") << a.raw;
}

TEST(QueryParse, PosesMayOmitEitherField) {
  const std::string ab = R"("a":)" + kUnitSphere + R"(,"b":)" + kUnitSphere;
  EXPECT_EQ(answer_one("{" + ab + R"(,"pb":{"t":[3,0,0]}})").distance, 1.0);
  EXPECT_EQ(answer_one("{" + ab + R"(,"pa":{"q":[1,0,0,0]},"pb":{"t":[3,0,0]}})").distance, 1.0);
  EXPECT_EQ(answer_one("{" + ab + R"(,"pa":{},"pb":{"t":[3,0,0]}})").distance, 1.0);
}

TEST(QueryParse, QuaternionNormToleranceIsOneInAMillion) {
  const std::string ab = R"("a":)" + kUnitSphere + R"(,"b":)" + kUnitSphere;
  // Norm 1 + 5e-7: accepted (and normalised). Norm 1 + 2e-6: rejected.
  EXPECT_EQ(answer_one("{" + ab + R"(,"pb":{"t":[3,0,0],"q":[1.0000005,0,0,0]}})").status, "ok");
  EXPECT_EQ(answer_one("{" + ab + R"(,"pb":{"t":[3,0,0],"q":[1.000002,0,0,0]}})").status, "error");
  EXPECT_EQ(answer_one("{" + ab + R"(,"pb":{"t":[3,0,0],"q":[0.999998,0,0,0]}})").status, "error");
}

TEST(QueryParse, ZeroSizedShapesAreValid) {
  // Radius 0 and half extents 0 are degenerate but legal: a sphere of radius 0 is a point.
  const Answer a = answer_one(R"({"a":{"type":"sphere","radius":0},)"
                              R"("b":{"type":"box","half_extents":[0,0,0]},"pb":{"t":[0,3,4]}})");
  EXPECT_EQ(a.status, "ok") << a.raw;
  EXPECT_EQ(a.distance, 5.0);
}

}  // namespace
}  // namespace mink::cli::test
