// libccd 2.1 (Debian, double build): ccdGJKIntersect and ccdMPRIntersect, and for penetrating
// pairs ccdGJKPenetration (GJK then EPA) and ccdMPRPenetration. libccd has no distance query (its
// dist_tolerance field is unused upstream; FCL's copy adds one, benchmarked as fcl_ccd), so it has
// no full answer for separated pairs. libccd has no shapes either: the support and centre
// callbacks below are ours, in the world frame, each shape with its pose baked in when the object
// is built (outside the timing).
//
// Penetration output: depth, a unit direction `dir` and one position `pos`. libccd documents that
// translating obj2 by depth along dir leaves the shapes touching: dir is mink's normal as it is.
// libccd gives no pair of points, only `pos` ("where the force should take place"): MPR takes the
// midpoint of the two witness points, GJK+EPA the mean of the witness points of the EPA
// polytope's vertices nearest the origin. We report point_a = pos + depth/2 * dir and point_b =
// pos - depth/2 * dir, which are the deepest points when pos is the midpoint of the deepest points;
// the points' error column says how far that is from true.
#include <ccd/ccd.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cmath>
#include <stdexcept>

#include "peer.hpp"

namespace mink_bench {

namespace {

struct CcdObject {
  ShapeKind kind = ShapeKind::Box;
  double rotation[9] = {};  // row-major, local to world
  double translation[3] = {};
  double half_extents[3] = {};
  double radius = 0;
  double half_height = 0;
  const double* xyz = nullptr;  // polytope points, interleaved
  int count = 0;
};

// libccd reads a vector it gets from a callback with a 16-byte load of x and y (movupd); written
// as three 8-byte stores, that load cannot be forwarded from them and stalls until they reach the
// cache (Clang's build of the callbacks wrote them so: libccd's box-box MPR took 58-73 ns a query
// against 31 ns from GCC's). One 16-byte store of x and y gives libccd its best.
void store_vec3(ccd_vec3_t* out, double x, double y, double z) {
#if defined(__SSE2__)
  _mm_storeu_pd(out->v, _mm_set_pd(y, x));
#else
  out->v[0] = x;
  out->v[1] = y;
#endif
  out->v[2] = z;
}

// Support of the whole shape (radius included), world frame.
void ccd_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto& o = *static_cast<const CcdObject*>(obj);
  const double* r = o.rotation;
  const double* d = dir->v;
  // Local direction: R^T d.
  const double lx = r[0] * d[0] + r[3] * d[1] + r[6] * d[2];
  const double ly = r[1] * d[0] + r[4] * d[1] + r[7] * d[2];
  const double lz = r[2] * d[0] + r[5] * d[1] + r[8] * d[2];
  double px = 0, py = 0, pz = 0;
  switch (o.kind) {
    // Signs by copysign, not by a comparison: Clang compiles `l >= 0 ? h : -h` to a branch,
    // which mispredicts on half of random directions (libccd's box-box MPR ran 2.3x slower).
    case ShapeKind::Box:
      px = std::copysign(o.half_extents[0], lx);
      py = std::copysign(o.half_extents[1], ly);
      pz = std::copysign(o.half_extents[2], lz);
      break;
    case ShapeKind::Capsule:
    case ShapeKind::Sphere: {
      const double len = std::sqrt(lx * lx + ly * ly + lz * lz);
      const double s = len > 0 ? o.radius / len : 0.0;
      px = lx * s;
      py = ly * s;
      pz = lz * s;
      if (o.kind == ShapeKind::Capsule) pz += std::copysign(o.half_height, lz);
      break;
    }
    case ShapeKind::Polytope: {
      int best = 0;
      double best_dot = -HUGE_VAL;
      for (int i = 0; i < o.count; ++i) {
        const double* p = o.xyz + 3 * i;
        const double dot = p[0] * lx + p[1] * ly + p[2] * lz;
        if (dot > best_dot) {
          best_dot = dot;
          best = i;
        }
      }
      px = o.xyz[3 * best];
      py = o.xyz[3 * best + 1];
      pz = o.xyz[3 * best + 2];
      break;
    }
  }
  store_vec3(out, r[0] * px + r[1] * py + r[2] * pz + o.translation[0],
             r[3] * px + r[4] * py + r[5] * pz + o.translation[1],
             r[6] * px + r[7] * py + r[8] * pz + o.translation[2]);
}

void ccd_center(const void* obj, ccd_vec3_t* out) {
  const auto& o = *static_cast<const CcdObject*>(obj);
  store_vec3(out, o.translation[0], o.translation[1], o.translation[2]);
}

class CcdQueries final : public PairQueries {
 public:
  CcdQueries(const Case& c, bool mpr) : mpr_(mpr) {
    // Polytope points, interleaved, one block per shape of each pool.
    auto flatten = [](const std::vector<ShapeDesc>& shapes, std::vector<std::vector<double>>& out) {
      for (const auto& s : shapes) {
        std::vector<double> xyz;
        for (const auto& p : s.points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
        out.push_back(std::move(xyz));
      }
    };
    flatten(c.shapes_a, points_a_);
    flatten(c.shapes_b, points_b_);
    for (const auto& p : c.pairs) {
      a_.push_back(make(c.shapes_a[p.a], points_a_[p.a], p.rotation_a, p.translation_a));
      b_.push_back(make(c.shapes_b[p.b], points_b_[p.b], p.rotation_b, p.translation_b));
    }
    CCD_INIT(&ccd_);
    ccd_.support1 = ccd_support;
    ccd_.support2 = ccd_support;
    ccd_.center1 = ccd_center;
    ccd_.center2 = ccd_center;
    // The default is unbounded (ULONG_MAX); a cap only guards against a hang and is never hit
    // on these inputs.
    ccd_.max_iterations = 1000;
  }
  bool intersect(std::size_t i) const override {
    return (mpr_ ? ccdMPRIntersect(&a_[i], &b_[i], &ccd_)
                 : ccdGJKIntersect(&a_[i], &b_[i], &ccd_)) != 0;
  }
  double distance(std::size_t) const override { throw std::logic_error("libccd has no distance"); }
  ContactAnswer contact(std::size_t i) const override {
    ccd_real_t depth = 0;
    ccd_vec3_t dir, pos;
    const int r = mpr_ ? ccdMPRPenetration(&a_[i], &b_[i], &ccd_, &depth, &dir, &pos)
                       : ccdGJKPenetration(&a_[i], &b_[i], &ccd_, &depth, &dir, &pos);
    if (r == -2) throw std::runtime_error("ccdGJKPenetration: out of memory");
    ContactAnswer out;
    out.intersect = r == 0;
    if (!out.intersect) return out;  // separated, but no distance
    out.depth = depth;
    out.normal = {dir.v[0], dir.v[1], dir.v[2]};
    const Eigen::Vector3d mid(pos.v[0], pos.v[1], pos.v[2]);
    out.point_a = mid + 0.5 * depth * out.normal;
    out.point_b = mid - 0.5 * depth * out.normal;
    return out;
  }

 private:
  static CcdObject make(const ShapeDesc& s, const std::vector<double>& xyz,
                        const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
    CcdObject o;
    o.kind = s.kind;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) o.rotation[3 * i + j] = r(i, j);
    for (int k = 0; k < 3; ++k) {
      o.translation[k] = t[k];
      o.half_extents[k] = s.half_extents[k];
    }
    o.radius = s.radius;
    o.half_height = s.half_height;
    o.xyz = xyz.data();
    o.count = static_cast<int>(s.points.size());
    return o;
  }

  bool mpr_;
  ccd_t ccd_;
  std::vector<std::vector<double>> points_a_, points_b_;
  std::vector<CcdObject> a_, b_;
};

}  // namespace

std::vector<Method> make_ccd_methods(const Case& c) {
  std::vector<Method> m;
  m.push_back({"ccd_gjk", true, false, std::make_unique<CcdQueries>(c, false), true, false});
  m.push_back({"ccd_mpr", true, false, std::make_unique<CcdQueries>(c, true), true, false});
  return m;
}

}  // namespace mink_bench
