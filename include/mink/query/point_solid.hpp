/// @file point_solid.hpp
/// A point core (Sphere, Point, and their Rounded versions) against a box, cylinder, cone,
/// ellipsoid or small polytope core (Box, Cylinder, Cone, Ellipsoid, Polytope, and their Rounded
/// versions) in closed form: the solid's point nearest to the point core is the point clamped to
/// the solid, and a point inside leaves through the nearest part of the surface (a box's nearest
/// face; a cylinder's side or nearer cap; a cone's base or slant; a polytope's nearest face
/// plane). An ellipsoid's nearest point, inside or out, is a one-dimensional root,
/// found to rounding by Newton's method. intersect(), distance() and contact() take this path for
/// such pairs, in either order: exact to rounding, 0 iterations, and for a sphere inside the solid
/// no EPA (whose answer for a sphere near a cylinder's axis, or deep in a nearly round ellipsoid,
/// where every direction is nearly as good, could only be bracketed). A polytope takes it once it
/// has its face planes (PolytopeT::face_planes()), and leaves to GJK the few answers the planes
/// cannot give exactly. The nearest point of a solid to a corner of the other core also places
/// the witness points of separated cores (gjk/corner_solid.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "mink/gjk/segment_cores.hpp"
#include "mink/math/lanes.hpp"
#include "mink/math/pose.hpp"
#include "mink/query/box_box.hpp"
#include "mink/shapes/cone.hpp"
#include "mink/shapes/cylinder.hpp"
#include "mink/shapes/ellipsoid.hpp"
#include "mink/shapes/support_scan.hpp"

namespace mink {
// Declared only: their headers bring in the hull's (convex_hull.hpp), whose HullStatus::Point and
// ::Segment GCC's -Wshadow reports against mink::Point and mink::Segment when they come after.
template <class S>
class PolytopeT;
template <class S>
struct FacePlanesT;
}  // namespace mink

namespace mink::detail {

/// Shapes whose core is one point: Sphere, Point, and Rounded versions of them.
template <class T>
struct PointCore : std::false_type {};
template <class S>
struct PointCore<SphereT<S>> : std::true_type {};
template <class S>
struct PointCore<PointT<S>> : std::true_type {};
template <class T>
struct PointCore<Rounded<T>> : std::bool_constant<PointCore<T>::value> {};

/// A point `p` in a solid core's frame against that solid: the solid's point nearest to p
/// (outside) or below it on the nearest part of the surface (inside), the solid's outward normal
/// there, and the signed distance (negative inside: minus the depth).
template <class S>
struct PointSolidLocal {
  Vec3T<S> p, on_solid, out_of_solid;
  S signed_distance;
  /// Inside only: another direction is as good (see the solid's local()); `out_of_solid` is then
  /// the one the solid's local() names.
  bool tie;

