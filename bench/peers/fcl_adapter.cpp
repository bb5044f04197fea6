// FCL 0.7.0 (Debian) through its narrowphase solvers, called directly (the fastest faithful path:
// fcl::collide / fcl::distance add a dispatch table and request/result objects on top):
//   fcl_ccd:   detail::GJKSolver_libccd<double>  (FCL's default, GST_LIBCCD)
//   fcl_indep: detail::GJKSolver_indep<double>   (GST_INDEP)
// with FCL's own shapes Box, Capsule, Sphere and Convex (hull vertices plus faces: FCL walks the
// hull's edges for supports when it has more than 32 vertices). Default solver tolerances.
// Note: FCL dispatches some pairs to dedicated primitive code rather than GJK: box-box
// intersection is a SAT test (boxBoxIntersect) in both solvers, and capsule-capsule distance is
// analytic (segment-segment) in both; the report marks those cells.
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/detail/gjk_solver_indep.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include <stdexcept>

#include "peer.hpp"

namespace mink_bench {

namespace {

using Contacts = std::vector<fcl::ContactPoint<double>>;

fcl::Box<double> to_fcl_box(const ShapeDesc& s) {
  return fcl::Box<double>(2 * s.half_extents);  // FCL takes the full side lengths
}
fcl::Capsule<double> to_fcl_capsule(const ShapeDesc& s) {
  return fcl::Capsule<double>(s.radius, 2 * s.half_height);  // lz: length of the core segment
}
fcl::Sphere<double> to_fcl_sphere(const ShapeDesc& s) {
  return fcl::Sphere<double>(s.radius);
}
fcl::Convex<double> to_fcl_convex(const ShapeDesc& s) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(s.points.begin(), s.points.end());
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& t : s.triangles) faces->insert(faces->end(), {3, t[0], t[1], t[2]});
  return fcl::Convex<double>(vertices, static_cast<int>(s.triangles.size()), faces, true);
}

template <class Solver, class A, class B>
class FclQueries final : public PairQueries {
 public:
  template <class MakeA, class MakeB>
  FclQueries(const Case& c, MakeA make_a, MakeB make_b) {
    for (const auto& s : c.shapes_a) a_.push_back(make_a(s));
    for (const auto& s : c.shapes_b) b_.push_back(make_b(s));
    for (const auto& p : c.pairs) {
      index_a_.push_back(p.a);
      index_b_.push_back(p.b);
      fcl::Transform3d ta = fcl::Transform3d::Identity(), tb = fcl::Transform3d::Identity();
      ta.linear() = p.rotation_a;
      ta.translation() = p.translation_a;
      tb.linear() = p.rotation_b;
      tb.translation() = p.translation_b;
      pose_a_.push_back(ta);
      pose_b_.push_back(tb);
    }
  }
  bool intersect(std::size_t i) const override {
    return solver_.shapeIntersect(a_[index_a_[i]], pose_a_[i], b_[index_b_[i]], pose_b_[i],
                                  static_cast<Contacts*>(nullptr));
  }
  double distance(std::size_t i) const override {
    double d = -1;
    fcl::Vector3d p1, p2;
    const bool separated = solver_.shapeDistance(a_[index_a_[i]], pose_a_[i], b_[index_b_[i]],
                                                 pose_b_[i], &d, &p1, &p2);
    return separated ? d : 0.0;
  }

 private:
  Solver solver_;
  std::vector<A> a_;
  std::vector<B> b_;
  std::vector<int> index_a_, index_b_;
  std::vector<fcl::Transform3d> pose_a_, pose_b_;
};

template <class A, class B, class MakeA, class MakeB>
std::vector<Method> both(const Case& c, MakeA make_a, MakeB make_b) {
  using Ccd = fcl::detail::GJKSolver_libccd<double>;
  using Indep = fcl::detail::GJKSolver_indep<double>;
  std::vector<Method> m;
  m.push_back({"fcl_ccd", true, true, std::make_unique<FclQueries<Ccd, A, B>>(c, make_a, make_b)});
  m.push_back(
      {"fcl_indep", true, true, std::make_unique<FclQueries<Indep, A, B>>(c, make_a, make_b)});
  return m;
}

}  // namespace

std::vector<Method> make_fcl_methods(const Case& c) {
  const ShapeKind ka = c.shapes_a.front().kind, kb = c.shapes_b.front().kind;
  if (ka == ShapeKind::Box && kb == ShapeKind::Box)
    return both<fcl::Box<double>, fcl::Box<double>>(c, to_fcl_box, to_fcl_box);
  if (ka == ShapeKind::Capsule && kb == ShapeKind::Capsule)
    return both<fcl::Capsule<double>, fcl::Capsule<double>>(c, to_fcl_capsule, to_fcl_capsule);
  if (ka == ShapeKind::Sphere && kb == ShapeKind::Polytope)
    return both<fcl::Sphere<double>, fcl::Convex<double>>(c, to_fcl_sphere, to_fcl_convex);
  if (ka == ShapeKind::Polytope && kb == ShapeKind::Polytope)
    return both<fcl::Convex<double>, fcl::Convex<double>>(c, to_fcl_convex, to_fcl_convex);
  throw std::logic_error("make_fcl_methods: unsupported pair");
}

}  // namespace mink_bench
