/// @file segment.hpp
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

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
  /// The larger of |a| and |b|, at any magnitude: one square root, the larger square's, where it
  /// is in range (the common case); else length_of() of each.
  S bounding_radius() const {
    const S larger = std::max(S(a.squaredNorm()), S(b.squaredNorm()));
    if (larger >= std::numeric_limits<S>::min() && larger <= std::numeric_limits<S>::max())
        [[likely]]
      return std::sqrt(larger);
    return std::max(detail::length_of(a), detail::length_of(b));
  }
  const char* error() const {
    return is_finite(a) && is_finite(b) ? nullptr : "segment points are not finite";
  }
};

using Segment = SegmentT<double>;

}  // namespace mink
