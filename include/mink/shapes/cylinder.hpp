/// @file cylinder.hpp
#pragma once

#include <cmath>

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// Solid cylinder with its axis along local z, from z = -half_height to +half_height.
template <class S>
struct CylinderT {
  using Scalar = S;

  S radius = S(0);       ///< (unit: length), finite and >= 0
  S half_height = S(0);  ///< (unit: length), finite and >= 0

  Vec3T<S> support_core(const Vec3T<S>& d) const {
    const S z = detail::sign_nonneg(d.z()) * half_height;
    // Along the axis every rim point is a support point; the centre of the cap is the tie-break.
    S ux, uy;
    if (!detail::planar_unit(d.x(), d.y(), ux, uy)) return {S(0), S(0), z};
    return {radius * ux, radius * uy, z};
  }
  Vec3T<S> core_centre() const { return Vec3T<S>::Zero(); }
  S core_radius() const { return S(0); }
  S bounding_radius() const { return std::hypot(radius, half_height); }
  const char* error() const {
    return detail::radius_height_error(radius, half_height,
                                       "cylinder radius must be finite and >= 0",
                                       "cylinder half_height must be finite and >= 0");
  }
};

using Cylinder = CylinderT<double>;

}  // namespace mink
