/// @file vec.hpp
/// Vector and matrix aliases over Eigen, templated on the scalar type (double by default).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace mink {

template <class S>
using Vec3T = Eigen::Matrix<S, 3, 1>;
template <class S>
using Mat3T = Eigen::Matrix<S, 3, 3>;
template <class S>
using QuatT = Eigen::Quaternion<S>;

using Vec3 = Vec3T<double>;
using Mat3 = Mat3T<double>;
using Quat = QuatT<double>;

/// True when every component is finite (neither NaN nor infinite).
template <class S>
inline bool is_finite(const Vec3T<S>& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

namespace detail {

/// 2^k, at compile time.
template <class S>
constexpr S power_of_two(int k) {
  S x = S(1);
  for (; k > 0; --k) x *= S(2);
  for (; k < 0; ++k) x *= S(0.5);
  return x;
}

/// p + s d, coordinate by coordinate. As an Eigen expression assigned into a large function's
/// result, GCC left Eigen's assignment loop out of line: a call and an expression object on the
/// stack for each of a contact's two points (1.5 ns of a sphere-box contact).
template <class S>
[[gnu::always_inline]] inline Vec3T<S> moved_along(const Vec3T<S>& p, S s, const Vec3T<S>& d) {
  return Vec3T<S>(p.x() + s * d.x(), p.y() + s * d.y(), p.z() + s * d.z());
}

/// (p + s d) + origin, coordinate by coordinate: a point computed about `origin` moved out along
/// d and then back to the world, in that order (p + s d is small beside a far-away origin).
template <class S>
[[gnu::always_inline]] inline Vec3T<S> moved_along(const Vec3T<S>& p, S s, const Vec3T<S>& d,
                                                   const Vec3T<S>& origin) {
  return Vec3T<S>((p.x() + s * d.x()) + origin.x(), (p.y() + s * d.y()) + origin.y(),
                  (p.z() + s * d.z()) + origin.z());
}

/// The part of v across unit u: v less its component along u, as v looks seen along u.
template <class S>
[[gnu::always_inline]] inline Vec3T<S> part_across(const Vec3T<S>& v, const Vec3T<S>& u) {
  return v - v.dot(u) * u;
}

/// a . (b x c), coordinate by coordinate. Through Eigen's cross() and dot(), GCC computed the
/// cross product in scalars, stored it and loaded it back as a vector for the dot product: a
/// load that stalls on store forwarding, five of them in each of GJK's tetrahedron tests.
template <class S>
[[gnu::always_inline]] inline S triple_product(const Vec3T<S>& a, const Vec3T<S>& b,
                                               const Vec3T<S>& c) {
  return a.x() * (b.y() * c.z() - b.z() * c.y()) + a.y() * (b.z() * c.x() - b.x() * c.z()) +
         a.z() * (b.x() * c.y() - b.y() * c.x());
}

/// Eigen's stableNorm(), out of line: the rare branch of length_of(), which is inlined (a box's
/// bounding radius is taken on every query, and a call there cost register spills on both sides).
template <class S>
[[gnu::noinline]] S stable_length(const Vec3T<S>& v) {
  return v.stableNorm();
}

/// |v| from its square `v_sq` (= v.squaredNorm()), also where that square underflows (vectors of
/// 1e-154 and shorter: the root of the rounded square is off by up to 1e-3, and a normal
/// v / |v| then is not unit) or overflows (1e154 and longer): Eigen's stableNorm() rescales first.
/// The zero vector (a sphere's centre, a vertex at the origin) stays off that call.
template <class S>
[[gnu::always_inline]] inline S length_of(const Vec3T<S>& v, S v_sq) {
  if (v_sq >= std::numeric_limits<S>::min() && v_sq <= std::numeric_limits<S>::max()) [[likely]]
    return std::sqrt(v_sq);
  if (v.x() == 0 && v.y() == 0 && v.z() == 0) return S(0);
  return stable_length(v);
}

/// |v| at any magnitude.
template <class S>
[[gnu::always_inline]] inline S length_of(const Vec3T<S>& v) {
  return length_of(v, S(v.squaredNorm()));
}

/// length_of(u) and length_of(v) with one packed square root, for two lengths a query needs at
/// its start (two boxes' bounding radii): two scalar roots, each with its branch to the library
/// for a negative argument, held up the box manifold by 3 % of its time.
template <class S>
[[gnu::always_inline]] inline void lengths_of(const Vec3T<S>& u, const Vec3T<S>& v, S& length_u,
                                              S& length_v) {
  const Eigen::Array<S, 2, 1> sq(u.squaredNorm(), v.squaredNorm());
  if (sq.minCoeff() >= std::numeric_limits<S>::min() &&
      sq.maxCoeff() <= std::numeric_limits<S>::max()) [[likely]] {
    const Eigen::Array<S, 2, 1> root = sq.sqrt();
    length_u = root[0];
    length_v = root[1];
  } else {
    length_u = length_of(u, sq[0]);
    length_v = length_of(v, sq[1]);
  }
}

/// Whether x and 1 / x are both normal numbers (x in [2^-1022, 2^1022] in double): then
/// unit_beside_root() applies.
template <class S>
[[gnu::always_inline]] inline bool reciprocal_in_range(S x) {
  return x >= std::numeric_limits<S>::min() && x <= S(1) / std::numeric_limits<S>::min();
}

/// v / |v| from v_sq = v.squaredNorm() and length = sqrt(v_sq), where reciprocal_in_range(v_sq):
/// (v / v_sq) length, whose division waits on v_sq only and so runs beside the root, where
/// v (1 / length) waits for the root first; the root is the last factor, as it comes last
/// (capsule distance 5 % faster). Within 2 ulps of unit.
template <class S>
[[gnu::always_inline]] inline Vec3T<S> unit_beside_root(const Vec3T<S>& v, S v_sq, S length) {
  return Vec3T<S>(v * (S(1) / v_sq)) * length;
}

/// v / |v| for v != 0, given v_sq = v.squaredNorm() and length = length_of(v, v_sq): by
/// unit_beside_root() where it applies. Where the square underflows or overflows, v is divided by
/// its largest component first: 1 / |v| overflows below 1e-308, and a subnormal |v| carries too
/// few digits for the plain quotient to be unit (so does Eigen's stableNormalized(), which
/// divides by such a product).
template <class S>
Vec3T<S> unit_of(const Vec3T<S>& v, S v_sq, S length) {
  if (reciprocal_in_range(v_sq)) [[likely]]
    return unit_beside_root(v, v_sq, length);
  if (v_sq >= std::numeric_limits<S>::min() && v_sq <= std::numeric_limits<S>::max())
    return v * (S(1) / length);
  const Vec3T<S> scaled = v / v.cwiseAbs().maxCoeff();  // components in [-1, 1], one of them +-1
  return scaled / scaled.norm();
}

/// v / |v| for v != 0, at any magnitude.
template <class S>
Vec3T<S> unit_of(const Vec3T<S>& v) {
  const S v_sq = v.squaredNorm();
  return unit_of(v, v_sq, length_of(v, v_sq));
}

/// |v| <= reach (>= 0), from |v|'s square `v_sq`: compared on squares, with no root, while the
/// reach's square lies well inside the normal range (4 min to max / 4). Then comparing squares is
/// exact whatever v_sq is: a v whose square underflows is shorter than the reach, one whose square
/// overflows longer. Outside that range length_of() decides. The range test waits on the reach
/// alone, not on the chain to v (a test on v_sq too cost capsule distance 4-6 %).
template <class S>
[[gnu::always_inline]] inline bool length_at_most(const Vec3T<S>& v, S v_sq, S reach) {
  const S reach_sq = reach * reach;
  constexpr S kSmallest = std::numeric_limits<S>::min(), kLargest = std::numeric_limits<S>::max();
  return reach_sq >= S(4) * kSmallest && reach_sq <= kLargest / S(4) ? v_sq <= reach_sq
                                                                     : length_of(v, v_sq) <= reach;
}

/// x > bound * |v| (bound >= 0), from |v|'s square `v_sq`: compared on squares, with no root,
/// unless a square underflows or overflows (sizes beyond about 2^+-250, where x^2 against
/// bound^2 |v|^2 multiplies four of them), where length_of() decides.
template <class S>
[[gnu::always_inline]] inline bool exceeds_times_length(S x, S bound, const Vec3T<S>& v, S v_sq) {
  if (!(x > S(0))) return false;
  const S x_sq = x * x, bound_sq = bound * bound, rhs = bound_sq * v_sq;
  constexpr S kSmallest = std::numeric_limits<S>::min(), kLargest = std::numeric_limits<S>::max();
  return x_sq >= kSmallest && bound_sq >= kSmallest && rhs >= kSmallest && x_sq <= kLargest &&
                 rhs <= kLargest
             ? x_sq > rhs
             : x > bound * length_of(v, v_sq);
}

}  // namespace detail

}  // namespace mink
