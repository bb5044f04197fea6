/// @file orthogonal.hpp
/// Directions orthogonal to others, computed so that rounding does not tilt them.
#pragma once

#include <cmath>
#include <limits>

#include "mink/math/vec.hpp"

namespace mink::detail {

/// A direction orthogonal to e (not normalised; zero only when e is): e crossed with the axis
/// it is least along.
template <class S>
Vec3T<S> orthogonal(const Vec3T<S>& e) {
  const Vec3T<S> abs = e.cwiseAbs();
  const Vec3T<S> axis = abs.x() <= abs.y() && abs.x() <= abs.z()
                            ? Vec3T<S>::UnitX()
                            : (abs.y() <= abs.z() ? Vec3T<S>::UnitY() : Vec3T<S>::UnitZ());
  return e.cross(axis);
}

/// Unit vectors u, v with (u, v, n) right-handed and orthonormal, for a unit n.
template <class S>
void plane_basis(const Vec3T<S>& n, Vec3T<S>& u, Vec3T<S>& v) {
  u = std::abs(n.x()) > std::abs(n.z()) ? Vec3T<S>(-n.y(), n.x(), S(0))
                                        : Vec3T<S>(S(0), -n.z(), n.y());
  u.normalize();
  v = n.cross(u);
}

/// Makes n a unit vector exactly orthogonal to the directions e1 and e2 (a zero one is no
/// constraint), on n's side. Used where n is known to be orthogonal to them but carries rounding
/// along them: the difference of two closest points some L from the origin that are only
/// 1e-12 L apart, whose tilt along a segment or face costs that feature's extent in depth.
///   - e1 and e2 1e-4 rad or more from parallel: n is along e1 x e2, its side n's.
///   - else each is projected out in turn; passing the same direction twice projects it out
///     twice, which removes what the first projection leaves (eps |n . e| / |n - (n . e) e|, large
///     when n is nearly along e).
/// Returns false, leaving n as it was, when less than 1e-3 of n is left: n was along them to
/// within rounding, and the projection would be rounding only.
template <class S>
bool make_orthogonal(Vec3T<S>& n, const Vec3T<S>& e1, const Vec3T<S>& e2) {
  const S ee1 = e1.squaredNorm(), ee2 = e2.squaredNorm();
  const Vec3T<S> both = e1.cross(e2);
  const S bb = both.squaredNorm();
  // (Not where |both|^2 underflows: its root would be off, and the normal not unit.)
  if (bb > S(1e-8) * ee1 * ee2 && bb >= std::numeric_limits<S>::min()) {
    n = (both.dot(n) >= S(0) ? S(1) : S(-1)) / std::sqrt(bb) * both;
    return true;
  }
  Vec3T<S> m = n;
  if (ee1 > S(0)) m -= e1 * (m.dot(e1) / ee1);
  if (ee2 > S(0)) m -= e2 * (m.dot(e2) / ee2);
  const S mm = m.squaredNorm();
  const S length = length_of(m, mm);
  if (!(length > S(1e-3) * length_of(n))) return false;
  n = unit_of(m, mm, length);
  return true;
}

}  // namespace mink::detail
