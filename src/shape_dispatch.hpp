// Run-time dispatch for the queries of src/shape_queries.cpp: a single-core Shape becomes its
// concrete core type with the radius attached, so the algorithms inline the support mapping; sums
// of several cores use Shape itself.
#pragma once

#include <cstddef>
#include <utility>

#include "mink/query/point_set_pair.hpp"
#include "mink/query/scale_range.hpp"
#include "mink/query/shape_queries.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// A polytope held by pointer, so dispatch copies no points.
struct PolytopeRef {
  using Scalar = double;
  const Polytope* polytope;
  // Always inlined, as Polytope's own: out of line, each support call of the run-time Shape cost
  // a call and its argument and result through memory.
  [[gnu::always_inline]] Vec3 support_core(const Vec3& d) const {
    return polytope->support_core(d);
  }
  Vec3 core_centre() const { return polytope->core_centre(); }
  double core_radius() const { return 0; }
  double bounding_radius() const { return polytope->bounding_radius(); }
  const char* error() const { return polytope->error(); }
};

/// The polytope's own faces for manifolds (found by argument-dependent lookup).
inline void support_feature(const PolytopeRef& p, const Vec3& d, double tolerance,
                            SupportFeatureT<double>& out) {
  mink::support_feature(*p.polytope, d, tolerance, out);
}

/// Its points for point_set_pair() (query/point_set_pair.hpp): the polytope's own.
template <>
struct PointSetCore<PolytopeRef> : std::true_type {
  static int points(const PolytopeRef& p, Vec3* out) {
    return PointSetCore<Polytope>::points(*p.polytope, out);
  }
};

/// Its face planes, as a Polytope's: the closed forms of a point core against it
/// (query/point_solid.hpp) and the first support call of two small polytopes
/// (query/polytope_pair.hpp). Without them a Shape, and so `mink query`, ran GJK on those pairs
/// (sphere-polytope8 distance 148 ns against the typed call's 75).
template <>
struct SolidCore<PolytopeRef> : SolidCore<Polytope> {
  static const Core* core(const PolytopeRef& p) { return p.polytope->face_planes(); }
};

/// Its polytope, for the first support call of two small polytopes (query/polytope_pair.hpp).
template <>
struct PolytopeCore<PolytopeRef> : std::true_type {
  static const Polytope& of(const PolytopeRef& p) { return *p.polytope; }
};

/// A hull shape held by pointer: support climbs from the shape's shared hint.
struct HullRef {
  using Scalar = double;
  const ConvexHullShape* hull;
  [[gnu::always_inline]] Vec3 support_core(const Vec3& d) const { return hull->support_core(d); }
  Vec3 core_centre() const { return hull->core_centre(); }
  double core_radius() const { return 0; }
  double bounding_radius() const { return hull->bounding_radius(); }
  const char* error() const { return hull->error(); }
};

/// The hull's own faces for manifolds (before, a hull shape's feature was sampled from its support
/// mapping).
inline void support_feature(const HullRef& h, const Vec3& d, double tolerance,
                            SupportFeatureT<double>& out) {
  mink::support_feature(*h.hull, d, tolerance, out);
}

template <class Fn>
auto with_concrete(const Shape& shape, Fn&& fn) {
  return std::visit(
      [&](const auto& core) {
        if constexpr (std::is_same_v<std::decay_t<decltype(core)>, SharedPolytope>)
          return fn(Rounded<PolytopeRef>{PolytopeRef{core.get()}, shape.core_radius()});
        else if constexpr (std::is_same_v<std::decay_t<decltype(core)>, SharedHull>)
          return fn(Rounded<HullRef>{HullRef{core.get()}, shape.core_radius()});
        else
          return fn(Rounded<std::decay_t<decltype(core)>>{core, shape.core_radius()});
      },
      shape.cores().front());
}

/// A concrete core's place in Core (the pointer types stand for their shared ones).
template <class T>
struct SharedCoreOf {
  using type = T;
};
template <>
struct SharedCoreOf<PolytopeRef> {
  using type = SharedPolytope;
};
template <>
struct SharedCoreOf<HullRef> {
  using type = SharedHull;
};

template <class T, class... Ts>
constexpr std::size_t core_rank(const std::variant<Ts...>*) {
  constexpr bool same[] = {std::is_same_v<T, Ts>...};
  std::size_t i = 0;
  while (i < sizeof...(Ts) && !same[i]) ++i;
  return i;
}

/// R is a Rounded<concrete core>.
template <class R>
inline constexpr std::size_t kCoreRank =
    core_rank<typename SharedCoreOf<decltype(R::shape)>::type>(static_cast<const Core*>(nullptr));

/// The answer for B against A, given the answer for A against B.
inline void swap_sides(IntersectResult&) {}

template <class Result>
void swap_sides(Result& r) {
  r.normal = -r.normal;
  std::swap(r.point_a, r.point_b);
}

inline void swap_sides(ManifoldResult& r) {
  r.normal = -r.normal;
  for (int i = 0; i < r.count; ++i) std::swap(r.points[i].point_a, r.points[i].point_b);
}

/// Runs query(a, pose_a, b, pose_b) on the concrete cores, or answers an empty Shape with its
/// error (the result's status stays InvalidInput). A pair whose core types come in the
/// other order than in Core runs as (b, a) and its answer is swapped back, so that each unordered
/// pair of core types compiles once: the library's instantiations, most of its build time, fall
/// from 121 pairs per query to 66. It also makes swapping A and B flip the answer exactly when the
/// core types differ (cores of one type, and sums, run in the caller's order). A GjkCache
/// therefore holds the directions of such a pair in Core's order, whichever order the caller
/// passes.
template <class Query>
auto dispatch(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
              Query&& query) {
  if (const char* error = a.error() ? a.error() : b.error()) {
    decltype(query(a, pose_a, b, pose_b)) result;
    result.error = error;
    return result;
  }
  const bool a_single = a.cores().size() == 1, b_single = b.cores().size() == 1;
  if (a_single && b_single)
    return with_concrete(a, [&](const auto& ca) {
      return with_concrete(b, [&](const auto& cb) {
        using CA = std::decay_t<decltype(ca)>;
        using CB = std::decay_t<decltype(cb)>;
        if constexpr (kCoreRank<CA> <= kCoreRank<CB>) {
          return query(ca, pose_a, cb, pose_b);
        } else {
          auto result = query(cb, pose_b, ca, pose_a);
          swap_sides(result);
          return result;
        }
      });
    });
  return query(a, pose_a, b, pose_b);
}

/// `Work` (a typed query's work, detail::*_in_range(), as a captureless lambda) on the pair's
/// concrete cores (dispatch()).
template <class Work, class... Options>
auto work_on_cores(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                   const Options&... options) {
  return dispatch(a, pose_a, b, pose_b,
                  [&](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb) {
                    return Work{}(ca, qa, cb, qb, options...);
                  });
}

/// The whole run-time query: work_on_cores(), through the typed queries' range test
/// (query/scale_range.hpp), which solves a pair outside the range of lengths on
/// ScaledCopy<Shape> copies (Shape::scaled()) and scales the answer back. The test is on the
/// Shapes, before the dispatch, since the concrete cores of polytopes and hulls are held by
/// pointer and have no copies of their own; the typed work then runs without a second one.
template <class Work, class... Options>
auto run_query(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b, Work,
               const Options&... options) {
  return solve_in_scale_range<&work_on_cores<Work, Options...>>(a, pose_a, b, pose_b, options...);
}

}  // namespace mink::detail
