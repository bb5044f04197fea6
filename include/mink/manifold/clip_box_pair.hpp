/// @file clip_box_pair.hpp
/// clip_features() for two boxes (Box or Rounded<Box>): the same features, reference face and
/// clipped points, found from the boxes' axes instead of general support features and clipped in
/// the reference box's frame, at about half the cost. The manifold and contact() of two boxes use
/// it after the separating axis test.
#pragma once

#include <algorithm>
#include <cmath>

#include "mink/manifold/clip_features.hpp"

namespace mink::detail {

/// clip_features() for two boxes a and b (Box or Rounded<Box>, see the file comment) whose cores
/// overlap along `n`, the separating axis test's normal, and when their features are two crossing
/// edges (no clipping), the edges' closest points as the one point (their difference is along n
/// because n is the edges' common perpendicular). The arguments are clip_features()': `rel` is B's
/// pose in A's frame, `n` the unit normal in A's frame; but instead of their sum `size`, the two
/// bounding radii, which the caller has already computed (their square roots would otherwise
/// stand at the head of this function's chain of dependencies).
template <ConvexShape A, ConvexShape B>
void clip_box_pair(const A& a, const B& b, const PoseT<typename A::Scalar>& rel,
                   const Vec3T<typename A::Scalar>& n, typename A::Scalar feature_tolerance,
                   typename A::Scalar min_depth, typename A::Scalar bound_a,
                   typename A::Scalar bound_b, typename A::Scalar slack,
                   ClippedPoints<typename A::Scalar>& out) {
  using S = typename A::Scalar;
  const Vec3T<S>& ha = BoxCore<A>::half_extents(a);
  const Vec3T<S>& hb = BoxCore<B>::half_extents(b);
  const S size = bound_a + bound_b;
  out.count = 0;
  // Each box's feature direction in its own frame: A's along n, B's against it.
  const Vec3T<S> nb = rel.inverse_rotate(-n);
  const BoxFeatureAxes fa = box_feature_axes(ha, n, feature_tolerance * bound_a, a.core_radius());
  const BoxFeatureAxes fb = box_feature_axes(hb, nb, feature_tolerance * bound_b, b.core_radius());

  // The reference face, as clip_features() picks it.
  bool ref_is_a;
  if (fa.face_axis >= 0 && fb.face_axis >= 0) {
    // A quarter of each face's area: h_u h_v.
    auto area = [](const Vec3T<S>& h, int k) { return h[kNextAxis[k]] * h[kPrevAxis[k]]; };
    ref_is_a = reference_is_a(
        std::abs(n[fa.face_axis]), std::abs(nb[fb.face_axis]),
        [&] { return area(ha, fa.face_axis); }, [&] { return area(hb, fb.face_axis); });
  } else if (fa.face_axis >= 0 || fb.face_axis >= 0) {
    ref_is_a = fa.face_axis >= 0;
  } else {
    if (fa.free_count != 1 || fb.free_count != 1) return;  // a vertex: no clipping
    const BoxEdgePair<S> edges(ha, fa.first_free(), n, hb, fb.first_free(), nb, rel.rotation,
                               rel.translation);
    // Parallel edges clip against each other's end planes (rare: the separating axis test skips
    // axes of nearly parallel edges; the test is clip_features()': |da x db| <= limit
    // max(|da|, |db|) for the edge vectors da, db); crossing ones touch at their closest points.
    const S limit = feature_tolerance * size;
    if (edges.parallel(limit))
      clip_features(a, b, rel, n, feature_tolerance, min_depth, size, slack, out);
    if (out.count == 0) {
      Vec3T<S> on_a, on_b;
      edges.closest_points(on_a, on_b);
      // Onto the rounded surfaces along n: for crossing edges their common perpendicular (the
      // separating axis test's normal is their cross product), in the normal cone of each edge and
      // of its ends; for parallel ones perpendicular to within the feature tolerance.
      on_a += a.core_radius() * n;
      on_b -= b.core_radius() * n;
      out.on_a[0] = on_a;
      out.on_b[0] = on_b;
      out.planar[0] = {S(0), S(0), (on_a - on_b).dot(n)};
      out.count = 1;
      out.pairs_along_normal = false;  // clamped to an edge's end, they need not be
    }
    return;
  }

  // Each box's half extents, feature, feature direction (in its own frame: out of the box, towards
  // the other) and radius, named once for the reference and the incident box.
  struct BoxSide {
    const Vec3T<S>& h;
    const BoxFeatureAxes& f;
    const Vec3T<S>& d;
    S radius;
  };
  const BoxSide side_a{ha, fa, n, a.core_radius()}, side_b{hb, fb, nb, b.core_radius()};
  const BoxSide& ref = ref_is_a ? side_a : side_b;
  const BoxSide& inc = ref_is_a ? side_b : side_a;
  const int k = ref.f.face_axis;
  if (!(std::abs(ref.d[k]) > S(0.5))) return;  // a face this oblique is not a contact face
  // The clipping works in the reference box's frame: the incident box's pose there. When that is
  // B's frame, the transpose is read in place: a copy of either rotation, chosen by ref_is_a,
  // was written entry by entry and read in pairs, which stalled on store forwarding (one such
  // load held 7 % of this function's samples). The offset takes the product of the transpose
  // made whole, which sums in the order it always did (the transpose expression's own product
  // sums in another).
  Vec3T<S> incident[4];
  const int count =
      ref_is_a
          ? box_feature_points(inc.h, inc.d, inc.f, rel.rotation, rel.translation, inc.radius,
                               Vec3T<S>(-ref.d), incident)
          : box_feature_points(inc.h, inc.d, inc.f, rel.rotation.transpose(),
                               Vec3T<S>(-(Mat3T<S>(rel.rotation.transpose()) * rel.translation)),
                               inc.radius, Vec3T<S>(-ref.d), incident);
  clip_by_box_face(ref.h, k, sign_nonneg(ref.d[k]), ref.h[k] + ref.radius, incident, count, ref.d,
                   ref_is_a, min_depth, slack, ref_is_a ? nullptr : &rel, out);
}

}  // namespace mink::detail
