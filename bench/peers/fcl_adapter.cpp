// FCL 0.7.0 (Debian) through its narrowphase solvers, called directly (the fastest faithful path:
// fcl::collide / fcl::distance add a dispatch table and request/result objects on top):
//   fcl_ccd:   detail::GJKSolver_libccd<double>  (FCL's default, GST_LIBCCD)
//   fcl_indep: detail::GJKSolver_indep<double>   (GST_INDEP)
// with FCL's own shapes Box, Capsule, Sphere and Convex (hull vertices plus faces: FCL walks the
// hull's edges for supports when it has more than 32 vertices). Default solver tolerances.
// Note: FCL dispatches some pairs to dedicated primitive code rather than GJK: box-box
// intersection is a SAT test (boxBoxIntersect) in both solvers, capsule-capsule distance is
// analytic (segment-segment) in both, and so are sphere-box intersection and distance
// (sphereBoxIntersect, sphereBoxDistance) and fcl_indep's sphere-box contact; the report marks
// those cells.
//
// Contact (the full answer: verdict, distance or depth, normal, points):
//   fcl_ccd:   shapeSignedDistance, which is what fcl::distance calls with enable_signed_distance:
//              libccd's GJK, then, when the shapes overlap, FCL's EPA (ccdGJKSignedDist: returns
//              minus the depth and the two deepest points p1 on A, p2 on B). No primitive
//              shortcuts: every pair runs GJK (and EPA). It gives no normal: we take it along the
//              points, (p2 - p1) / |p2 - p1| when separated and (p1 - p2) / |p1 - p2| when
//              penetrating (FCL's EPA witness p1 - p2 is the nearest boundary point of A - B, the
//              direction B must move), which is mink's convention. On some box-box overlaps its
//              EPA throws ("The origin is outside of the polytope"): the benchmark counts those
//              as wrong and times the other pairs.
//   fcl_indep: GJKSolver_indep has no signed distance (its shapeSignedDistance is the unsigned one,
//              "TODO" in FCL 0.7), so the full answer is shapeDistance and, when that finds the
//              shapes overlapping, shapeIntersect with contacts: what fcl::collide with
//              enable_contact and num_max_contacts = 1 calls. That is GJK then FCL's EPA (ported
//              from Bullet's), except box-box, where it is boxBoxIntersect (SAT with contact
//              clipping; we keep the deepest contact), and capsule-capsule, where the analytic
//              distance is already signed (overlapping capsules come back as a success with a
//              negative distance and the deepest points, so no second call is made). Its
//              ContactPoint has a normal, one position and a depth, converted to mink's
//              conventions in convert_indep(); the position is taken as the midpoint of the
//              deepest points: point_a = pos + depth/2 * normal, point_b = pos - depth/2 * normal.
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/detail/gjk_solver_indep.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

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

using Ccd = fcl::detail::GJKSolver_libccd<double>;
using Indep = fcl::detail::GJKSolver_indep<double>;

/// Separated answer from the closest points p1 (on A) and p2 (on B).
ContactAnswer separated_answer(double d, const fcl::Vector3d& p1, const fcl::Vector3d& p2) {
  ContactAnswer out;
  out.distance = d;
  out.normal = (p2 - p1).normalized();
  out.point_a = p1;
  out.point_b = p2;
  return out;
}

/// Penetrating answer from a signed distance d <= 0 and the deepest points p1 (on A), p2 (on B):
/// B must move along p1 - p2.
ContactAnswer penetrating_answer(double d, const fcl::Vector3d& p1, const fcl::Vector3d& p2) {
  ContactAnswer out;
  out.intersect = true;
  out.depth = -d;
  out.normal = (p1 - p2).normalized();
  out.point_a = p1;
  out.point_b = p2;
  return out;
}

/// GJKSolver_indep's deepest contact in mink's conventions. Box-box contacts come from
/// boxBoxIntersect and follow ContactPoint's documentation: world normal from A to B (the
/// direction B must move), positive depth. Every other pair comes from FCL 0.7's GJK + EPA branch,
/// which stores EPA's normal in A's frame, not the world's, and minus the depth (it writes
/// `normal = epa.normal` and `depth = -epa.depth`; its `pos` is in the world): we rotate the
/// normal into the world and negate the depth, so that the accuracy columns measure FCL's EPA
/// rather than those two slips. (Taken as they come, every such answer would count as wrong.)
template <class A>
void convert_indep(const fcl::ContactPoint<double>& c, const fcl::Transform3d& pose_a,
                   ContactAnswer& out) {
  if constexpr (std::is_same_v<A, fcl::Box<double>>) {
    out.depth = c.penetration_depth;
    out.normal = c.normal;
  } else {
    out.depth = -c.penetration_depth;
    out.normal = pose_a.linear() * c.normal;
  }
  out.point_a = c.pos + 0.5 * out.depth * out.normal;
  out.point_b = c.pos - 0.5 * out.depth * out.normal;
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
  ContactAnswer contact(std::size_t i) const override {
    const A& a = a_[index_a_[i]];
    const B& b = b_[index_b_[i]];
    double d = 0;
    fcl::Vector3d p1 = fcl::Vector3d::Zero(), p2 = fcl::Vector3d::Zero();
    if constexpr (std::is_same_v<Solver, Ccd>) {
      if (solver_.shapeSignedDistance(a, pose_a_[i], b, pose_b_[i], &d, &p1, &p2))
        return separated_answer(d, p1, p2);
      return penetrating_answer(d, p1, p2);
    } else {
      // FCL's capsule-capsule distance is signed: it reports overlapping capsules as a success
      // with a negative distance and the deepest points.
      if (solver_.shapeDistance(a, pose_a_[i], b, pose_b_[i], &d, &p1, &p2))
        return d > 0 ? separated_answer(d, p1, p2) : penetrating_answer(d, p1, p2);
      contacts_.clear();
      ContactAnswer out;
      out.intersect = true;
      if (!solver_.shapeIntersect(a, pose_a_[i], b, pose_b_[i], &contacts_) || contacts_.empty())
        return out;  // overlapping for the distance, not for the intersection: no depth
      const auto& deepest =
          *std::max_element(contacts_.begin(), contacts_.end(), [](const auto& x, const auto& y) {
            return std::fabs(x.penetration_depth) < std::fabs(y.penetration_depth);
          });
      convert_indep<A>(deepest, pose_a_[i], out);
      return out;
    }
  }

 private:
  Solver solver_;
  mutable Contacts contacts_;  // reused, as a caller of shapeIntersect would
  std::vector<A> a_;
  std::vector<B> b_;
  std::vector<int> index_a_, index_b_;
  std::vector<fcl::Transform3d> pose_a_, pose_b_;
};

template <class A, class B, class MakeA, class MakeB>
std::vector<Method> both(const Case& c, MakeA make_a, MakeB make_b) {
  std::vector<Method> m;
  m.push_back({"fcl_ccd", true, true, std::make_unique<FclQueries<Ccd, A, B>>(c, make_a, make_b),
               true, true});
  m.push_back({"fcl_indep", true, true,
               std::make_unique<FclQueries<Indep, A, B>>(c, make_a, make_b), true, true});
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
  if (ka == ShapeKind::Sphere && kb == ShapeKind::Box)
    return both<fcl::Sphere<double>, fcl::Box<double>>(c, to_fcl_sphere, to_fcl_box);
  throw std::logic_error("make_fcl_methods: unsupported pair");
}

}  // namespace mink_bench
