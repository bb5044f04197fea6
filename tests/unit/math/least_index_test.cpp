// The index of the least key (EPA's nearest open face) against a plain search written here:
// the lowest index among the least keys, NaN keys never winning, 0 when none can. Sizes 0 to 80
// cover every tail of the vector loop; ties, signed zeros, infinities and NaN keys are mixed in.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mink/math/least_index.hpp"

namespace mink::detail {
namespace {

template <class S>
std::size_t expected_least(const std::vector<S>& keys) {
  std::size_t found = 0;
  bool any = false;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (std::isnan(keys[i])) continue;
    if (!any || keys[i] < keys[found]) found = i;
    any = true;
  }
  // An infinite least key ties with the "nothing found" answer of a scan that starts at +inf.
  if (!any || keys[found] == std::numeric_limits<S>::infinity()) return 0;
  return found;
}

template <class S>
void check_keys() {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-3, 3);
  std::uniform_int_distribution<int> kind(0, 19);
  const S nan = std::numeric_limits<S>::quiet_NaN(), inf = std::numeric_limits<S>::infinity();
  for (int trial = 0; trial < 4000; ++trial) {
    const std::size_t n = std::size_t(trial % 81);
    std::vector<S> keys(n);
    for (S& k : keys) {
      switch (kind(rng)) {
        case 0:
          k = nan;
          break;
        case 1:
          k = inf;
          break;
        case 2:
          k = trial % 5 == 0 ? -inf : inf;
          break;
        case 3:
          k = S(-0.0);
          break;
        case 4:
          k = S(0.0);
          break;
        default:
          k = trial % 3 == 0 ? S(std::round(u(rng))) : S(u(rng));  // ties
      }
    }
    ASSERT_EQ(least_index(keys.data(), n), expected_least(keys)) << "trial " << trial;
  }
  // All NaN, and all +inf: 0.
  std::vector<S> none(37, nan);
  EXPECT_EQ(least_index(none.data(), none.size()), 0u);
  std::vector<S> high(37, inf);
  EXPECT_EQ(least_index(high.data(), high.size()), 0u);
  // The least key last, at every size: the tails.
  for (std::size_t n = 1; n <= 40; ++n) {
    std::vector<S> keys(n, S(1));
    keys.back() = S(-1);
    EXPECT_EQ(least_index(keys.data(), n), n - 1);
  }
}

TEST(LeastIndex, DoublesMatchAPlainSearch) {
  check_keys<double>();
}

TEST(LeastIndex, FloatsMatchAPlainSearch) {
  check_keys<float>();
}

}  // namespace
}  // namespace mink::detail
