// Run-time manifold on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

using detail::dispatch;
using detail::solve_in_range;

ManifoldResult manifold(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const ManifoldOptions& options) {
  return solve_in_range(
      a, pose_a, b, pose_b,
      [&](const Shape& sa, const Pose& pa, const Shape& sb, const Pose& pb, double factor) {
        ManifoldOptions scaled_options = options;
        scaled_options.margin *= factor;
        return dispatch(sa, pa, sb, pb,
                        [&](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb) {
                          return manifold<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(
                              ca, qa, cb, qb, scaled_options);
                        });
      });
}

}  // namespace mink
