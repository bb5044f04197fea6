// Boolean intersection, distance and contact (the full answer: verdict, distance or penetration
// depth, normal, points): mink against libccd, FCL and Bullet on identical inputs (cases.hpp).
// Each benchmark cycles through the 256 pairs of one case; its counters carry the accuracy of
// that library on the case, measured once before timing:
//   wrong        boolean answers (or distance answers' intersect/separated verdicts) that
//                disagree with the construction of the case; contact: also non-finite answers,
//                and depth (distance) or normal errors above kWrong (below);
//   max_rel_err  separated cases, distance queries: max |distance - reference| / size, size being
//                the sum of the shapes' bounding radii, against reference.hpp's long double answer;
//                contact: max |depth - reference depth| / size on overlapping cases, the distance
//                error on separated ones;
//   normal_err   contact: max (h_A(n) + h_B(-n) - reference depth) / size over the returned unit
//                normals n, h being the support function: how much farther B must move along n
//                than along the best normal (on separated cases: how much less gap n shows than
//                the distance). 0 for an optimal normal, O(size) for a wrong sign;
//   point_err    contact: max over the answers of the points' errors / size: each point's offset
//                from its shape's support plane along the normal, how far it lies outside its
//                shape, and |point_b - point_a + depth * normal| (- distance * normal);
//   iterations   mean GJK (and EPA) iterations per query (mink only);
//   threw        contact: pairs on which the library threw an exception (counted as wrong, and
//                left out of the timing, which cycles through the other pairs).
// Which libraries are compiled in is decided by the build (MINK_BENCH_WITH_*): Bullet's float and
// double builds cannot share an executable, so there are two.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "cases.hpp"
#include "peers/peer.hpp"
#include "reference.hpp"

namespace mink_bench {
namespace {

struct Accuracy {
  int wrong = 0;
  double max_rel_err = 0;
  double normal_err = std::nan("");
  double point_err = std::nan("");
  double mean_iterations = std::nan("");
  /// Contact: the pairs the library answered without throwing (FCL's libccd EPA throws on some
  /// configurations); only those are timed, the others count as wrong.
  std::vector<std::size_t> answered;
  int threw = 0;
};

/// Contact answers whose depth (distance) or normal error exceeds this (relative to size) count
/// as wrong.
constexpr double kWrong = 1e-6;

double relative(long double err, double size) {
  const double e = static_cast<double>(err) / size;
  return std::isnan(e) ? INFINITY : e;
}

/// Accuracy of a contact answer, against the reference (see the counters above).
Accuracy measure_contact(const Case& c, const PairQueries& q, const std::string& name) {
  Accuracy acc;
  acc.normal_err = acc.point_err = 0;
  double iterations = 0;
  int answered = 0;
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    const double size = c.size(i);
    // Signed depth: the depth when overlapping, minus the distance when separated.
    const long double reference = c.intersecting ? c.reference[i] : -c.reference[i];
    try {
      iterations += q.iterations(i, Query::Contact);
      const ContactAnswer r = q.contact(i);
      acc.answered.push_back(i);
      const double depth = r.intersect ? r.depth : -r.distance;
      const double depth_err = relative(std::fabs(depth - reference), size);
      double normal_err = INFINITY, point_err = INFINITY;
      const double length = r.normal.norm();
      if (std::isfinite(length) && std::fabs(length - 1) <= kWrong) {
        normal_err = relative(separation_along(c, i, r.normal) - reference, size);
        if (normal_err < -1e-12)  // a normal better than the reference's best: a reference bug
          std::fprintf(stderr, "gjk_bench: %s/%s pair %zu: normal beats the reference by %g\n",
                       c.name().c_str(), name.c_str(), i, -normal_err);
        const Vec3L n = r.normal.cast<long double>().normalized();
        const Vec3L pa = r.point_a.cast<long double>(), pb = r.point_b.cast<long double>();
        const long double errors[] = {std::fabs(n.dot(pa) - support_value(c, i, false, n)),
                                      std::fabs(n.dot(pb) + support_value(c, i, true, -n)),
                                      std::max(0.0L, outside(c, i, false, r.point_a)),
                                      std::max(0.0L, outside(c, i, true, r.point_b)),
                                      (pb - pa + static_cast<long double>(depth) * n).norm()};
        point_err = 0;
        for (long double e : errors) point_err = std::max(point_err, relative(e, size));
      }
      acc.wrong += r.intersect != c.intersecting || !(depth_err <= kWrong) ||
                   !(normal_err <= kWrong) || !r.point_a.allFinite() || !r.point_b.allFinite();
      // The maxima are over the answers given (finite); the others count as wrong only, so
      // that one failure does not hide the accuracy of the rest.
      if (std::isfinite(depth_err)) {
        ++answered;
        acc.max_rel_err = std::max(acc.max_rel_err, depth_err);
      }
      if (std::isfinite(normal_err)) acc.normal_err = std::max(acc.normal_err, normal_err);
      if (std::isfinite(point_err)) acc.point_err = std::max(acc.point_err, point_err);
    } catch (const std::exception&) {
      ++acc.wrong;
      ++acc.threw;
    }
  }
  if (answered == 0) acc.max_rel_err = acc.normal_err = acc.point_err = INFINITY;
  acc.mean_iterations = iterations / static_cast<double>(c.pairs.size());
  return acc;
}

Accuracy measure(const Case& c, const PairQueries& q, bool distance) {
  Accuracy acc;
  double iterations = 0;
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    try {
      iterations += q.iterations(i, distance ? Query::Distance : Query::Intersect);
      if (!distance) {
        acc.wrong += q.intersect(i) != c.intersecting;
        continue;
      }
      const double d = q.distance(i);
      if (c.intersecting) {
        acc.wrong += d > 0;
      } else {
        acc.wrong += !(d > 0);
        const double err =
            static_cast<double>(std::fabs(static_cast<long double>(d) - c.reference[i])) /
            c.size(i);
        acc.max_rel_err = std::isnan(err) ? INFINITY : std::max(acc.max_rel_err, err);
      }
    } catch (const std::exception&) {
      ++acc.wrong;
      if (distance && !c.intersecting) acc.max_rel_err = INFINITY;
    }
  }
  acc.mean_iterations = iterations / static_cast<double>(c.pairs.size());
  return acc;
}

