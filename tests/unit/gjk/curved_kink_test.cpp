// An ellipsoid (or a second rim) against a cone's slant or a cylinder's rim, where the answer is
// known exactly by construction: the ellipsoid is placed so that its support point along -n lies
// `gap` beyond a point e of the feature along n, with n the feature's normal there. The plane
// through e orthogonal to n has the cone or cylinder on one side and the ellipsoid `gap` away on
// the other, so the distance is the gap, the normal n and the closest points e and e + gap n (the
// ellipsoid is strictly convex, and the cone's or cylinder's support along n is e's feature).
//
// - A cone's slant: its support along n is the segment from the apex to a rim point, and the
//   support function of A - B has a kink along the small circle of such normals; the minimum
//   lies on it, sharp across it and curved along it. Touching to 1e-13 of the size, no Newton
//   step ran before stop 54 (the normal was taken to be ill-conditioned at touching): GJK's
//   normal stayed 1.6e-6 rad off and the points 5e-7 of the size off (probe 52, s11_525).
// - A cylinder's rim seen from close to its axis: its support point moves round the rim r / sin
//   of the angle to the axis as fast as the direction turns, faster than a core of the size's
//   curvature, and Newton's step took it for a kink and stopped at EPA's 1e-5 rad (s11_342).
// - Two rims, one of them seen from 1e-5 to 1e-3 rad off its axis: there the rim's curvature
//   along the rim is up to 1e5 times the other's and the Hessian of h nearly singular. A forward
//   difference made it indefinite, and no Newton step ran: the normal stayed up to 6e-7 rad off
//   and the points 1e-6 of the size (stop 62's curved probe, c11_112).
// - A capsule's end beside a swept cylinder's side line: a kink that Newton's step crossed
//   unseen (swept_side_scene()).
// - A rim over a swept cone's base: the sum's face had lost its rim (swept_cap_scene()).
// - An ellipsoid on the round end of a cap swept across its axis (stadium_scene()).
// - A capsule's end, or a cylinder's rim, just short of where its axis or side line crosses a
//   side line seen along the normal (side_end_scene(), side_rim_scene()).
// - A rim against a cap tilted 1e-9 to 1e-7 rad from facing it, the cap's rim point the contact
//   (rim_rim_scene()), and a side line across such a cap (side_cap_scene()).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "mink/mink.hpp"
#include "oracle/check.hpp"
#include "oracle/random.hpp"

namespace {

using mink::Pose;
using mink::Shape;
using mink::Vec3;

struct KinkScene {
  Shape solid, other;  // other: the ellipsoid, or the second rim's shape
  Pose pose_solid, pose_other;
  Vec3 contact;    // e: on the cone or cylinder, world frame
  Vec3 normal;     // n: from the cone or cylinder towards the other shape
  double gap = 0;  // < 0: the shapes overlap by -gap
  double size = 0;
  std::string note;
};

// Places an ellipsoid of random radii and orientation with its support point along -normal at
// contact + gap * normal.
void place_ellipsoid(oracle::Rng& rng, KinkScene& s) {
  const Vec3 radii(rng.uniform(0.05, 1), rng.uniform(0.05, 1), rng.uniform(0.05, 1));
  s.other = Shape::ellipsoid(radii).value();
  const mink::Quat q = rng.rotation();
  const Vec3 d = q.conjugate() * (-s.normal);
  const Vec3 scaled = radii.cwiseProduct(d);
  const Vec3 local_support = radii.cwiseProduct(scaled) / scaled.norm();
  s.size += radii.maxCoeff();
  const Vec3 target = s.contact + s.gap * s.normal;
  s.pose_other = Pose::from(target - q * local_support, q);
}

// A cone's or cylinder's size (random), its pose (sometimes 1e3 from the origin), and e and n
// from its frame to the world.
struct Solid {
  double radius, half_height;
  Pose pose;
};

Solid random_solid(oracle::Rng& rng) {
  Solid solid{rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5), Pose::identity()};
  const double far = rng.chance(0.2) ? 1e3 : 0;
  const Vec3 centre = rng.in_ball(3) + Vec3::Constant(far);
  solid.pose = Pose::from(centre, rng.rotation());
  return solid;
}

