/// @file scale_range.hpp
/// Pairs outside the range of lengths at which the algorithms are exact, solved scaled.
///
/// GJK's simplex tests multiply up to six lengths: in double, those products underflow for pairs
/// below about 1e-50 and overflow above about 1e51, and every tetrahedron then looks flat
/// (docs/benchmarks.md, "Stop 57"). A pair whose shapes and offset (B's origin from A's) are all
/// shorter than kSmallestLength, or whose shapes are larger than kLargestShape, is solved as copies
/// scaled by a power of two to about unit size, A at the origin, and the answer is scaled back.
/// Scaling by a power of two is exact, and flags, normals and iteration counts do not change with
/// the scale. Every query (intersect(), distance(), contact(), manifold()) does this for the
/// library's shapes, their sums and rounded versions, and the run-time Shape (its ScaledCopy is in
/// support/shape.hpp); a caller's own shape types are solved as they are unless they specialize
/// ScaledCopy.
///
/// How a typed query is laid out: the public function (solve_in_scale_range()) tests the pair's
/// ScaledCopy lengths and calls either the query's work (`detail::*_in_range()`) or
/// solve_out_of_range(), out of line, which makes the copies. Copies of boxes,
/// spheres and the other primitives are a few multiplications; a polytope or hull is copied and
/// rebuilt (an allocation), which matters in float, whose range is 2^-15 to 2^15.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "mink/gjk/gjk.hpp"
#include "mink/math/pose.hpp"
#include "mink/math/vec.hpp"
#include "mink/query/box_box.hpp"
#include "mink/query/status.hpp"
#include "mink/shapes/box.hpp"
#include "mink/shapes/capsule.hpp"
#include "mink/shapes/cone.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/shapes/hull_shape.hpp"
#include "mink/shapes/point.hpp"
#include "mink/shapes/polytope.hpp"
#include "mink/shapes/segment.hpp"
#include "mink/shapes/sphere.hpp"
#include "mink/shapes/triangle.hpp"
#include "mink/support/minkowski_sum.hpp"
#include "mink/support/rounded.hpp"

