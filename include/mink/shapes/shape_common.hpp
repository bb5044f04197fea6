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
///     (d need not be unit; ties are broken deterministically; d = 0 returns some core point);
///   - `S core_radius() const`: the radius added around the core (unit: length, >= 0);
///   - `S bounding_radius() const`: radius of a ball about the local origin containing the whole
///     shape, used to scale tolerances;
///   - `const char* error() const`: why the shape is invalid, or nullptr when it is valid.
#pragma once

#include <cmath>

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

/// True for a finite, non-negative length.
template <class S>
inline bool is_length(S x) {
  return std::isfinite(x) && x >= S(0);
}

}  // namespace mink::detail
