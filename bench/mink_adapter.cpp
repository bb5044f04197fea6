// mink through its public templates, on the same inputs as the peers.
#include <mink/mink.hpp>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "peers/peer.hpp"

namespace mink_bench {

namespace {

mink::Box to_mink_box(const ShapeDesc& s) {
  return mink::Box{s.half_extents};
}
mink::Capsule to_mink_capsule(const ShapeDesc& s) {
  return mink::Capsule{s.radius, s.half_height};
}
mink::Sphere to_mink_sphere(const ShapeDesc& s) {
  return mink::Sphere{s.radius};
}
mink::Polytope to_mink_polytope(const ShapeDesc& s) {
  auto p = mink::Polytope::make(s.points);
  if (!p) throw std::runtime_error("mink::Polytope::make: " + p.error());
  return std::move(p).value();
}

template <class A, class B>
class MinkQueries final : public PairQueries {
 public:
  template <class MakeA, class MakeB>
  MinkQueries(const Case& c, MakeA make_a, MakeB make_b) {
    for (const auto& s : c.shapes_a) a_.push_back(make_a(s));
    for (const auto& s : c.shapes_b) b_.push_back(make_b(s));
    for (const A& a : a_) settle(a);
    for (const B& b : b_) settle(b);
    for (const auto& p : c.pairs) {
      index_a_.push_back(p.a);
      index_b_.push_back(p.b);
      mink::Pose pa, pb;
      pa.rotation = p.rotation_a;
      pa.translation = p.translation_a;
      pb.rotation = p.rotation_b;
      pb.translation = p.translation_b;
      pose_a_.push_back(pa);
      pose_b_.push_back(pb);
    }
  }
  // A polytope of 64 points or more scans for its first kPolytopeHullAfterSupports support calls,
  // then builds its hull and climbs it; a smaller one builds its face planes, for spheres, after
  // kPolytopePlanesAfterQueries queries (polytope.hpp). Done here, before timing, as a simulation
  // does in its first frames: otherwise the switch lands in whichever benchmark first uses the
  // shape, and its time (a hull build per shape) depends on how Google Benchmark sizes its runs.
  template <class T>
  static void settle(const T& shape) {
    if constexpr (std::is_same_v<T, mink::Polytope>) {
      if (shape.size() < mink::kHullClimbMinVertices) {
        (void)shape.build_face_planes();  // null for more than 32 faces: GJK answers
        return;
      }
      for (std::uint32_t i = 0; i <= mink::kPolytopeHullAfterSupports && !shape.climbs(); ++i)
        (void)shape.support_core(mink::Vec3::UnitX());
    }
  }

  bool intersect(std::size_t i) const override {
    return mink::intersect(a_[index_a_[i]], pose_a_[i], b_[index_b_[i]], pose_b_[i]).intersect;
  }
  double distance(std::size_t i) const override {
    const auto r = mink::distance(a_[index_a_[i]], pose_a_[i], b_[index_b_[i]], pose_b_[i]);
    return r.intersect ? 0.0 : r.distance;
  }
  ContactAnswer contact(std::size_t i) const override {
    const auto r = mink::contact(a_[index_a_[i]], pose_a_[i], b_[index_b_[i]], pose_b_[i]);
    if (r.status == mink::Status::InvalidInput)
      throw std::runtime_error(std::string("mink::contact: ") + r.error);
    ContactAnswer out;  // mink's conventions are the benchmark's
    out.intersect = r.intersect;
    out.distance = r.distance;
    out.depth = r.depth;
    out.normal = r.normal;
    out.point_a = r.point_a;
    out.point_b = r.point_b;
    return out;
  }
  double iterations(std::size_t i, Query query) const override {
    const auto& a = a_[index_a_[i]];
    const auto& b = b_[index_b_[i]];
    switch (query) {
      case Query::Intersect:
        return mink::intersect(a, pose_a_[i], b, pose_b_[i]).iterations;
      case Query::Distance:
        return mink::distance(a, pose_a_[i], b, pose_b_[i]).iterations;
      case Query::Contact:
        return mink::contact(a, pose_a_[i], b, pose_b_[i]).iterations;
    }
    return 0;
  }

 private:
  std::vector<A> a_;
  std::vector<B> b_;
  std::vector<int> index_a_, index_b_;
  std::vector<mink::Pose> pose_a_, pose_b_;
};

template <class A, class B, class MakeA, class MakeB>
std::vector<Method> one(const Case& c, MakeA make_a, MakeB make_b) {
  std::vector<Method> m;
  m.push_back(
      {"mink", true, true, std::make_unique<MinkQueries<A, B>>(c, make_a, make_b), true, true});
  return m;
}

}  // namespace

std::vector<Method> make_mink_methods(const Case& c) {
  const ShapeKind ka = c.shapes_a.front().kind, kb = c.shapes_b.front().kind;
  if (ka == ShapeKind::Box && kb == ShapeKind::Box)
    return one<mink::Box, mink::Box>(c, to_mink_box, to_mink_box);
  if (ka == ShapeKind::Capsule && kb == ShapeKind::Capsule)
    return one<mink::Capsule, mink::Capsule>(c, to_mink_capsule, to_mink_capsule);
  if (ka == ShapeKind::Sphere && kb == ShapeKind::Polytope)
    return one<mink::Sphere, mink::Polytope>(c, to_mink_sphere, to_mink_polytope);
  if (ka == ShapeKind::Polytope && kb == ShapeKind::Polytope)
    return one<mink::Polytope, mink::Polytope>(c, to_mink_polytope, to_mink_polytope);
  if (ka == ShapeKind::Sphere && kb == ShapeKind::Box)
    return one<mink::Sphere, mink::Box>(c, to_mink_sphere, to_mink_box);
  throw std::logic_error("make_mink_methods: unsupported pair");
}

}  // namespace mink_bench
