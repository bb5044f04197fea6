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
#include "mink/shapes/face_planes.hpp"
#include "mink/shapes/hull_shape.hpp"
#include "mink/shapes/shape_common.hpp"
#include "mink/shapes/support_scan.hpp"

namespace mink {

/// A polytope of at least kHullClimbMinVertices points builds its hull after this many support
/// queries and climbs it from then on (PolytopeT, "From scan to hull").
inline constexpr std::uint32_t kPolytopeHullAfterSupports = 4096;
/// A polytope of fewer points builds its face planes after this many queries against a sphere or
/// a point (PolytopeT::face_planes()).
inline constexpr std::uint32_t kPolytopePlanesAfterQueries = 256;

namespace detail {

/// Something a shape builds once it has been queried often enough, shared by the shape's copies:
/// the query that brings the count to `after` builds it, in its own thread; others go on without
/// it meanwhile, none waits. The count is a relaxed load and store, not an atomic increment: a
/// count lost between racing threads only delays the build, and the query path pays no locked
/// instruction.
template <class T>
struct LazyBuild {
  enum : int { kCounting, kBuilding, kReady, kFailed };
  std::atomic<std::uint32_t> count{0};
  std::atomic<int> state{kCounting};
  std::optional<T> value;  // written once, before state becomes kReady

  const T* ready() const {
    return state.load(std::memory_order_acquire) == kReady ? &*value : nullptr;
  }
  /// Counts a query; the one that reaches `after` runs `build` (which returns a std::optional<T>;
  /// nothing: the shape goes on without it for good).
  template <class Build>
  void count_towards(std::uint32_t after, Build&& build) {
    // Once built, being built, or failed, a query neither counts nor tries: a shape whose build
    // failed would otherwise pay a store and a compare-and-swap on every query, for good.
    if (state.load(std::memory_order_relaxed) != kCounting) return;
    const std::uint32_t n = count.load(std::memory_order_relaxed) + 1;
    count.store(n, std::memory_order_relaxed);
    if (n >= after) build_now(build);
  }
  /// Builds it now unless another query has already started to: then ready() tells when it is.
  template <class Build>
  const T* build_now(Build&& build) {
    int expected = kCounting;
    if (!state.compare_exchange_strong(expected, kBuilding, std::memory_order_acq_rel))
      return ready();
    std::optional<T> built = build();
    if (!built) {
      state.store(kFailed, std::memory_order_release);
      return nullptr;
    }
    value.emplace(std::move(*built));
    state.store(kReady, std::memory_order_release);
    return &*value;
  }
};

/// The hull a large polytope climbs, and its vertices' indices among the polytope's points.
template <class S>
struct PolytopeHull {
  ConvexHullShapeT<S> hull;
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
///
/// Planes for spheres and points. A polytope of 4 to kHullClimbMinVertices - 1 points answers a
/// sphere, a point and their Rounded versions in closed form once it has its face planes
/// (face_planes.hpp, query/point_solid.hpp): it builds them, in the same way, after
/// kPolytopePlanesAfterQueries such queries, or at once with build_face_planes(). Answers are the
/// same to rounding either way; where the planes could not be exact (a face merged within the
/// hull's tolerance, more than FacePlanesT::kMaxFaces faces) GJK keeps answering.
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
      p.bounding_radius_ = std::max(p.bounding_radius_, detail::length_of(points[i]));
      p.centre_ += points[i] / S(n);  // divided first: no overflow near the largest doubles
    }
    if (n >= kHullClimbMinVertices && n <= std::numeric_limits<std::uint32_t>::max() / 2)
      p.lazy_hull_ = std::make_shared<detail::LazyBuild<detail::PolytopeHull<S>>>();
    else if (n >= 4)
      p.lazy_planes_ = std::make_shared<detail::LazyBuild<FacePlanesT<S>>>();
    return p;
  }

  std::size_t size() const { return x_.size(); }
  Vec3T<S> point(std::size_t i) const { return {x_[i], y_[i], z_[i]}; }

  /// Always inlined, as support_index() is: the body of every GJK and EPA iteration. `P`: how
  /// the caller's directions move between calls (support_scan.hpp). Scattered calls scan up to
  /// kScatteredScanMaxPoints points even once the polytope climbs its hull: a climb from the
  /// previous answer gains little when the directions jump, and its branches mispredict (contact
  /// of two 128-point polytopes overlapping, whose EPA calls are Scattered: 19 % faster; of two
  /// of 512 points, 41 % slower). Either gives a point of the largest support value.
  template <SupportPattern P = SupportPattern::Coherent>
  [[gnu::always_inline]] inline Vec3T<S> support_core(const Vec3T<S>& d) const {
    if constexpr (P == SupportPattern::Scattered)
      if (size() <= kScatteredScanMaxPoints) return point(scan_index<P>(d));
    if (lazy_hull_)
      if (const S* p = lazy_support_position(d)) return {p[0], p[1], p[2]};
    return point(scan_index<P>(d));
  }
  /// The mean of the points: inside the hull (any one point may be a vertex, on its boundary).
  const Vec3T<S>& core_centre() const { return centre_; }
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