  /// For p outside: signed_distance and out_of_solid from `gap`, p minus its nearest point on the
  /// solid, at any magnitude (length_of(), unit_of()). Returns false, out_of_solid untouched, when
  /// the gap has no length.
  bool set_outside_gap(const Vec3T<S>& gap) {
    const S gap_sq = gap.squaredNorm();
    signed_distance = length_of(gap, gap_sq);
    if (!(signed_distance > S(0))) return false;
    out_of_solid = unit_of(gap, gap_sq, signed_distance);
    return true;
  }
};

/// Whether two cores are within a reach of each other (intersect()'s closed forms): Overflow when
/// the square of their gap does, Unsure when a closed form cannot tell (GJK decides then).
enum class GapVerdict : unsigned char { Within, Beyond, Overflow, Unsure };

/// The verdict on `gap` (one core's point minus the other's nearest point) against `reach` (the
/// radii plus the touching tolerance). One coordinate at a time: a gap that comes through
/// memory is stored a coordinate at a time, and a packed load of two stalls on store forwarding.
template <class S>
[[gnu::always_inline]] inline GapVerdict gap_verdict(const Vec3T<S>& gap, S reach) {
  const S gap_sq = gap.x() * gap.x() + gap.y() * gap.y() + gap.z() * gap.z();
  if (!(gap_sq <= std::numeric_limits<S>::max())) return GapVerdict::Overflow;
  return length_at_most(gap, gap_sq, reach) ? GapVerdict::Within : GapVerdict::Beyond;
}

/// Solid cores with a closed-form nearest point: SolidCore<T>::core(t) points to the solid (a Box,
/// a Cylinder, a polytope's FacePlanes; null: no closed form for this shape yet),
/// SolidCore<T>::local(core, p) is the answer above, and SolidCore<T>::within_reach(core, p,
/// reach) the GapVerdict on p against the solid: whether p is within `reach` of it, the yes/no
/// test's whole answer. It returns a byte, not the gap: a vector returned through memory stalled
/// the caller's packed reads of it on store forwarding (a fifth of a sphere-polytope test under
/// Clang). local() may be nothing and within_reach() Unsure: GJK and EPA answer then.
template <class T>
struct SolidCore : std::false_type {};

/// within_reach() for a solid whose nearest point to p is a clamp (Solid::clamp(core, p)): exact,
/// whatever the reach.
template <class Solid>
struct GapOfClamp {
  template <class Core, class S>
  static GapVerdict within_reach(const Core& c, const Vec3T<S>& p, S reach) {
    return gap_verdict(Vec3T<S>(p - Solid::clamp(c, p)), reach);
  }
};

/// A box: the clamp to its extents; inside, out through the face nearest to p. Ties: p as deep
/// below two faces, or on the centre plane of the nearest one (then the + face).
template <class S>
struct SolidCore<BoxT<S>> : std::true_type, GapOfClamp<SolidCore<BoxT<S>>> {
  using Core = BoxT<S>;
  static const Core* core(const BoxT<S>& b) { return &b; }
  static Vec3T<S> clamp(const Core& b, const Vec3T<S>& p) {
    return p.cwiseMax(-b.half_extents).cwiseMin(b.half_extents);
  }
  static std::optional<PointSolidLocal<S>> local(const Core& b, const Vec3T<S>& p) {
    const Vec3T<S>& h = b.half_extents;
    PointSolidLocal<S> out;
    out.p = p;
    out.on_solid = clamp(b, p);
    out.tie = false;
    const Vec3T<S> gap = p - out.on_solid;
    // A coordinate was clamped: outside (a gap that is not zero has a length).
    if (gap != Vec3T<S>::Zero() && out.set_outside_gap(gap)) return out;
    // Inside (or on the surface): out through the face nearest to p.
    const Vec3T<S> below = h - p.cwiseAbs();
    int k = 0;
    if (below[1] < below[k]) k = 1;
    if (below[2] < below[k]) k = 2;
    out.tie = p[k] == S(0);
    for (int i = 0; i < 3; ++i) out.tie |= i != k && below[i] == below[k];
    out.out_of_solid = Vec3T<S>::Zero();
    out.out_of_solid[k] = sign_nonneg(p[k]);
    out.on_solid[k] = out.out_of_solid[k] * h[k];
    out.signed_distance = -below[k];
    return out;
  }
};

/// p's distance from the local z axis and its radial direction (ux, uy) (0 and +x on the axis),
/// for the solids of revolution below.
template <class S>
S axis_distance(const Vec3T<S>& p, S& ux, S& uy) {
  if (!planar_unit(p.x(), p.y(), ux, uy)) {
    ux = S(1);
    uy = S(0);
    return S(0);
  }
  // The distance along the unit direction: no square of a tiny or huge coordinate.
  return std::max(S(0), ux * p.x() + uy * p.y());
}

/// A cylinder (axis z): p's distance from the axis and from the caps' planes, each clamped, in
/// the plane through the axis and p, where the cylinder is a rectangle. Inside, out through the
/// side or the nearer cap, whichever is nearer (the side on a tie). Ties: side and cap equally
/// near; p on the axis with the side nearest (every radial direction: then +x); p on the centre
/// plane with a cap nearest (then the + cap).
template <class S>
struct SolidCore<CylinderT<S>> : std::true_type, GapOfClamp<SolidCore<CylinderT<S>>> {
  using Core = CylinderT<S>;
  static const Core* core(const CylinderT<S>& c) { return &c; }
  static Vec3T<S> clamp(const Core& c, const Vec3T<S>& p) {
    S ux, uy;
    const S rho = axis_distance(p, ux, uy);
    const S z = std::clamp(p.z(), -c.half_height, c.half_height);
    if (rho <= c.radius) return {p.x(), p.y(), z};
    return {ux * c.radius, uy * c.radius, z};
  }
  static std::optional<PointSolidLocal<S>> local(const Core& c, const Vec3T<S>& p) {
    PointSolidLocal<S> out;
    out.p = p;
    out.tie = false;
    S ux, uy;
    const S rho = axis_distance(p, ux, uy);
    const S beyond_side = rho - c.radius, beyond_cap = std::abs(p.z()) - c.half_height;
    const S side_z = std::clamp(p.z(), -c.half_height, c.half_height);
    const S cap_sign = sign_nonneg(p.z());
    if (beyond_side > S(0) || beyond_cap > S(0)) {
      // Outside: the gap in the (radial, axial) plane, from the clamped distances, which carry
      // no cancellation of p's coordinates against the clamp.
      const S radial_gap = std::max(S(0), beyond_side), axial_gap = std::max(S(0), beyond_cap);
      // Not zero: one of the two gaps is positive, along a unit direction.
      out.set_outside_gap(Vec3T<S>(ux * radial_gap, uy * radial_gap, cap_sign * axial_gap));
      out.on_solid = beyond_side > S(0) ? Vec3T<S>(ux * c.radius, uy * c.radius, side_z)
                                        : Vec3T<S>(p.x(), p.y(), side_z);
      return out;
    }
    const S below_side = -beyond_side, below_cap = -beyond_cap;
    out.tie = below_side == below_cap;
    if (below_side <= below_cap) {
      out.tie |= rho == S(0);
      out.out_of_solid = Vec3T<S>(ux, uy, S(0));
      out.on_solid = Vec3T<S>(ux * c.radius, uy * c.radius, p.z());
      out.signed_distance = -below_side;
    } else {
      out.tie |= p.z() == S(0);
      out.out_of_solid = Vec3T<S>(S(0), S(0), cap_sign);
      out.on_solid = Vec3T<S>(p.x(), p.y(), cap_sign * c.half_height);
      out.signed_distance = -below_cap;
    }
    return out;
  }
};

/// A cone (axis z, apex at +h, base disc of radius r at -h): in the plane through the axis and p,
/// where the cone is a triangle, the nearest point of a p outside is its foot on the base when it
/// lies below the base disc, else its foot on the slant from the apex to the rim, clamped to that
/// segment (at the apex or the rim when it falls beyond an end). A p inside leaves through the
/// nearer of the base and the slant. Ties: base and slant equally near; p on the axis with the
/// slant nearest (every radial direction: then +x). Nothing for a flat or needle cone (r or h 0),
/// which GJK handles as a disc or a segment.
template <class S>
struct SolidCore<ConeT<S>> : std::true_type, GapOfClamp<SolidCore<ConeT<S>>> {
  using Core = ConeT<S>;
  static const Core* core(const ConeT<S>& c) {
    return c.radius > S(0) && c.half_height > S(0) ? &c : nullptr;
  }
  /// The slant from the apex (0, h) to the rim (r, -h) in the plane through the axis, as r and
  /// 2h over the larger of them, `scale`: products of a coordinate with these cannot overflow
  /// where r (h - z) and 2h rho would (a cone and a point at 1e200 counted as inside). Taken once
  /// a query: two divisions.
  struct Slant {
    S scale, sr, s2h;
    explicit Slant(const Core& c)
        : scale(std::max(c.radius, S(2) * c.half_height)),
          sr(c.radius / scale),
          s2h(S(2) * c.half_height / scale) {}
  };
  static bool inside(const Core& c, const Slant& slant, S rho, S z) {
    return z >= -c.half_height && slant.s2h * rho <= slant.sr * (c.half_height - z);
  }
  /// The nearest point in the plane through the axis, as (distance from the axis, z), for a p
  /// outside the cone at (rho, z). Returns whether it lies inside the slant (not at its ends).
  static bool nearest_in_section(const Core& c, const Slant& slant, S rho, S z, S& rho_near,
                                 S& z_near) {
    const S r = c.radius, h = c.half_height;
    if (z < -h && rho <= r) {
      rho_near = rho;
      z_near = -h;
      return false;
    }
    // t = (p - apex) . slant / |slant|^2 in [0, 1], with the slant scaled so that its squared
    // length cannot overflow.
    const S sr = slant.sr, s2h = slant.s2h;
    const S t =
        std::clamp((rho * sr - (z - h) * s2h) / ((sr * sr + s2h * s2h) * slant.scale), S(0), S(1));
    rho_near = t == S(1) ? r : t * r;
    z_near = t == S(1) ? -h : h - S(2) * h * t;
    return t > S(0) && t < S(1);
  }
  static Vec3T<S> clamp(const Core& c, const Vec3T<S>& p) {
    S ux, uy;
    const S rho = axis_distance(p, ux, uy);
    const Slant slant(c);
    if (inside(c, slant, rho, p.z())) return p;
    S rho_near, z_near;
    nearest_in_section(c, slant, rho, p.z(), rho_near, z_near);
    return {ux * rho_near, uy * rho_near, z_near};
  }
  static std::optional<PointSolidLocal<S>> local(const Core& c, const Vec3T<S>& p) {
    S ux, uy;
    const S rho = axis_distance(p, ux, uy);
    const Slant slant(c);
    if (inside(c, slant, rho, p.z())) return local_inside(c, slant, p, rho, ux, uy);
    S rho_near, z_near;
    const bool on_slant = nearest_in_section(c, slant, rho, p.z(), rho_near, z_near);
    PointSolidLocal<S> out;
    out.p = p;
    out.tie = false;
    out.on_solid = Vec3T<S>(ux * rho_near, uy * rho_near, z_near);
    if (on_slant) {
      // Over the slant's inside: its own normal and p's height above its line, as local_inside()
      // takes them below it. The gap to the foot has the direction of its rounding when p is
      // a tiny height above the slant (2.6e-7 rad off at 2.6e-9 of the size; any direction at
      // all for a p on the slant to rounding).
      const S h = c.half_height, sr = slant.sr, s2h = slant.s2h;
      const S length = std::hypot(sr, s2h);
      out.signed_distance = (s2h * rho - sr * (h - p.z())) / length;
      const S out_radial = s2h / length;
      out.out_of_solid = Vec3T<S>(out_radial * ux, out_radial * uy, sr / length);
      if (out.signed_distance > S(0) && is_finite(out.on_solid)) return out;
    }
    // The gap from the section's differences, which carry no cancellation of p's coordinates
    // against the nearest point's.
    const S radial_gap = rho - rho_near;
    if (!is_finite(out.on_solid) ||
        !out.set_outside_gap(Vec3T<S>(ux * radial_gap, uy * radial_gap, p.z() - z_near)))
      return std::nullopt;
    return out;
  }
  /// local() for a p inside, at (rho, z) with radial direction (ux, uy): out through the nearer of
  /// the base and the slant. In the plane through the axis the cone is a triangle, and the foot
  /// of an inner point on the nearest of its edges' lines lies on that edge; the slant on p's side
  /// of the axis is the nearer of the two.
  static std::optional<PointSolidLocal<S>> local_inside(const Core& c, const Slant& slant,
                                                        const Vec3T<S>& p, S rho, S ux, S uy) {
    const S h = c.half_height, sr = slant.sr, s2h = slant.s2h;
    const S length = std::hypot(sr, s2h);  // of the slant, scaled as sr and s2h
    const S below_base = p.z() + h;
    const S below_slant = (sr * (h - p.z()) - s2h * rho) / length;
    PointSolidLocal<S> out;
    out.p = p;
    out.tie = below_slant == below_base;
    if (below_slant <= below_base) {
      out.tie |= rho == S(0);  // on the axis: every radial direction
      const S out_radial = s2h / length;
      out.out_of_solid = Vec3T<S>(out_radial * ux, out_radial * uy, sr / length);
      out.on_solid = p + below_slant * out.out_of_solid;
      out.signed_distance = -below_slant;
    } else {
      out.out_of_solid = Vec3T<S>(S(0), S(0), S(-1));
      out.on_solid = Vec3T<S>(p.x(), p.y(), -h);
      out.signed_distance = -below_base;
    }
    if (!is_finite(out.on_solid) || !std::isfinite(out.signed_distance)) return std::nullopt;
    return out;
  }
};

/// A polytope of 4 to 63 points, through its face planes (face_planes.hpp; none before the
/// polytope has built them). Inside: out through the face plane nearest to p. Outside: the
/// nearest corner when p lies in its normal cone, else (up to kNearestMaxFaces faces) the nearest
/// point of the faces whose planes p is above, in a face or on an edge; above that, the face p
/// is farthest above or one of its edges, where they are the nearest. Nothing (GJK answers) for
/// coordinates beyond 2^488 (2^40 in float), whose squares would overflow, and for a point
/// outside whose nearest point is on an edge or a corner less than 1e-3 of the coordinates' size
/// away: the gap's rounding would tilt the normal. Ties: p inside, as deep below two faces.
template <class S>
struct SolidCore<PolytopeT<S>> : std::true_type {
  using Core = FacePlanesT<S>;
  static const Core* core(const PolytopeT<S>& p) { return p.face_planes(); }

