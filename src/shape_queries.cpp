// Run-time intersect and distance on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

IntersectResult intersect(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                          const Tolerances& tolerances, GjkCache* cache) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [&](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, double) {
        return intersect<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(ca, qa, cb, qb,
                                                                                 tolerances, cache);
      });
}

DistanceResult distance(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const Tolerances& tolerances, GjkCache* cache) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [&](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, double) {
        return distance<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(ca, qa, cb, qb,
                                                                                tolerances, cache);
      });
}

}  // namespace mink
