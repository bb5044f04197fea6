// The run-time queries on two Shapes: see shape_dispatch.hpp. All four in one translation unit:
// for every pair of core types, contact() and manifold() instantiate much of what intersect() and
// distance() do (GJK, EPA, the supports), which three files each compiled again (Release: 284 s
// of CPU against 478 s; under the sanitizers, at -O0: 150 s against 351 s).
#include "shape_dispatch.hpp"

namespace mink {

IntersectResult intersect(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                          const Tolerances& tolerances, GjkCache* cache) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, const Tolerances& t,
         GjkCache* c) { return detail::intersect_in_range(ca, qa, cb, qb, t, c); },
      tolerances, cache);
}

DistanceResult distance(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const Tolerances& tolerances, GjkCache* cache) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, const Tolerances& t,
         GjkCache* c) { return detail::distance_in_range(ca, qa, cb, qb, t, c); },
      tolerances, cache);
}

ContactResult contact(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                      const Tolerances& tolerances, GjkCache* cache) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, const Tolerances& t,
         GjkCache* c) { return detail::contact_in_range(ca, qa, cb, qb, t, c); },
      tolerances, cache);
}

ManifoldResult manifold(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const ManifoldOptions& options) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, const ManifoldOptions& o) {
        return detail::manifold_in_range(ca, qa, cb, qb, o);
      },
      options);
}

}  // namespace mink