namespace mink {

/// ScaledCopy<T>::copy(shape, factor): `shape` with every length multiplied by `factor` (a power
/// of two), or nothing when the copy cannot be made. ScaledCopy<T>::length(shape): a length within
/// a factor of 2 of the shape's bounding radius, without roots (the queries test it first).
/// Specialized below for the library's shapes; a caller may specialize it for its own.
template <class T>
struct ScaledCopy {};

template <class S>
struct ScaledCopy<SphereT<S>> {
  static S length(const SphereT<S>& s) { return s.radius; }
  static std::optional<SphereT<S>> copy(const SphereT<S>& s, S f) {
    return SphereT<S>{f * s.radius};
  }
};

template <class S>
struct ScaledCopy<BoxT<S>> {
  static S length(const BoxT<S>& b) { return b.half_extents.maxCoeff(); }
  static std::optional<BoxT<S>> copy(const BoxT<S>& b, S f) {
    return BoxT<S>{Vec3T<S>(f * b.half_extents)};
  }
};

template <class S>
struct ScaledCopy<CapsuleT<S>> {
  static S length(const CapsuleT<S>& c) { return c.radius + c.half_height; }
  static std::optional<CapsuleT<S>> copy(const CapsuleT<S>& c, S f) {
    return CapsuleT<S>{f * c.radius, f * c.half_height};
  }
};

template <class S>
struct ScaledCopy<CylinderT<S>> {
  static S length(const CylinderT<S>& c) { return std::max(c.radius, c.half_height); }
  static std::optional<CylinderT<S>> copy(const CylinderT<S>& c, S f) {
    return CylinderT<S>{f * c.radius, f * c.half_height};
  }
};

template <class S>
struct ScaledCopy<ConeT<S>> {
  static S length(const ConeT<S>& c) { return std::max(c.radius, c.half_height); }
  static std::optional<ConeT<S>> copy(const ConeT<S>& c, S f) {
    return ConeT<S>{f * c.radius, f * c.half_height};
  }
};

template <class S>
struct ScaledCopy<EllipsoidT<S>> {
  static S length(const EllipsoidT<S>& e) { return e.radii.maxCoeff(); }
  static std::optional<EllipsoidT<S>> copy(const EllipsoidT<S>& e, S f) {
    return EllipsoidT<S>{Vec3T<S>(f * e.radii)};
  }
};

template <class S>
struct ScaledCopy<PointT<S>> {
  static S length(const PointT<S>& p) { return p.position.cwiseAbs().maxCoeff(); }
  static std::optional<PointT<S>> copy(const PointT<S>& p, S f) {
    return PointT<S>{Vec3T<S>(f * p.position)};
  }
};

template <class S>
struct ScaledCopy<SegmentT<S>> {
  static S length(const SegmentT<S>& s) {
    return std::max(s.a.cwiseAbs().maxCoeff(), s.b.cwiseAbs().maxCoeff());
  }
  static std::optional<SegmentT<S>> copy(const SegmentT<S>& s, S f) {
    return SegmentT<S>{Vec3T<S>(f * s.a), Vec3T<S>(f * s.b)};
  }
};

template <class S>
struct ScaledCopy<TriangleT<S>> {
  static S length(const TriangleT<S>& t) {
    return std::max(
        {t.a.cwiseAbs().maxCoeff(), t.b.cwiseAbs().maxCoeff(), t.c.cwiseAbs().maxCoeff()});
  }
  static std::optional<TriangleT<S>> copy(const TriangleT<S>& t, S f) {
    return TriangleT<S>{Vec3T<S>(f * t.a), Vec3T<S>(f * t.b), Vec3T<S>(f * t.c)};
  }
};

namespace detail {

/// A polytope's points or a hull's vertices, scaled, made into the same kind again (an allocation
/// and, for a hull, a rebuild: these pairs are rare).
template <class T, class S>
std::optional<T> scaled_point_set(const T& shape, S f) {
  std::vector<Vec3T<S>> points(shape.size());
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = f * shape.point(i);
  auto made = T::make(points);
  if (!made) return std::nullopt;
  return std::move(made).value();
}

}  // namespace detail

template <class S>
struct ScaledCopy<PolytopeT<S>> {
  static S length(const PolytopeT<S>& p) { return p.bounding_radius(); }
  static std::optional<PolytopeT<S>> copy(const PolytopeT<S>& p, S f) {
    return detail::scaled_point_set(p, f);
  }
};

template <class S>
struct ScaledCopy<ConvexHullShapeT<S>> {
  static S length(const ConvexHullShapeT<S>& h) { return h.bounding_radius(); }
  static std::optional<ConvexHullShapeT<S>> copy(const ConvexHullShapeT<S>& h, S f) {
    return detail::scaled_point_set(h, f);
  }
};

/// Shapes that ScaledCopy can measure and copy.
template <class T>
concept ScalableShape = requires(const T& t, typename T::Scalar f) {
  { ScaledCopy<T>::copy(t, f) } -> std::same_as<std::optional<T>>;
  { ScaledCopy<T>::length(t) } -> std::same_as<typename T::Scalar>;
};

template <ScalableShape T>
struct ScaledCopy<Rounded<T>> {
  using S = typename T::Scalar;
  static S length(const Rounded<T>& r) { return ScaledCopy<T>::length(r.shape) + r.margin; }
  static std::optional<Rounded<T>> copy(const Rounded<T>& r, S f) {
    auto shape = ScaledCopy<T>::copy(r.shape, f);
    if (!shape) return std::nullopt;
    return Rounded<T>{std::move(*shape), f * r.margin};
  }
};

template <ScalableShape A, ScalableShape B>
struct ScaledCopy<MinkowskiSum<A, B>> {
  using S = typename A::Scalar;
  static S length(const MinkowskiSum<A, B>& m) {
    return ScaledCopy<A>::length(m.a) + ScaledCopy<B>::length(m.b);
  }
  static std::optional<MinkowskiSum<A, B>> copy(const MinkowskiSum<A, B>& m, S f) {
    auto a = ScaledCopy<A>::copy(m.a, f);
    auto b = ScaledCopy<B>::copy(m.b, f);
    if (!a || !b) return std::nullopt;
    return MinkowskiSum<A, B>{std::move(*a), std::move(*b)};
  }
};

namespace detail {

/// Lengths at which the algorithms are exact: 2^-120 to 2^120 in double, a wide margin inside
/// 1e-50 and 1e51; 2^-15 to 2^15 in float, whose six-fold products leave its range outside about
/// 2^-21 and 2^21.
template <class S>
inline constexpr int kRangeExponent = std::numeric_limits<S>::max_exponent * 15 / 128;
template <class S>
inline constexpr S kSmallestLength = power_of_two<S>(-kRangeExponent<S>);
template <class S>
inline constexpr S kLargestShape = power_of_two<S>(kRangeExponent<S>);

/// out_of_range_exponent()'s answer outside the range, out of line: such pairs are rare.
template <class S>
[[gnu::noinline]] std::optional<int> exponent_out_of_range(S size, S offset) {
  if (!std::isfinite(size) || !std::isfinite(offset)) return std::nullopt;  // the queries report it
  const S largest = std::max(size, offset);
  // At least min_exponent + 1: 2^1074, which a subnormal length would ask for, overflows.
  if (largest > S(0) && largest < kSmallestLength<S>)
    return std::max(std::ilogb(largest), std::numeric_limits<S>::min_exponent + 1);
  if (size > kLargestShape<S>) return std::ilogb(size);
  return std::nullopt;
}

/// For a pair outside the range, the e for which the pair scaled by 2^-e has its lengths near 1:
/// its shapes (bounding radii bound_a, bound_b) and B's offset from A all below kSmallestLength,
/// or its shapes larger than kLargestShape. Nothing otherwise. A tiny pair far apart, or a huge
/// one close by, is no better scaled: its ratio of sizes stays. Two compares on the common path.
template <class S>
[[gnu::always_inline]] inline std::optional<int> out_of_range_exponent(S bound_a, S bound_b,
                                                                       const PoseT<S>& pose_a,
                                                                       const PoseT<S>& pose_b) {
  const S size = std::max(bound_a, bound_b);
  const S offset = (pose_b.translation - pose_a.translation).cwiseAbs().maxCoeff();
  if (std::max(size, offset) >= kSmallestLength<S> && size <= kLargestShape<S>) [[likely]]
    return std::nullopt;
  return exponent_out_of_range(size, offset);
}

/// An answer's pair of points, computed scaled about A's origin, in the world.
template <class Result, class S>
void points_back(Result& r, S back, const Vec3T<S>& origin) {
  r.point_a = back * r.point_a + origin;
  r.point_b = back * r.point_b + origin;
}

/// Lengths of an answer computed scaled, multiplied by `back` (a power of two, exact), and its
/// points shifted from A's origin to the world. By the fields the result has: a boolean answer
/// has none; distance() fills its points only for separated shapes; contact() and manifold()
/// always (InvalidInput aside, where nothing was computed).
template <class Result, class S>
void scale_back(Result& r, S back, const Vec3T<S>& origin) {
  if constexpr (requires { r.distance; }) {
    r.distance *= back;
    r.error_bound *= back;
  }
  if constexpr (requires { r.count; }) {
    r.depth *= back;
    for (int i = 0; i < r.count; ++i) {
      points_back(r.points[i], back, origin);
      r.points[i].depth *= back;
    }
  } else if constexpr (requires { r.depth; }) {
    r.depth *= back;
    if (r.status != Status::InvalidInput) points_back(r, back, origin);
  } else if constexpr (requires { r.point_a; }) {
    if (r.status != Status::InvalidInput && !r.intersect) points_back(r, back, origin);
  }
}

/// Runs `solve(a', pose_a', b', pose_b', factor)` on a and b scaled by factor = 2^-exponent
/// about A's origin (a', b' from `copy`) and scales its answer back. Nothing when a copy cannot
/// be made (the caller then solves the pair as it is). Out of line: the queries' common path
/// only tests the range.
template <class A, class B, class Copy, class Solve>
[[gnu::noinline]] auto solve_scaled(int exponent, const A& a,
                                    const PoseT<typename A::Scalar>& pose_a, const B& b,
                                    const PoseT<typename A::Scalar>& pose_b, Copy&& copy,
                                    Solve&& solve)
    -> std::optional<decltype(solve(*copy(a, typename A::Scalar(1)), pose_a,
                                    *copy(b, typename A::Scalar(1)), pose_b,
                                    typename A::Scalar(1)))> {
  using S = typename A::Scalar;
  const S factor = std::ldexp(S(1), -exponent);
  auto scaled_a = copy(a, factor);
  auto scaled_b = copy(b, factor);
  if (!scaled_a || !scaled_b) return std::nullopt;
  const PoseT<S> at_a{pose_a.rotation, Vec3T<S>::Zero()};
  const PoseT<S> at_b{pose_b.rotation,
                      Vec3T<S>(factor * (pose_b.translation - pose_a.translation))};
  auto result = solve(*scaled_a, at_a, *scaled_b, at_b, factor);
  scale_back(result, std::ldexp(S(1), exponent), pose_a.translation);
  return result;
}

/// Both shapes have a ScaledCopy.
template <class A, class B>
inline constexpr bool kScalablePair = ScalableShape<A>&& ScalableShape<B>;

/// ScaledCopy as a function object, for solve_scaled().
struct CopyScaled {
  template <class T, class S>
  std::optional<T> operator()(const T& shape, S factor) const {
    return ScaledCopy<T>::copy(shape, factor);
  }
};

/// The typed queries' first test for a kScalablePair, on ScaledCopy's lengths: no root, no
/// offset, two compares. Fails for pairs outside the range, shapes of size 0 and lengths that are
/// not finite, which solve_out_of_range() then sorts out.
template <class A, class B>
[[gnu::always_inline]] inline bool in_scale_range(const A& a, const B& b) {
  using S = typename A::Scalar;
  const S size = std::max(ScaledCopy<A>::length(a), ScaledCopy<B>::length(b));
  return size >= kSmallestLength<S> && size <= kLargestShape<S>;
}

/// A query's options for the pair scaled by `factor`: unchanged, unless they hold lengths
/// (manifold.hpp specializes it for the margin).
template <class Options>
struct OptionsAtScale {
  template <class S>
  static const Options& scaled(const Options& options, S) {
    return options;
  }
};

/// For the pairs that in_scale_range() turns away, out of line: `Work` (the query's work, without
/// the range test) on the pair scaled into the range when it is valid and out of it
/// (out_of_range_exponent(), on the bounding radii and B's offset), its answer scaled back; else
/// on the pair as it is, which reports invalid input.
template <auto Work, class A, class B, class... Options>
[[gnu::noinline, gnu::cold]] auto solve_out_of_range(const A& a,
                                                     const PoseT<typename A::Scalar>& pose_a,
                                                     const B& b,
                                                     const PoseT<typename A::Scalar>& pose_b,
                                                     const Options&... options) {
  using S = typename A::Scalar;
  // Invalid input as it is: scaled, a negative length of 1e-148 beside one of 1e300 rounds to
  // -0, which is valid.
  if (query_input_error(a, pose_a, b, pose_b)) return Work(a, pose_a, b, pose_b, options...);
  S bound_a, bound_b;
  bounding_radii(a, b, bound_a, bound_b);
  if (const std::optional<int> exponent = out_of_range_exponent(bound_a, bound_b, pose_a, pose_b)) {
    auto solve = [&](const A& sa, const PoseT<S>& pa, const B& sb, const PoseT<S>& pb, S factor) {
      return Work(sa, pa, sb, pb, OptionsAtScale<Options>::scaled(options, factor)...);
    };
    if (auto scaled = solve_scaled(*exponent, a, pose_a, b, pose_b, CopyScaled{}, solve))
      return std::move(*scaled);
  }
  return Work(a, pose_a, b, pose_b, options...);
}

/// Every typed query: `Work` (the query's work, a separate function) on a pair within the range,
/// else solve_out_of_range(). The work stays out of line (manifold's, a few checks and a call,
/// aside): a cold call beside it made the common path keep its arguments in saved registers, up
/// to 9 ns of an 18 ns query in spills.
template <auto Work, class A, class B, class... Options>
[[gnu::always_inline]] inline auto solve_in_scale_range(const A& a,
                                                        const PoseT<typename A::Scalar>& pose_a,
                                                        const B& b,
                                                        const PoseT<typename A::Scalar>& pose_b,
                                                        const Options&... options) {
  if constexpr (kScalablePair<A, B>) {
    if (!in_scale_range(a, b)) [[unlikely]]
      return solve_out_of_range<Work>(a, pose_a, b, pose_b, options...);
  }
  return Work(a, pose_a, b, pose_b, options...);
}

}  // namespace detail
}  // namespace mink
