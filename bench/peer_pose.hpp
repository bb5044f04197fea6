// mink's poses as Bullet's and FCL's transforms, for the benchmarks that call those libraries
// directly (coaxial_bench, curved_bench, manifold_bench); bench/peers/ converts in its adapters.
#pragma once

#include <LinearMath/btTransform.h>
#include <fcl/common/types.h>

#include "mink/math/pose.hpp"

namespace mink_bench {

inline btTransform bullet_pose(const mink::Pose& p) {
  const auto& r = p.rotation;
  return btTransform(
      btMatrix3x3(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)),
      btVector3(p.translation.x(), p.translation.y(), p.translation.z()));
}

inline fcl::Transform3d fcl_pose(const mink::Pose& p) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = p.rotation;
  t.translation() = p.translation;
  return t;
}

}  // namespace mink_bench
