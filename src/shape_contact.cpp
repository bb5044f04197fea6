// Run-time contact on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

using detail::dispatch;
using detail::solve_in_range;

ContactResult contact(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                      const Tolerances& tolerances, GjkCache* cache) {
  return solve_in_range(
      a, pose_a, b, pose_b,
      [&](const Shape& sa, const Pose& pa, const Shape& sb, const Pose& pb, double) {
        return dispatch(sa, pa, sb, pb,
                        [&](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb) {
                          return contact<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(
                              ca, qa, cb, qb, tolerances, cache);
                        });
      });
}

}  // namespace mink
