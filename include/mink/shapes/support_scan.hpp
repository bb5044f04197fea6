/// @file support_scan.hpp
/// The brute-force support of a point set: the index of the point with the largest dot product
/// with a direction, over coordinates stored as three arrays (structure of arrays).
///
/// Compilers do not vectorise an arg-max (the index has to follow the maximum), so the double
/// version takes the maximum of blocks of points with SIMD (math/lanes.hpp) and finds the index
/// only in the winning block. Up to 8 points take an always-inlined SSE2 path. More take AVX2
/// where the CPU has it, checked once at start-up, even in builds for plain x86-64, and SSE2
/// otherwise; builds with -mavx2 or -march=native (the MINK_NATIVE CMake option) take AVX2
/// without the check. The plain twin `support_index_scalar` defines the result, and the tests
/// compare every SIMD path against it.
///
/// Result: the lowest index among the points farthest along d. With a NaN direction, 0.
/// support_hit() also gives that point's dot product with d, the point set's support value.
#pragma once

#include <bit>
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "mink/math/lanes.hpp"

// Builds for x86-64 without -mavx2 still get the AVX2 scan where the CPU has it: a function with
// its own target attribute, chosen at run time (GCC and Clang). No FMA in that target: the same
// rounding as the scalar twin.
#if defined(__SSE2__) && !defined(__AVX2__) && defined(__x86_64__) && defined(__GNUC__)
#define MINK_AVX2_DISPATCH 1
#define MINK_AVX2_TARGET [[gnu::target("avx2")]]
#else
#define MINK_AVX2_TARGET
#endif

namespace mink {

/// How a caller's directions move from one support call to the next, which decides how a scan
/// finds the winning point's index once it has the largest dot product.
///   Coherent (GJK, the default): the directions converge and the same point wins call after
///     call. A branch on the data then predicts the index, and the caller's loads of the point
///     run ahead of the scan's arithmetic (distance of two 8-point polytopes apart: 12 % faster
///     than with the index from masks).
///   Scattered (EPA's expansions): the directions jump from face to face and such a branch
///     mispredicts about once a call; the index comes from the lanes' equality masks with no
///     branch (contact of two 32-point polytopes overlapping: 19 % faster than with a branch).
/// Both give the same index.
enum class SupportPattern { Coherent, Scattered };

}  // namespace mink

namespace mink::detail {

/// The support point's dot product with the direction, `value`: the largest over the points (-inf
/// or NaN for a NaN direction), and index(), the point's (0 for a NaN direction).
template <class S>
struct SupportHit {
  S value;
  std::size_t point = 0;

  static SupportHit of(S value, std::size_t index) { return {value, index}; }
  template <SupportPattern = SupportPattern::Coherent>
  std::size_t index() const {
    return point;
  }
};

#if defined(__SSE2__)
/// In double, the scan of at most 8 points (support_hit_few()) keeps its dot products, and
/// index() finds the point from them only when asked: the equality masks are a dozen
/// instructions that a caller deciding on the value alone never runs (the boolean test of two
/// polytopes apart, query/polytope_pair.hpp: polytope8 pairs 4 % faster).
template <>
struct SupportHit<double> {
  double value;
  __m128d dots[4];        ///< the dot products in pairs, -inf past `count`
  std::size_t count = 0;  ///< the points scanned, or 0: `point` is the index
  std::size_t point = 0;

  static SupportHit of(double value, std::size_t index) {
    SupportHit hit{};
    hit.value = value;
    hit.point = index;
    return hit;
  }
  /// The first lane that reaches the maximum (0 for none: a NaN direction), from the lanes'
  /// equality masks: pair by pair with a branch (Coherent), or all of them with none (Scattered).
  template <SupportPattern P = SupportPattern::Coherent>
  [[gnu::always_inline]] inline std::size_t index() const {
    if (count == 0) return point;
    if constexpr (P == SupportPattern::Scattered) {
      unsigned mask = 0;
      for (int c = 0; c < 4; ++c) mask |= lanes_mask<LaneTest::Equal>(dots[c], value) << (2 * c);
      mask &= (1u << count) - 1;
      return mask == 0 ? 0 : std::size_t(std::countr_zero(mask));
    } else {
      for (int c = 0; c < 4; ++c) {
        const unsigned mask = lanes_mask<LaneTest::Equal>(dots[c], value);
        if (mask != 0) {
          // Lanes past `count` hold -inf: one of them first means the maximum is -inf or NaN.
          const std::size_t i = std::size_t(2 * c) + std::size_t(std::countr_zero(mask));
          return i < count ? i : 0;
        }
      }
      return 0;
    }
  }
};
#endif

/// Point i's dot product with d, as every scan computes it (no fused multiply-add).
template <class S>
[[gnu::always_inline]] inline S point_dot(const S* xs, const S* ys, const S* zs, std::size_t i,
                                          S dx, S dy, S dz) {
  return xs[i] * dx + ys[i] * dy + zs[i] * dz;
}

template <class S>
SupportHit<S> support_hit_scalar(const S* xs, const S* ys, const S* zs, std::size_t n, S dx, S dy,
                                 S dz) {
  S best = -std::numeric_limits<S>::infinity();
  std::size_t best_i = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const S dot = point_dot(xs, ys, zs, i, dx, dy, dz);
    if (dot > best) {
      best = dot;
      best_i = i;
    }
  }
  return SupportHit<S>::of(best, best_i);
}

