// Independent reference answers in long double, written for the benchmark (no library code).
//   Separated pairs, distance: analytic segment-segment for capsules, point-to-hull for a sphere
//   against a polytope, and a brute force over hull feature pairs (vertex-triangle both ways,
//   edge-edge) for boxes and polytopes.
//   Overlapping pairs, penetration depth: the minimum over unit n of h_A(n) + h_B(-n) (h the
//   support function), taken over a candidate set of normals that provably contains the minimiser
//   (see reference.cpp).
// Plus the measuring tools for a library's contact answer: support values and a point's excess
// over a shape, all in long double.
#pragma once

#include "cases.hpp"

namespace mink_bench {

using Vec3L = Eigen::Matrix<long double, 3, 1>;

/// Distance between the shapes of pair i of `c`, which must be separated.
long double reference_distance(const Case& c, std::size_t i);

/// Penetration depth of pair i of `c`, which must overlap: the length of the shortest translation
/// of B that separates the shapes.
long double reference_depth(const Case& c, std::size_t i);

/// max over x in the shape of side A (side_b false) or B (true) of pair i of n.x, world frame.
long double support_value(const Case& c, std::size_t i, bool side_b, const Vec3L& n);

/// h_A(n) + h_B(-n) for the unit vector along `normal`: how far B must move along it to separate
/// the shapes (negative: the gap the shapes have along it). Every unit n gives at least the
/// penetration depth (at least minus the distance when separated); the best normal attains it.
long double separation_along(const Case& c, std::size_t i, const Eigen::Vector3d& normal);

/// How far world point p lies outside the shape of side A or B of pair i (<= 0: inside). For
/// boxes and polytopes the largest signed distance to a face plane, which is 0 exactly on the
/// boundary and a lower bound on the distance outside.
long double outside(const Case& c, std::size_t i, bool side_b, const Eigen::Vector3d& p);

}  // namespace mink_bench
