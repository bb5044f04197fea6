// Boolean intersection and distance: mink against libccd, FCL and Bullet on identical inputs
// (cases.hpp). Each benchmark cycles through the 256 pairs of one case; its counters carry the
// accuracy of that library on the case, measured once before timing:
//   wrong        boolean answers (or distance answers' intersect/separated verdicts) that
//                disagree with the construction of the case;
//   max_rel_err  separated cases, distance queries: max |distance - reference| / size, size being
//                the sum of the shapes' bounding radii, against reference.hpp's long double answer;
//   iterations   mean GJK iterations per query (mink only).
// Which libraries are compiled in is decided by the build (MINK_BENCH_WITH_*): Bullet's float and
// double builds cannot share an executable, so there are two.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cases.hpp"
#include "peers/peer.hpp"

namespace mink_bench {
namespace {

struct Accuracy {
  int wrong = 0;
  double max_rel_err = 0;
  double mean_iterations = std::nan("");
};

Accuracy measure(const Case& c, const PairQueries& q, bool distance) {
  Accuracy acc;
  double iterations = 0;
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    try {
      iterations += q.iterations(i, distance);
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

void run(benchmark::State& state, const PairQueries* q, bool distance, Accuracy acc) {
  const std::size_t n = kPairsPerCase;
  std::size_t i = 0;
  try {
    if (distance) {
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
  if (distance) state.counters["max_rel_err"] = acc.max_rel_err;
  if (!std::isnan(acc.mean_iterations)) state.counters["iterations"] = acc.mean_iterations;
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
        benchmark::RegisterBenchmark(name.c_str(), run, m.queries.get(), distance, acc);
      }
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
