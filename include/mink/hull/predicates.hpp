/// @file predicates.hpp
/// Exact geometric signs for the convex hull: orientation of four points, of three points against
/// a direction, of two points along a direction, and of three points in a coordinate plane.
///
/// Each predicate first evaluates its determinant in double precision together with a bound on
/// the rounding error of that evaluation (a "filter"). When the value is farther from zero than
/// the bound, its sign is the exact sign. Otherwise it is evaluated again, exactly, with
/// floating-point expansions: a number is kept as a sum of doubles of increasing magnitude whose
/// bits do not overlap, and sums and products are carried out with error-free transformations
/// (the sum and the product of two doubles are each a double plus an exactly representable
/// error). This is the arithmetic of Priest (1991) and Shewchuk ("Adaptive precision
/// floating-point arithmetic and fast robust geometric predicates", 1997); the code here is our
/// own, written from those definitions, and trades Shewchuk's staged adaptivity for brevity: the
/// exact path only runs when the filter cannot decide, and zero components are dropped as they
/// appear, so inputs whose coordinate differences are exact (lattices, points sharing a plane
/// z = c) stay cheap.
///
/// Filter bounds, with u = 2^-53 the unit roundoff. Every elementary product of a determinant
/// passes through at most k roundings (the differences of its factors, the products, and the
/// additions that combine them), so its computed contribution is exact times (1 + t) with
/// |t| <= k u / (1 - k u); the computed "permanent" P (the same sum with absolute values)
/// underestimates the exact one by at most the same factor. Hence |computed - exact| <= c u P
/// with c = k + 1 covering the second-order terms and the rounding of c u P itself:
///   - orient3d: three differences, two products, one subtraction, two additions: k = 8, c = 9;
///   - orient_along (a 3x3 determinant with one row a given vector): k = 7, c = 9;
///   - dot_sign (n . (b - a)): one difference, one product, two additions: k = 4, c = 5;
///   - orient2d: two differences, one product, one subtraction: k = 4, c = 5.
///
/// Exactness assumes no underflow: error terms of products must stay above 2^-1022. After the
/// hull scales its input so that the largest coordinate is about 1, this holds whenever nonzero
/// coordinate differences exceed about 1e-75; smaller differences are far below any tolerance.
/// Products are split with std::fma when the target has fused multiply-add (exact by definition
/// of fma), and with Dekker's splitting otherwise; in the latter case the target has no FMA
/// instruction, so a compiler cannot contract the splitting arithmetic. -ffast-math breaks the
/// error-free sums and must not be used.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

namespace mink::exact {

/// Unit roundoff of double: 2^-53.
inline constexpr double kUnitRoundoff = 1.1102230246251565e-16;

/// a + b = s + e exactly.
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}

/// a - b = d + e exactly.
inline void two_diff(double a, double b, double& d, double& e) {
  d = a - b;
  const double bv = a - d;
  const double av = d + bv;
  e = (a - av) + (bv - b);
}

/// a * b = p + e exactly (barring underflow).
inline void two_product(double a, double b, double& p, double& e) {
  p = a * b;
#if defined(__FMA__) || defined(FP_FAST_FMA)
  e = std::fma(a, b, -p);
#else
  // Dekker: split each factor into two halves of 26 bits whose products are exact.
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  double c = kSplitter * a;
  const double ahi = c - (c - a);
  const double alo = a - ahi;
  c = kSplitter * b;
  const double bhi = c - (c - b);
  const double blo = b - bhi;
  e = ((ahi * bhi - p) + ahi * blo + alo * bhi) + alo * blo;
#endif
}

/// A floating-point expansion of at most N components: the exact value is the sum of v[0..n),
/// stored in increasing magnitude with no overlapping bits and no zero components (except a
/// single 0 for the value zero).
template <int N>
struct Expansion {
  double v[N];
  int n = 0;
};

inline Expansion<1> expansion(double a) {
  Expansion<1> r;
  r.v[0] = a;
  r.n = 1;
  return r;
}

/// a - b, exactly.
inline Expansion<2> difference(double a, double b) {
  double d, e;
  two_diff(a, b, d, e);
  Expansion<2> r;
  if (e != 0) r.v[r.n++] = e;
  r.v[r.n++] = d;
  return r;
}

namespace detail {

/// h = e + b for an expansion e of length n; returns the length of h (at most n + 1).
inline int grow(const double* e, int n, double b, double* h) {
  double q = b;
  int k = 0;
  for (int i = 0; i < n; ++i) {
    double s, t;
    two_sum(q, e[i], s, t);
    if (t != 0) h[k++] = t;
    q = s;
  }
  if (q != 0 || k == 0) h[k++] = q;
  return k;
}

}  // namespace detail