void set_contact(const Solid& solid, const Vec3& e, const Vec3& n, KinkScene& s) {
  s.pose_solid = solid.pose;
  s.contact = solid.pose.apply(e);
  s.normal = solid.pose.rotate(n);
  s.size = std::hypot(solid.radius, solid.half_height);
}

KinkScene slant_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  KinkScene s;
  const Solid solid = random_solid(rng);
  const double radius = solid.radius, half_height = solid.half_height;
  s.solid = Shape::cone(radius, half_height).value();
  // The slant at azimuth phi runs from the apex (0, 0, h) to the rim point (r cos, r sin, -h);
  // (2h cos, 2h sin, r) is orthogonal to it, outwards.
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const Vec3 apex(0, 0, half_height);
  const Vec3 rim(radius * std::cos(phi), radius * std::sin(phi), -half_height);
  const Vec3 e = apex + rng.uniform(0.2, 0.8) * (rim - apex);
  const Vec3 n =
      Vec3(2 * half_height * std::cos(phi), 2 * half_height * std::sin(phi), radius).normalized();
  set_contact(solid, e, n, s);
  s.gap = s.size * rng.uniform(-1e-13, 1e-13);
  place_ellipsoid(rng, s);
  s.note =
      "cone slant, gap/size = " + std::to_string(s.gap / s.size) + ", " + oracle::seed_note(seed);
  return s;
}

// A rim point of a cylinder (top rim) or a cone (base rim) of the given size at azimuth phi, and
// the normal there tilted by alpha from the rim's cap or base normal towards the rim: inside the
// rim's cone of normals (alpha < pi / 2 for both), so that rim point alone is the support point.
struct RimPoint {
  Shape shape;
  Vec3 point, normal;  // in the shape's frame
};

RimPoint rim_point(bool cone, double radius, double half_height, double phi, double alpha) {
  const double z = cone ? -1 : 1;  // the cone's rim is its base's, at -h, the normal along -z
  return {
      cone ? Shape::cone(radius, half_height).value()
           : Shape::cylinder(radius, half_height).value(),
      Vec3(radius * std::cos(phi), radius * std::sin(phi), z * half_height),
      Vec3(std::sin(alpha) * std::cos(phi), std::sin(alpha) * std::sin(phi), z * std::cos(alpha))};
}

// The other shape: `rim` with its point at contact + gap n and its normal there along -n, turned
// about n at random.
void place_rim(oracle::Rng& rng, const RimPoint& rim, KinkScene& s) {
  s.other = rim.shape;
  const mink::Quat spin(Eigen::AngleAxisd(rng.uniform(0, 2 * std::numbers::pi), -s.normal));
  const mink::Quat q = spin * mink::Quat::FromTwoVectors(rim.normal, -s.normal);
  s.pose_other = Pose::from(Vec3(s.contact + s.gap * s.normal - q * rim.point), q);
}

KinkScene rim_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  KinkScene s;
  const Solid solid = random_solid(rng);
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const double alpha = rng.log_uniform(0.005, 0.3);
  const RimPoint rim = rim_point(false, solid.radius, solid.half_height, phi, alpha);
  s.solid = rim.shape;
  set_contact(solid, rim.point, rim.normal, s);
  s.gap = s.size * rng.log_uniform(1e-6, 1e-1);
  place_ellipsoid(rng, s);
  s.note = "cylinder rim, " + std::to_string(alpha) +
           " rad from the axis, gap/size = " + std::to_string(s.gap / s.size) + ", " +
           oracle::seed_note(seed);
  return s;
}

