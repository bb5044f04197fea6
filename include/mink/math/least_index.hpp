/// @file least_index.hpp
/// The index of the least of n keys, found with no branch on the keys' values.
///
/// A scan of a packed array replaces a priority queue where the queue is small and changes a
/// lot: EPA's open faces (a few dozen to a few hundred). The heap's sifts branched on every
/// comparison of keys, and those branches are unpredictable; the scan costs a vector minimum per
/// two keys and one branch at the end.
///
/// Result: the lowest index among the least keys. NaN keys never win; with no key that is not
/// NaN (or n = 0), 0.
#pragma once

#include <bit>
#include <cstddef>
#include <limits>

#include "mink/math/lanes.hpp"

namespace mink::detail {

template <class S>
std::size_t least_index(const S* keys, std::size_t n) {
  S least = std::numeric_limits<S>::infinity();
  std::size_t least_i = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (keys[i] < least) {
      least = keys[i];
      least_i = i;
    }
  return least_i;
}

#if defined(__SSE2__)
/// Doubles: the least value by vector minima in four independent chains, then the first index
/// that holds it. The comparison `k < m ? k : m` is the min instruction, and keeps m when k is
/// NaN.
template <>
inline std::size_t least_index<double>(const double* keys, std::size_t n) {
  using V = Lanes<kBuildLaneWidth>;
  constexpr std::size_t kWidth = kBuildLaneWidth;
  constexpr double kHigh = std::numeric_limits<double>::infinity();
  V chain[4];
  for (V& c : chain) lanes_fill(c, kHigh);
  std::size_t i = 0;
  for (; i + 4 * kWidth <= n; i += 4 * kWidth)
    for (int c = 0; c < 4; ++c) {
      V k;
      lanes_load(k, keys + i + c * kWidth);
      chain[c] = k < chain[c] ? k : chain[c];
    }
  chain[0] = chain[1] < chain[0] ? chain[1] : chain[0];
  chain[2] = chain[3] < chain[2] ? chain[3] : chain[2];
  chain[0] = chain[2] < chain[0] ? chain[2] : chain[0];
  double least = kHigh;
  for (int l = 0; l < int(kWidth); ++l) least = chain[0][l] < least ? chain[0][l] : least;
  for (; i < n; ++i) least = keys[i] < least ? keys[i] : least;
  if (!(least < kHigh)) return 0;  // every key NaN or +inf
  // The first index holding it, two keys at a time.
  const __m128d target = _mm_set1_pd(least);
  std::size_t j = 0;
  for (; j + 2 <= n; j += 2) {
    const int mask = _mm_movemask_pd(_mm_cmpeq_pd(_mm_loadu_pd(keys + j), target));
    if (mask != 0) return j + std::size_t(std::countr_zero(unsigned(mask)));
  }
  return n - 1;  // odd n, and the last key is the least
}
#endif

}  // namespace mink::detail
