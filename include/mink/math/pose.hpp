/// @file pose.hpp
/// Rigid motion from a shape's local frame to the world frame: world = rotation * local +
/// translation.
#pragma once

#include <cmath>

#include "mink/math/vec.hpp"

namespace mink {

/// A rigid pose. The rotation is stored as a matrix because queries rotate many directions and
/// points per call (9 multiply-adds each, against about 15 for a quaternion).
template <class S>
struct PoseT {
  Mat3T<S> rotation = Mat3T<S>::Identity();  ///< orthonormal, determinant +1
  Vec3T<S> translation = Vec3T<S>::Zero();   ///< (unit: length)

  static PoseT identity() { return {}; }

  /// Pose from a translation and a unit quaternion. The quaternion must be unit to within
  /// kQuaternionNormTolerance; validate it with quaternion_error() first when it comes from a user.
  static PoseT from(const Vec3T<S>& t, const QuatT<S>& q) {
    PoseT p;
    p.rotation = q.normalized().toRotationMatrix();
    p.translation = t;
    return p;
  }
  static PoseT from_translation(const Vec3T<S>& t) {
    PoseT p;
    p.translation = t;
    return p;
  }

  // Written out coefficient by coefficient, in the order of Eigen's own product ((r_i0 x_0 +
  // r_i1 x_1) + r_i2 x_2, so the results are the same to the bit) and always inlined: GCC left
  // Eigen's product expression out of line, and the expression objects it built on the stack for
  // the call stalled on store forwarding when copied (a few percent of the box pair queries).
  [[gnu::always_inline]] inline Vec3T<S> apply(const Vec3T<S>& local) const {
    return rotate(local) + translation;
  }
  [[gnu::always_inline]] inline Vec3T<S> rotate(const Vec3T<S>& local) const {
    const Mat3T<S>& r = rotation;
    const S x = local[0], y = local[1], z = local[2];
    return Vec3T<S>(r(0, 0) * x + r(0, 1) * y + r(0, 2) * z,
                    r(1, 0) * x + r(1, 1) * y + r(1, 2) * z,
                    r(2, 0) * x + r(2, 1) * y + r(2, 2) * z);
  }
  [[gnu::always_inline]] inline Vec3T<S> inverse_rotate(const Vec3T<S>& world) const {
    const Mat3T<S>& r = rotation;
    const S x = world[0], y = world[1], z = world[2];
    return Vec3T<S>(r(0, 0) * x + r(1, 0) * y + r(2, 0) * z,
                    r(0, 1) * x + r(1, 1) * y + r(2, 1) * z,
                    r(0, 2) * x + r(1, 2) * y + r(2, 2) * z);
  }
  [[gnu::always_inline]] inline Vec3T<S> inverse_apply(const Vec3T<S>& world) const {
    return inverse_rotate(Vec3T<S>(world - translation));
  }

  /// The pose of `other` expressed in this pose's frame: this^-1 * other. Always inlined: it is
  /// the set-up of every query, and out of line it costs as much as a one-iteration GJK.
  [[gnu::always_inline]] inline PoseT relative(const PoseT& other) const {
    PoseT r;
    relative(other, r.rotation, r.translation);
    return r;
  }
  /// The same into `rotation_out` and `translation_out`, for a caller that keeps them in a struct
  /// of its own: copied there from a PoseT, the matrix was read in other pieces than it had been
  /// written in, and the reads stalled on store forwarding (two stalls in every GJK query's
  /// set-up).
  [[gnu::always_inline]] inline void relative(const PoseT& other, Mat3T<S>& rotation_out,
                                              Vec3T<S>& translation_out) const {
    translation_out = relative_translation(other);
    relative_rotation(other, rotation_out);
  }
  /// The rotation of relative() alone, into `rotation_out`: for the boolean test of two small
  /// polytopes, which forms it only for a pair its first support values leave undecided.
  [[gnu::always_inline]] inline void relative_rotation(const PoseT& other,
                                                       Mat3T<S>& rotation_out) const {
    // Column by column as combinations of this rotation's rows, r.col(j) = sum_k row_k^T b_jk:
    // three vector multiply-adds a column, where dot products of columns need a horizontal sum
    // each (Eigen's 3x3 product expression itself is not inlined by GCC here, and the call costs
    // more than the arithmetic). 20-25 instructions fewer a query.
    const Vec3T<S> row0 = rotation.row(0).transpose(), row1 = rotation.row(1).transpose(),
                   row2 = rotation.row(2).transpose();
    for (int j = 0; j < 3; ++j) {
      const Vec3T<S> b = other.rotation.col(j);
      rotation_out.col(j) = row0 * b[0] + row1 * b[1] + row2 * b[2];
    }
  }
  /// The translation of relative() alone: `other`'s origin in this frame. The same combination
  /// of rows; written with the rows as expressions, Clang made it three dot products with
  /// horizontal sums (the boxes' boolean test 4 % slower, stop 100).
  [[gnu::always_inline]] inline Vec3T<S> relative_translation(const PoseT& other) const {
    const Vec3T<S> offset = other.translation - translation;
    const Vec3T<S> row0 = rotation.row(0).transpose(), row1 = rotation.row(1).transpose(),
                   row2 = rotation.row(2).transpose();
    return row0 * offset[0] + row1 * offset[1] + row2 * offset[2];
  }
};

using Pose = PoseT<double>;

/// A quaternion whose norm is off by more than this is rejected rather than silently normalised
/// (unit: dimensionless).
inline constexpr double kQuaternionNormTolerance = 1e-6;

/// Reason a pose is unusable, or nullptr when it is valid: finite translation and an orthonormal,
/// right-handed rotation (to 1e-6).
template <class S>
const char* pose_error(const PoseT<S>& pose) {
  if (!is_finite(pose.translation)) return "pose translation is not finite";
  if (!pose.rotation.allFinite()) return "pose rotation is not finite";
  const Mat3T<S> rtr = pose.rotation.transpose() * pose.rotation;
  if ((rtr - Mat3T<S>::Identity()).norm() > S(1e-6)) return "pose rotation is not orthonormal";
  if (pose.rotation.determinant() < S(0)) return "pose rotation is a reflection";
  return nullptr;
}

/// Reason a quaternion is unusable as a rotation, or nullptr.
template <class S>
const char* quaternion_error(const QuatT<S>& q) {
  if (!std::isfinite(q.w()) || !std::isfinite(q.x()) || !std::isfinite(q.y()) ||
      !std::isfinite(q.z()))
    return "quaternion is not finite";
  if (std::abs(q.norm() - S(1)) > S(kQuaternionNormTolerance))
    return "quaternion is not unit length (norm off by more than 1e-6)";
  return nullptr;
}

}  // namespace mink