  /// Outside, the nearest point is searched over the faces p is above only up to this many
  /// faces: each costs a few branches per edge, and from about 20 faces GJK's few support
  /// calls cost less. Above it, nearest_by_largest_face() tries one face and its edges.
  static constexpr std::uint32_t kNearestMaxFaces = 20;

  static constexpr S kLargest = power_of_two<S>(std::numeric_limits<S>::max_exponent / 2 - 24);

  /// The signed distances of p from the face planes (positive above), into `above` unless it is
  /// null; returns the largest, or nothing for p beyond kLargest. With `above` null, the scan
  /// may stop at the first distance above `enough` and return it: the yes/no test needs no more.
  static std::optional<S> plane_distances(const Core& c, const Vec3T<S>& p, S* above,
                                          S enough = std::numeric_limits<S>::infinity()) {
    // Coordinate by coordinate: p was computed so, and a packed load of two stalls on store
    // forwarding.
    if (!(std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())}) <= kLargest))
      return std::nullopt;
    const std::size_t n = c.scan_count();  // a multiple of 4: whole SIMD blocks, padding -inf
#if defined(__SSE2__)
    if constexpr (std::is_same_v<S, double>) {
      // The maximum in registers: an arg-max loop would carry a compare and a select from one
      // face to the next. Same operations, in the same order, as the scalar loop below.
      using Vec = Lanes<kBuildLaneWidth>;
      Vec largest;
      lanes_fill(largest, -std::numeric_limits<double>::infinity());
      for (std::size_t f = 0; f < n; f += kBuildLaneWidth) {
        Vec nx, ny, nz, offset;
        lanes_load(nx, c.nx.data() + f);
        lanes_load(ny, c.ny.data() + f);
        lanes_load(nz, c.nz.data() + f);
        lanes_load(offset, c.offset.data() + f);
        const Vec d = ((nx * p.x() + ny * p.y()) + nz * p.z()) - offset;
        if (above)
          lanes_store(above + f, d);
        else if (lanes_any_greater(d, enough))
          return lanes_max(largest > d ? largest : d);
        largest = largest > d ? largest : d;
      }
      return lanes_max(largest);
    }
