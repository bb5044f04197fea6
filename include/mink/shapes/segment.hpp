/// @file segment.hpp
#pragma once

#include <algorithm>

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// The segment between two points of the local frame (they may coincide).
template <class S>
struct SegmentT {
  using Scalar = S;

  Vec3T<S> a = Vec3T<S>::Zero();
  Vec3T<S> b = Vec3T<S>::Zero();

  Vec3T<S> support_core(const Vec3T<S>& d) const { return d.dot(b - a) > S(0) ? b : a; }
  Vec3T<S> core_centre() const { return S(0.5) * a + S(0.5) * b; }
  S core_radius() const { return S(0); }
  S bounding_radius() const {  // at any magnitude (length_of())
    return std::max(detail::length_of(a), detail::length_of(b));
  }
  const char* error() const {
    return is_finite(a) && is_finite(b) ? nullptr : "segment points are not finite";
  }
};

using Segment = SegmentT<double>;

}  // namespace mink
