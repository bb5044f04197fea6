// Run-time dispatch of the queries: a single-core Shape becomes its concrete core type with the
// radius attached, so GJK inlines the support mapping; sums of several cores use Shape itself.
#include "mink/query/shape_queries.hpp"

#include "mink/support/rounded.hpp"

namespace mink {

namespace {

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
void support_feature(const PolytopeRef& p, const Vec3& d, double tolerance,
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

}  // namespace

IntersectResult intersect(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                          const Tolerances& tolerances, GjkCache* cache) {
  if (a.error() || b.error()) {
    IntersectResult r;
    r.error = a.error() ? a.error() : b.error();
    return r;
  }
  return dispatch(a, b, [&](const auto& ca, const auto& cb) {
    return intersect<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(ca, pose_a, cb, pose_b,
                                                                             tolerances, cache);
  });
}

DistanceResult distance(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const Tolerances& tolerances, GjkCache* cache) {
  if (a.error() || b.error()) {
    DistanceResult r;
    r.error = a.error() ? a.error() : b.error();
    return r;
  }
  return dispatch(a, b, [&](const auto& ca, const auto& cb) {
    return distance<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(ca, pose_a, cb, pose_b,
                                                                            tolerances, cache);
  });
}

ContactResult contact(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                      const Tolerances& tolerances, GjkCache* cache) {
  if (a.error() || b.error()) {
    ContactResult r;
    r.error = a.error() ? a.error() : b.error();
    return r;
  }
  return dispatch(a, b, [&](const auto& ca, const auto& cb) {
    return contact<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(ca, pose_a, cb, pose_b,
                                                                           tolerances, cache);
  });
}

ManifoldResult manifold(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const ManifoldOptions& options) {
  if (a.error() || b.error()) {
    ManifoldResult r;
    r.error = a.error() ? a.error() : b.error();
    return r;
  }
  return dispatch(a, b, [&](const auto& ca, const auto& cb) {
    return manifold<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(ca, pose_a, cb, pose_b,
                                                                            options);
  });
}

}  // namespace mink
