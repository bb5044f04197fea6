// Run-time contact on two Shapes: see shape_dispatch.hpp.
#include "shape_dispatch.hpp"

namespace mink {

using detail::dispatch;

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

}  // namespace mink
