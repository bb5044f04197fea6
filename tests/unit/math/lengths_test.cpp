// lengths_of() (two lengths with one packed square root) against length_of() one at a time, to
// the last bit, at every magnitude a length can have: 0, subnormal, the ranges where the square
// underflows or overflows, and ordinary ones; and box_bounding_radii() against bounding_radius().
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mink/query/box_box.hpp"

namespace mink::detail {
namespace {

template <class S>
void check_lengths() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<S> unit(S(-1), S(1));
  std::uniform_int_distribution<int> exponent(std::numeric_limits<S>::min_exponent - 30,
                                              std::numeric_limits<S>::max_exponent - 2);
  auto vector = [&] {
    // Coordinates of mixed magnitudes, some exactly 0.
    Vec3T<S> v;
    for (int i = 0; i < 3; ++i)
      v[i] = rng() % 5 == 0 ? S(0) : std::ldexp(unit(rng), exponent(rng) / (1 + int(rng() % 3)));
    return v;
  };
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3T<S> u = vector(), v = vector();
    S lu = S(-1), lv = S(-1);
    lengths_of(u, v, lu, lv);
    EXPECT_EQ(lu, length_of(u)) << u.transpose();
    EXPECT_EQ(lv, length_of(v)) << v.transpose();
  }
}

TEST(Lengths, TwoAtOnceEqualOneAtATimeDouble) {
  check_lengths<double>();
}
TEST(Lengths, TwoAtOnceEqualOneAtATimeFloat) {
  check_lengths<float>();
}

TEST(Lengths, BoxBoundingRadiiEqualBoundingRadius) {
  const Box tiny{Vec3(1e-200, 3e-201, 0)}, huge{Vec3(1e200, 2e199, 5e199)}, plain{Vec3(1, 2, 3)};
  const Rounded<Box> rounded{plain, 0.25};
  const Box boxes[] = {tiny, huge, plain, Box{Vec3::Zero()}};
  for (const Box& a : boxes) {
    for (const Box& b : boxes) {
      double ra = -1, rb = -1;
      box_bounding_radii(a, b, ra, rb);
      EXPECT_EQ(ra, a.bounding_radius());
      EXPECT_EQ(rb, b.bounding_radius());
    }
    double ra = -1, rb = -1;
    box_bounding_radii(a, rounded, ra, rb);
    EXPECT_EQ(ra, a.bounding_radius());
    EXPECT_EQ(rb, rounded.bounding_radius());
  }
}

}  // namespace
}  // namespace mink::detail
