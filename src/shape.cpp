#include "mink/support/shape.hpp"

#include <cmath>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace mink {

namespace {

double core_bounding_radius(const Core& core) {
  return visit_core(core, [](const auto& c) -> double { return c.bounding_radius(); });
}

/// A shape's bounding radius: its cores' summed, and its radius.
double bounding_radius_of(const std::vector<Core>& cores, double radius) {
  double r = radius;
  for (const Core& core : cores) r += core_bounding_radius(core);
  return r;
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

/// Half of a segment symmetric about the origin (its end points b and -b): b, else nothing.
std::optional<Vec3> symmetric_half(const Core& core) {
  if (const auto* capsule = std::get_if<Capsule>(&core)) return Vec3(0, 0, capsule->half_height);
  const auto* segment = std::get_if<Segment>(&core);
  if (!segment || segment->a != -segment->b) return std::nullopt;
  return segment->b;
}

/// The segment from -b to b as a core: a Capsule core when it lies along z (a Sphere core when it
/// has no length).
Core symmetric_segment(const Vec3& b) {
  if (b.x() == 0 && b.y() == 0) {
    if (b.z() == 0) return Sphere{0};
    return Capsule{0, std::abs(b.z())};
  }
  return Segment{-b, b};
}

/// A Shape's point at the origin: its cores are canonical_core()'s, so a Sphere of radius 0.
bool is_origin_point(const Core& core) {
  const auto* sphere = std::get_if<Sphere>(&core);
  return sphere && sphere->radius == 0;
}

/// The form of `core` with the fastest paths, the same set of points: a point at the origin (or a
/// capsule's core of no length) is a Sphere core and a segment symmetric about the origin along z
/// a Capsule core, as Shape::sphere() and Shape::capsule() make them (the typed closed forms and
/// axial paths, where a Point or Segment core is rotated and checked coordinate by coordinate).
Core canonical_core(Core core) {
  if (const auto* capsule = std::get_if<Capsule>(&core);
      capsule && capsule->radius == 0 && capsule->half_height == 0)
    return Sphere{0};
  if (const auto* point = std::get_if<Point>(&core); point && point->position == Vec3::Zero())
    return Sphere{0};
  if (const auto* segment = std::get_if<Segment>(&core); segment && segment->a == -segment->b)
    return symmetric_segment(segment->b);
  return core;
}

/// Folds `part` into `into` when their sum is again one core of a kind Core holds, exactly (to
/// the rounding of one addition): a point at the origin adds nothing, and a segment symmetric
/// about the origin lengthens a cylinder or a segment along it, or a box along one of its axes.
/// Returns false, `into` untouched, otherwise.
bool fold_core(Core& into, const Core& part) {
  if (is_origin_point(part)) return true;
  if (is_origin_point(into)) {
    into = part;
    return true;
  }
  const std::optional<Vec3> half = symmetric_half(part);
  if (!half) return false;
  const Vec3 reach = half->cwiseAbs();
  if (auto* cylinder = std::get_if<Cylinder>(&into)) {
    if (reach.x() != 0 || reach.y() != 0) return false;
    cylinder->half_height += reach.z();
    return true;
  }
  if (auto* box = std::get_if<Box>(&into)) {
    int axis;
    if (reach.maxCoeff(&axis) != reach.sum()) return false;  // not along one axis
    box->half_extents[axis] += reach[axis];
    return true;
  }
  if (const std::optional<Vec3> own = symmetric_half(into)) {
    if (own->cross(*half) != Vec3::Zero()) return false;
    const Vec3 b = *own + (own->dot(*half) >= 0 ? *half : Vec3(-*half));
    into = symmetric_segment(b);
    return true;
  }
  return false;
}

/// `core` with every length multiplied by `factor`.
Expected<Core> scaled_core(const Core& core, double factor) {
  return std::visit(
      [factor](const auto& c) -> Expected<Core> {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, Point>) {
          return Core{Point{factor * c.position}};
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return Core{Sphere{factor * c.radius}};
        } else if constexpr (std::is_same_v<T, Segment>) {
          return Core{Segment{factor * c.a, factor * c.b}};
        } else if constexpr (std::is_same_v<T, Capsule>) {
          return Core{Capsule{factor * c.radius, factor * c.half_height}};
        } else if constexpr (std::is_same_v<T, Triangle>) {
          return Core{Triangle{factor * c.a, factor * c.b, factor * c.c}};
        } else if constexpr (std::is_same_v<T, Box>) {
          return Core{Box{factor * c.half_extents}};
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return Core{Cylinder{factor * c.radius, factor * c.half_height}};
        } else if constexpr (std::is_same_v<T, Cone>) {
          return Core{Cone{factor * c.radius, factor * c.half_height}};
        } else if constexpr (std::is_same_v<T, Ellipsoid>) {
          return Core{Ellipsoid{factor * c.radii}};
        } else {
          // A polytope's points or a hull's vertices, scaled, made into the same kind again.
          std::vector<Vec3> points(c->size());
          for (std::size_t i = 0; i < points.size(); ++i) points[i] = factor * c->point(i);
          using Made = std::decay_t<decltype(*c)>;
          auto made = Made::make(points);
          if (!made) return Expected<Core>::failure(made.error());
          return Core{std::make_shared<const Made>(std::move(made).value())};
        }
      },
      core);
}

}  // namespace

