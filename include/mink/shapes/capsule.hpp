/// @file capsule.hpp
#pragma once

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// Capsule: the segment (0,0,-half_height)-(0,0,+half_height) swept by a ball of `radius`. Its core
/// is the segment, so capsule queries are exact (no iteration on the curved surface).
template <class S>
struct CapsuleT {
  using Scalar = S;

  S radius = S(0);       ///< (unit: length), finite and >= 0
  S half_height = S(0);  ///< half the length of the core segment (unit: length), finite and >= 0

  Vec3T<S> support_core(const Vec3T<S>& d) const {
    return {S(0), S(0), detail::sign_nonneg(d.z()) * half_height};
  }
  Vec3T<S> core_centre() const { return Vec3T<S>::Zero(); }
  S core_radius() const { return radius; }
  S bounding_radius() const { return radius + half_height; }
  const char* error() const {
    return detail::radius_height_error(radius, half_height,
                                       "capsule radius must be finite and >= 0",
                                       "capsule half_height must be finite and >= 0");
  }
};

using Capsule = CapsuleT<double>;

}  // namespace mink
