// Run-time manifold on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

ManifoldResult manifold(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const ManifoldOptions& options) {
  return detail::run_query(
      a, pose_a, b, pose_b,
      [&](const auto& ca, const Pose& qa, const auto& cb, const Pose& qb, double factor) {
        ManifoldOptions scaled_options = options;
        scaled_options.margin *= factor;
        return manifold<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(ca, qa, cb, qb,
                                                                                scaled_options);
      });
}

}  // namespace mink
