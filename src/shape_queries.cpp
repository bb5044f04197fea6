// Run-time intersect and distance on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

using detail::dispatch;

IntersectResult intersect(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                          const Tolerances& tolerances, GjkCache* cache) {
  return dispatch(a, pose_a, b, pose_b,
                  [&](const auto& ca, const Pose& pa, const auto& cb, const Pose& pb) {
                    return intersect<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(
                        ca, pa, cb, pb, tolerances, cache);
                  });
}

DistanceResult distance(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const Tolerances& tolerances, GjkCache* cache) {
  return dispatch(a, pose_a, b, pose_b,
                  [&](const auto& ca, const Pose& pa, const auto& cb, const Pose& pb) {
                    return distance<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(
                        ca, pa, cb, pb, tolerances, cache);
                  });
}

}  // namespace mink
