/// @file support_scan.hpp
/// The brute-force support of a point set: the index of the point with the largest dot product
/// with a direction, over coordinates stored as three arrays (structure of arrays).
///
/// This is the one hand-vectorised loop of mink. Compilers do not vectorise an arg-max (the index
/// has to follow the maximum), so the double version takes the maximum of blocks of points with
/// SIMD and finds the index only in the winning block: SSE2 on any x86-64, AVX2 where the build
/// enables it (-mavx2 or -march=native; the MINK_NATIVE CMake option). The plain twin
/// `support_index_scalar` defines the result, and the tests compare the SIMD paths against it.
///
/// Result: the lowest index among the points farthest along d. With a NaN direction, 0.
#pragma once

#include <bit>
#include <cstddef>
#include <limits>
#include <type_traits>

#if defined(__AVX2__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mink::detail {

template <class S>
std::size_t support_index_scalar(const S* xs, const S* ys, const S* zs, std::size_t n, S dx, S dy,
                                 S dz) {
  S best = -std::numeric_limits<S>::infinity();
  std::size_t best_i = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const S dot = xs[i] * dx + ys[i] * dy + zs[i] * dz;
    if (dot > best) {
      best = dot;
      best_i = i;
    }
  }
  return best_i;
}

template <class S>
std::size_t support_index(const S* xs, const S* ys, const S* zs, std::size_t n, S dx, S dy, S dz) {
  return support_index_scalar(xs, ys, zs, n, dx, dy, dz);
}

#if defined(__AVX2__) || defined(__SSE2__)
#if defined(__AVX2__)
using LaneVec = __m256d;
constexpr int kLaneWidth = 4;
inline LaneVec lane_set1(double x) {
  return _mm256_set1_pd(x);
}
inline LaneVec lane_load(const double* p) {
  return _mm256_loadu_pd(p);
}
inline LaneVec lane_add(LaneVec a, LaneVec b) {
  return _mm256_add_pd(a, b);
}
inline LaneVec lane_sub(LaneVec a, LaneVec b) {
  return _mm256_sub_pd(a, b);
}
inline LaneVec lane_mul(LaneVec a, LaneVec b) {
  return _mm256_mul_pd(a, b);
}
inline LaneVec lane_max(LaneVec a, LaneVec b) {
  return _mm256_max_pd(a, b);
}
inline double lane_hmax(LaneVec v) {
  const __m128d m = _mm_max_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_max_sd(m, _mm_unpackhi_pd(m, m)));
}
inline void lane_store(double* p, LaneVec v) {
  _mm256_storeu_pd(p, v);
}
inline bool lane_any_greater(LaneVec a, LaneVec b) {
  return _mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_GT_OQ)) != 0;
}
#else
using LaneVec = __m128d;
constexpr int kLaneWidth = 2;
inline LaneVec lane_set1(double x) {
  return _mm_set1_pd(x);
}
inline LaneVec lane_load(const double* p) {
  return _mm_loadu_pd(p);
}
inline LaneVec lane_add(LaneVec a, LaneVec b) {
  return _mm_add_pd(a, b);
}
inline LaneVec lane_sub(LaneVec a, LaneVec b) {
  return _mm_sub_pd(a, b);
}
inline LaneVec lane_mul(LaneVec a, LaneVec b) {
  return _mm_mul_pd(a, b);
}
inline LaneVec lane_max(LaneVec a, LaneVec b) {
  return _mm_max_pd(a, b);
}
inline double lane_hmax(LaneVec v) {
  return _mm_cvtsd_f64(_mm_max_sd(v, _mm_unpackhi_pd(v, v)));
}
inline void lane_store(double* p, LaneVec v) {
  _mm_storeu_pd(p, v);
}
inline bool lane_any_greater(LaneVec a, LaneVec b) {
  return _mm_movemask_pd(_mm_cmpgt_pd(a, b)) != 0;
}
#endif

