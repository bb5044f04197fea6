/// @file polytope_core.hpp
/// Which cores are a point set's polytope, and that polytope: for the code that reads its points
/// rather than calling its support mapping (query/polytope_pair.hpp, gjk.hpp's FramedPointsT).
#pragma once

#include <type_traits>

#include "mink/shapes/polytope.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// The polytope of a core that is one: PolytopeT and Rounded<PolytopeT> here, the run-time Shape's
/// PolytopeRef in src/shape_dispatch.hpp.
template <class T>
struct PolytopeCore : std::false_type {};
template <class S>
struct PolytopeCore<PolytopeT<S>> : std::true_type {
  static const PolytopeT<S>& of(const PolytopeT<S>& p) { return p; }
};
template <class T>
requires(PolytopeCore<T>::value) struct PolytopeCore<Rounded<T>> : std::true_type {
  static const auto& of(const Rounded<T>& r) { return PolytopeCore<T>::of(r.shape); }
};

}  // namespace mink::detail
