/// @file fuzz_input.hpp
/// Reading a fuzzer's bytes as the values a query needs, biased towards the ones that break
/// geometry code: zero, tiny, huge, negative, NaN and infinity, repeated values (duplicate points),
/// exact quarter turns.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include "mink/mink.hpp"

namespace mink::fuzz {

/// Consumes the input from the front; once it runs out, every read gives 0.
class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  /// An integer in [0, n).
  int choice(int n) { return n > 0 ? byte() % n : 0; }

  /// A length or coordinate: one byte picks a class of value, the next ones its digits.
  double value() {
    switch (byte() % 16) {
      case 0:
        return 0.0;
      case 1:
        return 1.0;
      case 2:
        return -1.0;
      case 3:
        return std::numeric_limits<double>::quiet_NaN();
      case 4:
        return std::numeric_limits<double>::infinity();
      case 5:
        return std::numeric_limits<double>::denorm_min();
      case 6:
        return 1e-300;
      case 7:
        return 1e300;
      case 8:
        return std::ldexp(1.0, choice(120) - 60);  // a power of two, 1e-18 .. 1e18
      case 9:
        return -std::ldexp(1.0, choice(120) - 60);
      case 10: {  // any bits at all
        std::uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits = bits << 8 | byte();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
      default: {  // a moderate value with 16 bits of mantissa, scaled by 1e-6 .. 1e6
        const int mantissa = byte() << 8 | byte();
        const int exponent = choice(41) - 20;
        return (mantissa / 65536.0 - 0.5) * std::ldexp(1.0, exponent);
      }
    }
  }

  /// A length (radius, half extent): usually a valid one, 1e-6 .. 1e6 or 0, sometimes any value.
  double length() {
    if (byte() % 8 == 0) return value();
    const double v = std::abs(value());
    return std::isfinite(v) && v < 1e9 ? v : 1.0;
  }

  Vec3 lengths() {
    const double x = length(), y = length(), z = length();
    return {x, y, z};
  }

  Vec3 vec3() {
    const double x = value(), y = value(), z = value();
    return {x, y, z};
  }

  /// A rotation: identity, an exact quarter turn, a normalised quaternion from the input, or a
  /// raw quaternion's matrix, which breaks the callers' contract (orthonormal rotations) unless
  /// it happens to be unit; `proper` says which. Out of contract, a query must still return and
  /// touch no memory it should not, but its numbers mean nothing.
  Mat3 rotation(bool& proper) {
    proper = true;
    switch (byte() % 4) {
      case 0:
        return Mat3::Identity();
      case 1: {
        Mat3 r = Mat3::Zero();  // a signed permutation with determinant +1
        const int k = choice(3);
        r(0, k) = 1;
        r(1, (k + 1) % 3) = 1;
        r(2, (k + 2) % 3) = 1;
        return r;
      }
      case 2: {
        // Normalised only where |q|^2 is a normal double: a quaternion of norm 1e-160 normalised
        // by Eigen comes out 1e-5 off unit (the root of a subnormal square), an improper rotation
        // that the checks would then blame on the queries.
        Quat q(value(), value(), value(), value());
        if (!(q.norm() > 1e-150 && q.norm() < 1e150)) return Mat3::Identity();
        return q.normalized().toRotationMatrix();
      }
      default: {
        const Quat q(value(), value(), value(), value());
        proper = std::abs(q.norm() - 1.0) <= 1e-12;
        return q.toRotationMatrix();
      }
    }
  }

  Pose pose(bool& proper) {
    Pose p;
    p.rotation = rotation(proper);
    p.translation = vec3();
    return p;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace mink::fuzz