/// At most 8 points (SSE2, also under AVX2): the dot products in pairs, their maximum by a tree
/// of vector maxima, and the first index that reaches it from the lanes' equality masks, with no
/// branch on the data. A NaN dot product (a NaN direction, or inf times a 0 coordinate) counts as
/// -inf, as it never wins in the scalar twin; lanes past n hold -inf and are masked off.
[[gnu::always_inline]] inline std::size_t support_index_few(const double* xs, const double* ys,
                                                            const double* zs, std::size_t n,
                                                            double dx, double dy, double dz) {
  constexpr double kLow = -std::numeric_limits<double>::infinity();
  const __m128d vx = _mm_set1_pd(dx), vy = _mm_set1_pd(dy), vz = _mm_set1_pd(dz);
  const __m128d low = _mm_set1_pd(kLow);
  __m128d dots[4];
  for (std::size_t c = 0, i = 0; c < 4; ++c, i += 2) {
    // No fused multiply-add: the same rounding as the scalar twin.
    if (i + 2 <= n)
      dots[c] = _mm_add_pd(
          _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(xs + i), vx), _mm_mul_pd(_mm_loadu_pd(ys + i), vy)),
          _mm_mul_pd(_mm_loadu_pd(zs + i), vz));
    else
      dots[c] = _mm_set_pd(kLow, i < n ? xs[i] * dx + ys[i] * dy + zs[i] * dz : kLow);
    // maxpd returns its second operand when the first is NaN.
    dots[c] = _mm_max_pd(dots[c], low);
  }
  const __m128d pair_max = _mm_max_pd(_mm_max_pd(dots[0], dots[1]), _mm_max_pd(dots[2], dots[3]));
  const __m128d best = _mm_max_pd(pair_max, _mm_shuffle_pd(pair_max, pair_max, 1));
  unsigned mask = 0;
  for (int c = 0; c < 4; ++c)
    mask |= unsigned(_mm_movemask_pd(_mm_cmpeq_pd(dots[c], best))) << (2 * c);
  mask &= (1u << n) - 1;
  return mask == 0 ? 0 : std::size_t(std::countr_zero(mask));  // 0: no points
}

/// More than 8 points: blocks of SIMD dot products (below). Out of line, since the inlined path
/// is the one for small sets; a template (of double only) so that the header may hold it.
template <class S>
[[gnu::noinline]] std::size_t support_index_many(const S* xs, const S* ys, const S* zs,
                                                 std::size_t n, S dx, S dy, S dz);

/// Always inlined, the 8-point path included: for the small hulls of a scene the support call is
/// the body of every GJK and EPA iteration, and the calls into a scan of 8 points (saving and
/// restoring registers on both sides) cost about as many instructions as the scan itself.
template <>
[[gnu::always_inline]] inline std::size_t support_index<double>(const double* xs, const double* ys,
                                                                const double* zs, std::size_t n,
                                                                double dx, double dy, double dz) {
  if (n <= 8) return support_index_few(xs, ys, zs, n, dx, dy, dz);
  return support_index_many(xs, ys, zs, n, dx, dy, dz);
}

template <class S>
std::size_t support_index_many(const S* xs, const S* ys, const S* zs, std::size_t n, S dx, S dy,
                               S dz) {
  static_assert(std::is_same_v<S, double>, "the SIMD scan is for double");
  constexpr int kVectors = 4;
  constexpr std::size_t kBlock = kVectors * kLaneWidth;
  if (n < kBlock) return support_index_scalar(xs, ys, zs, n, dx, dy, dz);
  // Blocks of kBlock points: the dot products and the block's maximum are pure SIMD with no
  // loop-carried dependency; only a block that beats the best so far (about log n of them for a
  // random direction) costs a branch. The winner's index is found at the end by recomputing its
  // block with the same instructions, so the equality test compares bit-identical values.
  const LaneVec vx = lane_set1(dx), vy = lane_set1(dy), vz = lane_set1(dz);
  auto block_dots = [&](std::size_t i, LaneVec* dots) {
    for (int c = 0; c < kVectors; ++c) {
      const std::size_t j = i + std::size_t(c * kLaneWidth);
      // No fused multiply-add: the same rounding as the scalar twin and the tail.
      dots[c] = lane_add(lane_add(lane_mul(lane_load(xs + j), vx), lane_mul(lane_load(ys + j), vy)),
                         lane_mul(lane_load(zs + j), vz));
    }
  };
  double best = -std::numeric_limits<double>::infinity();
  std::size_t best_block = 0;
  std::size_t i = 0;
  for (; i + kBlock <= n; i += kBlock) {
    LaneVec dots[kVectors];
    block_dots(i, dots);
    const double block_max =
        lane_hmax(lane_max(lane_max(dots[0], dots[1]), lane_max(dots[2], dots[3])));
    if (block_max > best) {
      best = block_max;
      best_block = i;
    }
  }
  std::size_t best_i = 0;
  if (best > -std::numeric_limits<double>::infinity()) {
    LaneVec dots[kVectors];
    block_dots(best_block, dots);
    double values[kBlock];
    for (int c = 0; c < kVectors; ++c) lane_store(values + c * kLaneWidth, dots[c]);
    for (std::size_t k = 0; k < kBlock; ++k)
      if (values[k] == best) {
        best_i = best_block + k;
        break;
      }
  }
  for (; i < n; ++i) {
    const double dot = xs[i] * dx + ys[i] * dy + zs[i] * dz;
    if (dot > best) {
      best = dot;
      best_i = i;
    }
  }
  return best_i;
}
#endif

}  // namespace mink::detail
