// The SIMD lane helpers against plain loops over the same doubles, for both widths: the
// horizontal maximum (ties of +0 and -0 included) and the ordered "any lane greater" test, whose
// NaN lanes never count.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mink/math/lanes.hpp"

#if defined(__SSE2__)
namespace mink::detail {
namespace {

template <int W>
void check_width() {
  using V = Lanes<W>;
  std::mt19937_64 rng(W);
  std::uniform_real_distribution<double> u(-2, 2);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int trial = 0; trial < 2000; ++trial) {
    double lane[W];
    for (double& l : lane) l = trial % 7 == 0 ? std::round(u(rng)) : u(rng);  // ties, signed zeros
    V v;
    lanes_load(v, lane);
    double largest = lane[0];
    for (int k = 1; k < W; ++k) largest = std::max(largest, lane[k]);
    EXPECT_EQ(lanes_max(v), largest);
    const double x = u(rng);
    bool any = false;
    for (double l : lane) any = any || l > x;
    EXPECT_EQ(lanes_any_greater(v, x), any);
    // One lane NaN: it never counts as greater.
    lane[trial % W] = nan;
    lanes_load(v, lane);
    any = false;
    for (double l : lane) any = any || l > x;
    EXPECT_EQ(lanes_any_greater(v, x), any);
    double stored[W];
    lanes_store(stored, v);
    for (int k = 0; k < W; ++k)
      EXPECT_TRUE(stored[k] == lane[k] || (std::isnan(stored[k]) && std::isnan(lane[k])));
  }
  V filled;
  lanes_fill(filled, -0.0);
  double out[W];
  lanes_store(out, filled);
  for (double o : out) EXPECT_TRUE(o == 0 && std::signbit(o));
}

TEST(Lanes, TwoLanesMatchPlainLoops) {
  check_width<2>();
}

// Four lanes in a build without AVX: the operators are lowered to pairs of SSE2 instructions (the
// AVX2 instructions themselves are checked by the support scan's tests).
TEST(Lanes, FourLanesMatchPlainLoops) {
  check_width<4>();
}

}  // namespace
}  // namespace mink::detail
#endif
