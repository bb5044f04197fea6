/// @file capsule.hpp
#pragma once

#include "mink/shapes/shape_common.hpp"

namespace mink {

/// Capsule: the segment (0,0,-half_height)-(0,0,+half_height) swept by a ball of `radius`. Its core
/// is the segment, so capsule queries are exact (no iteration on the curved surface).
template <class S>
struct CapsuleT {
  using Scalar = S;

  S radius = S(0);       ///< (unit: length), finite and >= 0
  S half_height = S(0);  ///< half the length of the core segment (unit: length), finite and >= 0

  Vec3T<S> support_core(const Vec3T<S>& d) const {
    return {S(0), S(0), detail::sign_nonneg(d.z()) * half_height};
  }
  Vec3T<S> core_centre() const { return Vec3T<S>::Zero(); }
  S core_radius() const { return radius; }
  S bounding_radius() const { return radius + half_height; }
  const char* error() const {
    // One branch for both (& on ints does not short-circuit); the message out of line: inlined,
    // Clang chose between the messages with a chain of conditional moves on every query (a
    // capsule pair's distance 41 -> 36 ns).
    if (int(detail::is_length(radius)) & int(detail::is_length(half_height))) [[likely]]
      return nullptr;
    return error_message();
  }

 private:
  [[gnu::noinline, gnu::cold]] const char* error_message() const {
    if (!detail::is_length(radius)) return "capsule radius must be finite and >= 0";
    if (!detail::is_length(half_height)) return "capsule half_height must be finite and >= 0";
    return nullptr;
  }
};

using Capsule = CapsuleT<double>;

}  // namespace mink
