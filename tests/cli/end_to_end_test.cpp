// The real `mink` binary (MINK_EXE), run through the shell: files and stdin, --timing,
// --version, unreadable files, and the demo's queries.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "answer_check.hpp"
#include "run_mink.hpp"

namespace mink::cli::test {
namespace {

const std::string kQueries =
    R"({"id":"apart","a":{"type":"sphere","radius":1},"b":{"type":"sphere","radius":0.5},"pb":{"t":[0,4,0]}})"
    "\n"
    R"({"id":"boxes","a":{"type":"box","half_extents":[1,1,1]},"b":{"type":"box","half_extents":[1,1,1]},"pb":{"t":[2.5,0,0]},"want":"intersect"})"
    "\n\n"
    R"({"a":{"type":"sphere","radius":-1},"b":{"type":"sphere","radius":1}})"
    "\n"
    R"({"id":5,"a":{"type":"capsule","radius":0.5,"half_height":1},"b":{"type":"point","points":[[0,0,4]]},"want":"distance"})"
    "\n";

void expect_answers(const std::vector<Answer>& answers) {
  ASSERT_EQ(answers.size(), 4u);
  EXPECT_EQ(answers[0].id, "\"apart\"");
  EXPECT_EQ(answers[0].status, "ok");
  EXPECT_NEAR(*answers[0].distance, 2.5, 1e-15);
  EXPECT_EQ(answers[1].id, "\"boxes\"");
  EXPECT_EQ(answers[1].intersect, false);
  EXPECT_EQ(answers[2].id, "4");
  EXPECT_EQ(answers[2].status, "error");
  EXPECT_EQ(answers[2].error, "a.radius must be >= 0");
  EXPECT_EQ(answers[3].id, "5");
  EXPECT_NEAR(*answers[3].distance, 2.5, 1e-15);  // 4 - 1 - 0.5
}

TEST(EndToEnd, AnswersAFile) {
  const ProcessResult r = run_mink("query '" + write_temp("e2e.jsonl", kQueries) + "'");
  EXPECT_EQ(r.exit_code, 0);
  expect_answers(parse_answers(r.out));
}

TEST(EndToEnd, AnswersStandardInput) {
  const std::string path = write_temp("e2e_stdin.jsonl", kQueries);
  expect_answers(parse_answers(run_mink("query < '" + path + "'").out));
  const ProcessResult dash = run_mink("query - < '" + path + "'");
  EXPECT_EQ(dash.exit_code, 0);
}

TEST(EndToEnd, TimingAddsMicroseconds) {
  const ProcessResult r =
      run_mink("query --timing '" + write_temp("e2e_timing.jsonl", kQueries) + "'");
  ASSERT_EQ(r.exit_code, 0);
  const auto answers = parse_answers(r.out);
  ASSERT_EQ(answers.size(), 4u);
  for (const Answer& a : answers) EXPECT_EQ(a.us.has_value(), a.status != "error") << a.raw;
}

TEST(EndToEnd, MissingFileIsReportedAndOthersStillAnswered) {
  const std::string path = write_temp("e2e_more.jsonl", kQueries);
  const ProcessResult r = run_mink("query /nonexistent/queries.jsonl '" + path + "'");
  EXPECT_EQ(r.exit_code, 1);
  const auto answers = parse_answers(r.out);
  expect_answers(answers);
}

TEST(EndToEnd, Version) {
  const ProcessResult r = run_mink("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("mink 0."), std::string::npos) << r.out;
}

TEST(EndToEnd, NoSubcommandIsAUsageError) {
  EXPECT_NE(run_mink("").exit_code, 0);
}

TEST(EndToEnd, DemoQueriesAllAnswer) {
  std::ifstream file(MINK_DEMO_QUERIES);
  ASSERT_TRUE(file) << MINK_DEMO_QUERIES;
  std::size_t lines = 0;
  for (std::string line; std::getline(file, line);)
    if (!line.empty()) ++lines;
  const ProcessResult r = run_mink(std::string("query '") + MINK_DEMO_QUERIES + "'");
  ASSERT_EQ(r.exit_code, 0);
  const auto answers = parse_answers(r.out);
  ASSERT_EQ(answers.size(), lines);
  int errors = 0, penetrating = 0;
  for (const Answer& a : answers) {
    ASSERT_TRUE(a.valid_json) << a.raw;
    errors += a.status == "error";
    penetrating += a.depth.has_value() && *a.depth > 0;
    if (a.status != "error") {
      EXPECT_EQ(a.status, "ok") << a.raw;
    }
  }
  // The demo shows exactly one malformed line and at least one penetrating pair.
  EXPECT_EQ(errors, 1);
  EXPECT_GE(penetrating, 1);
}

}  // namespace
}  // namespace mink::cli::test
