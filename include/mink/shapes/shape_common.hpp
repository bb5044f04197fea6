/// @file shape_common.hpp
/// What every shape provides, and the small helpers the shapes share.
///
/// Every shape is a *core* plus a *radius* (docs/architecture.md): the shape is the set of points
/// within `core_radius()` of its core. Queries run GJK on the cores and add the radius at the end,
/// which is exact and keeps GJK off curved surfaces where it converges slowly. A sphere is a point
/// core with a radius, a capsule a segment core with one; a box has radius 0.
///
/// Each shape type provides, in its own local frame:
///   - `Vec3T<S> support_core(const Vec3T<S>& d) const`: a point of the core farthest along d
///     (d need not be unit, and may be of any finite length down to subnormal: GJK's v near
///     touching is as short as the gap; ties are broken deterministically; d = 0 returns some
///     core point);
///   - `S core_radius() const`: the radius added around the core (unit: length, >= 0);
///   - `S bounding_radius() const`: radius of a ball about the local origin containing the whole
///     shape, used to scale tolerances;
///   - `const char* error() const`: why the shape is invalid, or nullptr when it is valid;
///   - optionally, `Vec3T<S> core_centre() const`: a point of the core towards its middle. GJK's
///     first phase starts from the difference of the two shapes' centres, a point of A - B that
///     costs no support call (gjk.hpp, enclose_origin()); a shape without it starts as before.
#pragma once

#include <cmath>
#include <limits>

#include "mink/math/vec.hpp"

namespace mink::detail {

/// +1 for x >= 0, -1 otherwise: support points break the tie at 0 towards +, deterministically.
template <class S>
inline S sign_nonneg(S x) {
  return x >= S(0) ? S(1) : S(-1);
}

/// The next and the previous axis in cyclic order: e_i x e_(i+1) = e_(i+2).
inline constexpr int kNextAxis[3] = {1, 2, 0}, kPrevAxis[3] = {2, 0, 1};

/// Index of the largest |v[i]| (the first on ties): the axis of the box face most aligned with v.
template <class S>
inline int dominant_axis(const Vec3T<S>& v) {
  const Vec3T<S> a = v.cwiseAbs();
  return a.x() >= a.y() && a.x() >= a.z() ? 0 : (a.y() >= a.z() ? 1 : 2);
}

/// Directions whose components are all below this are scaled up by kDirectionUp (a power of two,
/// so exactly) before a curved shape's support works with their lengths: below min / epsilon a
/// root of a sum of squares is subnormal and keeps too few digits (hypot(5e-324, 1e-323) is off
/// by 20 %), and radius / |d| overflows.
template <class S>
inline constexpr S kTinyDirection =
    std::numeric_limits<S>::min() / std::numeric_limits<S>::epsilon();
template <class S>
inline constexpr S kDirectionUp = S(1) / (std::numeric_limits<S>::epsilon() *
                                          std::numeric_limits<S>::epsilon());

/// d scaled by kDirectionUp when every component is tiny; a support point depends on d's
/// orientation only.
template <class S>
inline Vec3T<S> rescaled_direction(const Vec3T<S>& d) {
  return d.cwiseAbs().maxCoeff() < kTinyDirection<S> ? Vec3T<S>(d * kDirectionUp<S>) : d;
}

/// The length of (x, y): the root of the sum of squares, within an ulp of std::hypot(), which is
/// a library call five times as slow (a seventh of two cylinders' distance() was in it); hypot
/// where the squares leave the normal range.
template <class S>
inline S planar_length(S x, S y) {
  const S squares = x * x + y * y;
  if (squares >= std::numeric_limits<S>::min() && squares <= std::numeric_limits<S>::max())
    return std::sqrt(squares);
  return std::hypot(x, y);
}

/// The unit vector (ux, uy) along (x, y) for a rim point of a cylinder or cone; false when (x, y)
/// is 0 (d along the axis). Each component over the length, not 1 / length times it: the length
/// is tiny when d is the axis give or take 1e-300, and its reciprocal overflows.
template <class S>
inline bool planar_unit(S x, S y, S& ux, S& uy) {
  S rho = planar_length(x, y);
  if (rho == S(0)) return false;
  if (rho < kTinyDirection<S>) {
    x *= kDirectionUp<S>;
    y *= kDirectionUp<S>;
    rho = planar_length(x, y);
  }
  ux = x / rho;
  uy = y / rho;
  return true;
}

/// True for a finite, non-negative length. Two comparisons, which NaN and both infinities fail:
/// every query checks its shapes' lengths, and std::isfinite() costs a mask and a third compare.
/// Quiet comparisons: a NaN length must give an error message, not FE_INVALID (a trap, where
/// floating-point exceptions are enabled).
template <class S>
[[gnu::always_inline]] inline bool is_length(S x) {
  return std::isgreaterequal(x, S(0)) && std::islessequal(x, std::numeric_limits<S>::max());
}

/// Out of line and cold: which of two messages applies is only asked of an invalid shape.
[[gnu::noinline, gnu::cold]] inline const char* first_failed(bool first_ok, const char* first,
                                                             const char* second) {
  return first_ok ? second : first;
}

/// error() of a shape given by a radius and a half-height (capsule, cylinder, cone): nullptr when
/// both are lengths, else the message of the first that is not. One branch (& on ints does not
/// short-circuit) and the choice of message out of line: inlined, Clang chose between the messages
/// with a chain of conditional moves on every query (a capsule pair's distance 41 -> 36 ns).
template <class S>
[[gnu::always_inline]] inline const char* radius_height_error(S radius, S half_height,
                                                              const char* radius_message,
                                                              const char* height_message) {
  if (int(is_length(radius)) & int(is_length(half_height))) [[likely]]
    return nullptr;
  return first_failed(is_length(radius), radius_message, height_message);
}

}  // namespace mink::detail