void run(benchmark::State& state, const PairQueries* q, Query query, Accuracy acc) {
  const std::size_t n = kPairsPerCase;
  std::size_t i = 0;
  try {
    if (query == Query::Contact) {
      if (acc.answered.empty()) throw std::runtime_error("no pair answered");
      const std::size_t m = acc.answered.size();
      for (auto _ : state) {
        ContactAnswer r = q->contact(acc.answered[i]);
        benchmark::DoNotOptimize(r);
        if (++i == m) i = 0;
      }
    } else if (query == Query::Distance) {
      for (auto _ : state) {
        benchmark::DoNotOptimize(q->distance(i));
        if (++i == n) i = 0;
      }
    } else {
      for (auto _ : state) {
        benchmark::DoNotOptimize(q->intersect(i));
        if (++i == n) i = 0;
      }
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["wrong"] = acc.wrong;
  if (query != Query::Intersect) state.counters["max_rel_err"] = acc.max_rel_err;
  if (!std::isnan(acc.normal_err)) state.counters["normal_err"] = acc.normal_err;
  if (!std::isnan(acc.point_err)) state.counters["point_err"] = acc.point_err;
  if (!std::isnan(acc.mean_iterations)) state.counters["iterations"] = acc.mean_iterations;
  if (acc.threw) state.counters["threw"] = acc.threw;
}

std::vector<Method> methods_for(const Case& c) {
  std::vector<Method> all;
  auto add = [&all](std::vector<Method> more) {
    for (auto& m : more) all.push_back(std::move(m));
  };
#ifdef MINK_BENCH_WITH_MINK
  add(make_mink_methods(c));
#endif
#ifdef MINK_BENCH_WITH_CCD
  add(make_ccd_methods(c));
#endif
#ifdef MINK_BENCH_WITH_FCL
  add(make_fcl_methods(c));
#endif
#ifdef MINK_BENCH_WITH_BULLET
  add(make_bullet_methods(c));
#endif
  (void)c;
  (void)add;
  return all;
}

}  // namespace
}  // namespace mink_bench

int main(int argc, char** argv) {
  using namespace mink_bench;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const std::vector<Case>& cases = all_cases();
  static std::vector<std::vector<Method>> methods;  // outlive the registered benchmarks
  for (const Case& c : cases) {
    methods.push_back(methods_for(c));
    for (const Method& m : methods.back()) {
      for (bool distance : {false, true}) {
        if (distance ? !m.has_distance : !m.has_intersect) continue;
        const Accuracy acc = measure(c, *m.queries, distance);
        const std::string name =
            std::string(distance ? "distance/" : "intersect/") + c.name() + "/" + m.name;
        benchmark::RegisterBenchmark(name.c_str(), run, m.queries.get(),
                                     distance ? Query::Distance : Query::Intersect, acc);
      }
      if (c.intersecting ? m.has_contact : m.has_separated_contact) {
        const Accuracy acc = measure_contact(c, *m.queries, m.name);
        const std::string name = "contact/" + c.name() + "/" + m.name;
        benchmark::RegisterBenchmark(name.c_str(), run, m.queries.get(), Query::Contact, acc);
      }
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
