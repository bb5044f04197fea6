// Run-time manifold on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

using detail::dispatch;

ManifoldResult manifold(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const ManifoldOptions& options) {
  return dispatch(a, pose_a, b, pose_b,
                  [&](const auto& ca, const Pose& pa, const auto& cb, const Pose& pb) {
                    return manifold<std::decay_t<decltype(ca)>, std::decay_t<decltype(cb)>>(
                        ca, pa, cb, pb, options);
                  });
}

}  // namespace mink