/// a + b, exactly: the components of both merged by magnitude, then accumulated with
/// error-free sums, keeping the non-zero errors (linear time). Correct under round-to-nearest-
/// even for strongly nonoverlapping inputs (Shewchuk 1997, theorem 13), which every function
/// here produces: differences, sums, and products by a double (theorem 19).
template <int A, int B>
Expansion<A + B> add(const Expansion<A>& a, const Expansion<B>& b) {
  Expansion<A + B> r;
  int i = 0, j = 0;
  // Next component in increasing magnitude.
  auto take = [&]() {
    if (j >= b.n || (i < a.n && std::fabs(a.v[i]) <= std::fabs(b.v[j]))) return a.v[i++];
    return b.v[j++];
  };
  double q = take();
  while (i < a.n || j < b.n) {
    double s, e;
    two_sum(q, take(), s, e);
    if (e != 0) r.v[r.n++] = e;
    q = s;
  }
  if (q != 0 || r.n == 0) r.v[r.n++] = q;
  return r;
}

/// a + b by repeated growth (quadratic time, but needs only nonoverlapping inputs): the
/// reference the tests compare add() with.
template <int A, int B>
Expansion<A + B> add_by_growth(const Expansion<A>& a, const Expansion<B>& b) {
  Expansion<A + B> r, t;
  for (int i = 0; i < a.n; ++i) r.v[i] = a.v[i];
  r.n = a.n;
  Expansion<A + B>*src = &r, *dst = &t;
  for (int j = 0; j < b.n; ++j) {
    dst->n = detail::grow(src->v, src->n, b.v[j], dst->v);
    std::swap(src, dst);
  }
  return *src;
}

template <int A>
Expansion<A> negate(Expansion<A> a) {
  for (int i = 0; i < a.n; ++i) a.v[i] = -a.v[i];
  return a;
}

/// a - b, exactly.
template <int A, int B>
Expansion<A + B> sub(const Expansion<A>& a, const Expansion<B>& b) {
  return add(a, negate(b));
}

/// a * b for a double b, exactly.
template <int A>
Expansion<2 * A> scale(const Expansion<A>& a, double b) {
  Expansion<2 * A> r;
  if (b == 0) {
    r.v[0] = 0;
    r.n = 1;
    return r;
  }
  double q, h;
  two_product(a.v[0], b, q, h);
  if (h != 0) r.v[r.n++] = h;
  for (int i = 1; i < a.n; ++i) {
    double p, pe, s, se, q2;
    two_product(a.v[i], b, p, pe);
    two_sum(q, pe, s, se);
    if (se != 0) r.v[r.n++] = se;
    two_sum(p, s, q2, se);
    if (se != 0) r.v[r.n++] = se;
    q = q2;
  }
  if (q != 0 || r.n == 0) r.v[r.n++] = q;
  return r;
}

/// a * b, exactly: the sum of a times each component of b.
template <int A, int B>
Expansion<2 * A * B> mul(const Expansion<A>& a, const Expansion<B>& b) {
  Expansion<2 * A * B> r;
  const Expansion<2 * A> first = scale(a, b.v[0]);
  for (int i = 0; i < first.n; ++i) r.v[i] = first.v[i];
  r.n = first.n;
  for (int j = 1; j < b.n; ++j) {
    // r holds at most 2 A j components, so r + a b_j fits.
    const auto t = add(r, scale(a, b.v[j]));
    for (int i = 0; i < t.n; ++i) r.v[i] = t.v[i];
    r.n = t.n;
  }
  return r;
}

/// The sign of an expansion: that of its largest component.
template <int N>
int sign(const Expansion<N>& e) {
  const double top = e.v[e.n - 1];
  return top > 0 ? 1 : (top < 0 ? -1 : 0);
}

/// Nearest double to the value of an expansion (within one unit in the last place).
template <int N>
double estimate(const Expansion<N>& e) {
  double s = 0;
  for (int i = 0; i < e.n; ++i) s += e.v[i];
  return s;
}

/// Exact sign of det[b - a, c - a, d - a] for points given as 3 doubles: positive when d lies on
/// the side of the plane through a, b, c that (b - a) x (c - a) points to.
inline int orient3d_exact(const double* a, const double* b, const double* c, const double* d);

/// det[b - a, c - a, d - a] in double, and in `bound` a bound on its rounding error: the filter
/// of orient3d().
inline double orient3d_estimate(const double* a, const double* b, const double* c, const double* d,
                                double& bound) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double p1 = uy * vz, p2 = uz * vy, p3 = uz * vx, p4 = ux * vz, p5 = ux * vy, p6 = uy * vx;
  const double perm = std::fabs(wx) * (std::fabs(p1) + std::fabs(p2)) +
                      std::fabs(wy) * (std::fabs(p3) + std::fabs(p4)) +
                      std::fabs(wz) * (std::fabs(p5) + std::fabs(p6));
  bound = 9 * kUnitRoundoff * perm;
  return wx * (p1 - p2) + wy * (p3 - p4) + wz * (p5 - p6);
}

