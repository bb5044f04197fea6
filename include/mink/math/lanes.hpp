/// @file lanes.hpp
/// SIMD lanes of doubles for mink's few hand-vectorised loops (shapes/support_scan.hpp,
/// query/point_solid.hpp), as GCC and Clang vector extensions, on x86-64.
///
/// The arithmetic is written with operators (`x * d + y`, `a > b ? a : b`), which compile to the
/// widest instructions of the function they end up in: one loop, written once, is SSE2 in
/// ordinary code and AVX2 inside a function with the AVX2 target attribute. That is how the
/// support scan picks its instruction set at run time.
///
/// The helpers take and give vectors by reference or pointer, never by value: a 32-byte vector
/// passed by value from code compiled without AVX changes the calling convention, and both
/// compilers reject or warn about it even where the call is inlined away.
///
/// `a > b ? a : b` is exactly what the SSE and AVX max instructions compute (b when either is
/// NaN), and both compilers emit the instruction for it.
#pragma once

#if defined(__SSE2__)
#include <emmintrin.h>

#include <cstring>

namespace mink::detail {

template <int W>
struct LanesOf;
template <>
struct LanesOf<2> {
  typedef double type __attribute__((vector_size(16)));
  // Typedefs, not using-aliases: Clang lowers a vector's alignment only on a typedef (through an
  // alias the unaligned loads kept 32-byte alignment, which UBSan reports).
  typedef double unaligned __attribute__((vector_size(16), aligned(8), may_alias));
};
template <>
struct LanesOf<4> {
  typedef double type __attribute__((vector_size(32)));
  typedef double unaligned __attribute__((vector_size(32), aligned(8), may_alias));
};

/// W doubles in one register (W = 2: SSE2, W = 4: AVX).
template <int W>
using Lanes = typename LanesOf<W>::type;

template <class V>
constexpr int lane_count = int(sizeof(V) / sizeof(double));

/// The widest lanes the build itself enables: the loops that are not chosen at run time use these.
#if defined(__AVX__)
constexpr int kBuildLaneWidth = 4;
#else
constexpr int kBuildLaneWidth = 2;
#endif

/// v = p[0 .. W-1], unaligned. Through a may_alias type, as the intrinsics' own loads are: a copy
/// by memcpy made GCC spill the vector to the stack and copy it in halves.
template <class V>
[[gnu::always_inline]] inline void lanes_load(V& v, const double* p) {
  v = *reinterpret_cast<const typename LanesOf<lane_count<V>>::unaligned*>(p);
}

/// p[0 .. W-1] = v, unaligned.
template <class V>
[[gnu::always_inline]] inline void lanes_store(double* p, const V& v) {
  *reinterpret_cast<typename LanesOf<lane_count<V>>::unaligned*>(p) = v;
}

/// Every lane = x.
template <class V>
[[gnu::always_inline]] inline void lanes_fill(V& v, double x) {
  double lane[lane_count<V>];
  for (double& l : lane) l = x;
  std::memcpy(&v, lane, sizeof v);
}

/// The largest lane: the halves' maximum, then the max instruction on the last two lanes. Which
/// NaN lane, if any, comes out depends on the operand order. The last step is the SSE2 intrinsic
/// on purpose: written as a comparison, GCC turned the support scan's `if (block_max > best)`
/// into conditional moves, which made the end of the scan wait for every block (intersect of two
/// 32-point polytopes: 221 against 190 ns).
template <class V>
[[gnu::always_inline]] inline double lanes_max(const V& v) {
  Lanes<2> pair;
  if constexpr (lane_count<V> == 4) {
    Lanes<2> low, high;
    std::memcpy(&low, &v, sizeof low);
    std::memcpy(&high, reinterpret_cast<const double*>(&v) + 2, sizeof high);
    pair = low > high ? low : high;
  } else {
    pair = v;
  }
  const __m128d x = __m128d(pair);
  return _mm_cvtsd_f64(_mm_max_sd(x, _mm_unpackhi_pd(x, x)));
}

/// Which comparison lanes_mask() makes.
enum class LaneTest { Greater, Equal };

/// Bit l set where lane l of v is greater than (equal to) x, ordered: NaN lanes never are. Two
/// lanes at a time, a compare and a sign-bit mask each.
template <LaneTest kTest, class V>
[[gnu::always_inline]] inline unsigned lanes_mask(const V& v, double x) {
  const __m128d limit = _mm_set1_pd(x);
  unsigned mask = 0;
  for (int k = 0; k < lane_count<V>; k += 2) {
    __m128d pair;
    std::memcpy(&pair, reinterpret_cast<const double*>(&v) + k, sizeof pair);
    const __m128d hit =
        kTest == LaneTest::Greater ? _mm_cmpgt_pd(pair, limit) : _mm_cmpeq_pd(pair, limit);
    mask |= unsigned(_mm_movemask_pd(hit)) << k;
  }
  return mask;
}

/// Whether any lane of v is greater than x (ordered: NaN lanes are not).
template <class V>
[[gnu::always_inline]] inline bool lanes_any_greater(const V& v, double x) {
  return lanes_mask<LaneTest::Greater>(v, x) != 0;
}

/// v = take_a ? a : b, through a mask of every lane, with no branch on `take_a`.
template <class V>
[[gnu::always_inline]] inline void lanes_pick(V& v, bool take_a, const V& a, const V& b) {
  typedef long long Mask __attribute__((vector_size(sizeof(V))));
  const Mask all = Mask{} - static_cast<long long>(take_a);  // every bit set when taken
  v = V((Mask(a) & all) | (Mask(b) & ~all));
}

}  // namespace mink::detail
#endif
