/// @file core_terms.hpp
/// A property of primitive cores asked of a core built from them: a Rounded<T>'s core is T's, and a
/// MinkowskiSum's or a run-time Shape's is the sum of its terms. every_term() holds when each term
/// has the property, any_term() when one has. The property is a trait on primitives,
/// `Property<T>::value` (gjk/corner_solid.hpp's CornerCore, gjk/separation.hpp's
/// NewtonHandOffCore).
#pragma once

#include <type_traits>

#include "mink/support/minkowski_sum.hpp"
#include "mink/support/rounded.hpp"
#include "mink/support/shape.hpp"

namespace mink::detail {

template <template <class> class Property, class T>
struct EveryTerm : std::bool_constant<Property<T>::value> {};
template <template <class> class Property, class T>
struct EveryTerm<Property, Rounded<T>> : EveryTerm<Property, T> {};
template <template <class> class Property, class X, class Y>
struct EveryTerm<Property, MinkowskiSum<X, Y>>
    : std::bool_constant<EveryTerm<Property, X>::value && EveryTerm<Property, Y>::value> {};

template <template <class> class Property, class T>
struct AnyTerm : std::bool_constant<Property<T>::value> {};
template <template <class> class Property, class T>
struct AnyTerm<Property, Rounded<T>> : AnyTerm<Property, T> {};
template <template <class> class Property, class X, class Y>
struct AnyTerm<Property, MinkowskiSum<X, Y>>
    : std::bool_constant<AnyTerm<Property, X>::value || AnyTerm<Property, Y>::value> {};

/// Whether every term of `core` has the property; a run-time Shape asks each of its terms.
template <template <class> class Property, ConvexShape T>
bool every_term(const T& core) {
  if constexpr (std::is_same_v<T, Shape>) {
    for (const Core& term : core.cores())
      if (!visit_core(term, [](const auto& c) {
            return EveryTerm<Property, std::decay_t<decltype(c)>>::value;
          }))
        return false;
    return true;
  } else {
    return EveryTerm<Property, T>::value;
  }
}

/// Whether some term of `core` has the property; a run-time Shape asks each of its terms.
template <template <class> class Property, ConvexShape T>
bool any_term(const T& core) {
  if constexpr (std::is_same_v<T, Shape>) {
    for (const Core& term : core.cores())
      if (visit_core(term, [](const auto& c) {
            return AnyTerm<Property, std::decay_t<decltype(c)>>::value;
          }))
        return true;
    return false;
  } else {
    return AnyTerm<Property, T>::value;
  }
}

}  // namespace mink::detail