/// The same sign, filtered: the exact evaluation only runs when rounding could flip it.
inline int orient3d(const double* a, const double* b, const double* c, const double* d) {
  double bound;
  const double det = orient3d_estimate(a, b, c, d, bound);
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return orient3d_exact(a, b, c, d);
}

/// det[b - a, c - a, d - a] within a unit or so of roundoff of its exact value, however flat the
/// tetrahedron: the exact expansion, rounded. (Where orient3d_estimate()'s bound exceeds the
/// value: volumes of a hull 1e-9 thin.)
inline double orient3d_value(const double* a, const double* b, const double* c, const double* d);

/// Exact sign of det[b - a, c - a, n] = ((b - a) x (c - a)) . n for points a, b, c and a vector
/// n: positive when a, b, c turn counter-clockwise seen from the tip of n.
inline int orient_along_exact(const double* a, const double* b, const double* c, const double* n);

inline int orient_along(const double* a, const double* b, const double* c, const double* n) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double p1 = uy * vz, p2 = uz * vy, p3 = uz * vx, p4 = ux * vz, p5 = ux * vy, p6 = uy * vx;
  const double det = n[0] * (p1 - p2) + n[1] * (p3 - p4) + n[2] * (p5 - p6);
  const double perm = std::fabs(n[0]) * (std::fabs(p1) + std::fabs(p2)) +
                      std::fabs(n[1]) * (std::fabs(p3) + std::fabs(p4)) +
                      std::fabs(n[2]) * (std::fabs(p5) + std::fabs(p6));
  const double bound = 9 * kUnitRoundoff * perm;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return orient_along_exact(a, b, c, n);
}

/// Exact sign of n . (b - a): whether b lies farther than a along n.
inline int dot_sign_exact(const double* n, const double* a, const double* b);

inline int dot_sign(const double* n, const double* a, const double* b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  const double s = n[0] * dx + n[1] * dy + n[2] * dz;
  const double bound =
      5 * kUnitRoundoff * (std::fabs(n[0] * dx) + std::fabs(n[1] * dy) + std::fabs(n[2] * dz));
  if (s > bound) return 1;
  if (s < -bound) return -1;
  return dot_sign_exact(n, a, b);
}

/// Exact sign of (b - a) x (c - a) in the plane of coordinates i, j (a, b, c given as 3
/// doubles): positive when a, b, c turn counter-clockwise in that plane.
inline int orient2d_exact(const double* a, const double* b, const double* c, int i, int j);

inline int orient2d(const double* a, const double* b, const double* c, int i, int j) {
  const double ux = b[i] - a[i], uy = b[j] - a[j];
  const double vx = c[i] - a[i], vy = c[j] - a[j];
  const double l = ux * vy, r = uy * vx;
  const double det = l - r;
  const double bound = 5 * kUnitRoundoff * (std::fabs(l) + std::fabs(r));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return orient2d_exact(a, b, c, i, j);
}

/// (b - a) x (c - a), each component rounded from its exact value (so the direction is right to
/// within a few units of roundoff however thin the triangle).
inline void cross_rounded(const double* a, const double* b, const double* c, double* out);

// ---- exact evaluations (inline: the header is self-contained) --------------------------------

namespace detail {

/// The exact cross product of u and v, component k (k = 0, 1, 2), from exact differences.
inline Expansion<16> cross_component(const Expansion<2>* u, const Expansion<2>* v, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  return sub(mul(u[i], v[j]), mul(u[j], v[i]));
}

}  // namespace detail

namespace detail {

/// det[b - a, c - a, d - a] as an exact expansion.
inline auto orient3d_expansion(const double* a, const double* b, const double* c, const double* d) {
  Expansion<2> u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = difference(b[k], a[k]);
    v[k] = difference(c[k], a[k]);
    w[k] = difference(d[k], a[k]);
  }
  const auto t0 = mul(w[0], cross_component(u, v, 0));
  const auto t1 = mul(w[1], cross_component(u, v, 1));
  const auto t2 = mul(w[2], cross_component(u, v, 2));
  return add(add(t0, t1), t2);
}

}  // namespace detail

inline int orient3d_exact(const double* a, const double* b, const double* c, const double* d) {
  return sign(detail::orient3d_expansion(a, b, c, d));
}