template <class S>
std::size_t support_index_scalar(const S* xs, const S* ys, const S* zs, std::size_t n, S dx, S dy,
                                 S dz) {
  return support_hit_scalar(xs, ys, zs, n, dx, dy, dz).index();
}

template <class S>
SupportHit<S> support_hit(const S* xs, const S* ys, const S* zs, std::size_t n, S dx, S dy, S dz) {
  return support_hit_scalar(xs, ys, zs, n, dx, dy, dz);
}

template <SupportPattern = SupportPattern::Coherent, class S>
std::size_t support_index(const S* xs, const S* ys, const S* zs, std::size_t n, S dx, S dy, S dz) {
  return support_index_scalar(xs, ys, zs, n, dx, dy, dz);
}

#if defined(__SSE2__)
/// At most 8 points (SSE2, also under AVX2): the dot products in pairs and their maximum by a tree
/// of vector maxima; the index comes from the lanes when asked (SupportHit<double>::index()). A NaN
/// dot product (a NaN direction, or inf times a 0 coordinate) counts as -inf, as it never wins in
/// the scalar twin; lanes past n hold -inf and are masked off.
[[gnu::always_inline]] inline SupportHit<double> support_hit_few(const double* xs, const double* ys,
                                                                 const double* zs, std::size_t n,
                                                                 double dx, double dy, double dz) {
  constexpr double kLow = -std::numeric_limits<double>::infinity();
  const __m128d vx = _mm_set1_pd(dx), vy = _mm_set1_pd(dy), vz = _mm_set1_pd(dz);
  const __m128d low = _mm_set1_pd(kLow);
  SupportHit<double> hit;
  __m128d(&dots)[4] = hit.dots;
  for (std::size_t c = 0, i = 0; c < 4; ++c, i += 2) {
    // No fused multiply-add: the same rounding as the scalar twin.
    if (i + 2 <= n)
      dots[c] = _mm_add_pd(
          _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(xs + i), vx), _mm_mul_pd(_mm_loadu_pd(ys + i), vy)),
          _mm_mul_pd(_mm_loadu_pd(zs + i), vz));
    else
      dots[c] = _mm_set_pd(kLow, i < n ? point_dot(xs, ys, zs, i, dx, dy, dz) : kLow);
    // maxpd returns its second operand when the first is NaN.
    dots[c] = _mm_max_pd(dots[c], low);
  }
  const __m128d pair_max = _mm_max_pd(_mm_max_pd(dots[0], dots[1]), _mm_max_pd(dots[2], dots[3]));
  hit.value = _mm_cvtsd_f64(_mm_max_pd(pair_max, _mm_shuffle_pd(pair_max, pair_max, 1)));
  hit.count = n;
  return hit;
}

template <SupportPattern P>
[[gnu::always_inline]] inline std::size_t support_index_few(const double* xs, const double* ys,
                                                            const double* zs, std::size_t n,
                                                            double dx, double dy, double dz) {
  return support_hit_few(xs, ys, zs, n, dx, dy, dz).index<P>();
}