// Rim against rim: the first shape's rim seen from `near_lo` to `near_hi` rad off its axis, the
// second's from `tilt_lo` to `tilt_hi` rad off its axis (by default anywhere in its cone of
// normals), the second turned about the normal at random. Closer to the first's axis than 1e-5 rad,
// GJK's normal may lie beyond the axis, where the rim's point is across the rim, and Cartesian
// Newton steps from there did not always reach the minimum (3 of 300 scenes from 1e-6 rad;
// docs/benchmarks.md, "Stop 65"); steps in polar coordinates about the axis do
// (newton_about_axis()).
KinkScene rim_rim_scene(std::uint64_t seed, double near_lo, double near_hi, double tilt_lo = 1e-6,
                        double tilt_hi = 1.2) {
  oracle::Rng rng(seed);
  KinkScene s;
  const Solid solid = random_solid(rng);
  // One draw per statement: the order of a call's arguments is the compiler's choice.
  const double near_axis = rng.log_uniform(near_lo, near_hi);
  const bool cone_a = rng.chance(0.5);
  const double phi_a = rng.uniform(0, 2 * std::numbers::pi);
  const RimPoint a = rim_point(cone_a, solid.radius, solid.half_height, phi_a, near_axis);
  s.solid = a.shape;
  set_contact(solid, a.point, a.normal, s);
  s.gap = s.size * rng.log_uniform(1e-6, 1e-1);
  const double radius = rng.uniform(0.2, 1.5), half_height = rng.uniform(0.2, 1.5);
  const bool cone_b = rng.chance(0.5);
  const double phi_b = rng.uniform(0, 2 * std::numbers::pi);
  const double alpha_b = rng.log_uniform(tilt_lo, tilt_hi);
  place_rim(rng, rim_point(cone_b, radius, half_height, phi_b, alpha_b), s);
  s.size += std::hypot(radius, half_height);
  char note[128];
  std::snprintf(note, sizeof note,
                "rims, the first %.2e rad from its axis, the second %.2e, gap/size = %.2e, ",
                near_axis, alpha_b, s.gap / s.size);
  s.note = note + oracle::seed_note(seed);
  return s;
}

// A capsule's end beside the side of a flat cylinder swept by a segment: the sum's support along
// the normal n (radial) is the side line moved by the segment's end, and h has a kink across it.
// The capsule's segment points away from the side, so its end centre p, (gap + radius) from the
// line along n, is the capsule's nearest core point: the closest points are e on the line and
// p - radius n. GJK left the normal 6e-7 rad off in 13 % of these scenes, and Newton's step, taken
// on the smooth side of the kink, drew 5e-3 rad without a jump longer than a smooth core's over
// that turn, so the kink went unseen and the points stayed up to 4e-7 of the size off (stop 62's
// curved probe, c11_137).
KinkScene swept_side_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  KinkScene s;
  Solid solid = random_solid(rng);
  solid.half_height = solid.radius * rng.log_uniform(1e-3, 1);
  const Vec3 sweep = rng.uniform(0, 0.4) * rng.unit();
  s.solid =
      Shape::sum(*Shape::segment(-sweep, sweep), *Shape::cylinder(solid.radius, solid.half_height))
          .value();
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const Vec3 radial(std::cos(phi), std::sin(phi), 0);
  const Vec3 sweep_end = sweep.dot(radial) >= 0 ? sweep : Vec3(-sweep);
  const double z = solid.half_height * rng.uniform(-0.99, 0.99);
  set_contact(solid, Vec3(sweep_end + solid.radius * radial + Vec3(0, 0, z)), radial, s);
  s.size += sweep.norm();
  s.gap = s.size * rng.log_uniform(1e-5, 1e-1);
  const double radius = rng.uniform(0.1, 1), half_height = rng.uniform(0.1, 1);
  s.other = Shape::capsule(radius, half_height).value();
  // The capsule's axis: n tilted by up to 0.25 either way along the side, its -z end nearest.
  const Vec3 along = s.pose_solid.rotate(Vec3(-radial.y(), radial.x(), 0));
  const Vec3 up = s.pose_solid.rotate(Vec3(0, 0, 1));
  const double tilt_along = rng.uniform(-0.25, 0.25);
  const double tilt_up = rng.uniform(-0.25, 0.25);
  const Vec3 axis = (s.normal + tilt_along * along + tilt_up * up).normalized();
  const Vec3 end = s.contact + (s.gap + radius) * s.normal;
  s.pose_other =
      Pose::from(Vec3(end + half_height * axis), mink::Quat::FromTwoVectors(Vec3(0, 0, 1), axis));
  s.size += radius + half_height;
  s.note = "swept cylinder's side, half height / radius = " +
           std::to_string(solid.half_height / solid.radius) +
           ", gap/size = " + std::to_string(s.gap / s.size) + ", " + oracle::seed_note(seed);
  return s;
}