#endif
    S largest = -std::numeric_limits<S>::infinity();
    for (std::size_t f = 0; f < n; ++f) {
      const S d = c.nx[f] * p.x() + c.ny[f] * p.y() + c.nz[f] * p.z() - c.offset[f];
      if (above) above[f] = d;
      largest = std::max(largest, d);
    }
    return largest;
  }
#if defined(__SSE2__)
  /// For each block of corners (padding included), `value(x, y, z)` of their coordinates' lanes
  /// into `out`; returns the largest value or, with kSmallest, the smallest (the largest
  /// negated), in registers to the end.
  template <bool kSmallest, class Value>
  static double scan_corners(const Core& c, double* out, Value value) {
    using Vec = Lanes<kBuildLaneWidth>;
    Vec largest;
    lanes_fill(largest, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < c.corner_scan_count(); i += kBuildLaneWidth) {
      Vec x, y, z;
      lanes_load(x, c.cx.data() + i);
      lanes_load(y, c.cy.data() + i);
      lanes_load(z, c.cz.data() + i);
      const Vec v = value(x, y, z);
      lanes_store(out + i, v);
      const Vec key = kSmallest ? Vec(0.0 - v) : v;
      largest = largest > key ? largest : key;
    }
    return kSmallest ? -lanes_max(largest) : lanes_max(largest);
  }
