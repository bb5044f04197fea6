/// @file box.hpp
#pragma once

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// Box centred at the local origin with its edges along the local axes.
template <class S>
struct BoxT {
  using Scalar = S;

  Vec3T<S> half_extents = Vec3T<S>::Zero();  ///< (unit: length), each finite and >= 0

  Vec3T<S> support_core(const Vec3T<S>& d) const {
    return {detail::sign_nonneg(d.x()) * half_extents.x(),
            detail::sign_nonneg(d.y()) * half_extents.y(),
            detail::sign_nonneg(d.z()) * half_extents.z()};
  }
  Vec3T<S> core_centre() const { return Vec3T<S>::Zero(); }
  S core_radius() const { return S(0); }
  /// |half_extents|, also where its square overflows or underflows (half extents beyond 1e154 or
  /// under 1e-154: a plain norm() is inf or 0 there, and every tolerance scaled by it with it).
  S bounding_radius() const { return detail::length_of(half_extents); }
  const char* error() const {
    // One branch for the three (& on ints does not short-circuit).
    const int valid = int(detail::is_length(half_extents[0])) &
                      int(detail::is_length(half_extents[1])) &
                      int(detail::is_length(half_extents[2]));
    return valid ? nullptr : "box half_extents must be finite and >= 0";
  }
};

using Box = BoxT<double>;

}  // namespace mink