// A cylinder's rim over the base of a cone swept along its axis by a segment: the sum's face is
// the base moved by the segment's end, the rim's point (seen from 0.05 to 1.2 rad off its axis)
// lies `gap` beyond a point e of it along the base's normal, often between the base's rim and
// the polygon of 16 samples of it that stood for the sum's face: the point was taken to lie
// outside the face, and the points stayed GJK's, 4e-7 of the size off (stop 62's curved probe,
// c11_398).
KinkScene swept_cap_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  KinkScene s;
  Solid solid = random_solid(rng);
  const double sweep = rng.uniform(0.05, 0.5);
  s.solid = Shape::sum(*Shape::segment(Vec3(0, 0, -sweep), Vec3(0, 0, sweep)),
                       *Shape::cone(solid.radius, solid.half_height))
                .value();
  const double theta = rng.uniform(0, 2 * std::numbers::pi);
  const double from_axis =
      solid.radius * (rng.chance(0.5) ? rng.uniform(0.981, 0.999) : rng.uniform(0, 0.999));
  const Vec3 e(from_axis * std::cos(theta), from_axis * std::sin(theta),
               -solid.half_height - sweep);
  set_contact(solid, e, Vec3(0, 0, -1), s);
  s.size += sweep;
  s.gap = s.size * rng.log_uniform(1e-6, 1e-1);
  const double radius = rng.uniform(0.2, 1.5), half_height = rng.uniform(0.2, 1.5);
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const double alpha = rng.uniform(0.05, 1.2);
  place_rim(rng, rim_point(false, radius, half_height, phi, alpha), s);
  s.size += std::hypot(radius, half_height);
  s.note = "rim over a swept cone's base, " + std::to_string(from_axis / solid.radius) +
           " of its radius from the axis, gap/size = " + std::to_string(s.gap / s.size) + ", " +
           oracle::seed_note(seed);
  return s;
}

// A cone's base or a cylinder's cap swept across its axis by a segment: the sum's face is a
// stadium, and e lies on one of its round ends at or just inside the outline, where the polygon
// of the outline's samples cuts a chord off: an ellipsoid touching there kept EPA's points, 1e-6
// of the size off (stop 62's curved probe, c11_2558). `touching`: gaps of 1e-13 of the size,
// else 1e-6 to 1e-1.
KinkScene stadium_scene(std::uint64_t seed, bool touching) {
  oracle::Rng rng(seed);
  KinkScene s;
  const Solid solid = random_solid(rng);
  const bool cone = rng.chance(0.5);
  const double sweep = rng.uniform(0.05, 0.5);
  const double psi = rng.uniform(0, 2 * std::numbers::pi);
  const Vec3 across(std::cos(psi), std::sin(psi), 0);
  s.solid = Shape::sum(*Shape::segment(Vec3(-sweep * across), Vec3(sweep * across)),
                       cone ? *Shape::cone(solid.radius, solid.half_height)
                            : *Shape::cylinder(solid.radius, solid.half_height))
                .value();
  const double end = rng.chance(0.5) ? 1 : -1;
  const double theta = psi + (end > 0 ? 0 : std::numbers::pi) +
                       rng.uniform(-std::numbers::pi / 2, std::numbers::pi / 2);
  const double from_centre = solid.radius * (rng.chance(0.5) ? 1 : rng.uniform(0.99, 1));
  const Vec3 e = end * sweep * across + from_centre * Vec3(std::cos(theta), std::sin(theta), 0) +
                 Vec3(0, 0, -solid.half_height);
  set_contact(solid, e, Vec3(0, 0, -1), s);
  s.size += sweep;
  s.gap = touching ? s.size * rng.uniform(-1e-13, 1e-13) : s.size * rng.log_uniform(1e-6, 1e-1);
  place_ellipsoid(rng, s);
  s.note = std::string(cone ? "cone" : "cylinder") + "'s cap swept across, " +
           std::to_string(from_centre / solid.radius) +
           " of its radius from the end's centre, gap/size = " + std::to_string(s.gap / s.size) +
           ", " + oracle::seed_note(seed);
  return s;
}

