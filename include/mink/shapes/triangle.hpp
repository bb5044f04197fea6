/// @file triangle.hpp
#pragma once

#include <algorithm>

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// The (solid, two-sided) triangle with the given corners in the local frame; corners may coincide
/// or be collinear, which makes it a segment or a point.
template <class S>
struct TriangleT {
  using Scalar = S;

  Vec3T<S> a = Vec3T<S>::Zero();
  Vec3T<S> b = Vec3T<S>::Zero();
  Vec3T<S> c = Vec3T<S>::Zero();

  Vec3T<S> support_core(const Vec3T<S>& d) const {
    const S da = d.dot(a), db = d.dot(b), dc = d.dot(c);
    if (da >= db) return da >= dc ? a : c;
    return db >= dc ? b : c;
  }
  Vec3T<S> core_centre() const { return a / S(3) + b / S(3) + c / S(3); }
  S core_radius() const { return S(0); }
  S bounding_radius() const {  // at any magnitude (length_of())
    return std::max({detail::length_of(a), detail::length_of(b), detail::length_of(c)});
  }
  const char* error() const {
    return is_finite(a) && is_finite(b) && is_finite(c) ? nullptr
                                                        : "triangle points are not finite";
  }
};

using Triangle = TriangleT<double>;

}  // namespace mink
