/// @file shape_lengths.hpp
/// The lengths a shape is made of (radii, half extents, half heights, margins), for the shapes
/// made of lengths alone: each must be finite and >= 0, and the typed queries check them together
/// with the poses in one sum and one minimum (gjk.hpp, query_input_error()) instead of shape by
/// shape and length by length.
#pragma once

#include "mink/shapes/box.hpp"
#include "mink/shapes/capsule.hpp"
#include "mink/shapes/cone.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/shapes/sphere.hpp"
#include "mink/support/rounded.hpp"

namespace mink::detail {

/// kCount lengths of a shape and `of()`, an array of them; kCount 0 for shapes that are not made
/// of lengths alone (points, segments, triangles, polytopes, hulls, sums), which error() checks.
template <class T>
struct ShapeLengths {
  static constexpr int kCount = 0;
};

template <class S>
struct ShapeLengths<SphereT<S>> {
  static constexpr int kCount = 1;
  static Eigen::Array<S, 1, 1> of(const SphereT<S>& s) { return Eigen::Array<S, 1, 1>(s.radius); }
};

template <class S>
struct ShapeLengths<BoxT<S>> {
  static constexpr int kCount = 3;
  static Eigen::Array<S, 3, 1> of(const BoxT<S>& b) { return b.half_extents.array(); }
};

template <class S>
struct ShapeLengths<EllipsoidT<S>> {
  static constexpr int kCount = 3;
  static Eigen::Array<S, 3, 1> of(const EllipsoidT<S>& e) { return e.radii.array(); }
};

/// Capsules, cylinders and cones: a radius and a half height.
template <class T>
struct RadiusHeightLengths {
  using S = typename T::Scalar;
  static constexpr int kCount = 2;
  static Eigen::Array<S, 2, 1> of(const T& t) { return {t.radius, t.half_height}; }
};
template <class S>
struct ShapeLengths<CapsuleT<S>> : RadiusHeightLengths<CapsuleT<S>> {};
template <class S>
struct ShapeLengths<CylinderT<S>> : RadiusHeightLengths<CylinderT<S>> {};
template <class S>
struct ShapeLengths<ConeT<S>> : RadiusHeightLengths<ConeT<S>> {};

/// A rounded shape made of lengths: the shape's, then the margin.
template <class T>
requires(ShapeLengths<T>::kCount > 0) struct ShapeLengths<Rounded<T>> {
  using S = typename T::Scalar;
  static constexpr int kCount = ShapeLengths<T>::kCount + 1;
  static Eigen::Array<S, kCount, 1> of(const Rounded<T>& r) {
    Eigen::Array<S, kCount, 1> lengths;
    lengths << ShapeLengths<T>::of(r.shape), r.margin;
    return lengths;
  }
};

/// Both shapes are made of lengths alone.
template <class A, class B>
inline constexpr bool kLengthPair = ShapeLengths<A>::kCount > 0 && ShapeLengths<B>::kCount > 0;

}  // namespace mink::detail