// A point e on a cone's side line or a cylinder's (random solid), its normal n there; returns
// which solid.
const char* place_on_side_line(oracle::Rng& rng, KinkScene& s) {
  const Solid solid = random_solid(rng);
  const double radius = solid.radius, half_height = solid.half_height;
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const Vec3 radial(std::cos(phi), std::sin(phi), 0);
  const bool cone = rng.chance(0.5);
  const double along_line = rng.uniform(0.05, 0.95);
  if (cone) {
    s.solid = Shape::cone(radius, half_height).value();
    const Vec3 apex(0, 0, half_height), rim(radius * radial - Vec3(0, 0, half_height));
    set_contact(solid, Vec3(apex + along_line * (rim - apex)),
                Vec3(2 * half_height * radial + Vec3(0, 0, radius)).normalized(), s);
  } else {
    s.solid = Shape::cylinder(radius, half_height).value();
    set_contact(solid, Vec3(radius * radial + Vec3(0, 0, (2 * along_line - 1) * half_height)),
                radial, s);
  }
  return cone ? "cone's" : "cylinder's";
}

// A direction rising 1e-9 to 1e-2 rad from the plane orthogonal to n, at any angle in it.
Vec3 rising_axis(oracle::Rng& rng, const Vec3& n, double& rise) {
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  const double turn = rng.uniform(0, 2 * std::numbers::pi);
  rise = rng.log_uniform(1e-9, 1e-2);
  return std::cos(rise) * (std::cos(turn) * t1 + std::sin(turn) * t2) + std::sin(rise) * n;
}

std::string rising_note(const char* solid, const char* what, double rise, const KinkScene& s,
                        std::uint64_t seed) {
  char note[128];
  std::snprintf(note, sizeof note, "%s side line, %s rising %.2e rad, gap/size = %.2e, ", solid,
                what, rise, s.gap / s.size);
  return note + oracle::seed_note(seed);
}

// A capsule's end beside a cone's side line or a cylinder's: the end's centre p lies
// (gap + radius) beyond the line's point e along its normal n, and the capsule's axis leaves p
// rising from the line's tangent plane (rising_axis()). The solid lies below that plane and the
// rest of the axis above p, so p is the capsule's nearest core point: the closest points are e
// and p - radius n. The minimum then lies among the directions whose support is the capsule's
// end, within the rise of where the lines cross, and h is flat there to second order: a pair
// 3.6e-8 rad off passed for one at the crossing, the points 5e-7 of the size off (stop 62's
// curved probe, c11_2; newton_at_end()).
// What both scenes below draw, in this order: the side line's point, the gap, the other shape's
// radius and half height, and its axis rising from the tangent plane.
struct RisingScene {
  KinkScene s;
  const char* solid;
  double radius, half_height, rise = 0;
  Vec3 axis;
};

RisingScene rising_scene(oracle::Rng& rng) {
  RisingScene r;
  r.solid = place_on_side_line(rng, r.s);
  r.s.gap = r.s.size * rng.log_uniform(1e-11, 1e-1);
  r.radius = rng.uniform(0.1, 1);
  r.half_height = rng.uniform(0.1, 1);
  r.axis = rising_axis(rng, r.s.normal, r.rise);
  return r;
}

KinkScene side_end_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  RisingScene r = rising_scene(rng);
  KinkScene& s = r.s;
  s.other = Shape::capsule(r.radius, r.half_height).value();
  const Vec3 end = s.contact + (s.gap + r.radius) * s.normal;
  s.pose_other = Pose::from(Vec3(end + r.half_height * r.axis),
                            mink::Quat::FromTwoVectors(Vec3(0, 0, 1), r.axis));
  s.size += r.radius + r.half_height;
  s.note = rising_note(r.solid, "capsule's axis", r.rise, s, seed);
  return s;
}

// The same with a cylinder whose side line rises from the tangent plane: its support along -n
// is the end of that line on its lower rim, q = c - h a + r u (a its axis, u the unit part of -n
// across a), placed at e + gap n. That end is a rim's point, not a vertex, and newton_at_end()
// takes the rim's cap instead (c11_521: the points 5e-7 of the size off).
KinkScene side_rim_scene(std::uint64_t seed) {
  oracle::Rng rng(seed);
  RisingScene r = rising_scene(rng);
  KinkScene& s = r.s;
  s.other = Shape::cylinder(r.radius, r.half_height).value();
  const Vec3 down = -s.normal;
  const Vec3 across = (down - down.dot(r.axis) * r.axis).normalized();
  const Vec3 centre = s.contact + s.gap * s.normal + r.half_height * r.axis - r.radius * across;
  const mink::Quat spin(Eigen::AngleAxisd(rng.uniform(0, 2 * std::numbers::pi), r.axis));
  s.pose_other = Pose::from(centre, spin * mink::Quat::FromTwoVectors(Vec3(0, 0, 1), r.axis));
  s.size += std::hypot(r.radius, r.half_height);
  s.note = rising_note(r.solid, "cylinder's side", r.rise, s, seed);
  return s;
}

