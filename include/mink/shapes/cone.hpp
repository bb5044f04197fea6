/// @file cone.hpp
#pragma once

#include <cmath>

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// Solid cone with its axis along local z: base disc of `radius` at z = -half_height, apex at
/// z = +half_height. Its local origin is the middle of the axis, not the centroid.
template <class S>
struct ConeT {
  using Scalar = S;

  S radius = S(0);       ///< base radius (unit: length), finite and >= 0
  S half_height = S(0);  ///< (unit: length), finite and >= 0

  Vec3T<S> support_core(const Vec3T<S>& direction) const {
    // The support is the apex or a point of the base rim, whichever reaches farther along d:
    // apex: h*dz; rim: radius*|d_xy| - h*dz.
    const Vec3T<S> d = detail::rescaled_direction(direction);
    const S rho = detail::planar_length(d.x(), d.y());
    const S apex = half_height * d.z();
    const S rim = radius * rho - half_height * d.z();
    if (apex >= rim) return {S(0), S(0), half_height};
    S ux, uy;
    if (!detail::planar_unit(d.x(), d.y(), ux, uy)) return {S(0), S(0), -half_height};
    return {radius * ux, radius * uy, -half_height};
  }
  Vec3T<S> core_centre() const { return Vec3T<S>::Zero(); }
  S core_radius() const { return S(0); }
  S bounding_radius() const { return std::hypot(radius, half_height); }
  const char* error() const {
    return detail::radius_height_error(radius, half_height, "cone radius must be finite and >= 0",
                                       "cone half_height must be finite and >= 0");
  }
};

using Cone = ConeT<double>;

}  // namespace mink
