// Run-time contact on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

ContactResult contact(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                      const Tolerances& tolerances, GjkCache* cache) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, const Tolerances& t,
         GjkCache* c) { return detail::contact_in_range(ca, qa, cb, qb, t, c); },
      tolerances, cache);
}

}  // namespace mink
