// The mink shape that an oracle CurvedShape describes, handed to a generic callable: the bridge
// between the independent oracle (curved.hpp, which knows nothing of mink) and the tests that
// compare the two.
#pragma once

#include "mink/mink.hpp"
#include "oracle/curved.hpp"

namespace oracle {

/// A mink pose as the oracle takes it, in long double.
inline RigidPose to_oracle_pose(const mink::Pose& p) {
  return {p.rotation.cast<Real>(), p.translation.cast<Real>()};
}

/// f(mink shape) for the shape s describes (its dimensions rounded to double).
template <class F>
auto with_mink_shape(const CurvedShape& s, F&& f) {
  const double r = static_cast<double>(s.radius), h = static_cast<double>(s.half_height);
  const mink::Vec3 e = s.extents.cast<double>();
  switch (s.kind) {
    case CurvedKind::Sphere:
      return f(mink::Sphere{r});
    case CurvedKind::Box:
      return f(mink::Box{e});
    case CurvedKind::Capsule:
      return f(mink::Capsule{r, h});
    case CurvedKind::Cylinder:
      return f(mink::Cylinder{r, h});
    case CurvedKind::Cone:
      return f(mink::Cone{r, h});
    case CurvedKind::Ellipsoid:
      return f(mink::Ellipsoid{e});
  }
  return f(mink::Sphere{r});
}

/// The run-time mink::Shape that s describes. Queries on it go through the library's dispatch,
/// compiled once, where with_mink_shape() makes a test file instantiate a query for every pair of
/// kinds (minutes of CI's compile time under the sanitizers).
inline mink::Shape to_mink_shape(const CurvedShape& s) {
  const double r = static_cast<double>(s.radius), h = static_cast<double>(s.half_height);
  const mink::Vec3 e = s.extents.cast<double>();
  switch (s.kind) {
    case CurvedKind::Sphere:
      break;
    case CurvedKind::Box:
      return mink::Shape::box(e).value();
    case CurvedKind::Capsule:
      return mink::Shape::capsule(r, h).value();
    case CurvedKind::Cylinder:
      return mink::Shape::cylinder(r, h).value();
    case CurvedKind::Cone:
      return mink::Shape::cone(r, h).value();
    case CurvedKind::Ellipsoid:
      return mink::Shape::ellipsoid(e).value();
  }
  return mink::Shape::sphere(r).value();
}

}  // namespace oracle
