// Bullet 3.24 (Debian). Built twice: against the float libraries (the default libbullet-dev
// build) and against the float64 ones that libbullet-dev also ships (-DBT_USE_DOUBLE_PRECISION,
// libBulletCollision-float64 / libLinearMath-float64); the two cannot share an executable.
//   bullet*_pd:   btGjkPairDetector + btVoronoiSimplexSolver, no penetration solver (so an
//                 overlap ends GJK with no result: that is the boolean answer).
//   bullet*_epa2: btGjkEpaSolver2::Distance (GJK of btGjkEpa2; returns false when inside).
// Neither has an early-exit boolean test, so both answer `intersect` with their distance query.
// Shapes: btBoxShape and btConvexHullShape with margin 0 (so they equal ours exactly; their
// default margin 0.04 would round them), btSphereShape and btCapsuleShapeZ whose margin *is*
// the radius (GJK runs on the point / segment core, as in mink). btGjkPairDetector subtracts the
// margins itself; btGjkEpaSolver2::Distance works on the cores, so we subtract the radii.
//
// Contact (bullet*_epa2 only), the full answer as Bullet offers it: btGjkEpaSolver2::Distance on
// the cores; when it finds them apart, the shapes are separated by the core distance minus the
// radii, or penetrate by the difference (spheres, capsules), the points being the core witnesses
// moved by the radii along the normal; when it finds the cores overlapping,
// btGjkEpaSolver2::Penetration (GJK then EPA, margins included), whose witnesses are the deepest
// points (witnesses[1] - witnesses[0] = -depth * normal in mink's terms). Both return their normal
// in A's frame pointing from B to A: we rotate it into the world and negate it (mink's normal
// points from A to B). Penetration needs the transforms, which we pass as for Distance.
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <stdexcept>

#include "peer.hpp"

