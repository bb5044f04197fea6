// What the benchmark asks of each library: answer the pairs of one case, by index.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "../cases.hpp"

namespace mink_bench {

/// The queries of one library (one method) on one case; shapes and poses are converted to the
/// library's own types when the object is built, outside the timed loop.
class PairQueries {
 public:
  virtual ~PairQueries() = default;
  /// Do the shapes of pair i intersect?
  virtual bool intersect(std::size_t i) const = 0;
  /// Distance of pair i (0 when the library reports an intersection), with closest points
  /// computed where the method offers them.
  virtual double distance(std::size_t i) const = 0;
  /// Mean GJK iterations of the last pass, when the library reports them.
  virtual double iterations(std::size_t i, bool distance_query) const {
    (void)i;
    (void)distance_query;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

/// A library's method, with what it can answer.
struct Method {
  std::string name;  ///< column in the report, e.g. "fcl_ccd"
  bool has_intersect = true;
  bool has_distance = true;
  std::unique_ptr<PairQueries> queries;
};

std::vector<Method> make_mink_methods(const Case& c);
std::vector<Method> make_ccd_methods(const Case& c);
std::vector<Method> make_fcl_methods(const Case& c);
std::vector<Method> make_bullet_methods(const Case& c);

}  // namespace mink_bench
