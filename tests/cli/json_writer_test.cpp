// The answer writer: numbers read back to the same double, strings are escaped, nothing that is
// not JSON is ever written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>

#include "json_writer.hpp"

namespace mink::cli {
namespace {

double read_back(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  EXPECT_EQ(end, text.c_str() + text.size()) << text;
  return value;
}

TEST(JsonWriter, NumbersRoundTripExactly) {
  const double cases[] = {0.1,
                          1.0 / 3.0,
                          2.5,
                          -7,
                          1e-310,  // subnormal
                          std::numeric_limits<double>::min(),
                          std::numeric_limits<double>::max(),
                          std::numeric_limits<double>::lowest(),
                          123456789012345678.0,
                          0.30000000000000004};
  for (const double x : cases) {
    std::string out;
    append_number(out, x);
    EXPECT_EQ(read_back(out), x) << out;
  }
  const unsigned seed = 20261122;
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 10000; ++i) {
    // Random bit patterns cover every exponent; NaN and infinities are skipped.
    const std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    std::string out;
    append_number(out, x);
    ASSERT_EQ(read_back(out), x) << out << " (seed " << seed << ")";
  }
}

TEST(JsonWriter, NumbersAreShortest) {
  std::string out;
  append_number(out, 0.1);
  EXPECT_EQ(out, "0.1");
  out.clear();
  append_number(out, 3);
  EXPECT_EQ(out, "3");
  out.clear();
  append_number(out, 1e-7);
  EXPECT_EQ(out, "1e-07");
}

TEST(JsonWriter, NegativeZeroIsWrittenAsZero) {
  std::string out;
  append_number(out, -0.0);
  EXPECT_EQ(out, "0");
}

TEST(JsonWriter, NonFiniteBecomesNullNeverNan) {
  for (const double x :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    std::string out;
    append_number(out, x);
    EXPECT_EQ(out, "null");
  }
}

TEST(JsonWriter, StringsAreEscaped) {
  std::string out;
  append_string(out, std::string_view("a\"b\\c\nd\te\x01"
                                      "f\xc3\xa9",
                                      13));
  EXPECT_EQ(out, "\"a\\\"b\\\\c\\nd\\te\\u0001f\xc3\xa9\"");
}

TEST(JsonWriter, Vec3) {
  std::string out;
  append_vec3(out, Vec3(1, -0.5, 0));
  EXPECT_EQ(out, "[1,-0.5,0]");
}

TEST(JsonWriter, ComponentsAndFields) {
  std::string out;
  append_components(out, Vec3(1, -0.5, 1e300), ' ');
  EXPECT_EQ(out, "1 -0.5 1e+300");
  out = "{\"a\":1";
  append_field(out, "b");
  out += "2}";
  EXPECT_EQ(out, R"({"a":1,"b":2})");
}

TEST(JsonWriter, Integers) {
  std::string out;
  append_integer(out, -9223372036854775807 - 1);
  EXPECT_EQ(out, "-9223372036854775808");
}

}  // namespace
}  // namespace mink::cli
