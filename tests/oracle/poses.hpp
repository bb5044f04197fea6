// Poses the hand-built test cases are written in.
#pragma once

#include "mink/math/pose.hpp"

namespace oracle {

/// A translation only.
inline mink::Pose at(double x, double y, double z) {
  return mink::Pose::from_translation(mink::Vec3(x, y, z));
}

/// A translation and a turn of `angle` radians about `axis` (any length).
inline mink::Pose rotated(const mink::Vec3& t, double angle, const mink::Vec3& axis) {
  return mink::Pose::from(t, mink::Quat(Eigen::AngleAxisd(angle, axis.normalized())));
}

}  // namespace oracle
