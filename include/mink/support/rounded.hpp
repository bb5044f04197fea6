/// @file rounded.hpp
#pragma once

#include <cmath>

#include "mink/support/concept.hpp"

namespace mink {

/// A shape grown by a margin ("collision skin"): every point within `margin` of the shape. The
/// margin joins the shape's own radius, so queries stay exact and run on the unchanged core.
template <ConvexShape T>
struct Rounded {
  using Scalar = typename T::Scalar;
  T shape;
  Scalar margin = Scalar(0);  ///< (unit: length), finite and >= 0

  /// Always inlined: a call of its own passed the direction and the point through memory (the
  /// run-time Shape's cores are all Rounded).
  [[gnu::always_inline]] Vec3T<Scalar> support_core(const Vec3T<Scalar>& d) const {
    return shape.support_core(d);
  }
  Vec3T<Scalar> core_centre() const requires HasCoreCentre<T> { return shape.core_centre(); }
  Scalar core_radius() const { return shape.core_radius() + margin; }
  Scalar bounding_radius() const { return shape.bounding_radius() + margin; }
  const char* error() const {
    if (!std::isfinite(margin) || margin < Scalar(0))
      return "rounded margin must be finite and >= 0";
    return shape.error();
  }
};

template <ConvexShape T, class S>
Rounded(T, S) -> Rounded<T>;

}  // namespace mink
