/// @file point.hpp
#pragma once

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// A single point of the local frame (a zero-radius sphere that need not sit at the origin).
template <class S>
struct PointT {
  using Scalar = S;

  Vec3T<S> position = Vec3T<S>::Zero();

  Vec3T<S> support_core(const Vec3T<S>&) const { return position; }
  Vec3T<S> core_centre() const { return position; }
  S core_radius() const { return S(0); }
  S bounding_radius() const {  // at any magnitude (length_of())
    return detail::length_of(position);
  }
  const char* error() const { return is_finite(position) ? nullptr : "point is not finite"; }
};

using Point = PointT<double>;

}  // namespace mink
