/// @file polytope.hpp
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mink/expected.hpp"
#include "mink/shapes/hull_shape.hpp"
#include "mink/shapes/shape_common.hpp"
#include "mink/shapes/support_scan.hpp"

namespace mink {

/// A polytope of at least kHullClimbMinVertices points builds its hull after this many support
/// queries and climbs it from then on (PolytopeT, "From scan to hull").
inline constexpr std::uint32_t kPolytopeHullAfterSupports = 4096;

namespace detail {

/// The hull a large polytope builds once it has been queried enough, shared by its copies.
template <class S>
struct PolytopeHull {
  enum : int { kScanning, kBuilding, kReady, kFailed };
  std::atomic<std::uint32_t> supports{0};
  std::atomic<int> state{kScanning};
  std::optional<ConvexHullShapeT<S>> hull;     // written once, before state becomes kReady
  std::vector<std::uint32_t> point_of_vertex;  // hull vertex -> index of the polytope's point
};

}  // namespace detail

/// The convex hull of a point set in the local frame; interior and duplicate points are allowed.
/// Support is a brute-force scan over coordinates stored as three separate arrays (structure of
/// arrays) so that the dot products vectorise. Build it with make(), which validates the points.
///
/// From scan to hull. Scanning costs nothing to set up, which suits a polytope used in a few
/// queries; climbing a hull (hull_shape.hpp) is 10 to 100 times faster per query from a few
/// hundred points up, but building the hull costs about as much as 1,800 to 3,900 scans
/// (docs/architecture.md, "Hull shape"). So a polytope of at least kHullClimbMinVertices points
/// scans for its first kPolytopeHullAfterSupports support queries, then builds its hull once, in
/// the thread whose query reached the count (others keep scanning meanwhile, none waits), and
/// climbs from then on: a one-off query never pays for a hull, a shape kept across many queries
/// pays at most about twice the best choice made in hindsight. After the switch, support answers
/// a hull vertex whose support value is the maximum within the hull's tolerance (1e-10 of the
/// points' extent; exact for exactly coplanar faces), and on ties (a face facing d) it may name
/// another point of the same face than the scan did. Copies share the hull.
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
    if (n >= kHullClimbMinVertices && n <= std::numeric_limits<std::uint32_t>::max() / 2)
      p.lazy_hull_ = std::make_shared<detail::PolytopeHull<S>>();
    return p;
  }

  std::size_t size() const { return x_.size(); }
  Vec3T<S> point(std::size_t i) const { return {x_[i], y_[i], z_[i]}; }

  /// Always inlined, as support_index() is: the body of every GJK and EPA iteration.
  [[gnu::always_inline]] inline Vec3T<S> support_core(const Vec3T<S>& d) const {
    return point(support_index(d));
  }
  S core_radius() const { return S(0); }
  S bounding_radius() const { return bounding_radius_; }
  const char* error() const { return x_.empty() ? "polytope has no points" : nullptr; }

  /// Index of a point farthest along d: the lowest such index on ties while scanning (see
  /// support_scan.hpp), a hull vertex once the polytope climbs (see the class comment). Always
  /// inlined, with the scan of small point sets; the count towards the hull and the climb, for
  /// polytopes of kHullClimbMinVertices points or more, stay out of line.
  [[gnu::always_inline]] inline std::size_t support_index(const Vec3T<S>& d) const {
    return lazy_hull_ ? lazy_support_index(d) : scan_index(d);
  }

  /// The brute-force answer, whatever support_index does: lowest index among the farthest.
  [[gnu::always_inline]] inline std::size_t scan_index(const Vec3T<S>& d) const {
    return detail::support_index(x_.data(), y_.data(), z_.data(), x_.size(), d.x(), d.y(), d.z());
  }

  /// The hull support climbs once the polytope has switched, else null (see the class comment).
  const ConvexHullShapeT<S>* hull() const {
    if (!lazy_hull_ ||
        lazy_hull_->state.load(std::memory_order_acquire) != detail::PolytopeHull<S>::kReady)
      return nullptr;
    return &*lazy_hull_->hull;
  }
  bool climbs() const { return hull() != nullptr; }

 private:
  PolytopeT() = default;

  /// support_index() of a polytope that may climb: its hull once built, else the scan, counted.
  [[gnu::noinline]] std::size_t lazy_support_index(const Vec3T<S>& d) const {
    detail::PolytopeHull<S>& lazy = *lazy_hull_;
    if (lazy.state.load(std::memory_order_acquire) == lazy.kReady)
      return lazy.point_of_vertex[lazy.hull->support_index(d)];
    count_support(lazy);
    return scan_index(d);
  }

  /// Counts a scanned query and builds the hull at the kPolytopeHullAfterSupports-th. The count
  /// is a relaxed load and store, not an atomic increment: a lost count between racing threads
  /// only delays the switch, and it costs no locked instruction on the query path.
  void count_support(detail::PolytopeHull<S>& lazy) const {
    const std::uint32_t count = lazy.supports.load(std::memory_order_relaxed) + 1;
    lazy.supports.store(count, std::memory_order_relaxed);
    if (count < kPolytopeHullAfterSupports) return;
    int expected = lazy.kScanning;
    if (!lazy.state.compare_exchange_strong(expected, lazy.kBuilding, std::memory_order_acq_rel))
      return;
    std::vector<Vec3T<S>> points(size());
    for (std::size_t i = 0; i < size(); ++i) points[i] = point(i);
    Expected<ConvexHullShapeT<S>> hull = ConvexHullShapeT<S>::make(points);
    // A hull of finite points always builds; on a failure (a bug of the builder) keep scanning.
    if (!hull) {
      lazy.state.store(lazy.kFailed, std::memory_order_release);
      return;
    }
    lazy.point_of_vertex.resize(hull->size());
    for (std::size_t v = 0; v < hull->size(); ++v) lazy.point_of_vertex[v] = hull->input_index(v);
    lazy.hull.emplace(std::move(hull).value());
    lazy.state.store(lazy.kReady, std::memory_order_release);
  }

  std::vector<S> x_, y_, z_;
  S bounding_radius_ = S(0);
  std::shared_ptr<detail::PolytopeHull<S>> lazy_hull_;  // null below kHullClimbMinVertices
};

using Polytope = PolytopeT<double>;

}  // namespace mink
