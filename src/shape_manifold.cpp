// Run-time manifold on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

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
