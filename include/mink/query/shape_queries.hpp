/// @file shape_queries.hpp
/// intersect(), distance() and contact() on run-time Shapes: one dispatch on the pair of core
/// types, then the same template code as the static shapes (see gjk/intersect.hpp, gjk/distance.hpp
/// and epa/contact.hpp for the conventions, which are identical).
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
