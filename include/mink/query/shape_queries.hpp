/// @file shape_queries.hpp
/// intersect(), distance() and contact() on run-time Shapes: one dispatch on the pair of core
/// types, then the same template code as the static shapes (see gjk/intersect.hpp, gjk/distance.hpp
/// and epa/contact.hpp for the conventions, which are identical).
///
/// Each pair of different core types runs in one fixed order, the order of `Core`, and the answer
/// is swapped back (normal negated, points exchanged) when the caller's order is the other one.
/// So for single-core shapes of different core types, swapping A and B flips every answer exactly,
/// and a `GjkCache` belongs to the unordered pair. Cores of one type, and sums of several cores,
/// run in the caller's order; their swapped answers agree within the error bounds.
///
/// Scale: a pair whose shapes and offset (B's origin from A's) are all shorter than 2^-120
/// (about 7.5e-37), or whose shapes are larger than 2^120, is solved as copies scaled by a power
/// of two to about unit size (Shape::scaled(), an allocation) and its answer scaled back, exactly
/// (query/scale_range.hpp; the templated queries do the same on typed shapes).
#pragma once

#include "mink/epa/contact.hpp"
#include "mink/gjk/distance.hpp"
#include "mink/gjk/intersect.hpp"
#include "mink/manifold/manifold.hpp"
#include "mink/support/shape.hpp"

namespace mink {

IntersectResult intersect(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                          const Tolerances& tolerances = {}, GjkCache* cache = nullptr);

DistanceResult distance(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const Tolerances& tolerances = {}, GjkCache* cache = nullptr);

ContactResult contact(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                      const Tolerances& tolerances = {}, GjkCache* cache = nullptr);

/// Contact manifold (manifold/manifold.hpp). Shapes that are sums of several cores have no
/// closed-form features: theirs are sampled from the support mapping.
ManifoldResult manifold(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b,
                        const ManifoldOptions& options = {});

}  // namespace mink
