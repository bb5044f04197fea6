// Run-time dispatch shared by the query files (src/shape_*.cpp): a single-core Shape becomes its
// concrete core type with the radius attached, so the algorithms inline the support mapping; sums
// of several cores use Shape itself. Each query lives in its own file so that the instantiations
// over every pair of core types compile in parallel.
#pragma once

#include "mink/query/shape_queries.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// A polytope held by pointer, so dispatch copies no points.
struct PolytopeRef {
  using Scalar = double;
  const Polytope* polytope;
  Vec3 support_core(const Vec3& d) const { return polytope->support_core(d); }
  double core_radius() const { return 0; }
  double bounding_radius() const { return polytope->bounding_radius(); }
  const char* error() const { return polytope->error(); }
};

/// The polytope's own faces for manifolds (found by argument-dependent lookup).
inline void support_feature(const PolytopeRef& p, const Vec3& d, double tolerance,
                            SupportFeatureT<double>& out) {
  mink::support_feature(*p.polytope, d, tolerance, out);
}

/// A hull shape held by pointer: support climbs from the shape's shared hint.
struct HullRef {
  using Scalar = double;
  const ConvexHullShape* hull;
  Vec3 support_core(const Vec3& d) const { return hull->support_core(d); }
  double core_radius() const { return 0; }
  double bounding_radius() const { return hull->bounding_radius(); }
  const char* error() const { return hull->error(); }
};

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

template <class Query>
auto dispatch(const Shape& a, const Shape& b, Query&& query) {
  const bool a_single = a.cores().size() == 1, b_single = b.cores().size() == 1;
  if (a_single && b_single)
    return with_concrete(a, [&](const auto& ca) {
      return with_concrete(b, [&](const auto& cb) { return query(ca, cb); });
    });
  return query(a, b);
}

}  // namespace mink::detail