Expected<Shape> Shape::scaled(double factor) const {
  if (!(factor > 0) || !std::isfinite(factor))
    return Expected<Shape>::failure("scale factor must be finite and > 0");
  if (cores_.empty()) return Expected<Shape>::failure("scaled shape is empty");
  Shape s;
  s.radius_ = factor * radius_;
  for (const Core& core : cores_) {
    auto c = scaled_core(core, factor);
    if (!c) return Expected<Shape>::failure(c.error());
    if (const char* e = core_error(c.value())) return Expected<Shape>::failure(e);
    s.cores_.push_back(canonical_core(std::move(c).value()));
  }
  s.bounding_radius_ = bounding_radius_of(s.cores_, s.radius_);
  if (!std::isfinite(s.radius_) || !std::isfinite(s.bounding_radius_))
    return Expected<Shape>::failure("scaled shape's lengths overflow");
  return s;
}

Expected<Shape> Shape::from_core(Core core, double radius) {
  if (const char* e = core_error(core)) return Expected<Shape>::failure(e);
  if (!std::isfinite(radius) || radius < 0)
    return Expected<Shape>::failure("radius must be finite and >= 0");
  Shape s;
  s.cores_.push_back(canonical_core(std::move(core)));
  s.radius_ = radius;
  s.bounding_radius_ = bounding_radius_of(s.cores_, radius);
  return s;
}

Expected<Shape> Shape::sphere(double radius) {
  if (const char* e = Sphere{radius}.error()) return Expected<Shape>::failure(e);
  return from_core(Sphere{0}, radius);
}

Expected<Shape> Shape::box(const Vec3& half_extents) {
  return from_core(Box{half_extents}, 0);
}

Expected<Shape> Shape::capsule(double radius, double half_height) {
  const Capsule c{radius, half_height};
  if (const char* e = c.error()) return Expected<Shape>::failure(e);
  return from_core(Capsule{0, half_height}, radius);
}

Expected<Shape> Shape::cylinder(double radius, double half_height) {
  return from_core(Cylinder{radius, half_height}, 0);
}

Expected<Shape> Shape::cone(double radius, double half_height) {
  return from_core(Cone{radius, half_height}, 0);
}

Expected<Shape> Shape::ellipsoid(const Vec3& radii) {
  // Three equal radii make a sphere: its centre and a radius, so that queries take the exact
  // sphere paths. On its curved surface, EPA ran into its cap on near-concentric pairs (a sphere
  // 1e-6 off a capsule's axis: the normal 40 degrees off, the depth 5e-8 of the size).
  const Ellipsoid ellipsoid{radii};
  if (const char* e = ellipsoid.error()) return Expected<Shape>::failure(e);
  if (radii.x() == radii.y() && radii.y() == radii.z()) return from_core(Sphere{0}, radii.x());
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
  // A part that folds into a core already there (a sphere's centre, a capsule's segment along a
  // cylinder's axis) leaves fewer cores: a sum of one core takes that core's closed forms and
  // axial paths, where a sum of several runs GJK and EPA on their sum (a cylinder plus a sphere
  // against its copy ended at EPA's cap).
  Shape s = a;
  for (const Core& part : b.cores_) {
    bool folded = false;
    for (Core& core : s.cores_) {
      // Either way round (a capsule's segment into a cylinder, or a cylinder into it); kept only
      // when valid: two lengths near the largest double overflow.
      Core trial = core;
      if (!fold_core(trial, part)) {
        trial = part;
        if (!fold_core(trial, core)) continue;
      }
      if ((folded = !core_error(trial))) {
        core = std::move(trial);
        break;
      }
    }
    if (!folded) s.cores_.push_back(part);
  }
  s.radius_ = a.radius_ + b.radius_;
  s.bounding_radius_ = bounding_radius_of(s.cores_, s.radius_);
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
