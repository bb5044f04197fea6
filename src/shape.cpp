#include "mink/support/shape.hpp"

#include <cmath>

namespace mink {

namespace {

double core_bounding_radius(const Core& core) {
  return visit_core(core, [](const auto& c) -> double { return c.bounding_radius(); });
}

const char* core_error(const Core& core) {
  return std::visit(
      [](const auto& c) -> const char* {
        if constexpr (detail::kSharedCore<std::decay_t<decltype(c)>>)
          return c ? c->error() : "polytope is null";
        else
          return c.error();
      },
      core);
}

}  // namespace

Expected<Shape> Shape::from_core(Core core, double radius) {
  if (const char* e = core_error(core)) return Expected<Shape>::failure(e);
  if (!std::isfinite(radius) || radius < 0)
    return Expected<Shape>::failure("radius must be finite and >= 0");
  Shape s;
  s.bounding_radius_ = core_bounding_radius(core) + radius;
  s.cores_.push_back(std::move(core));
  s.radius_ = radius;
  return s;
}

Expected<Shape> Shape::sphere(double radius) {
  if (const char* e = Sphere{radius}.error()) return Expected<Shape>::failure(e);
  return from_core(Point{}, radius);
}

Expected<Shape> Shape::box(const Vec3& half_extents) {
  return from_core(Box{half_extents}, 0);
}

Expected<Shape> Shape::capsule(double radius, double half_height) {
  const Capsule c{radius, half_height};
  if (const char* e = c.error()) return Expected<Shape>::failure(e);
  return from_core(Segment{Vec3(0, 0, -half_height), Vec3(0, 0, half_height)}, radius);
}

Expected<Shape> Shape::cylinder(double radius, double half_height) {
  return from_core(Cylinder{radius, half_height}, 0);
}

Expected<Shape> Shape::cone(double radius, double half_height) {
  return from_core(Cone{radius, half_height}, 0);
}

Expected<Shape> Shape::ellipsoid(const Vec3& radii) {
  // Three equal radii make a sphere: a point core and a radius, so that queries take the exact
  // sphere paths. On its curved surface, EPA ran into its cap on near-concentric pairs (a sphere
  // 1e-6 off a capsule's axis: the normal 40 degrees off, the depth 5e-8 of the size).
  const Ellipsoid ellipsoid{radii};
  if (const char* e = ellipsoid.error()) return Expected<Shape>::failure(e);
  if (radii.x() == radii.y() && radii.y() == radii.z()) return from_core(Point{}, radii.x());
  return from_core(ellipsoid, 0);
}

Expected<Shape> Shape::point(const Vec3& p) {
  return from_core(Point{p}, 0);
}

Expected<Shape> Shape::segment(const Vec3& a, const Vec3& b) {
  return from_core(Segment{a, b}, 0);
}

Expected<Shape> Shape::triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return from_core(Triangle{a, b, c}, 0);
}

Expected<Shape> Shape::polytope(std::span<const Vec3> points) {
  auto p = Polytope::make(points);
  if (!p) return Expected<Shape>::failure(p.error());
  return from_core(std::make_shared<const Polytope>(std::move(p).value()), 0);
}

Expected<Shape> Shape::convex_hull(const ConvexHull& hull) {
  auto h = ConvexHullShape::make(hull);
  if (!h) return Expected<Shape>::failure(h.error());
  return from_core(std::make_shared<const ConvexHullShape>(std::move(h).value()), 0);
}

Expected<Shape> Shape::convex_hull(std::span<const Vec3> points) {
  auto h = ConvexHullShape::make(points);
  if (!h) return Expected<Shape>::failure(h.error());
  return from_core(std::make_shared<const ConvexHullShape>(std::move(h).value()), 0);
}

Expected<Shape> Shape::sum(const Shape& a, const Shape& b) {
  if (a.cores_.empty() || b.cores_.empty())
    return Expected<Shape>::failure("sum of an empty shape");
  Shape s = a;
  s.cores_.insert(s.cores_.end(), b.cores_.begin(), b.cores_.end());
  s.radius_ = a.radius_ + b.radius_;
  s.bounding_radius_ = a.bounding_radius_ + b.bounding_radius_;
  return s;
}

Expected<Shape> Shape::rounded(const Shape& shape, double margin) {
  if (shape.cores_.empty()) return Expected<Shape>::failure("rounded shape is empty");
  if (!std::isfinite(margin) || margin < 0)
    return Expected<Shape>::failure("rounded radius must be finite and >= 0");
  Shape s = shape;
  s.radius_ += margin;
  s.bounding_radius_ += margin;
  return s;
}

}  // namespace mink
