/// @file flat_pair.hpp
/// The witness pair of two nearly parallel flat support features: a cylinder's cap on a box's
/// face or a cone's base, a capsule lying on a cap, two parallel edges.
///
/// Why: where both cores show a face or an edge on their support planes along the normal (within
/// the features' tolerance, 1e-9 of the size), every point of the overlap of the two features,
/// seen along the normal, is a pair of points within that tolerance of the value, and GJK's and
/// EPA's points are any one of them: a cylinder standing on a box tilted 2.2e-9 rad had its point
/// 0.05 of its radius from its lowest rim point, the exact witness. The depth (or the gap) along
/// the normal is affine over the overlap, so its largest value lies at a corner of the overlap,
/// or where a disc's rim is farthest along the slope: a short list of candidates, each a point
/// of both features.
///
/// Frame: A's, u the unit normal (B's feature lies along -u).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/manifold/feature.hpp"
#include "mink/math/orthogonal.hpp"

namespace mink::detail {

/// Least area of a polygon feature, over its longest side squared, whose plane is trusted.
inline constexpr double kFlatMinAspect = 1e-3;

/// A flat support feature seen along u: its outline across u (coordinates in a basis e1, e2 of
/// the plane orthogonal to u) and its height along u anywhere on it.
template <class S>
struct FlatShadow {
  using Planar = Eigen::Matrix<S, 2, 1>;
  int count = 0;  ///< 2: an edge; >= 3: a polygon, counter-clockwise seen along u (or a disc)
  Planar corners[kMaxFeaturePoints];
  S heights[kMaxFeaturePoints];
  bool disc = false;  ///< the outline is the circle of `radius` about `centre`
  Planar centre = Planar::Zero();
  S radius = S(0);
  /// Polygons and discs: height(x) = base + slope . (x - anchor), the plane of the face.
  Planar anchor = Planar::Zero(), slope = Planar::Zero();
  S base = S(0);

  /// An edge's weight t in [0, 1] of its point corners[0] + t (corners[1] - corners[0]) nearest
  /// x (0 for an edge of no length).
  S edge_weight(const Planar& x) const {
    const Planar edge = corners[1] - corners[0];
    const S length_sq = edge.squaredNorm();
    return length_sq > S(0) ? std::clamp((x - corners[0]).dot(edge) / length_sq, S(0), S(1)) : S(0);
  }

  /// The height along u of the feature's point seen at x (x on the feature). An edge's height is
  /// taken at x's nearest point on it.
  S height_at(const Planar& x) const {
    if (count >= 3) return base + slope.dot(x - anchor);
    return heights[0] + edge_weight(x) * (heights[1] - heights[0]);
  }

  /// Whether x lies in the outline, to `tolerance` (unit: length).
  bool holds(const Planar& x, S tolerance) const {
    if (disc) return (x - centre).norm() <= radius + tolerance;
    if (count == 2)
      return (x - corners[0] - edge_weight(x) * (corners[1] - corners[0])).norm() <= tolerance;
    for (int i = 0; i < count; ++i) {
      const Planar edge = corners[i + 1 == count ? 0 : i + 1] - corners[i];
      const Planar to = x - corners[i];
      if (edge.x() * to.y() - edge.y() * to.x() < -tolerance * edge.norm()) return false;
    }
    return true;
  }

