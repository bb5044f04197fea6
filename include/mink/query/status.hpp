/// @file status.hpp
/// The status every query reports, and which outputs it makes valid.
#pragma once

namespace mink {

enum class Status {
  Separated,       ///< the shapes are apart: distance, normal and witness points are valid
  Intersecting,    ///< the shapes share a point (touching within tolerance counts): distance is 0;
                   ///< normal and points are valid only where the query says so
  IterationLimit,  ///< the iteration cap was hit: the outputs are the best estimate so far and
                   ///< `error_bound` bounds the distance error
  InvalidInput,    ///< a shape or pose is invalid (NaN, infinite, negative radius, ...): nothing
                   ///< was computed and `error` says why
};

/// Lower-case name of a status as the JSON protocol writes it ("separated", ...).
constexpr const char* to_string(Status status) {
  switch (status) {
    case Status::Separated:
      return "separated";
    case Status::Intersecting:
      return "intersecting";
    case Status::IterationLimit:
      return "iteration_limit";
    case Status::InvalidInput:
      return "invalid_input";
  }
  return "unknown";
}

}  // namespace mink
