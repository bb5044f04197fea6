/// @file sphere.hpp
#pragma once

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// Ball of the given radius centred at the local origin: a point core plus a radius.
template <class S>
struct SphereT {
  using Scalar = S;

  S radius = S(0);  ///< (unit: length), finite and >= 0

  Vec3T<S> support_core(const Vec3T<S>&) const { return Vec3T<S>::Zero(); }
  Vec3T<S> core_centre() const { return Vec3T<S>::Zero(); }
  S core_radius() const { return radius; }
  S bounding_radius() const { return radius; }
  const char* error() const {
    return detail::is_length(radius) ? nullptr : "sphere radius must be finite and >= 0";
  }
};

using Sphere = SphereT<double>;

}  // namespace mink