  /// The sides of the outline (an edge is one side; a disc has none).
  int sides() const { return disc ? 0 : count == 2 ? 1 : count; }
};

/// The shadow of feature `f` (points in a core's frame, mapped to A's by `rotation`,
/// `translation`) along unit u in the basis e1, e2. False when a face is not seen along u (its
/// normal more than 60 degrees off: not the features of a contact).
template <class S>
bool flat_shadow(const SupportFeatureT<S>& f, const Mat3T<S>& rotation, const Vec3T<S>& translation,
                 const Vec3T<S>& u, const Vec3T<S>& e1, const Vec3T<S>& e2, FlatShadow<S>& out) {
  using Planar = typename FlatShadow<S>::Planar;
  out.count = f.count;
  for (int i = 0; i < f.count; ++i) {
    const Vec3T<S> p = rotation * f.points[i] + translation;
    out.corners[i] = Planar(e1.dot(p), e2.dot(p));
    out.heights[i] = u.dot(p);
  }
  if (f.count < 3) return f.count == 2;
  const Vec3T<S> normal = rotation * f.normal;
  const S along = normal.dot(u);
  if (!(std::abs(along) > S(0.5))) return false;
  out.anchor = out.corners[0];
  out.base = out.heights[0];
  out.slope = Planar(-normal.dot(e1) / along, -normal.dot(e2) / along);
  if (f.is_cap()) {
    const Vec3T<S> c = rotation * f.disc_centre + translation;
    out.disc = true;
    out.centre = Planar(e1.dot(c), e2.dot(c));
    out.radius = f.disc_radius;
    out.anchor = out.centre;
    out.base = u.dot(c);
    return true;
  }
  // Counter-clockwise seen along u, for holds(). A sliver's plane is not known to better than
  // the rounding over its width: its slope would pick the point (a triangle 1e-8 wide moved a
  // witness that EPA had exact by 1e-9 of the size).
  S area = S(0), diameter_sq = S(0);
  for (int i = 0; i < f.count; ++i) {
    const Planar& a = out.corners[i];
    const Planar& b = out.corners[i + 1 == f.count ? 0 : i + 1];
    area += a.x() * b.y() - a.y() * b.x();
    diameter_sq = std::max(diameter_sq, (b - a).squaredNorm());
  }
  if (!(std::abs(area) > S(kFlatMinAspect) * diameter_sq)) return false;
  if (area < S(0)) {
    std::reverse(out.corners, out.corners + f.count);
    std::reverse(out.heights, out.heights + f.count);
  }
  return true;
}

/// The points where the segment p0-p1 crosses the segment q0-q1 (one, or none when they miss or
/// are parallel), handed to `take`.
template <class S, class Take>
void segment_crossings(const Eigen::Matrix<S, 2, 1>& p0, const Eigen::Matrix<S, 2, 1>& p1,
                       const Eigen::Matrix<S, 2, 1>& q0, const Eigen::Matrix<S, 2, 1>& q1,
                       Take&& take) {
  const Eigen::Matrix<S, 2, 1> d = p1 - p0, e = q1 - q0, w = q0 - p0;
  const S denominator = d.x() * e.y() - d.y() * e.x();
  if (!(std::abs(denominator) > S(0))) return;
  const S s = (w.x() * e.y() - w.y() * e.x()) / denominator;
  const S t = (w.x() * d.y() - w.y() * d.x()) / denominator;
  if (s >= S(0) && s <= S(1) && t >= S(0) && t <= S(1)) take(Eigen::Matrix<S, 2, 1>(p0 + s * d));
}

/// The points where the segment p0-p1 crosses the circle of `radius` about `centre`, handed to
/// `take`.
template <class S, class Take>
void circle_crossings(const Eigen::Matrix<S, 2, 1>& p0, const Eigen::Matrix<S, 2, 1>& p1,
                      const Eigen::Matrix<S, 2, 1>& centre, S radius, Take&& take) {
  const Eigen::Matrix<S, 2, 1> d = p1 - p0, f = p0 - centre;
  const S a = d.squaredNorm();
  if (!(a > S(0))) return;
  // |f + t d| = radius: t = (-b +- sqrt(b^2 - a c)) / a, b = f . d, c = |f|^2 - radius^2.
  const S b = f.dot(d), c = (f.norm() - radius) * (f.norm() + radius);
  const S discriminant = b * b - a * c;
  if (!(discriminant >= S(0))) return;
  const S root = std::sqrt(discriminant);
  for (const S t : {(-b - root) / a, (-b + root) / a})
    if (t >= S(0) && t <= S(1)) take(Eigen::Matrix<S, 2, 1>(p0 + t * d));
}

/// The points where two circles cross, handed to `take`.
template <class S, class Take>
void circles_crossings(const Eigen::Matrix<S, 2, 1>& c0, S r0, const Eigen::Matrix<S, 2, 1>& c1,
                       S r1, Take&& take) {
  const Eigen::Matrix<S, 2, 1> d = c1 - c0;
  const S distance = d.norm();
  if (!(distance > S(0)) || distance > r0 + r1 || distance < std::abs(r0 - r1)) return;
  // Along the line of centres by `along`, across it by +-`across`.
  const S along = (distance * distance + (r0 - r1) * (r0 + r1)) / (S(2) * distance);
  const S across = std::sqrt(std::max(S(0), (r0 - along) * (r0 + along)));
  const Eigen::Matrix<S, 2, 1> axis = d / distance, normal(-axis.y(), axis.x());
  take(Eigen::Matrix<S, 2, 1>(c0 + along * axis + across * normal));
  take(Eigen::Matrix<S, 2, 1>(c0 + along * axis - across * normal));
}

/// The pair of A's feature `fa` (A's frame) and B's feature `fb` (B's frame, mapped to A's by
/// `rotation`, `translation`) where the depth along unit u, A's height minus B's, is largest over
/// the overlap of the features seen along u (the least gap, for features apart), written to
/// `on_a` and `on_b` (A's frame; on_a - on_b is along u). Each feature is an edge (2 points), a
/// polygon or a disc. `noise` (unit: length) is the rounding of the heights: when the depth
/// varies by no more than that over the candidates, the features are parallel to rounding, any
/// point of the overlap is as good, and false is returned (as when the features do not overlap).
/// The candidates: corners of either feature inside the other, crossings of their sides and rims,
/// and on a disc facing a face the rim point farthest up the depth's slope. At least one feature
/// must be a polygon or disc that is not a sliver (two edges cross at one point, or run
/// parallel where the closed forms of segments answer).
template <class S>
bool flat_pair_witness(const SupportFeatureT<S>& fa, const SupportFeatureT<S>& fb,
                       const Mat3T<S>& rotation, const Vec3T<S>& translation, const Vec3T<S>& u,
                       S noise, Vec3T<S>& on_a, Vec3T<S>& on_b) {
  using Planar = typename FlatShadow<S>::Planar;
  Vec3T<S> e1, e2;
  plane_basis(u, e1, e2);
  if (fa.count < 3 && fb.count < 3) return false;
  FlatShadow<S> a, b;
  if (!flat_shadow<S>(fa, Mat3T<S>::Identity(), Vec3T<S>::Zero(), u, e1, e2, a) ||
      !flat_shadow<S>(fb, rotation, translation, u, e1, e2, b))
    return false;
  S best = -std::numeric_limits<S>::infinity(), least = std::numeric_limits<S>::infinity();
  Planar at = Planar::Zero();
  auto offer = [&](const Planar& x) {
    if (!a.holds(x, noise) || !b.holds(x, noise)) return;
    const S depth = a.height_at(x) - b.height_at(x);
    if (!std::isfinite(depth)) return;
    least = std::min(least, depth);
    if (depth > best) {
      best = depth;
      at = x;
    }
  };
  auto corners_of = [&](const FlatShadow<S>& f) {
    if (!f.disc)
      for (int i = 0; i < f.count; ++i) offer(f.corners[i]);
  };
  corners_of(a);
  corners_of(b);
  auto side = [](const FlatShadow<S>& f, int i, Planar& p, Planar& q) {
    p = f.corners[i];
    q = f.corners[i + 1 == f.count ? 0 : i + 1];
  };
  Planar p0, p1, q0, q1;
  for (int i = 0; i < a.sides(); ++i) {
    side(a, i, p0, p1);
    for (int j = 0; j < b.sides(); ++j) {
      side(b, j, q0, q1);
      segment_crossings<S>(p0, p1, q0, q1, offer);
    }
    if (b.disc) circle_crossings<S>(p0, p1, b.centre, b.radius, offer);
  }
  if (a.disc) {
    for (int j = 0; j < b.sides(); ++j) {
      side(b, j, q0, q1);
      circle_crossings<S>(q0, q1, a.centre, a.radius, offer);
    }
    if (b.disc) circles_crossings<S>(a.centre, a.radius, b.centre, b.radius, offer);
  }
  // Both faces: the depth rises along a.slope - b.slope, and a rim's farthest point that way
  // may be the deepest (its farthest point the other way, the shallowest, tells the depth's
  // range over the overlap).
  if (a.count >= 3 && b.count >= 3) {
    const Planar rise = a.slope - b.slope;
    const S steep = rise.norm();
    if (steep > S(0)) {
      for (const S way : {S(1), S(-1)}) {
        if (a.disc) offer(Planar(a.centre + (way * a.radius / steep) * rise));
        if (b.disc) offer(Planar(b.centre + (way * b.radius / steep) * rise));
      }
    }
  }
  if (!(best - least > noise)) return false;
  on_a = at.x() * e1 + at.y() * e2 + a.height_at(at) * u;
  on_b = at.x() * e1 + at.y() * e2 + b.height_at(at) * u;
  return is_finite(on_a) && is_finite(on_b);
}

}  // namespace mink::detail
