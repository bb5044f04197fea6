// Fuzz target: two shapes of any kind and size and their poses from the input, then every query
// (intersect, distance, contact, manifold) on them. A valid query must answer with finite numbers,
// a unit normal, consistent flags and points that agree with the distance or depth; an invalid
// one must say why; neither may crash, read out of bounds (sanitizers) or hang (each query's
// loops are capped). Any broken promise aborts with a message. A typed pair read from the rest of
// the input then goes through the templated queries the same way.
#include <cstdio>
#include <cstdlib>
#include <variant>
#include <vector>

#include "fuzz_input.hpp"
#include "mink/mink.hpp"

namespace {

using mink::Shape;
using mink::Status;
using mink::Vec3;

[[noreturn]] void fail(const char* what, int query) {
  std::fprintf(stderr, "fuzz_queries: %s (query %d)\n", what, query);
  std::abort();
}

/// A shape of any kind from the input, or nothing when its parameters are rejected (which is
/// itself checked: a rejection must come with a reason).
mink::Expected<Shape> make_shape(mink::fuzz::FuzzInput& in, int depth) {
  switch (in.choice(depth > 0 ? 11 : 13)) {
    case 0:
      return Shape::sphere(in.length());
    case 1:
      return Shape::box(in.lengths());
    case 2:
      return Shape::capsule(in.length(), in.length());
    case 3:
      return Shape::cylinder(in.length(), in.length());
    case 4:
      return Shape::cone(in.length(), in.length());
    case 5:
      return Shape::ellipsoid(in.lengths());
    case 6:
      return Shape::point(in.vec3());
    case 7:
      return Shape::segment(in.vec3(), in.vec3());
    case 8:
      return Shape::triangle(in.vec3(), in.vec3(), in.vec3());
    case 9:
    case 10: {
      // Up to 12 points, often repeated (duplicates) or collinear.
      std::vector<Vec3> points;
      const int n = in.choice(13);
      for (int i = 0; i < n; ++i) {
        const int how = in.choice(4);
        if (how == 0 && !points.empty()) {
          points.push_back(points[in.choice(static_cast<int>(points.size()))]);
        } else if (how == 1 && points.size() >= 2) {
          const double t = in.value();
          points.push_back(points[0] + t * (points[1] - points[0]));
        } else {
          points.push_back(in.vec3());
        }
      }
      return in.choice(2) ? Shape::polytope(points) : Shape::convex_hull(points);
    }
    case 11: {
      auto a = make_shape(in, depth + 1);
      auto b = make_shape(in, depth + 1);
      if (!a || !b) return a ? b : a;
      return Shape::sum(a.value(), b.value());
    }
    default: {
      auto a = make_shape(in, depth + 1);
      if (!a) return a;
      return Shape::rounded(a.value(), in.length());
    }
  }
}

/// Builds the face planes of every small polytope in `shape`, as kPolytopePlanesAfterQueries
/// queries on a kept shape would: the closed forms that read them (a point or sphere against a
/// polytope, the first support call of two polytopes, a corner against a solid) run only then,
/// and a one-off query never reaches them.
void build_face_planes(const Shape& shape) {
  for (const mink::Core& core : shape.cores())
    if (const auto* polytope = std::get_if<mink::SharedPolytope>(&core))
      (void)(*polytope)->build_face_planes();
}

bool finite(const Vec3& v) {
  return v.allFinite();
}

/// Promises every answer keeps: InvalidInput exactly when there is an error, and then a reason.
template <class Result>
void check_common(const Result& r, int query) {
  if (r.status == Status::InvalidInput) {
    if (!r.error) fail("InvalidInput without a reason", query);
    return;
  }
  if (r.error) fail("an error with a status other than InvalidInput", query);
}

void check_distance(const mink::DistanceResult& r, double scale) {
  check_common(r, 1);
  if (r.status == Status::InvalidInput) return;
  if (!(std::isfinite(r.distance) && r.distance >= 0)) fail("distance not finite and >= 0", 1);
  if (!std::isfinite(r.error_bound) || r.error_bound < 0) fail("bad error_bound", 1);
  if (r.intersect) {
    if (r.distance != 0) fail("intersecting with a distance", 1);
    return;
  }
  if (!finite(r.normal) || !finite(r.point_a) || !finite(r.point_b)) fail("non-finite output", 1);
  if (std::abs(r.normal.norm() - 1) > 1e-9) fail("normal not unit", 1);
  const double gap = (r.point_b - r.point_a - r.distance * r.normal).norm();
  if (gap > 1e-6 * scale) fail("point_b - point_a != distance * normal", 1);
}

void check_contact(const mink::ContactResult& r, double scale) {
  check_common(r, 2);
  if (r.status == Status::InvalidInput) return;
  if (!(std::isfinite(r.distance) && r.distance >= 0 && std::isfinite(r.depth) && r.depth >= 0))
    fail("distance or depth not finite and >= 0", 2);
  if (!finite(r.normal) || !finite(r.point_a) || !finite(r.point_b)) fail("non-finite output", 2);
  if (std::abs(r.normal.norm() - 1) > 1e-9) fail("normal not unit", 2);
  if (r.intersect ? r.distance != 0 : r.depth != 0) fail("flags and lengths disagree", 2);
  const double signed_gap = r.intersect ? -r.depth : r.distance;
  const double gap = (r.point_b - r.point_a - signed_gap * r.normal).norm();
  if (gap > 1e-6 * scale) fail("point_b - point_a != (distance or -depth) * normal", 2);
}

void check_manifold(const mink::ManifoldResult& r) {
  check_common(r, 3);
  if (r.status == Status::InvalidInput) return;
  if (r.count < 0 || r.count > 4) fail("manifold count out of range", 3);
  if (!finite(r.normal) || std::abs(r.normal.norm() - 1) > 1e-9) fail("bad manifold normal", 3);
  for (int i = 0; i < r.count; ++i)
    if (!finite(r.points[i].point_a) || !finite(r.points[i].point_b) ||
        !std::isfinite(r.points[i].depth))
      fail("non-finite manifold point", 3);
}

/// The four templated queries on typed shapes a and b, whose fields are unchecked (any value,
/// NaN and negative included), so that the typed queries' own input checks and their range test
/// (query/scale_range.hpp: tiny, huge and non-finite pairs go out of line) are fuzzed too.
template <class A, class B>
void check_typed_pair(const A& a, const mink::Pose& pa, const B& b, const mink::Pose& pb,
                      bool checked) {
  const auto i = mink::intersect(a, pa, b, pb);
  const auto d = mink::distance(a, pa, b, pb);
  const auto c = mink::contact(a, pa, b, pb);
  const auto m = mink::manifold(a, pa, b, pb);
  const bool invalid = a.error() || b.error();
  if (invalid && (i.status != Status::InvalidInput || d.status != Status::InvalidInput ||
                  c.status != Status::InvalidInput || m.status != Status::InvalidInput))
    fail("a typed shape's error not reported", 4);
  const double scale =
      1 + a.bounding_radius() + b.bounding_radius() + pa.translation.norm() + pb.translation.norm();
  if (invalid || !checked || !std::isfinite(scale) || scale > 1e150) return;
  check_common(i, 4);
  check_distance(d, scale);
  check_contact(c, scale);
  check_manifold(m);
}

/// One of a few typed pairs, one for each kind of path (separating axes, closed forms, GJK and
/// EPA, rounded cores), with its fields from the input. A before B, each in a statement of its
/// own: the order of a call's arguments is the compiler's, and the corpus must replay anywhere.
void check_typed(mink::fuzz::FuzzInput& in, const mink::Pose& pa, const mink::Pose& pb,
                 bool checked) {
  switch (in.choice(5)) {
    case 0: {
      const mink::Sphere a{in.length()};
      const mink::Box b{in.lengths()};
      return check_typed_pair(a, pa, b, pb, checked);
    }
    case 1: {
      const mink::Box a{in.lengths()};
      const mink::Box b{in.lengths()};
      return check_typed_pair(a, pa, b, pb, checked);
    }
    case 2: {
      const mink::Capsule a{in.length(), in.length()};
      const mink::Capsule b{in.length(), in.length()};
      return check_typed_pair(a, pa, b, pb, checked);
    }
    case 3: {
      const mink::Rounded<mink::Box> a{mink::Box{in.lengths()}, in.length()};
      const mink::Cone b{in.length(), in.length()};
      return check_typed_pair(a, pa, b, pb, checked);
    }
    default: {
      const mink::Segment a{in.vec3(), in.vec3()};
      const mink::Ellipsoid b{in.lengths()};
      return check_typed_pair(a, pa, b, pb, checked);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mink::fuzz::FuzzInput in(data, size);
  const auto a = make_shape(in, 0);
  const auto b = make_shape(in, 0);
  if (!a && a.error().empty()) fail("shape rejected without a reason", 0);
  if (!b && b.error().empty()) fail("shape rejected without a reason", 0);
  if (!a || !b) return 0;
  bool proper_a = true, proper_b = true;
  const mink::Pose pa = in.pose(proper_a), pb = in.pose(proper_b);
  const mink::Shape& sa = a.value();
  const mink::Shape& sb = b.value();
  // Read after the poses, so that the inputs kept in corpus/ still make the same shapes.
  if (in.choice(2)) {
    build_face_planes(sa);
    build_face_planes(sb);
  }
  // Out of contract (a rotation that is not one): the queries must return, nothing more.
  const bool checked = proper_a && proper_b;
  // The scale the points' agreement is measured against: sizes and distances from the origin.
  const double scale = 1 + sa.bounding_radius() + sb.bounding_radius() + pa.translation.norm() +
                       pb.translation.norm();
  const auto i = mink::intersect(sa, pa, sb, pb);
  const auto d = mink::distance(sa, pa, sb, pb);
  const auto c = mink::contact(sa, pa, sb, pb);
  const auto m = mink::manifold(sa, pa, sb, pb);
  if (checked && std::isfinite(scale) && scale <= 1e150) {
    check_common(i, 0);
    check_distance(d, scale);
    check_contact(c, scale);
    check_manifold(m);
  }
  // Read last, so that the inputs kept in corpus/ still make the same run-time shapes.
  check_typed(in, pa, pb, checked);
  return 0;
}
