/// @file concept.hpp
/// The one requirement queries place on a shape: a support mapping of its core, plus its radius.
#pragma once

#include <concepts>

#include "mink/math/vec.hpp"

namespace mink {

/// A convex shape as a core plus a radius (see shapes/shape_common.hpp for the contract).
template <class T>
concept ConvexShape = requires(const T& shape, const Vec3T<typename T::Scalar>& d) {
  typename T::Scalar;
  { shape.support_core(d) } -> std::convertible_to<Vec3T<typename T::Scalar>>;
  { shape.core_radius() } -> std::convertible_to<typename T::Scalar>;
  { shape.bounding_radius() } -> std::convertible_to<typename T::Scalar>;
  { shape.error() } -> std::convertible_to<const char*>;
};

/// A shape that names a point of its core towards its middle (shapes/shape_common.hpp).
template <class T>
concept HasCoreCentre = ConvexShape<T> && requires(const T& shape) {
  { shape.core_centre() } -> std::convertible_to<Vec3T<typename T::Scalar>>;
};

/// The full support mapping of a shape in its own frame: the core's support pushed out by the
/// radius along the unit direction. d must not be zero when the radius is not.
template <ConvexShape T>
Vec3T<typename T::Scalar> support(const T& shape, const Vec3T<typename T::Scalar>& d) {
  using S = typename T::Scalar;
  const S r = shape.core_radius();
  if (r == S(0)) return shape.support_core(d);
  return shape.support_core(d) + d.normalized() * r;
}

}  // namespace mink
