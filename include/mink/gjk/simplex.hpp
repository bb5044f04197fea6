/// @file simplex.hpp
/// GJK's simplex: up to four points of the Minkowski difference A - B, each with the support
/// points on A and B that made it and the direction that found it.
#pragma once

#include "mink/math/vec.hpp"

namespace mink {

template <class S>
struct SimplexVertexT {
  Vec3T<S> w;    ///< a - b, a point of the Minkowski difference of the cores
  Vec3T<S> a;    ///< support point on A's core (A's local frame)
  Vec3T<S> b;    ///< support point on B's core (A's local frame)
  Vec3T<S> dir;  ///< the search direction that produced it (A's local frame)
};

template <class S>
struct SimplexT {
  SimplexVertexT<S> vertices[4];
  S weights[4] = {};  ///< barycentric weights of the closest point, > 0 and summing to 1
  int size = 0;       ///< 0..4

  /// Whether a vertex has the point `w` of A - B: a support point met again.
  bool holds_point(const Vec3T<S>& w) const {
    bool held = false;  // no early exit: the loop is short and its branch unpredictable
    for (int k = 0; k < size; ++k) held |= vertices[k].w == w;
    return held;
  }

  /// Appends `vertex` unless its point of A - B is already held. The caller keeps size < 4.
  void append_unless_held(const SimplexVertexT<S>& vertex) {
    if (!holds_point(vertex.w)) vertices[size++] = vertex;
  }

  /// The closest point's witnesses on A and B: the weighted sums of the vertices' support
  /// points. Weights are renormalised (equal weights if they are all 0) so that a simplex whose
  /// weights were never set still gives a point of each shape.
  void witness_points(Vec3T<S>& on_a, Vec3T<S>& on_b) const {
    S total = S(0);
    for (int i = 0; i < size; ++i) total += weights[i];
    on_a = Vec3T<S>::Zero();
    on_b = Vec3T<S>::Zero();
    for (int i = 0; i < size; ++i) {
      const S weight = total > S(0) ? weights[i] / total : S(1) / S(size);
      on_a += weight * vertices[i].a;
      on_b += weight * vertices[i].b;
    }
  }
};

/// Warm start for temporally coherent queries: the directions of the last final simplex in A's
/// local frame. A zero-initialised cache is a valid cold start. The cache is only a hint: a stale
/// cache costs iterations, never accuracy.
template <class S>
struct GjkCacheT {
  Vec3T<S> directions[4];
  int size = 0;
};

using GjkCache = GjkCacheT<double>;

}  // namespace mink