inline double orient3d_value(const double* a, const double* b, const double* c, const double* d) {
  return estimate(detail::orient3d_expansion(a, b, c, d));
}

inline int orient_along_exact(const double* a, const double* b, const double* c, const double* n) {
  Expansion<2> u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = difference(b[k], a[k]);
    v[k] = difference(c[k], a[k]);
  }
  const auto t0 = scale(detail::cross_component(u, v, 0), n[0]);
  const auto t1 = scale(detail::cross_component(u, v, 1), n[1]);
  const auto t2 = scale(detail::cross_component(u, v, 2), n[2]);
  return sign(add(add(t0, t1), t2));
}

inline int dot_sign_exact(const double* n, const double* a, const double* b) {
  const auto t0 = scale(difference(b[0], a[0]), n[0]);
  const auto t1 = scale(difference(b[1], a[1]), n[1]);
  const auto t2 = scale(difference(b[2], a[2]), n[2]);
  return sign(add(add(t0, t1), t2));
}

inline int orient2d_exact(const double* a, const double* b, const double* c, int i, int j) {
  const auto ux = difference(b[i], a[i]), uy = difference(b[j], a[j]);
  const auto vx = difference(c[i], a[i]), vy = difference(c[j], a[j]);
  return sign(sub(mul(ux, vy), mul(uy, vx)));
}

namespace detail {

/// Half the distance from a normal double r != 0 to its nearer neighbour (exact), or 0 when r
/// is too small for that to be a normal double.
inline double half_gap(double r) {
  std::uint64_t bits;
  std::memcpy(&bits, &r, sizeof bits);
  const int e = static_cast<int>((bits >> 52) & 0x7ff);
  const bool power_of_two = (bits & ((std::uint64_t{1} << 52) - 1)) == 0;
  // r in [2^(e-1023), 2^(e-1022)): gaps of 2^(e-1075) above, and below unless r is a power of
  // two (then half that); half of the smaller one is 2^(e-1076) or 2^(e-1077).
  const int f = e - 53 - (power_of_two ? 1 : 0);
  if (e == 0x7ff || f < 1) return 0;
  const std::uint64_t g = static_cast<std::uint64_t>(f) << 52;
  double out;
  std::memcpy(&out, &g, sizeof out);
  return out;
}

/// Component k of u x v for u = uh + ul, v = vh + vl (exact differences), rounded to nearest,
/// when a double-double evaluation settles the rounding; false otherwise. The value
/// u_i v_j - u_j v_i is taken as s + lo: s and the errors of the leading products are exact
/// (two_product, two_diff); the cross terms uh vl + ul vh are rounded and ul vl is dropped,
/// all of relative size u, so with M = |uh_i vh_j| + |uh_j vh_i| the total error is below
/// 14 u^2 M (+ O(u^3 M)); 40 u^2 M is used. With r = fl(s + lo) and s + lo = r + re exactly,
/// r is the nearest double to the exact value when |re| + error is below half the gap from r
/// to its nearer neighbour.
inline bool cross_component_fast(const double* uh, const double* ul, const double* vh,
                                 const double* vl, int k, double& out) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  double p1, p2, q1, q2, s, se, r, re;
  two_product(uh[i], vh[j], p1, p2);
  two_product(uh[j], vh[i], q1, q2);
  const double tp = uh[i] * vl[j] + ul[i] * vh[j];
  const double tq = uh[j] * vl[i] + ul[j] * vh[i];
  two_diff(p1, q1, s, se);
  const double lo = se + (p2 - q2) + (tp - tq);
  two_sum(s, lo, r, re);
  const double err = 40 * kUnitRoundoff * kUnitRoundoff * (std::fabs(p1) + std::fabs(q1));
  if (r != 0 && std::fabs(re) + err < half_gap(r)) {
    out = r;
    return true;
  }
  return false;
}

}  // namespace detail

inline void cross_rounded(const double* a, const double* b, const double* c, double* out) {
  // Most triangles: a double-double evaluation whose rounding is provably the exact value's.
  double uh[3], ul[3], vh[3], vl[3];
  for (int k = 0; k < 3; ++k) {
    two_diff(b[k], a[k], uh[k], ul[k]);
    two_diff(c[k], a[k], vh[k], vl[k]);
  }
  bool fast = true;
  for (int k = 0; k < 3 && fast; ++k)
    fast = detail::cross_component_fast(uh, ul, vh, vl, k, out[k]);
  if (fast) return;
  Expansion<2> u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = difference(b[k], a[k]);
    v[k] = difference(c[k], a[k]);
  }
  for (int k = 0; k < 3; ++k) out[k] = estimate(detail::cross_component(u, v, k));
}

}  // namespace mink::exact