/// More than 8 points: blocks of 4 W dot products. The dot products and each block's maximum are
/// pure SIMD with no loop-carried dependency. A block that beats the best so far keeps its dot
/// products, through a branch (Coherent: about log n such blocks for a random direction) or
/// through masks (Scattered), and the winner's index is found at the end among those, by a loop
/// or by masks (SupportPattern): recomputing the winning block instead would load from an address
/// known only after the last block. Always inlined into the out-of-line entry points below, which
/// give it its instruction set.
template <int W, SupportPattern P>
[[gnu::always_inline]] inline std::size_t support_index_blocks(const double* xs, const double* ys,
                                                               const double* zs, std::size_t n,
                                                               double dx, double dy, double dz) {
  using Vec = Lanes<W>;
  constexpr int kVectors = 4;
  constexpr std::size_t kBlock = kVectors * W;
  double best = -std::numeric_limits<double>::infinity();
  std::size_t best_block = 0;
  Vec best_dots[kVectors] = {};  // the best block's dot products, for the winner's index
  std::size_t i = 0;
  for (; i + kBlock <= n; i += kBlock) {
    Vec dots[kVectors];
    for (int c = 0; c < kVectors; ++c) {
      const std::size_t j = i + std::size_t(c * W);
      Vec x, y, z;
      lanes_load(x, xs + j);
      lanes_load(y, ys + j);
      lanes_load(z, zs + j);
      // No fused multiply-add: the same rounding as the scalar twin and the tail.
      dots[c] = (x * dx + y * dy) + z * dz;
    }
    const Vec low = dots[0] > dots[1] ? dots[0] : dots[1];
    const Vec high = dots[2] > dots[3] ? dots[2] : dots[3];
    const Vec block = low > high ? low : high;
    const double block_max = lanes_max(block);
    if constexpr (P == SupportPattern::Scattered) {
      const bool better = block_max > best;
      best = better ? block_max : best;
      best_block = better ? i : best_block;
      for (int c = 0; c < kVectors; ++c) lanes_pick(best_dots[c], better, dots[c], best_dots[c]);
    } else if (block_max > best) {
      best = block_max;
      best_block = i;
      for (int c = 0; c < kVectors; ++c) best_dots[c] = dots[c];
    }
  }
  std::size_t best_i = 0;
  if (best > -std::numeric_limits<double>::infinity()) {
    if constexpr (P == SupportPattern::Scattered) {
      unsigned mask = 0;
      for (int c = 0; c < kVectors; ++c)
        mask |= lanes_mask<LaneTest::Equal>(best_dots[c], best) << (c * W);
      if (mask != 0) best_i = best_block + std::size_t(std::countr_zero(mask));
    } else {
      double values[kBlock];
      for (int c = 0; c < kVectors; ++c) lanes_store(values + c * W, best_dots[c]);
      for (std::size_t k = 0; k < kBlock; ++k)
        if (values[k] == best) {
          best_i = best_block + k;
          break;
        }
    }
  }
  for (; i < n; ++i) {
    const double dot = point_dot(xs, ys, zs, i, dx, dy, dz);
    if (dot > best) {
      best = dot;
      best_i = i;
    }
  }
  return best_i;
}

/// More than 8 points with SSE2 lanes. Out of line, since the inlined path is the one for small
/// sets.
template <SupportPattern P = SupportPattern::Coherent>
[[gnu::noinline]] inline std::size_t support_index_many_sse2(const double* xs, const double* ys,
                                                             const double* zs, std::size_t n,
                                                             double dx, double dy, double dz) {
  return support_index_blocks<2, P>(xs, ys, zs, n, dx, dy, dz);
}

#if defined(__AVX2__) || defined(MINK_AVX2_DISPATCH)
/// More than 8 points with AVX2 lanes (blocks of 16; fewer points take the SSE2 blocks of 8).
template <SupportPattern P = SupportPattern::Coherent>
[[gnu::noinline]] MINK_AVX2_TARGET inline std::size_t support_index_many_avx2(
    const double* xs, const double* ys, const double* zs, std::size_t n, double dx, double dy,
    double dz) {
  if (n < 16) return support_index_blocks<2, P>(xs, ys, zs, n, dx, dy, dz);
  return support_index_blocks<4, P>(xs, ys, zs, n, dx, dy, dz);
}
#endif

#if defined(MINK_AVX2_DISPATCH)
/// Whether this CPU (and its operating system, which must save the wide registers) runs AVX2:
/// asked once at start-up. Read before its initialiser has run (from another static initialiser),
/// it is false, which only chooses the SSE2 scan: both give the same answer.
inline const bool cpu_has_avx2 = [] {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") != 0;
}();
#endif

/// Always inlined, the 8-point path included: for the small hulls of a scene the support call is
/// the body of every GJK and EPA iteration, and the calls into a scan of 8 points (saving and
/// restoring registers on both sides) cost about as many instructions as the scan itself. Larger
/// sets take the widest scan this CPU runs.
template <SupportPattern P = SupportPattern::Coherent>
[[gnu::always_inline]] inline std::size_t support_index(const double* xs, const double* ys,
                                                        const double* zs, std::size_t n, double dx,
                                                        double dy, double dz) {
  if (n <= 8) return support_index_few<P>(xs, ys, zs, n, dx, dy, dz);
#if defined(__AVX2__)
  return support_index_many_avx2<P>(xs, ys, zs, n, dx, dy, dz);
#else
#if defined(MINK_AVX2_DISPATCH)
  if (cpu_has_avx2) return support_index_many_avx2<P>(xs, ys, zs, n, dx, dy, dz);
#endif
  return support_index_many_sse2<P>(xs, ys, zs, n, dx, dy, dz);
#endif
}

/// The same, with the support value: for more than 8 points the winner's dot product again,
/// computed as the scans compute it.
template <>
[[gnu::always_inline]] inline SupportHit<double> support_hit<double>(const double* xs,
                                                                     const double* ys,
                                                                     const double* zs,
                                                                     std::size_t n, double dx,
                                                                     double dy, double dz) {
  if (n <= 8) return support_hit_few(xs, ys, zs, n, dx, dy, dz);
  const std::size_t i = support_index(xs, ys, zs, n, dx, dy, dz);
  return SupportHit<double>::of(point_dot(xs, ys, zs, i, dx, dy, dz), i);
}
#endif

}  // namespace mink::detail