// A cap tilted 1e-9 to 1e-6 rad from facing a cone's side line or a cylinder's, whose rim point
// q, its support along -n, is placed at e + gap n: the closest points are e and q. h has kinks
// across the line and across the cap's normal there, Newton's steps stopped at GJK's normal, and
// the side line's place round its core moved with the normal: the points stayed up to 6e-5 of
// the size off (stop 62's curved probe, c11_2318, c11_2958; rim_against_edge()). 277 of these
// 300 scenes failed then; at 20 times as many, 6 of 6,000 still do (seeds past 70800; 7 before
// stop 72). `tilt_lo`, `tilt_hi`: the range of the cap's tilt (rad), log-uniform.
KinkScene side_cap_scene(std::uint64_t seed, double tilt_lo = 1e-9, double tilt_hi = 1e-6) {
  oracle::Rng rng(seed);
  KinkScene s;
  const char* solid = place_on_side_line(rng, s);
  s.gap = s.size * rng.log_uniform(1e-9, 1e-1);
  const double radius = rng.uniform(0.2, 1.5), half_height = rng.uniform(0.2, 1.5);
  const bool cone = rng.chance(0.5);
  const double phi = rng.uniform(0, 2 * std::numbers::pi);
  const double tilt = rng.log_uniform(tilt_lo, tilt_hi);
  place_rim(rng, rim_point(cone, radius, half_height, phi, tilt), s);
  s.size += std::hypot(radius, half_height);
  char note[128];
  std::snprintf(note, sizeof note, "%s side line, a %s cap tilted %.2e rad, gap/size = %.2e, ",
                solid, cone ? "cone's" : "cylinder's", tilt, s.gap / s.size);
  s.note = note + oracle::seed_note(seed);
  return s;
}

// A cone's base or a cylinder's cap swept across its axis by a segment (a stadium), tilted 1e-9 to
// 1e-6 rad from facing a side line (`side_line`) or a rim's point seen from 0.05 to 1.2 rad off
// its axis: the stadium's support along -n is a point q on the rim of one round end, placed at
// e + gap n, so the closest points are e and q. The stadium counted as a face there, whose round
// ends neither rim_against_edge() nor newton_about_axis() took for rims, and EPA's or GJK's
// points stayed up to 3e-4 of the size off (stop 62's curved probe, c11_2077, c11_1960, c12_364).
KinkScene tilted_stadium_scene(std::uint64_t seed, bool side_line) {
  oracle::Rng rng(seed);
  KinkScene s;
  const char* first = "a rim's point";
  if (side_line) {
    first = place_on_side_line(rng, s);
  } else {
    const Solid solid = random_solid(rng);
    const bool cone = rng.chance(0.5);
    const double phi = rng.uniform(0, 2 * std::numbers::pi);
    const double alpha = rng.uniform(0.05, 1.2);
    const RimPoint rim = rim_point(cone, solid.radius, solid.half_height, phi, alpha);
    s.solid = rim.shape;
    set_contact(solid, rim.point, rim.normal, s);
  }
  s.gap = s.size * rng.log_uniform(1e-9, 1e-1);
  const double radius = rng.uniform(0.2, 1.5), half_height = rng.uniform(0.2, 1.5);
  const bool cone = rng.chance(0.5);
  const double sweep = rng.uniform(0.05, 0.5);
  const double psi = rng.uniform(0, 2 * std::numbers::pi);
  const Vec3 across(std::cos(psi), std::sin(psi), 0);
  // The rim's point on the round end across from psi's (end -1) or at it (end 1), away from
  // where the end meets the straight sides; the normal there tilted from -z towards it.
  const double end = rng.chance(0.5) ? 1 : -1;
  const double theta = psi + (end > 0 ? 0 : std::numbers::pi) + rng.uniform(-1.5, 1.5);
  const double tilt = rng.log_uniform(1e-9, 1e-6);
  const Vec3 radial(std::cos(theta), std::sin(theta), 0);
  const RimPoint stadium{
      Shape::sum(*Shape::segment(Vec3(-sweep * across), Vec3(sweep * across)),
                 cone ? *Shape::cone(radius, half_height) : *Shape::cylinder(radius, half_height))
          .value(),
      Vec3(end * sweep * across + radius * radial - Vec3(0, 0, half_height)),
      Vec3(std::sin(tilt) * radial - Vec3(0, 0, std::cos(tilt)))};
  place_rim(rng, stadium, s);
  s.size += std::hypot(radius, half_height) + sweep;
  char note[160];
  std::snprintf(note, sizeof note,
                "%s against a swept %s's round end tilted %.2e rad, gap/size = %.2e, ", first,
                cone ? "cone" : "cylinder", tilt, s.gap / s.size);
  s.note = note + oracle::seed_note(seed);
  return s;
}

