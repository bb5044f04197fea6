/// @file vec.hpp
/// Vector and matrix aliases over Eigen, templated on the scalar type (double by default).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace mink {

template <class S>
using Vec3T = Eigen::Matrix<S, 3, 1>;
template <class S>
using Mat3T = Eigen::Matrix<S, 3, 3>;
template <class S>
using QuatT = Eigen::Quaternion<S>;

using Vec3 = Vec3T<double>;
using Mat3 = Mat3T<double>;
using Quat = QuatT<double>;

/// True when every component is finite (neither NaN nor infinite).
template <class S>
inline bool is_finite(const Vec3T<S>& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

}  // namespace mink
