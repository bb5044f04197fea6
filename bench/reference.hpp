// Independent reference distances for separated pairs, in long double, written for the benchmark
// (no library code): analytic segment-segment for capsules, point-to-hull for a sphere against a
// polytope, and a brute force over hull feature pairs (vertex-triangle both ways, edge-edge) for
// boxes and polytopes.
#pragma once

#include "cases.hpp"

namespace mink_bench {

/// Distance between the shapes of pair i of `c`, which must be separated.
long double reference_distance(const Case& c, std::size_t i);

}  // namespace mink_bench