double kink_far_rounding(const KinkScene& s) {
  return oracle::world_rounding(s.pose_solid.translation);
}

// One argument order: `flip` puts the other shape first, which turns the normal round. Touching
// pairs answer both points at the contact.
template <class Result>
void expect_exact(const KinkScene& s, const Result& r, bool flip, bool touching) {
  const double tolerance = 1e-9 * s.size + kink_far_rounding(s);
  const std::string order = flip ? " (other first)" : " (other second)";
  const Vec3 on_solid = s.contact;
  const Vec3 on_other = touching ? s.contact : Vec3(s.contact + s.gap * s.normal);
  if (touching) {
    ASSERT_TRUE(r.intersect) << s.note << order;
  } else {
    ASSERT_EQ(r.status, mink::Status::Separated) << s.note << order;
    EXPECT_NEAR(r.distance, s.gap, tolerance) << s.note << order;
  }
  EXPECT_LE(oracle::angle(r.normal, flip ? Vec3(-s.normal) : s.normal), 1e-9) << s.note << order;
  EXPECT_LE((r.point_a - (flip ? on_other : on_solid)).norm(), tolerance) << s.note << order;
  EXPECT_LE((r.point_b - (flip ? on_solid : on_other)).norm(), tolerance) << s.note << order;
}

TEST(CurvedKink, EllipsoidTouchingAConeSlant) {
  const int count = oracle::sweep_count(300, 100);
  for (int i = 0; i < count; ++i) {
    const KinkScene s = slant_scene(54100 + i);
    expect_exact(s, mink::contact(s.solid, s.pose_solid, s.other, s.pose_other), false, true);
    expect_exact(s, mink::contact(s.other, s.pose_other, s.solid, s.pose_solid), true, true);
    if (::testing::Test::HasFailure()) break;  // one scene's messages, not hundreds
  }
}

// `count` scenes apart from `make_scene(first_seed + i)`: distance() and contact(), both orders.
template <class MakeScene>
void expect_exact_apart(MakeScene make_scene, std::uint64_t first_seed, int count) {
  for (int i = 0; i < count; ++i) {
    const KinkScene s = make_scene(first_seed + i);
    expect_exact(s, mink::distance(s.solid, s.pose_solid, s.other, s.pose_other), false, false);
    expect_exact(s, mink::distance(s.other, s.pose_other, s.solid, s.pose_solid), true, false);
    expect_exact(s, mink::contact(s.solid, s.pose_solid, s.other, s.pose_other), false, false);
    expect_exact(s, mink::contact(s.other, s.pose_other, s.solid, s.pose_solid), true, false);
    if (::testing::Test::HasFailure()) break;
  }
}

TEST(CurvedKink, EllipsoidBesideACylinderRimNearItsAxis) {
  expect_exact_apart(rim_scene, 54500, oracle::sweep_count(300, 100));
}

TEST(CurvedKink, CapsuleEndBesideASweptCylindersSide) {
  expect_exact_apart(swept_side_scene, 68100, oracle::sweep_count(300, 100));
}

TEST(CurvedKink, CapsuleEndBesideASideLine) {
  expect_exact_apart(side_end_scene, 69100, oracle::sweep_count(300, 100));
}

