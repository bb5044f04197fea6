// Stop 57's probe: the queries under a change of scale. Every length of a pair (the shapes and
// both translations) is multiplied by `scale`; intersect(), distance() and contact() must then give
// the same flags, and distance or depth divided by the scale must match the unit pair's to 1e-9
// of its size (a property, not an oracle: the unit pair's answers are checked elsewhere).
// Pairs of 11 kinds (sphere, box, capsule, cylinder, cone, ellipsoid, triangle, segment,
// 8-point polytope, rounded box, cone + box) through the run-time Shape, overlapping (a third)
// or apart. Build and run (README.md):
//   g++ -O2 -std=c++20 -Iinclude -isystem /usr/include/eigen3 \
//     tests/slow/probe_stop57/scale_probe.cpp build/release/libmink.a -o scale_probe
//   ./scale_probe 1e-60 1500
#include <cstdio>
#include <cstdlib>
#include <mink/mink.hpp>
#include <random>
using mink::Pose;
using mink::Quat;
using mink::Shape;
using mink::Vec3;
Shape make(int kind, double s, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.3, 1.0);
  std::normal_distribution<double> g;
  auto rv = [&] { return Vec3(g(rng), g(rng), g(rng)); };
  switch (kind) {
    case 0:
      return Shape::sphere(s * u(rng)).value();
    case 1:
      return Shape::box(s * Vec3(u(rng), u(rng), u(rng))).value();
    case 2:
      return Shape::capsule(s * u(rng), s * u(rng)).value();
    case 3:
      return Shape::cylinder(s * u(rng), s * u(rng)).value();
    case 4:
      return Shape::cone(s * u(rng), s * u(rng)).value();
    case 5:
      return Shape::ellipsoid(s * Vec3(u(rng), u(rng), u(rng))).value();
    case 6:
      return Shape::triangle(s * rv(), s * rv(), s * rv()).value();
    case 7:
      return Shape::segment(s * rv(), s * rv()).value();
    case 8: {
      std::vector<Vec3> p;
      for (int i = 0; i < 8; ++i) p.push_back(s * rv());
      return Shape::polytope(p).value();
    }
    case 9:
      return Shape::rounded(Shape::box(s * Vec3(u(rng), u(rng), u(rng))).value(), s * 0.2 * u(rng))
          .value();
    default:
      return Shape::sum(Shape::cone(s * u(rng), s * u(rng)).value(),
                        Shape::box(s * Vec3(u(rng), u(rng), u(rng))).value())
          .value();
  }
}
int main(int argc, char** argv) {
  double tiny = argc > 1 ? atof(argv[1]) : 1e-200;
  int n = argc > 2 ? atoi(argv[2]) : 2000;
  int bad = 0;
  int by_kind[11] = {};  // pairs that differ, counted for each kind they hold
  for (int k = 0; k < n; ++k) {
    std::mt19937_64 r1(k), r2(k);
    int ka = k % 11, kb = (k / 11) % 11;
    std::mt19937_64 rp(1000 + k);
    std::normal_distribution<double> g;
    Quat qa(g(rp), g(rp), g(rp), g(rp)), qb(g(rp), g(rp), g(rp), g(rp));
    qa.normalize();
    qb.normalize();
    Vec3 ta(g(rp), g(rp), g(rp)), tb(g(rp), g(rp), g(rp));
    tb = ta + (tb - ta) * (k % 3 == 0 ? 0.5 : 1.2);
    Shape a1 = make(ka, 1, r1), b1 = make(kb, 1, r1);
    Shape a2 = make(ka, tiny, r2), b2 = make(kb, tiny, r2);
    Pose pa1 = Pose::from(ta, qa), pb1 = Pose::from(tb, qb), pa2 = Pose::from(tiny * ta, qa),
         pb2 = Pose::from(tiny * tb, qb);
    auto i1 = mink::intersect(a1, pa1, b1, pb1), i2 = mink::intersect(a2, pa2, b2, pb2);
    auto c1 = mink::contact(a1, pa1, b1, pb1), c2 = mink::contact(a2, pa2, b2, pb2);
    auto d2 = mink::distance(a2, pa2, b2, pb2);
    double size = a1.bounding_radius() + b1.bounding_radius();
    double e_len = std::abs((c1.intersect ? -c1.depth : c1.distance) -
                            (c2.intersect ? -c2.depth : c2.distance) / tiny) /
                   size;
    bool flags = i1.intersect != i2.intersect || c1.intersect != c2.intersect ||
                 d2.intersect != c2.intersect || i2.intersect != c2.intersect;
    if (flags || !(e_len < 1e-9) || c2.status == mink::Status::InvalidInput) {
      ++by_kind[ka];
      if (kb != ka) ++by_kind[kb];
      if (++bad <= 25)
        printf("k %d kinds %d-%d: flags i %d/%d c %d/%d d2 %d; value err %.3g; status %d/%d; %s\n",
               k, ka, kb, i1.intersect, i2.intersect, c1.intersect, c2.intersect, d2.intersect,
               e_len, (int)c1.status, (int)c2.status, c2.error ? c2.error : "");
    }
  }
  printf("scale %g: %d of %d differ; by kind:", tiny, bad, n);
  const char* names[11] = {"sphere",    "box",         "capsule",  "cylinder",
                           "cone",      "ellipsoid",   "triangle", "segment",
                           "polytope8", "rounded box", "cone+box"};
  for (int k = 0; k < 11; ++k) printf(" %s %d", names[k], by_kind[k]);
  printf("\n");
}
