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

/// The support point of `shape`'s core along d, in its frame: a polytope core scans by the
/// caller's pattern (SupportPattern); the other shapes have no choice to make.
template <SupportPattern P, class Shape, class S>
[[gnu::always_inline]] inline Vec3T<S> core_support(const Shape& shape, const Vec3T<S>& d) {
  if constexpr (PolytopeCore<Shape>::value)
    return PolytopeCore<Shape>::of(shape).template support_core<P>(d);
  else
    return shape.support_core(d);
}

}  // namespace mink::detail