namespace mink_bench {

namespace {

#ifdef BT_USE_DOUBLE_PRECISION
constexpr const char* kPrefix = "bullet64";
#else
constexpr const char* kPrefix = "bullet32";
#endif

std::unique_ptr<btConvexShape> to_bullet(const ShapeDesc& s) {
  switch (s.kind) {
    case ShapeKind::Box: {
      auto box = std::make_unique<btBoxShape>(btVector3(btScalar(s.half_extents.x()),
                                                        btScalar(s.half_extents.y()),
                                                        btScalar(s.half_extents.z())));
      box->setMargin(0);  // btBoxShape keeps the outer extents when the margin changes
      return box;
    }
    case ShapeKind::Capsule:
      return std::make_unique<btCapsuleShapeZ>(btScalar(s.radius), btScalar(2 * s.half_height));
    case ShapeKind::Sphere:
      return std::make_unique<btSphereShape>(btScalar(s.radius));
    case ShapeKind::Polytope: {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const auto& p : s.points)
        hull->addPoint(btVector3(btScalar(p.x()), btScalar(p.y()), btScalar(p.z())), false);
      hull->recalcLocalAabb();
      hull->setMargin(0);
      return hull;
    }
  }
  throw std::logic_error("to_bullet: unknown shape");
}

Eigen::Vector3d to_eigen(const btVector3& v) {
  return {double(v.x()), double(v.y()), double(v.z())};
}

btTransform to_bullet(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
  const btMatrix3x3 basis(btScalar(r(0, 0)), btScalar(r(0, 1)), btScalar(r(0, 2)),
                          btScalar(r(1, 0)), btScalar(r(1, 1)), btScalar(r(1, 2)),
                          btScalar(r(2, 0)), btScalar(r(2, 1)), btScalar(r(2, 2)));
  return btTransform(basis, btVector3(btScalar(t.x()), btScalar(t.y()), btScalar(t.z())));
}

/// Radius GJK leaves out: the margin of spheres and capsules (0 for our boxes and hulls).
double core_radius(const ShapeDesc& s) {
  return s.kind == ShapeKind::Sphere || s.kind == ShapeKind::Capsule ? s.radius : 0.0;
}

class BulletQueries final : public PairQueries {
 public:
  BulletQueries(const Case& c, bool epa2) : epa2_(epa2) {
    for (const auto& s : c.shapes_a) a_.push_back(to_bullet(s));
    for (const auto& s : c.shapes_b) b_.push_back(to_bullet(s));
    for (const auto& p : c.pairs) {
      index_a_.push_back(p.a);
      index_b_.push_back(p.b);
      pose_a_.push_back(to_bullet(p.rotation_a, p.translation_a));
      pose_b_.push_back(to_bullet(p.rotation_b, p.translation_b));
      radii_.push_back(btScalar(core_radius(c.shapes_a[p.a]) + core_radius(c.shapes_b[p.b])));
      radius_a_.push_back(core_radius(c.shapes_a[p.a]));
      radius_b_.push_back(core_radius(c.shapes_b[p.b]));
    }
  }
  bool intersect(std::size_t i) const override { return !(query(i) > 0); }
  double distance(std::size_t i) const override { return std::max(0.0, double(query(i))); }
  ContactAnswer contact(std::size_t i) const override {
    const btConvexShape* a = a_[index_a_[i]].get();
    const btConvexShape* b = b_[index_b_[i]].get();
    const btVector3 guess = pose_a_[i].getOrigin() - pose_b_[i].getOrigin();
    btGjkEpaSolver2::sResults r;
    ContactAnswer out;
    if (btGjkEpaSolver2::Distance(a, pose_a_[i], b, pose_b_[i], guess, r)) {
      // The cores are apart: separated, or penetrating by the radii only.
      const Eigen::Vector3d w0 = to_eigen(r.witnesses[0]), w1 = to_eigen(r.witnesses[1]);
      const double core = r.distance;
      // Bullet's normal is in A's frame and points from B towards A (in both queries).
      out.normal = -to_eigen(pose_a_[i].getBasis() * r.normal);
      const double gap = core - radius_a_[i] - radius_b_[i];
      out.intersect = gap <= 0;
      if (out.intersect)
        out.depth = -gap;
      else
        out.distance = gap;
      out.point_a = w0 + radius_a_[i] * out.normal;
      out.point_b = w1 - radius_b_[i] * out.normal;
      return out;
    }
    out.intersect = true;
    if (!btGjkEpaSolver2::Penetration(a, pose_a_[i], b, pose_b_[i], guess, r)) return out;
    out.depth = -r.distance;
    out.point_a = to_eigen(r.witnesses[0]);
    out.point_b = to_eigen(r.witnesses[1]);
    out.normal = -to_eigen(pose_a_[i].getBasis() * r.normal);
    return out;
  }

 private:
  // Distance, or 0 when the method finds the shapes overlapping.
  btScalar query(std::size_t i) const {
    const btConvexShape* a = a_[index_a_[i]].get();
    const btConvexShape* b = b_[index_b_[i]].get();
    if (epa2_) {
      btGjkEpaSolver2::sResults results;
      const btVector3 guess = pose_a_[i].getOrigin() - pose_b_[i].getOrigin();
      if (!btGjkEpaSolver2::Distance(a, pose_a_[i], b, pose_b_[i], guess, results)) return 0;
      return results.distance - radii_[i];
    }
    btVoronoiSimplexSolver simplex;
    btGjkPairDetector gjk(a, b, &simplex, nullptr);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA = pose_a_[i];
    input.m_transformB = pose_b_[i];
    btPointCollector output;
    gjk.getClosestPoints(input, output, nullptr);
    return output.m_hasResult ? output.m_distance : btScalar(0);
  }

  bool epa2_;
  std::vector<std::unique_ptr<btConvexShape>> a_, b_;
  std::vector<int> index_a_, index_b_;
  btAlignedObjectArray<btTransform> pose_a_, pose_b_;
  std::vector<btScalar> radii_;
  std::vector<double> radius_a_, radius_b_;
};

}  // namespace

std::vector<Method> make_bullet_methods(const Case& c) {
  std::vector<Method> m;
  m.push_back(
      {std::string(kPrefix) + "_pd", true, true, std::make_unique<BulletQueries>(c, false)});
  m.push_back({std::string(kPrefix) + "_epa2", true, true, std::make_unique<BulletQueries>(c, true),
               true, true});
  return m;
}

}  // namespace mink_bench
