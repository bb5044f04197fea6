/// @file expected.hpp
/// A value or the reason there is none: how constructors of shapes report bad input without
/// exceptions (std::expected is C++23; mink targets C++20).
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace mink {

template <class T>
class Expected {
 public:
  Expected(T value)
      : value_(std::move(value)) {}  // NOLINT: implicit on purpose, like std::expected
  static Expected failure(std::string reason) {
    Expected e;
    e.error_ = std::move(reason);
    return e;
  }

  bool has_value() const { return value_.has_value(); }
  explicit operator bool() const { return has_value(); }
  /// The value; only call when has_value().
  const T& value() const& { return *value_; }
  T&& value() && { return std::move(*value_); }
  const T& operator*() const& { return *value_; }
  const T* operator->() const { return &*value_; }
  /// Why there is no value; empty when there is one.
  const std::string& error() const { return error_; }

 private:
  Expected() = default;
  std::optional<T> value_;
  std::string error_;
};

}  // namespace mink