#endif
  /// For each corner w (padding included), |p - w|^2 into `distance_sq`; returns the smallest.
  static S corner_distances(const Core& c, const Vec3T<S>& p, S* distance_sq) {
    const std::size_t n = c.corner_scan_count();
#if defined(__SSE2__)
    if constexpr (std::is_same_v<S, double>) {
      using Vec = Lanes<kBuildLaneWidth>;
      return scan_corners<true>(c, distance_sq, [&](const Vec& x, const Vec& y, const Vec& z) {
        const Vec dx = p.x() - x, dy = p.y() - y, dz = p.z() - z;
        return Vec((dx * dx + dy * dy) + dz * dz);
      });
    }
#endif
    S smallest = std::numeric_limits<S>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      distance_sq[i] = (p - c.corner_point(i)).squaredNorm();
      smallest = std::min(smallest, distance_sq[i]);
    }
    return smallest;
  }
  /// For each corner w (padding included), d . w into `dots`; returns the largest.
  static S corner_dots(const Core& c, const Vec3T<S>& d, S* dots) {
    const std::size_t n = c.corner_scan_count();
#if defined(__SSE2__)
    if constexpr (std::is_same_v<S, double>) {
      using Vec = Lanes<kBuildLaneWidth>;
      return scan_corners<false>(c, dots, [&](const Vec& x, const Vec& y, const Vec& z) {
        return Vec((x * d.x() + y * d.y()) + z * d.z());
      });
    }
#endif
    S largest = -std::numeric_limits<S>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      dots[i] = c.cx[i] * d.x() + c.cy[i] * d.y() + c.cz[i] * d.z();
      largest = std::max(largest, dots[i]);
    }
    return largest;
  }

  /// The corner v nearest to p, and |p - v|^2; `values` receives every corner's.
  struct NearestCorner {
    Vec3T<S> corner;
    S distance_sq;
    std::size_t index;
  };
  static NearestCorner nearest_corner(const Core& c, const Vec3T<S>& p, S* values) {
    const S nearest_sq = corner_distances(c, p, values);
    std::size_t v = 0;
    while (v + 1 < c.corner_count && values[v] != nearest_sq) ++v;
    return {c.corner_point(v), nearest_sq, v};
  }
  /// With d = p - v: h - d . v >= 0, h the largest d . w over the corners (the polytope's support
  /// along d). Both dots come from the same scan, so a corner that attains the support gives
  /// exactly 0.
  static S support_beyond_corner(const Core& c, const Vec3T<S>& d, std::size_t v, S* values) {
    const S support = corner_dots(c, d, values);
    return support - values[v];
  }

  /// The yes/no test for p outside, within reach of every face plane, by the corner v nearest to
  /// p, which decides most such points for a few dozen flops (nearest_outside() walks the edges
  /// of every face p is above). Within reach: p - v. Else, with d = p - v, the polytope lies
  /// where d . x <= h, h the largest d . w over the corners, so p is at least
  /// (|d|^2 - (h - d . v)) / |d| from it: beyond reach, d itself (longer than reach) will do; it
  /// is exact when v is the nearest point, which is where p lies in v's normal cone. Nothing: an
  /// edge or a face may be within reach.
  static GapVerdict verdict_by_corner(const Core& c, const Vec3T<S>& p, S reach) {
    alignas(32) std::array<S, Core::kMaxCorners> values;
    const NearestCorner v = nearest_corner(c, p, values.data());
    const Vec3T<S> d = p - v.corner;
    if (v.distance_sq <= reach * reach) return gap_verdict(d, reach);
    const S beyond = support_beyond_corner(c, d, v.index, values.data());
    if (v.distance_sq - beyond > reach * std::sqrt(v.distance_sq)) return gap_verdict(d, reach);
    return GapVerdict::Unsure;
  }

  /// The first face whose distance is `largest`.
  static std::uint32_t face_at(const Core& c, const S* above, S largest) {
    std::uint32_t f = 0;
    while (f + 1 < c.face_count && above[f] != largest) ++f;
    return f;
  }

  /// p outside: the nearest point of the polytope, its squared distance, the face whose interior
  /// holds it (-1: an edge or a corner), and the edge whose interior holds it (else 0). It lies on
  /// a face p is above (at an edge or a corner, p - q is a positive combination of the faces'
  /// normals there, so p is above one of them): at p's foot on that face when p projects into
  /// it, else on an edge p lies beyond.
  ///
  /// "Above" within the planes' rounding: faces flat to 256 eps of the coordinates may be
  /// neighbours split from one flat face, whose planes differ by that much. A point on such a
  /// face, computed 2e-16 above its neighbour and 1e-16 below its own plane, was searched for on
  /// the neighbour's edges only, and came out 0.75 of the size away (found by review: a cube with
  /// points on its edges). A face a little below p adds only candidates on the surface.
  ///
  /// One pass over the faces p is above. A face p projects into is decided alone, whatever edge
  /// points came before it: its foot is the nearest point (the distance is at least p's height
  /// above every plane). Compared by squared distance with the points of its edges, which the
  /// faces beyond an obtuse edge offer, it can lose to rounding to an edge point a little off it,
  /// whose direction is then tilted by up to 1e-7 rad (the support along it moves to the face's
  /// far side; found by review on an octahedron).
  ///
  /// kExact (local()): among edge points whose squared distances differ by less than their
  /// rounding (a few eps of the coordinates times the distance), an edge's interior point is
  /// preferred to a corner, as its gap is orthogonal to the edge. Otherwise (gap(): yes or no)
  /// the search stops at the first point within sqrt(`enough_sq`) of p, and any face p projects
  /// into is within it (gap() searches only when every height is).
  struct Nearest {
    Vec3T<S> point;
    S distance_sq;
    int face;
    Vec3T<S> edge;
  };
  template <bool kExact>
  static Nearest nearest_outside(const Core& c, const Vec3T<S>& p, const S* above,
                                 S enough_sq = S(-1)) {
    const S scale = p.cwiseAbs().maxCoeff() + c.largest;
    const S rounding = kExact ? S(64) * std::numeric_limits<S>::epsilon() * scale : S(0);
    const S below_by = S(256) * std::numeric_limits<S>::epsilon() * scale;
    Nearest out{p, std::numeric_limits<S>::infinity(), -1, Vec3T<S>::Zero()};
    for (std::uint32_t f = 0; f < c.face_count; ++f) {
      if (!(above[f] > -below_by)) continue;
      bool enough = false;
      const bool in_face =
          visit_edges_beyond(c, p, f, [&](const Vec3T<S>& corner, const Vec3T<S>& edge, S along) {
            const S t = std::clamp(along, S(0), S(1));
            const Vec3T<S> q = corner + t * edge;
            const S distance_sq = (p - q).squaredNorm();
            if constexpr (kExact) {
              const bool inside_edge = t > S(0) && t < S(1);
              const S slack = rounding * std::sqrt(distance_sq);
              if (distance_sq < out.distance_sq - slack ||
                  (inside_edge && out.edge == Vec3T<S>::Zero() &&
                   distance_sq <= out.distance_sq + slack))
                out = {q, distance_sq, -1, inside_edge ? edge : Vec3T<S>::Zero()};
            } else {
              if (distance_sq < out.distance_sq) out = {q, distance_sq, -1, Vec3T<S>::Zero()};
              enough = out.distance_sq <= enough_sq;
            }
            return enough;
          });
      if (enough) return out;
      if (in_face)
        return {p - above[f] * c.normal(f), above[f] * above[f], int(f), Vec3T<S>::Zero()};
    }
    return out;
  }

  /// Calls visit(corner, edge, t) for each edge of face f that p lies beyond (outside the edge,
  /// seen in f's plane): the edge runs from `corner` along `edge`, and p projects on its line at
  /// corner + t edge (t unclamped; 0 for an edge of length 0). A visit returning true stops.
  /// Returns whether p projects into f (no edge visited).
  template <class Visit>
  static bool visit_edges_beyond(const Core& c, const Vec3T<S>& p, std::uint32_t f, Visit&& visit) {
    const std::uint32_t begin = c.edge_begin[f], end = c.edge_begin[f + 1];
    bool in_face = true;
    for (std::uint32_t k = begin; k < end; ++k) {
      const Vec3T<S> from_corner = p - c.corner[k];
      if (c.inward[k].dot(from_corner) >= S(0)) continue;
      in_face = false;
      const Vec3T<S> edge = c.corner[k + 1 == end ? begin : k + 1] - c.corner[k];
      const S edge_sq = edge.squaredNorm();
      if (visit(c.corner[k], edge, edge_sq > S(0) ? from_corner.dot(edge) / edge_sq : S(0))) break;
    }
    return in_face;
  }

  /// p outside, above kNearestMaxFaces faces, where the edge search costs more than GJK: the
  /// nearest point when it lies on the face f that p is farthest above or inside one of its
  /// edges, else an infinite distance (a corner, which the caller tried first, or a corner of f). f
  /// decides when p projects into it, as in nearest_outside(). Else p's foot on f's plane is beyond
  /// one or two of f's edges, and over the interior of at most one of them, e (a convex polygon's
  /// edge regions do not overlap). Then e's nearest point q to p is the polytope's: p - q is in
  /// e's normal cone, between f's normal and that of the face g across e, since otherwise p would
  /// be over g's side of e, and then (in the plane normal to e, with g dropping by an angle
  /// d < 90 degrees from f's plane) p's height above g exceeds its height h above f by at least
  /// h (1 - cos d) / cos d, against f being the farthest.
  static Nearest nearest_by_largest_face(const Core& c, const Vec3T<S>& p, const S* above,
                                         S largest) {
    const std::uint32_t f = face_at(c, above, largest);
    Nearest out{p, std::numeric_limits<S>::infinity(), -1, Vec3T<S>::Zero()};
    const bool in_face =
        visit_edges_beyond(c, p, f, [&](const Vec3T<S>& corner, const Vec3T<S>& edge, S t) {
          if (!(t > S(0) && t < S(1))) return false;  // beyond a corner of f
          const Vec3T<S> q = corner + t * edge;
          out = {q, (p - q).squaredNorm(), -1, edge};
          return true;
        });
    if (!in_face) return out;
    return {p - above[f] * c.normal(f), above[f] * above[f], int(f), Vec3T<S>::Zero()};
  }

  static GapVerdict within_reach(const Core& c, const Vec3T<S>& p, S reach) {
    // The distances are kept only for the edge search, which few points need; the stores cost
    // more than their time (one run in three was 50 % slower, from where the stack fell).
    const std::optional<S> scanned = plane_distances(c, p, nullptr, reach);
    if (!scanned) return GapVerdict::Unsure;
    const S largest = *scanned;
    if (largest <= S(0)) return GapVerdict::Within;
    // Farther from a plane than reach: as far from the polytope.
    if (largest > reach) return GapVerdict::Beyond;
    if (const GapVerdict by_corner = verdict_by_corner(c, p, reach);
        by_corner != GapVerdict::Unsure)
      return by_corner;
    alignas(32) std::array<S, Core::kMaxFaces> above;
    plane_distances(c, p, above.data());
    if (c.face_count > kNearestMaxFaces) {
      const Nearest nearest = nearest_by_largest_face(c, p, above.data(), largest);
      if (!(nearest.distance_sq < std::numeric_limits<S>::infinity())) return GapVerdict::Unsure;
      return gap_verdict(Vec3T<S>(p - nearest.point), reach);
    }
    return gap_verdict(
        Vec3T<S>(p - nearest_outside<false>(c, p, above.data(), reach * reach).point), reach);
  }

  static std::optional<PointSolidLocal<S>> local(const Core& c, const Vec3T<S>& p) {
    alignas(32) std::array<S, Core::kMaxFaces> above;
    const std::optional<S> largest = plane_distances(c, p, above.data());
    if (!largest) return std::nullopt;
    PointSolidLocal<S> out;
    out.p = p;
    out.tie = false;
    if (*largest <= S(0)) {
      // Inside: the ball of radius -above[best] about p is below every plane, so inside, and the
      // foot of p on the nearest plane is on the surface.
      const std::uint32_t best = face_at(c, above.data(), *largest);
      for (std::uint32_t f = 0; f < c.face_count; ++f)
        out.tie |= f != best && above[f] == above[best];
      out.out_of_solid = c.normal(best);
      out.on_solid = p - above[best] * out.out_of_solid;
      out.signed_distance = above[best];
      return out;
    }
    // An edge or a corner: the direction of the gap, whose rounding (eps of the coordinates)
    // tilts it by eps |p| / |gap|; such a tilt moves the support to the next corner, by the tilt
    // times an edge's length. Kept below 1e3 eps, and none along an edge the point is inside.
    const S scale_sq = p.squaredNorm() + c.largest * c.largest;
    {
      // p in the normal cone of its nearest corner v (the support along p - v is at v): the
      // polytope lies below the plane through v normal to p - v, so v is the nearest point. Most
      // points outside a small polytope are there, and the edge walk costs ten times this.
      alignas(32) std::array<S, Core::kMaxCorners> values;
      const NearestCorner v = nearest_corner(c, p, values.data());
      const Vec3T<S> d = p - v.corner;
      if (v.distance_sq >= S(1e-6) * scale_sq &&
          support_beyond_corner(c, d, v.index, values.data()) <= S(0)) {
        out.on_solid = v.corner;
        out.signed_distance = length_of(d, v.distance_sq);
        out.out_of_solid = unit_of(d, v.distance_sq, out.signed_distance);
        return out;
      }
    }
    const Nearest nearest = c.face_count > kNearestMaxFaces
                                ? nearest_by_largest_face(c, p, above.data(), *largest)
                                : nearest_outside<true>(c, p, above.data());
    if (!(nearest.distance_sq < std::numeric_limits<S>::infinity())) return std::nullopt;
    out.on_solid = nearest.point;
    if (nearest.face >= 0) {
      out.out_of_solid = c.normal(std::size_t(nearest.face));
      out.signed_distance = above[std::size_t(nearest.face)];
      return out;
    }
    if (!(nearest.distance_sq >= S(1e-6) * scale_sq)) return std::nullopt;
    Vec3T<S> gap = p - nearest.point;
    if (nearest.edge != Vec3T<S>::Zero())
      gap -= (gap.dot(nearest.edge) / nearest.edge.squaredNorm()) * nearest.edge;
    out.signed_distance = std::sqrt(nearest.distance_sq);
    out.out_of_solid = unit_of(gap);
    return out;
  }
};