  /// support_index() with the support value of the core, h(d) = max over the points of p.d: for
  /// tests that need only how far the polytope reaches along d, which the scan of 8 points or
  /// fewer has before the point's index (support_scan.hpp).
  [[gnu::always_inline]] inline detail::SupportHit<S> support_core_hit(const Vec3T<S>& d) const {
    if (lazy_hull_) {
      const std::size_t i = lazy_support_index(d);
      return detail::SupportHit<S>::of(
          detail::point_dot(x_.data(), y_.data(), z_.data(), i, d.x(), d.y(), d.z()), i);
    }
    return detail::support_hit(x_.data(), y_.data(), z_.data(), x_.size(), d.x(), d.y(), d.z());
  }

  /// The brute-force answer, whatever support_index does: lowest index among the farthest.
  template <SupportPattern P = SupportPattern::Coherent>
  [[gnu::always_inline]] inline std::size_t scan_index(const Vec3T<S>& d) const {
    return detail::support_index<P>(x_.data(), y_.data(), z_.data(), x_.size(), d.x(), d.y(),
                                    d.z());
  }

  /// The hull support climbs once the polytope has switched, else null (see the class comment).
  const ConvexHullShapeT<S>* hull() const {
    const auto* climb = lazy_hull_ ? lazy_hull_->ready() : nullptr;
    return climb ? &climb->hull : nullptr;
  }
  bool climbs() const { return hull() != nullptr; }

  /// The planes of a polytope of 4 to kHullClimbMinVertices - 1 points, which answer a sphere's
  /// or a point's queries in closed form (query/point_solid.hpp), or null: before the polytope
  /// has been asked kPolytopePlanesAfterQueries times (a hull of a few points costs 10-25 us, about
  /// as much as that many GJK distance queries save), or when its hull has no exact planes
  /// (FacePlanesT::make). Counts the call. Copies share the planes.
  const FacePlanesT<S>* face_planes() const {
    if (!lazy_planes_) return nullptr;
    if (const FacePlanesT<S>* planes = lazy_planes_->ready()) return planes;
    lazy_planes_->count_towards(kPolytopePlanesAfterQueries, [this] { return build_planes(); });
    return nullptr;
  }
  /// Builds the planes now, for a polytope that will be queried often (as a simulation prepares
  /// its shapes); null as for face_planes(), or while another thread is building them.
  const FacePlanesT<S>* build_face_planes() const {
    if (!lazy_planes_) return nullptr;
    return lazy_planes_->build_now([this] { return build_planes(); });
  }

 private:
  PolytopeT() = default;

  template <class T>
  std::vector<Vec3T<T>> points_as() const {
    std::vector<Vec3T<T>> points(size());
    for (std::size_t i = 0; i < size(); ++i) points[i] = point(i).template cast<T>();
    return points;
  }

  /// support_index() of a polytope that may climb: its hull once built, else the scan, counted.
  [[gnu::noinline]] std::size_t lazy_support_index(const Vec3T<S>& d) const {
    if (const auto* climb = lazy_hull_->ready())
      return climb->point_of_vertex[climb->hull.support_index(d)];
    lazy_hull_->count_towards(kPolytopeHullAfterSupports, [this] { return build_hull(); });
    return scan_index(d);
  }

  /// support_core() of a polytope that may climb: the hull's point once built (the same
  /// coordinates, read in the vertex record where the climb ended), else nullptr, counted, and the
  /// caller scans. A pointer, not the point: a point is returned through memory, and support_core()
  /// then joined its two paths there, three scalar stores read back as a pair and a scalar, which
  /// stalled every support call of a small polytope on store forwarding.
  [[gnu::noinline]] const S* lazy_support_position(const Vec3T<S>& d) const {
    if (const auto* climb = lazy_hull_->ready()) return climb->hull.support_position(d);
    lazy_hull_->count_towards(kPolytopeHullAfterSupports, [this] { return build_hull(); });
    return nullptr;
  }

  std::optional<detail::PolytopeHull<S>> build_hull() const {
    Expected<ConvexHullShapeT<S>> hull = ConvexHullShapeT<S>::make(points_as<S>());
    // A hull of finite points always builds; on a failure (a bug of the builder) keep scanning.
    if (!hull) return std::nullopt;
    detail::PolytopeHull<S> climb{std::move(hull).value(), {}};
    climb.point_of_vertex.resize(climb.hull.size());
    // support_core() returns the coordinates in the hull's vertex records for the polytope's:
    // they must be the same numbers (the builder copies its input; a failure here would be its
    // bug: keep scanning).
    for (std::size_t v = 0; v < climb.hull.size(); ++v) {
      climb.point_of_vertex[v] = climb.hull.input_index(v);
      const S* position = climb.hull.vertex_position(v);
      if (Vec3T<S>(position[0], position[1], position[2]) != point(climb.point_of_vertex[v]))
        return std::nullopt;
    }
    return climb;
  }

  std::optional<FacePlanesT<S>> build_planes() const {
    const std::vector<Vec3> points = points_as<double>();
    const Expected<ConvexHull> hull = build_convex_hull(points);
    if (!hull) return std::nullopt;
    return FacePlanesT<S>::make(*hull, points);
  }

  std::vector<S> x_, y_, z_;
  S bounding_radius_ = S(0);
  Vec3T<S> centre_ = Vec3T<S>::Zero();
  // At most one of the two: the hull from kHullClimbMinVertices points, the planes below.
  std::shared_ptr<detail::LazyBuild<detail::PolytopeHull<S>>> lazy_hull_;
  std::shared_ptr<detail::LazyBuild<FacePlanesT<S>>> lazy_planes_;
};

using Polytope = PolytopeT<double>;

}  // namespace mink