TEST(CurvedKink, CylindersRimBesideASideLine) {
  expect_exact_apart(side_rim_scene, 69500, oracle::sweep_count(300, 100));
}

TEST(CurvedKink, RimOverASweptConesBase) {
  expect_exact_apart(swept_cap_scene, 68700, oracle::sweep_count(300, 100));
}

TEST(CurvedKink, EllipsoidBesideASweptCapsRoundEnd) {
  expect_exact_apart([](std::uint64_t seed) { return stadium_scene(seed, false); }, 74100,
                     oracle::sweep_count(300, 100));
}

TEST(CurvedKink, EllipsoidTouchingASweptCapsRoundEnd) {
  const int count = oracle::sweep_count(300, 100);
  for (int i = 0; i < count; ++i) {
    const KinkScene s = stadium_scene(74500 + i, true);
    expect_exact(s, mink::contact(s.solid, s.pose_solid, s.other, s.pose_other), false, true);
    expect_exact(s, mink::contact(s.other, s.pose_other, s.solid, s.pose_solid), true, true);
    if (::testing::Test::HasFailure()) break;
  }
}

TEST(CurvedKink, RimBesideARimNearItsAxis) {
  expect_exact_apart([](std::uint64_t seed) { return rim_rim_scene(seed, 1e-5, 1e-3); }, 65100,
                     oracle::sweep_count(300, 100));
}

// Closer still: the rim's point turns up to 1e6 times faster than the normal. Closer than that,
// the rounding of the normal's components across the axis (1e-16 of it, turned into the rim's
// frame) moves the rim's point by 1e-16 / psi of its radius, beyond 1e-9 below psi = 1e-7.
TEST(CurvedKink, RimBesideARimCloseToItsAxis) {
  expect_exact_apart([](std::uint64_t seed) { return rim_rim_scene(seed, 1e-6, 1e-5); }, 68400,
                     oracle::sweep_count(300, 100));
}

// A rim against a cap tilted 1e-9 to 1e-7 rad from the normal, whose rim point is the contact:
// the first rim's point, seen along the cap's axis, lies over the cap by up to the normal's error
// times its radius, not beyond its rim, and Newton's steps in polar coordinates about the cap's
// axis were not tried (kRimContactReach): the normal stayed 3e-7 rad off and the points 2e-7 of
// the size (stop 62's curved probe, c11_1521). 260 of these 300 scenes failed then; at 20 times
// as many, 7 of 6,000 still do (gaps of 5e-7 to 9e-5 of the size; seeds past 71000, beyond the
// default count).
TEST(CurvedKink, RimBesideANearlyFacingCap) {
  expect_exact_apart([](std::uint64_t seed) { return rim_rim_scene(seed, 0.05, 1.2, 1e-9, 1e-7); },
                     70100, oracle::sweep_count(300, 100));
}

TEST(CurvedKink, SideLineAcrossANearlyFacingCap) {
  expect_exact_apart([](std::uint64_t seed) { return side_cap_scene(seed); }, 70500,
                     oracle::sweep_count(300, 100));
}

// A rim's point against a side line, the cap turned 1e-6 to 1.2 rad from the normal: the
// support feature was a plain point, Newton's steps settled with the normal up to 1e-9 rad off
// (flat to second order along the side line's kink), and 84 of these 300 scenes failed (1,344 of
// 6,000 at 20 times as many). The rim point moved along its rim (rim_against_edge()) leaves none
// here, and 15 of the 6,000 (47 with rounds that had to settle to 64 eps, at most 6), their points
// up to 3e-8 of the size off.
TEST(CurvedKink, RimPointAgainstASideLine) {
  expect_exact_apart([](std::uint64_t seed) { return side_cap_scene(seed, 1e-6, 1.2); }, 72100,
                     oracle::sweep_count(300, 100));
}

TEST(CurvedKink, SideLineAgainstATiltedStadiumsEnd) {
  expect_exact_apart([](std::uint64_t seed) { return tilted_stadium_scene(seed, true); }, 76100,
                     oracle::sweep_count(300, 100));
}

TEST(CurvedKink, RimPointAgainstATiltedStadiumsEnd) {
  expect_exact_apart([](std::uint64_t seed) { return tilted_stadium_scene(seed, false); }, 76500,
                     oracle::sweep_count(300, 100));
}

}  // namespace