/// An ellipsoid (semi-axes `radii`, all positive and within 1e6 of one another; else GJK and EPA
/// answer): its point nearest to p, outside or inside, where the outward normal x / radii^2 is
/// along p - x. With y = |p| coordinate by coordinate (the answer is mirrored back) and
/// x_i = r_i^2 y_i / (r_i^2 + t), t is the root of F(t) = sum (r_i y_i / (r_i^2 + t))^2 - 1
/// beyond -min r_i^2 (t > 0 outside, < 0 inside), which is unique there and gives the nearest point
/// (Eberly, "Distance from a point to an ellipse, an ellipsoid, or a hyperellipsoid"). Solved for
/// u = t + min r_i^2, whose offsets r_i^2 - min r_i^2 are exact (0 on the shortest axes), by
/// Newton's method from the left: F is convex and decreasing in u, so each step stays below the
/// root. When p lies on the plane of the shortest axes and F has no root there (inside, near the
/// centre), the nearest point leaves that plane: u = 0, and the rest of the unit norm goes to the
/// first shortest axis, on its + side (a tie with its mirror image). Nothing (GJK and EPA answer)
/// when the iteration cap is hit or coordinates are beyond 2^(max_exponent / 4) of the largest
/// radius.
template <class S>
struct SolidCore<EllipsoidT<S>> : std::true_type {
  using Core = EllipsoidT<S>;
  static constexpr S kLargest = power_of_two<S>(std::numeric_limits<S>::max_exponent / 4);
  static constexpr int kMaxSteps = 128;

