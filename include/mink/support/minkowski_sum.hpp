/// @file minkowski_sum.hpp
#pragma once

#include "mink/support/concept.hpp"

namespace mink {

/// Minkowski sum ("sweep") of two shapes given in the same local frame: every a + b. The support
/// of a sum is the sum of the supports, and its core is the sum of the cores with the radii added,
/// so segment + sphere is exactly a capsule.
template <ConvexShape A, ConvexShape B>
requires std::same_as<typename A::Scalar, typename B::Scalar>
struct MinkowskiSum {
  using Scalar = typename A::Scalar;
  A a;
  B b;

  Vec3T<Scalar> support_core(const Vec3T<Scalar>& d) const {
    return a.support_core(d) + b.support_core(d);
  }
  Vec3T<Scalar> core_centre() const requires HasCoreCentre<A> && HasCoreCentre<B> {
    return a.core_centre() + b.core_centre();
  }
  Scalar core_radius() const { return a.core_radius() + b.core_radius(); }
  Scalar bounding_radius() const { return a.bounding_radius() + b.bounding_radius(); }
  const char* error() const {
    if (const char* e = a.error()) return e;
    return b.error();
  }
};

template <ConvexShape A, ConvexShape B>
MinkowskiSum(A, B) -> MinkowskiSum<A, B>;

}  // namespace mink
