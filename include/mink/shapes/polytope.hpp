/// @file polytope.hpp
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "mink/expected.hpp"
#include "mink/shapes/shape_common.hpp"
#include "mink/shapes/support_scan.hpp"

namespace mink {

/// The convex hull of a point set in the local frame; interior and duplicate points are allowed.
/// Support is a brute-force scan over coordinates stored as three separate arrays (structure of
/// arrays) so that the dot products vectorise. Build it with make(), which validates the points.
template <class S>
class PolytopeT {
 public:
  using Scalar = S;

  /// A polytope over `points`: error when the set is empty or a coordinate is NaN or infinite.
  static Expected<PolytopeT> make(std::span<const Vec3T<S>> points) {
    if (points.empty()) return Expected<PolytopeT>::failure("polytope has no points");
    PolytopeT p;
    const std::size_t n = points.size();
    p.x_.resize(n);
    p.y_.resize(n);
    p.z_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!is_finite(points[i]))
        return Expected<PolytopeT>::failure("polytope point " + std::to_string(i) +
                                            " is not finite");
      p.x_[i] = points[i].x();
      p.y_[i] = points[i].y();
      p.z_[i] = points[i].z();
      p.bounding_radius_ = std::max(p.bounding_radius_, points[i].norm());
    }
    return p;
  }

  std::size_t size() const { return x_.size(); }
  Vec3T<S> point(std::size_t i) const { return {x_[i], y_[i], z_[i]}; }

  Vec3T<S> support_core(const Vec3T<S>& d) const { return point(support_index(d)); }
  S core_radius() const { return S(0); }
  S bounding_radius() const { return bounding_radius_; }
  const char* error() const { return x_.empty() ? "polytope has no points" : nullptr; }

  /// Index of a point farthest along d; the lowest such index on ties (see support_scan.hpp).
  std::size_t support_index(const Vec3T<S>& d) const {
    return detail::support_index(x_.data(), y_.data(), z_.data(), x_.size(), d.x(), d.y(), d.z());
  }

 private:
  PolytopeT() = default;
  std::vector<S> x_, y_, z_;
  S bounding_radius_ = S(0);
};

using Polytope = PolytopeT<double>;

}  // namespace mink