  static const Core* core(const EllipsoidT<S>& e) {
    const S smallest = e.radii.minCoeff(), largest = e.radii.maxCoeff();
    return smallest > S(0) && largest <= S(1e6) * smallest ? &e : nullptr;
  }
  static bool inside(const Core& e, const Vec3T<S>& p) {
    return p.cwiseQuotient(e.radii).squaredNorm() <= S(1);
  }
  static GapVerdict within_reach(const Core& e, const Vec3T<S>& p, S reach) {
    if (inside(e, p)) return GapVerdict::Within;
    const auto l = local(e, p, false);
    if (!l) return GapVerdict::Unsure;
    return gap_verdict(Vec3T<S>(p - l->on_solid), reach);
  }
  static std::optional<PointSolidLocal<S>> local(const Core& e, const Vec3T<S>& p) {
    return local(e, p, inside(e, p));
  }
  /// local() for a p already known to be inside (`in`) or not.
  static std::optional<PointSolidLocal<S>> local(const Core& e, const Vec3T<S>& p, bool in) {
    // In units of the largest radius, so that the squares below neither overflow nor underflow.
    const S scale = e.radii.maxCoeff();
    const Vec3T<S> r = e.radii / scale, y = p.cwiseAbs() / scale;
    if (!(y.maxCoeff() <= kLargest)) return std::nullopt;
    const S r_min = r.minCoeff(), m = r_min * r_min;
    Vec3T<S> d, a;  // d_i = r_i^2 - min r^2 (exactly 0 on the shortest axes), a_i = r_i y_i
    for (int i = 0; i < 3; ++i) {
      d[i] = r[i] == r_min ? S(0) : r[i] * r[i] - m;
      a[i] = r[i] * y[i];
    }
    Vec3T<S> x, g;  // the nearest point (first octant), and the outward normal's direction there
    bool off_plane = false;
    // The root leaves u > 0 only when p lies on the shortest axes' plane (a_i = 0 wherever d_i =
    // 0) and F(0) <= 0 there.
    S f0 = S(-1);
    for (int i = 0; i < 3; ++i) {
      if (d[i] > S(0)) {
        const S q = a[i] / d[i];
        f0 += q * q;
      } else if (a[i] > S(0)) {
        f0 = std::numeric_limits<S>::infinity();
        break;
      }
    }
    if (!(f0 > S(0))) {
      off_plane = true;
      S rest = S(1);
      int first_short = -1;
      for (int i = 0; i < 3; ++i) {
        if (d[i] > S(0)) {
          x[i] = r[i] * a[i] / d[i];
          const S q = x[i] / r[i];
          rest -= q * q;
        } else {
          x[i] = S(0);
          if (first_short < 0) first_short = i;
        }
      }
      x[first_short] = r_min * std::sqrt(std::max(S(0), rest));
      g = x.cwiseQuotient(r.cwiseProduct(r));
    } else {
      // F(u) = sum (a_i / (d_i + u))^2 - 1. F(lo) >= 0 (the term of the largest a_i - d_i is
      // 1 there), F(|a|) <= 0 (every term is at most a_i^2 / |a|^2).
      S u = S(0);
      for (int i = 0; i < 3; ++i) u = std::max(u, a[i] - d[i]);
      const S hi = a.norm();
      constexpr S kEps = std::numeric_limits<S>::epsilon();
      bool converged = false;
      for (int step = 0; step < kMaxSteps; ++step) {
        S f = S(-1), slope = S(0);
        for (int i = 0; i < 3; ++i) {
          if (!(a[i] > S(0))) continue;
          const S q = a[i] / (d[i] + u);
          f += q * q;
          slope -= S(2) * q * q / (d[i] + u);
        }
        // Past the root (rounding), or a step below the rounding of u: done.
        const S move = f > S(0) && slope < S(0) ? -f / slope : S(0);
        if (!(move > S(4) * kEps * u)) {
          converged = true;
          break;
        }
        u = std::min(u + move, hi);
      }
      if (!converged) return std::nullopt;
      for (int i = 0; i < 3; ++i) {
        g[i] = y[i] / (d[i] + u);
        x[i] = r[i] * r[i] * g[i];
      }
    }
    // Back to p's octant and scale.
    PointSolidLocal<S> out;
    out.p = p;
    Vec3T<S> normal;
    for (int i = 0; i < 3; ++i) {
      const S sign = p[i] < S(0) ? S(-1) : S(1);
      out.on_solid[i] = sign * x[i] * scale;
      normal[i] = sign * g[i];
    }
    out.out_of_solid = unit_of(normal);
    const Vec3T<S> gap = p - out.on_solid;
    out.signed_distance = in ? -gap.norm() : gap.norm();
    out.tie = in && off_plane;
    if (!is_finite(out.on_solid) || !is_finite(out.out_of_solid) ||
        !std::isfinite(out.signed_distance))
      return std::nullopt;
    return out;
  }
};

template <class T>
requires(SolidCore<T>::value) struct SolidCore<Rounded<T>> : std::true_type {
  using S = typename T::Scalar;
  using Core = typename SolidCore<T>::Core;
  static const Core* core(const Rounded<T>& r) { return SolidCore<T>::core(r.shape); }
  static GapVerdict within_reach(const Core& c, const Vec3T<S>& p, S reach) {
    return SolidCore<T>::within_reach(c, p, reach);
  }
  static std::optional<PointSolidLocal<S>> local(const Core& c, const Vec3T<S>& p) {
    return SolidCore<T>::local(c, p);
  }
};

/// A point core against a solid core, A first or B first.
template <class A, class B>
inline constexpr bool kPointSolid = (PointCore<A>::value && SolidCore<B>::value) ||
                                    (SolidCore<A>::value && PointCore<B>::value);

/// Closest (apart) or deepest (overlapping) points of two cores, in the world frame.
template <class S>
struct CorePair {
  Vec3T<S> on_a;    ///< on A's core
  Vec3T<S> on_b;    ///< on B's core
  Vec3T<S> normal;  ///< unit, from A towards B: the direction B moves to separate
  /// on_b - on_a = distance * normal; negative when the cores overlap (minus the depth).
  S distance;
  /// Overlapping only: another direction is as good (see the solid's local()).
  bool tie;
};

