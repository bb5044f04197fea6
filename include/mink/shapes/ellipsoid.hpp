/// @file ellipsoid.hpp
#pragma once

#include <cmath>

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// Solid ellipsoid centred at the local origin with semi-axes `radii` along the local axes.
template <class S>
struct EllipsoidT {
  using Scalar = S;

  Vec3T<S> radii = Vec3T<S>::Zero();  ///< semi-axes (unit: length), each finite and >= 0

  Vec3T<S> support_core(const Vec3T<S>& d) const {
    // The ellipsoid is the image of the unit ball under D = diag(radii):
    // support(d) = D^2 d / |D d| = D u with u the unit vector along D d. d is divided by its
    // largest component first and u comes from unit_of(), so that a d of 1e-170 neither
    // underflows D d to zero nor leaves u off unit.
    const S largest = d.cwiseAbs().maxCoeff();
    if (!(largest > S(0))) return Vec3T<S>::Zero();
    const Vec3T<S> dd = radii.cwiseProduct(d / largest);
    // D d = 0 only when d is orthogonal to every non-zero axis: the centre is then a support
    // point.
    if (dd.isZero(S(0))) return Vec3T<S>::Zero();
    return radii.cwiseProduct(detail::unit_of(dd));
  }
  Vec3T<S> core_centre() const { return Vec3T<S>::Zero(); }
  S core_radius() const { return S(0); }
  S bounding_radius() const { return radii.maxCoeff(); }
  const char* error() const {
    for (int i = 0; i < 3; ++i)
      if (!detail::is_length(radii[i])) return "ellipsoid radii must be finite and >= 0";
    return nullptr;
  }
};

using Ellipsoid = EllipsoidT<double>;

}  // namespace mink