/// The point core of a point-core shape in the frame of the other shape, a solid core or any
/// other (either order).
/// Always inlined: out of line, GCC returned the point through memory, stored a coordinate at a
/// time, for callers that load it two at a time, which stalls on store forwarding (with the range
/// check's and gap_verdict()'s packed reads, a third of a sphere-polytope test).
template <class A, class B>
[[gnu::always_inline]] inline Vec3T<typename A::Scalar> point_in_other_frame(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b) {
  if constexpr (PointCore<B>::value)
    return pose_a.inverse_rotate(SegmentCore<B>::world(b, pose_b, pose_a.translation).centre);
  else
    return pose_b.inverse_rotate(SegmentCore<A>::world(a, pose_a, pose_b.translation).centre);
}

/// The SolidCore of the pair (either order).
template <class A, class B>
using SolidOf = std::conditional_t<SolidCore<A>::value, SolidCore<A>, SolidCore<B>>;

/// The solid core of the pair (either order); null when it has no closed form yet.
template <class A, class B>
const auto* solid_of(const A& a, const B& b) {
  if constexpr (SolidCore<A>::value)
    return SolidCore<A>::core(a);
  else
    return SolidCore<B>::core(b);
}

/// Whether the point core is within `reach` of the solid core, whose closed form is `solid`
/// (solid_of(a, b), when it has one), for the yes/no test (Unsure: GJK decides).
template <class A, class B>
GapVerdict point_solid_verdict(const typename SolidOf<A, B>::Core& solid, const A& a,
                               const PoseT<typename A::Scalar>& pose_a, const B& b,
                               const PoseT<typename A::Scalar>& pose_b, typename A::Scalar reach) {
  return SolidOf<A, B>::within_reach(solid, point_in_other_frame(a, pose_a, b, pose_b), reach);
}

/// A point core against any other core that is not a point or a segment (either order).
template <class A, class B>
inline constexpr bool kPointCorePair = (PointCore<A>::value || PointCore<B>::value) &&
                                       !kSegmentCores<A, B>;

/// A point core against a core with no closed form (a polytope of 64 points or more, which
/// climbs its hull; a hull; a sum): one support call of the other core, in its own frame, along
/// the line from its centre (its origin when it names none) to the point. Its support plane,
/// like GJK's first (which GJK takes along the line of origins), decides most such pairs apart
/// (beyond()); it costs one rotation of the point into the other's frame, where GJK first
/// builds the whole relative pose. When it does not decide, GJK starts from it (intersect.hpp),
/// so the support call is not wasted.
template <class S>
struct PointSupportPlane {
  Vec3T<S> point;    ///< the point core, in the other core's frame
  Vec3T<S> d;        ///< from the other core's centre to the point (the other's frame)
  Vec3T<S> support;  ///< the other core's support point along d (the other's frame)
  S d_sq = S(0);     ///< |d|^2; 0 when the point is at the centre (no plane: nothing computed)

  /// The point lies beyond the support plane by more than `reach`.
  bool beyond(S reach) const {
    return d_sq > S(0) && exceeds_times_length(S(d.dot(point - support)), reach, d, d_sq);
  }
};

/// The PointSupportPlane of a kPointCorePair (either order).
template <class A, class B>
PointSupportPlane<typename A::Scalar> point_support_plane(const A& a,
                                                          const PoseT<typename A::Scalar>& pose_a,
                                                          const B& b,
                                                          const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  const auto& other = [&]() -> const auto& {
    if constexpr (PointCore<B>::value)
      return a;
    else
      return b;
  }
  ();
  PointSupportPlane<S> plane;
  plane.point = point_in_other_frame(a, pose_a, b, pose_b);
  plane.d = plane.point;
  if constexpr (HasCoreCentre<std::remove_cvref_t<decltype(other)>>) plane.d -= other.core_centre();
  plane.d_sq = plane.d.squaredNorm();
  if (!(plane.d_sq > S(0))) {
    plane.d_sq = S(0);
    return plane;
  }
  plane.support = other.support_core(plane.d);
  return plane;
}

/// The point core against the solid core in the solid's frame (PointSolidLocal). Nothing: GJK and
/// EPA answer.
template <class A, class B>
std::optional<PointSolidLocal<typename A::Scalar>> point_solid_local(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b) {
  const auto* solid = solid_of(a, b);
  if (!solid) return std::nullopt;
  return SolidOf<A, B>::local(*solid, point_in_other_frame(a, pose_a, b, pose_b));
}

/// A CorePair from a point of the solid core, the other core's point and the solid's outward
/// normal there (world frame), with A's first whether the solid is A (kSolidIsA) or B.
template <bool kSolidIsA, class S>
[[gnu::always_inline]] inline CorePair<S> ordered_core_pair(const Vec3T<S>& on_solid,
                                                            const Vec3T<S>& on_other,
                                                            const Vec3T<S>& out_of_solid,
                                                            S distance, bool tie) {
  CorePair<S> out;
  out.distance = distance;
  out.tie = tie;
  if constexpr (kSolidIsA) {
    out.on_a = on_solid;
    out.on_b = on_other;
    out.normal = out_of_solid;
  } else {
    out.on_a = on_other;
    out.on_b = on_solid;
    out.normal = -out_of_solid;
  }
  return out;
}

/// point_solid_local()'s answer as the cores' points and normal in the world frame, A's and B's.
/// Always inlined: with the pose's transforms written out, GCC returned the points through memory
/// a coordinate at a time, and the caller's packed reads stalled on store forwarding (sphere-box
/// distance 32 -> 38 ns; inlined, 33, and contact 41 -> 36).
template <class A, class B>
[[gnu::always_inline]] inline CorePair<typename A::Scalar> point_solid_world(
    const PointSolidLocal<typename A::Scalar>& local, const PoseT<typename A::Scalar>& pose_a,
    const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  constexpr bool kSolidIsA = SolidCore<A>::value;
  const PoseT<S>& solid_pose = kSolidIsA ? pose_a : pose_b;
  return ordered_core_pair<kSolidIsA>(solid_pose.apply(local.on_solid), solid_pose.apply(local.p),
                                      solid_pose.rotate(local.out_of_solid), local.signed_distance,
                                      local.tie);
}

}  // namespace mink::detail
