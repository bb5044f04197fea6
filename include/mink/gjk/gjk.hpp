/// @file gjk.hpp
/// The GJK loop shared by intersect() and distance() (Gilbert, Johnson, Keerthi 1988; the
/// termination and the lower bound follow van den Bergen, "A fast and robust GJK implementation
/// for collision detection of convex objects", JGT 1999).
///
/// It runs on the *cores* of the shapes, in A's local frame with B's pose made relative to A, so
/// that shapes far from the world origin lose no precision. Each iteration asks the Minkowski
/// difference of the cores for its support point w in direction -v, where v is the point of the
/// current simplex closest to the origin. Then:
///   - |v| is an upper bound on the core distance, v.w / |v| a lower bound;
///   - the loop stops when the bounds meet within the tolerance, when w brings nothing new
///     (already in the simplex, or |v| stops decreasing: the rounding floor), when the simplex
///     encloses the origin, or at the iteration cap;
///   - run_gjk_boolean() also stops as soon as a bound decides "do they intersect?".
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "mink/gjk/signed_volumes.hpp"
#include "mink/gjk/simplex.hpp"
#include "mink/math/pose.hpp"
#include "mink/query/status.hpp"
#include "mink/query/tolerances.hpp"
#include "mink/shapes/shape_lengths.hpp"
#include "mink/shapes/support_scan.hpp"
#include "mink/support/concept.hpp"
#include "mink/support/polytope_core.hpp"

namespace mink::detail {

inline constexpr const char* kOverflowError =
    "coordinates too large: the computation overflowed the floating-point range";

/// The points of a small polytope B in A's frame, moved there once per query (frame_points_of_b())
/// so that each support call on B scans them along the direction as it is. Otherwise every call
/// turns the direction into B's frame and its answer back, two 3x3 products on the chain of
/// dependent steps from one support call to the next (see CoreDifference::support()).
template <class S>
struct FramedPointsT {
  /// The inlined scan's size (support_scan.hpp). Larger sets cost more to move than their calls
  /// save: polytope32 pairs apart took 551 -> 584 ns for distance() when moved.
  static constexpr std::size_t kMaxPoints = 8;
  alignas(16) S x[kMaxPoints];
  alignas(16) S y[kMaxPoints];
  alignas(16) S z[kMaxPoints];
  std::size_t size = 0;

  template <SupportPattern P = SupportPattern::Coherent>
  [[gnu::always_inline]] inline Vec3T<S> support(const Vec3T<S>& d) const {
    const std::size_t i = support_index<P>(x, y, z, size, d.x(), d.y(), d.z());
    return {x[i], y[i], z[i]};
  }
};

/// Support mapping of the Minkowski difference of the cores, A - B, in A's local frame.
template <ConvexShape A, ConvexShape B>
struct CoreDifference {
  using S = typename A::Scalar;
  const A& a;
  const B& b;
  Mat3T<S> rotation;     ///< B's rotation relative to A
  Vec3T<S> translation;  ///< B's origin in A's frame
  /// B's core points in A's frame (frame_points_of_b()), or null: B's support turns the direction.
  const FramedPointsT<S>* b_points = nullptr;

  // Always inlined: it is the body of every GJK iteration, and the compiler's cost model
  // otherwise leaves it out of line for the larger shapes. `P`: how the directions move between
  // calls (SupportPattern); polytope cores' scans take it, the other shapes need no choice.
  template <SupportPattern P = SupportPattern::Coherent>
  [[gnu::always_inline]] inline void support(const Vec3T<S>& d, SimplexVertexT<S>& out) const {
    out.a = core_support<P>(a, d);
    out.b = support_b<P>(d);
    out.w = out.a - out.b;
    out.dir = d;
  }

  /// B's core support point in A's frame for the direction -d (d as for support()).
  template <SupportPattern P = SupportPattern::Coherent>
  [[gnu::always_inline]] inline Vec3T<S> support_b(const Vec3T<S>& d) const {
    if constexpr (PolytopeCore<B>::value)
      if (b_points) return b_points->template support<P>(-d);
    return rotation * core_support<P>(b, Vec3T<S>(rotation.transpose() * (-d))) + translation;
  }

  /// Both shapes name a point of their core towards its middle (HasCoreCentre).
  static constexpr bool kCentred = HasCoreCentre<A> && HasCoreCentre<B>;

  /// The difference of the cores' centres: a point of A - B that costs no support call.
  Vec3T<S> centre_point() const requires kCentred {
    return a.core_centre() - (rotation * b.core_centre() + translation);
  }

  /// The point of A - B alone, for the boolean test, which needs no witness points.
  [[gnu::always_inline]] inline Vec3T<S> support_point(const Vec3T<S>& d) const {
    if constexpr (PolytopeCore<B>::value)
      if (b_points) return a.support_core(d) - b_points->support(-d);
    return a.support_core(d) - (rotation * b.support_core(direction_in_b(d)) + translation);
  }

  /// -d in B's frame, R^T (-d), as three dot products: the product expression's conversion to a
  /// vector was left out of line, its result passed through memory (a tenth of the boolean test on
  /// 8-point polytopes). support() keeps the expression: there the call was no slower.
  [[gnu::always_inline]] inline Vec3T<S> direction_in_b(const Vec3T<S>& d) const {
    return Vec3T<S>(-rotation.col(0).dot(d), -rotation.col(1).dot(d), -rotation.col(2).dot(d));
  }
};

/// A warm-start cache is only a hint: one with a bad size or a non-finite direction is ignored.
template <class S>
bool cache_is_usable(const GjkCacheT<S>* cache) {
  if (!cache || cache->size <= 0 || cache->size > 4) return false;
  for (int i = 0; i < cache->size; ++i)
    if (!is_finite(cache->directions[i])) return false;
  return true;
}

/// Stores the final simplex's directions (`direction_of(i)`, i < count) for the next query; an
/// empty simplex stores the last search direction instead.
template <class S, class DirectionOf>
void save_cache(GjkCacheT<S>* cache, int count, DirectionOf&& direction_of, const Vec3T<S>& v) {
  if (!cache) return;
  cache->size = count;
  for (int i = 0; i < count; ++i) cache->directions[i] = direction_of(i);
  if (count == 0 && v.squaredNorm() > S(0)) {
    cache->size = 1;
    cache->directions[0] = -v;
  }
}

template <class S>
struct GjkOutcome {
  Status status = Status::Separated;
  SimplexT<S> simplex;            ///< final simplex with weights
  Vec3T<S> v = Vec3T<S>::Zero();  ///< closest point of A - B's core to the origin (A's frame)
  S upper = std::numeric_limits<S>::infinity();  ///< upper bound on the core distance
  S lower = S(0);                                ///< lower bound on the core distance
  /// The v whose support point proved `lower` (its normal is -lower_v / |lower_v|, A's frame);
  /// meaningful when lower > 0. Only the direction: the point is rarely needed (separation.hpp)
  /// and copying it on every improvement costs the hot loop.
  Vec3T<S> lower_v = Vec3T<S>::Zero();
  int iterations = 0;
  /// gjk_apart() (separation.hpp): Newton's steps closed the bracket from the loose run's normal;
  /// `refined_normal` is theirs (unit, A's frame, from A to B), `refined_value` the support value
  /// of A - B along it and simplex.vertices[0] their witness pair, so separate_cores() takes them
  /// instead of taking the steps again.
  bool refined = false;
  Vec3T<S> refined_normal = Vec3T<S>::Zero();
  S refined_value = S(0);
};

/// What the cheap first phase of the boolean test found (enclose_origin()).
enum class EncloseVerdict { Separated, Intersecting, Unsure };

/// The signed volume det(x, y, z) = x . (y x z) of the tetrahedron (origin, x, y, z), and whether
/// its sign is certain.
template <class S>
struct OriginVolume {
  S value;
  /// The computed value exceeds its rounding error bound, about 5 eps times the permanent (the
  /// same sum with every term taken absolute; the bound used is 8 eps): the static filter of
  /// Shewchuk's orient3d with the origin as the fourth point, which needs no subtraction of the
  /// inputs. False on underflow (a permanent below min / eps), overflow and NaN.
  bool certain;
};

template <class S>
[[gnu::always_inline]] inline OriginVolume<S> origin_volume(const Vec3T<S>& x, const Vec3T<S>& y,
                                                            const Vec3T<S>& z) {
  const S yz0 = y[1] * z[2], zy0 = y[2] * z[1];
  const S yz1 = y[2] * z[0], zy1 = y[0] * z[2];
  const S yz2 = y[0] * z[1], zy2 = y[1] * z[0];
  const S det = x[0] * (yz0 - zy0) + x[1] * (yz1 - zy1) + x[2] * (yz2 - zy2);
  const S permanent = std::abs(x[0]) * (std::abs(yz0) + std::abs(zy0)) +
                      std::abs(x[1]) * (std::abs(yz1) + std::abs(zy1)) +
                      std::abs(x[2]) * (std::abs(yz2) + std::abs(zy2));
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  constexpr S kSmallest = std::numeric_limits<S>::min() / kEps;
  return {det, std::abs(det) > S(8) * kEps * permanent && permanent >= kSmallest};
}

/// The first phase's first search direction (enclose_origin()): towards the origin from A - B's
/// centre, B's origin seen from A, or +x when the origins coincide.
template <ConvexShape A, ConvexShape B>
Vec3T<typename A::Scalar> first_direction(const CoreDifference<A, B>& diff) {
  using S = typename A::Scalar;
  return diff.translation.squaredNorm() > S(0) ? Vec3T<S>(diff.translation) : Vec3T<S>::UnitX();
}

/// A point of the first phase's simplex (enclose_origin()): the point w of A - B and the direction
/// that found it, and with `kWitnesses` the support points on A and B that made it.
template <class S>
struct PointAndDirection {
  Vec3T<S> w;
  Vec3T<S> dir;
};
template <class S, bool kWitnesses>
using EnclosePointT = std::conditional_t<kWitnesses, SimplexVertexT<S>, PointAndDirection<S>>;

/// The first phase of the boolean test on cores with no radius: GJK that steers by the simplex
/// feature facing the origin (its plane's or line's normal, from cross products) instead of the
/// point closest to the origin (Casey Muratori's formulation, as in the seed article). On
/// overlapping shapes it needs no more support calls than the distance loop but a fraction of its
/// arithmetic and branches, and it is why the boolean test is worth having on polytopes.
///
/// Without `kWitnesses`, and when both shapes name a centre (HasCoreCentre), the simplex starts
/// as the segment from the first support point to the difference of the centres, a point of
/// A - B that costs no support call and lies inside it: enclosing the origin then takes three
/// support calls instead of four (MPR's portal starts from such a point for the same reason).
///
/// It only says what it can prove: Separated when a support plane leaves the origin more than
/// `inside` away (as the distance loop does), Intersecting when the four barycentric volumes of
/// its tetrahedron have one sign, each beyond its rounding error (origin_volume()): the origin
/// is then strictly inside the tetrahedron of the computed points, so within rounding of A - B.
/// Without `kWitnesses` also when the origin lies within `inside` of a segment of the simplex,
/// whose ends are points of A - B: the cores then touch or overlap, and the origin on the line of
/// centres (a box stacked on a box) is decided after one support call. Anything else (a volume
/// too small to sign, the origin near a face, a degenerate simplex, `max_supports` spent) is
/// Unsure, and the distance-based loop decides. Steering needs no such care: a wrong turn costs a
/// support call, not a wrong answer. `iterations` counts the support calls; when it decides,
/// `directions[0..count)` are those of the final simplex (or the separating direction), for the
/// warm-start cache.
///
/// `first` (optional): a support point and its direction (usually diff.translation), already
/// computed (and counted in `iterations`) by the caller: the phase starts from it. With
/// `kWitnesses` (contact(), whose EPA starts from the tetrahedron) the points carry their support
/// points on A and B, and `simplex` receives the final simplex: when the answer is Intersecting,
/// the enclosing tetrahedron with the origin's barycentric weights; when it is Separated, the
/// simplex and last the support point whose plane separates (no weights).
template <bool kWitnesses = false, ConvexShape A, ConvexShape B>
EncloseVerdict enclose_origin(const CoreDifference<A, B>& diff, typename A::Scalar inside,
                              int max_supports, int& iterations,
                              Vec3T<typename A::Scalar> (&directions)[4], int& count,
                              const EnclosePointT<typename A::Scalar, kWitnesses>* first = nullptr,
                              SimplexT<typename A::Scalar>* simplex = nullptr) {
  using S = typename A::Scalar;
  using V = Vec3T<S>;
  using P = EnclosePointT<S, kWitnesses>;
  // The simplex, oldest first; the support point of this iteration, w, is not stored until the
  // step below decides what to keep. Points are moved whole (no index lists): this loop is the
  // whole boolean test on small hulls, and its bookkeeping once cost as much as the supports.
  P p[3];
  V d = first ? V(first->dir) : first_direction(diff);
  count = 0;

  while (iterations < max_supports) {
    P next;
    if (first) {
      next = *first;
      first = nullptr;
    } else {
      if constexpr (kWitnesses) {
        // Scattered: contact()'s enclosing directions jump about as EPA's do, and not converging,
        // a branch on the winning point mispredicts (polytope32 contact overlapping 6 % faster).
        diff.template support<SupportPattern::Scattered>(d, next);  // sets next.dir
      } else {
        next.w = diff.support_point(d);
        next.dir = d;
      }
      ++iterations;
    }
    const V& w = next.w;
    const S wd = w.dot(d);
    if (!(wd >= S(0))) {
      // The support plane normal to d passes short of the origin: separated by -wd / |d|. It
      // decides only with room for the radii and the touching tolerance (NaN: not decided).
      if (exceeds_times_length(-wd, inside, d, S(d.squaredNorm()))) {
        if constexpr (kWitnesses) {
          if (simplex) {
            const int kept = count;
            for (int k = 0; k < kept; ++k) simplex->vertices[k] = p[k];
            simplex->vertices[kept] = next;
            simplex->size = kept + 1;
          }
        }
        directions[0] = d;  // the separating direction: the best warm start
        count = 1;
        return EncloseVerdict::Separated;
      }
      return EncloseVerdict::Unsure;
    }
    // Segment (p[k], w), w newest: the origin lies beside the segment (keep both, steer
    // perpendicular to it) or beyond w's end (keep w alone).
    bool on_segment = false;  // the origin within `inside` of the segment kept
    auto segment_with = [&](int k) {
      const V ab = p[k].w - w;
      const S ab_w = ab.dot(-w);
      if (ab_w > S(0)) {
        d = ab.cross(-w).cross(ab);
        if constexpr (!kWitnesses) {
          // The segment's point nearest the origin, from its parameter (a point, not the
          // cross products' lengths, so that no square leaves the range of doubles).
          const S t = ab_w / ab.squaredNorm();
          const V nearest = w + t * ab;
          on_segment = t <= S(1) && length_at_most(nearest, nearest.squaredNorm(), inside);
        }
        p[0] = p[k];
        p[1] = next;
        count = 2;
      } else {
        d = -w;
        p[0] = next;
        count = 1;
      }
    };
    // Triangle (p[i], p[j], w), w newest: an edge's side or the face's side facing the origin.
    auto triangle_with = [&](int i, int j) {
      const V ao = -w;
      const V ab = p[j].w - w, ac = p[i].w - w;
      const V abc = ab.cross(ac);
      if (abc.cross(ac).dot(ao) > S(0)) {
        if (ac.dot(ao) > S(0)) {
          // Edge (p[i], w).
          d = ac.cross(ao).cross(ac);
          const P pi = p[i];
          p[0] = pi;
          p[1] = next;
          count = 2;
        } else {
          segment_with(j);
        }
      } else if (ab.cross(abc).dot(ao) > S(0)) {
        segment_with(j);
      } else {
        d = abc.dot(ao) > S(0) ? abc : V(-abc);
        const P pi = p[i], pj = p[j];
        p[0] = pi;
        p[1] = pj;
        p[2] = next;
        count = 3;
      }
    };
    switch (count) {
      case 0:
        if constexpr (!kWitnesses && CoreDifference<A, B>::kCentred) {
          p[0].w = diff.centre_point();
          p[0].dir = -p[0].w;  // for the cache: its support point serves as well
          if (is_finite(p[0].w)) {
            segment_with(0);
            break;
          }
        }
        d = -w;
        p[0] = next;
        count = 1;
        break;
      case 1:
        segment_with(0);
        break;
      case 2:
        triangle_with(0, 1);
        break;
      default: {
        // Tetrahedron (p[0], p[1], p[2], w). The origin's barycentric coordinate for vertex k
        // is volume[k] / (their sum), volume[k] the signed volume with vertex k replaced by the
        // origin. The origin was on w's side of the old face (p[0], p[1], p[2]) when w was
        // sought, so volume[3] gives the orientation; a face whose volume has the other sign
        // has the origin beyond it, and its opposite vertex goes.
        const OriginVolume<S> faces[4] = {
            origin_volume(p[1].w, p[2].w, w), origin_volume(p[0].w, p[2].w, w),
            origin_volume(p[0].w, p[1].w, w), origin_volume(p[0].w, p[1].w, p[2].w)};
        const S volume[4] = {-faces[0].value, faces[1].value, -faces[2].value, faces[3].value};
        const S orientation = volume[3];
        if (volume[0] * orientation < S(0)) {
          triangle_with(1, 2);
          break;
        }
        if (volume[2] * orientation < S(0)) {
          triangle_with(0, 1);
          break;
        }
        if (volume[1] * orientation < S(0)) {
          triangle_with(2, 0);
          break;
        }
        // Enclosed by the rounded volumes; confirm each beyond its error, or leave it undecided.
        const bool certain =
            faces[0].certain && faces[1].certain && faces[2].certain && faces[3].certain;
        const bool one_sign =
            (volume[0] > S(0) && volume[1] > S(0) && volume[2] > S(0) && volume[3] > S(0)) ||
            (volume[0] < S(0) && volume[1] < S(0) && volume[2] < S(0) && volume[3] < S(0));
        if (certain && one_sign) {
          for (int k = 0; k < 3; ++k) directions[k] = p[k].dir;
          directions[3] = next.dir;
          count = 4;
          if constexpr (kWitnesses) {
            if (simplex) {
              const S total = volume[0] + volume[1] + volume[2] + volume[3];
              for (int k = 0; k < 3; ++k) simplex->vertices[k] = p[k];
              simplex->vertices[3] = next;
              for (int k = 0; k < 4; ++k) simplex->weights[k] = volume[k] / total;
              simplex->size = 4;
            }
          }
          return EncloseVerdict::Intersecting;
        }
        return EncloseVerdict::Unsure;
      }
    }
    if constexpr (!kWitnesses) {
      if (on_segment) {
        for (int k = 0; k < count; ++k) directions[k] = p[k].dir;
        return EncloseVerdict::Intersecting;
      }
    }
    if (!(d.squaredNorm() > S(0))) return EncloseVerdict::Unsure;  // the origin on the feature
  }
  return EncloseVerdict::Unsure;
}

/// Support calls the first phase of the boolean test may spend before the loop takes over.
inline constexpr int kEnclosePhaseSupports = 24;

/// enclose_origin() for distance() and contact(), out of line, so that the distance loop's code
/// stays as small as it was; with `kWitnesses` (contact()), `simplex` receives the final simplex
/// (see enclose_origin()). `first`: the support point along diff.translation, already computed.
template <bool kWitnesses, ConvexShape A, ConvexShape B>
[[gnu::noinline]] EncloseVerdict enclose_first_phase(
    const CoreDifference<A, B>& diff, typename A::Scalar inside, int max_supports, int& iterations,
    Vec3T<typename A::Scalar> (&directions)[4], int& count,
    const SimplexVertexT<typename A::Scalar>& first, SimplexT<typename A::Scalar>& simplex) {
  if constexpr (kWitnesses) {
    return enclose_origin<true>(diff, inside, max_supports, iterations, directions, count, &first,
                                &simplex);
  } else {
    const PointAndDirection<typename A::Scalar> start{first.w, first.dir};
    return enclose_origin<false>(diff, inside, max_supports, iterations, directions, count, &start);
  }
}

/// Whether run_gjk_distance() tries the boolean test's first phase, and what it keeps (see there).
enum class EnclosePhase { Off, Verdict, Simplex };

/// Runs GJK between the cores of a and b until the distance converges; `radius` is the sum of the
/// shapes' radii and `size` the sum of their bounding radii. Status is Separated or Intersecting
/// for the *full* shapes (cores within `radius`, touching within tolerance counts),
/// IterationLimit, or InvalidInput when the arithmetic overflowed (kOverflowError).
///
/// `kEnclose` (distance() and contact() set it): for cores with no radius and no warm start whose
/// first support point (along the line of centres) does not already prove them apart, the boolean
/// test's first phase runs on from that point (enclose_first_phase()). It proves most
/// overlapping pairs enclosed at a fraction of this loop's cost. With EnclosePhase::Verdict
/// (distance(), which reports no points for such pairs) the outcome's simplex is then empty, and
/// otherwise the loop goes on from the same first point. EnclosePhase::Simplex (contact()) has the
/// phase carry witness points, at some cost: the outcome's simplex is then the enclosing
/// tetrahedron with the origin's weights, which EPA starts from; when the phase finds a separating
/// plane, the loop goes on from the phase's simplex with the support point that showed it; when it
/// proves nothing, from the same first point.
///
/// A template parameter, so that each caller compiles only the phase it uses (the run-time Shape
/// instantiates every query for every pair of shape types).
template <EnclosePhase kEnclose = EnclosePhase::Off, ConvexShape A, ConvexShape B>
GjkOutcome<typename A::Scalar> run_gjk_distance(const CoreDifference<A, B>& diff,
                                                typename A::Scalar radius, typename A::Scalar size,
                                                const TolerancesT<typename A::Scalar>& tol,
                                                GjkCacheT<typename A::Scalar>* cache,
                                                typename A::Scalar stop_gap = 0) {
  using S = typename A::Scalar;
  // The bracket's width at which the loop stops (unit: length): `tol.relative * size` unless the
  // caller asks for a looser one (gjk_apart(), whose Newton steps close it).
  const S converged = stop_gap > S(0) ? stop_gap : tol.relative * size;
  GjkOutcome<S> out;
  // Two buffers: the simplex, and the trial simplices of the recombination below, which take its
  // place when they get closer.
  SimplexT<S> buffers[2];
  int current = 0;
  constexpr int kMaxRestarts = 8;
  int restarts = 0;
  SimplexT<S> saved;  // best simplex before a restart
  Vec3T<S> saved_v = Vec3T<S>::Zero();
  S saved_sq = std::numeric_limits<S>::infinity();
  const S touch = tol.relative * size;  // core distances up to this count as touching
  const S inside = radius + touch;

  Vec3T<S> v;
  bool v_in_set = false;  // v is a point of A - B (so |v| bounds the distance from above)
  // The boolean first phase is tried once, from the first support point (see above).
  const bool warm = cache_is_usable(cache);
  bool try_enclose = kEnclose != EnclosePhase::Off && radius == S(0) && !warm &&
                     diff.translation.squaredNorm() > S(0);
  if (warm) {
    // Rebuild the previous simplex from its directions: fresh support points of the current poses.
    for (int i = 0; i < cache->size; ++i) {
      SimplexVertexT<S> vertex;
      diff.support(cache->directions[i], vertex);
      ++out.iterations;
      buffers[current].append_unless_held(vertex);
    }
    v = reduce_to_closest_cold(buffers[current], buffers[current]);
    v_in_set = true;
    out.upper = v.norm();
  } else {
    // Start along the line of centres: A's farthest point towards B minus B's towards A.
    v = -diff.translation;
    if (!(v.squaredNorm() > S(0))) v = Vec3T<S>::UnitX();
  }

  while (true) {
    SimplexT<S>& simplex = buffers[current];
    const S v_sq = v.squaredNorm();
    if (v_in_set && (simplex.size == 4 || length_at_most(v, v_sq, touch))) {
      out.status = Status::Intersecting;
      break;
    }
    if (v_in_set && out.iterations >= tol.max_iterations) {
      out.status = Status::IterationLimit;
      break;
    }
    // Written past the simplex's end, where the step below keeps it if it makes progress: no copy
    // of the vertex's four vectors per iteration. simplex.size < 4 here (4 exits above).
    SimplexVertexT<S>& vertex = simplex.vertices[simplex.size];
    diff.support(-v, vertex);
    ++out.iterations;
    const S vw = v.dot(vertex.w);
    const S v_length = std::sqrt(v_sq);
    if constexpr (kEnclose != EnclosePhase::Off) {
      if (try_enclose) {
        try_enclose = false;
        Vec3T<S> directions[4];
        int count = 0;
        const int supports = std::min(kEnclosePhaseSupports, tol.max_iterations);
        // No phase when the first point already proves the cores apart.
        EncloseVerdict verdict = EncloseVerdict::Unsure;
        if (!(vw > touch * v_length))
          verdict = enclose_first_phase<kEnclose == EnclosePhase::Simplex>(
              diff, touch, supports, out.iterations, directions, count, vertex, out.simplex);
        if (verdict == EncloseVerdict::Intersecting) {
          out.status = Status::Intersecting;
          out.upper = S(0);
          save_cache(
              cache, count, [&directions](int i) { return directions[i]; },
              Vec3T<S>(Vec3T<S>::Zero()));
          return out;
        }
        if (kEnclose == EnclosePhase::Simplex && verdict == EncloseVerdict::Separated) {
          // The phase found a separating plane. Its support point bounds the distance from below,
          // and the loop goes on from the phase's simplex with that point in it, which is nearer
          // the answer than the line of centres' point alone.
          const SimplexVertexT<S>& last = out.simplex.vertices[out.simplex.size - 1];
          const Vec3T<S> last_v = -last.dir;  // the v whose support point that is
          const S last_lower = last_v.dot(last.w) / std::sqrt(last_v.squaredNorm());
          if (last_lower > out.lower) {
            out.lower = last_lower;
            out.lower_v = last_v;
          }
          SimplexT<S>& start = buffers[current];
          start.size = 0;
          for (int i = 0; i < out.simplex.size; ++i)
            start.append_unless_held(out.simplex.vertices[i]);
          v = reduce_to_closest_cold(start, start);
          v_in_set = true;
          continue;
        }
      }
    }
    // Selects, not a branch: whether the bound rises depends on the data, and a mispredicted
    // branch on it waited on the root and the division before the next support call.
    const S lower_here = vw / v_length;
    const bool rises = lower_here > out.lower;
    out.lower = rises ? lower_here : out.lower;
    out.lower_v = rises ? v : out.lower_v;
    if (v_in_set) {
      // Bounds met: |v| - v.w/|v| <= tol * size, i.e. gap = |v|^2 - v.w <= tol * size * |v|.
      // Relative to the shapes' size, not to the distance: far apart shapes still get their
      // distance to within tol * size (or to the rounding floor, which the no-progress test
      // below catches). A NaN makes both comparisons false instead of exiting. Not squared:
      // (tol * size)^2 |v|^2 underflows for shapes of 1e-100, and the loop then ran on to a false
      // rounding floor, 0.5% short.
      const S gap = v_sq - vw;
      if (gap <= S(0) || gap <= converged * v_length) {
        out.status = Status::Separated;
        break;
      }
      if (simplex.holds_point(vertex.w)) {
        out.status = Status::Separated;
        break;
      }
    }
    // The closest point with w, which lies past the end; `simplex` changes only once the step
    // makes progress (then in place, which moves only the vertices whose place changes).
    const KeptVertices<S> kept = closest_vertices(simplex, simplex.size + 1);
    const Vec3T<S> next = kept.v;
    const S next_sq = next.squaredNorm();
    if (!(next_sq <= std::numeric_limits<S>::max())) {
      // NaN or infinity: finite input whose products overflow (coordinates near 1e154 in
      // double). Nothing trustworthy can be said.
      out.status = Status::InvalidInput;
      break;
    }
    if (v_in_set && next_sq >= v_sq) {
      // No progress although the bounds may not have met. This happens when one shape is curved
      // and the other contributes a flat feature (a polytope edge against an ellipsoid): the
      // simplex mixes support points of A taken at different iterations, so the convex
      // combination sags inside A's curved surface, and the new w alone cannot lift it within
      // rounding. Any a - b with a on A and b on B is a point of A - B, so recombine: pair the
      // newest support point of A with every support point of B in the simplex (and the other
      // way round). One of those simplices holds the closest point without the sag. If neither
      // gets closer, this is the rounding floor and the previous simplex is the answer.
      const SimplexVertexT<S> newest = vertex;  // the trial buffer may become the simplex
      Vec3T<S> best_v = v;
      S best_sq = v_sq;
      for (int side = 0; side < 2; ++side) {
        SimplexT<S>& trial = buffers[current ^ 1];
        trial.size = 0;
        for (int k = 0; k <= simplex.size; ++k) {
          SimplexVertexT<S> mixed = k < simplex.size ? simplex.vertices[k] : newest;
          if (side == 0)
            mixed.a = newest.a;
          else
            mixed.b = newest.b;
          mixed.w = mixed.a - mixed.b;
          if (trial.size < 4) trial.append_unless_held(mixed);
        }
        const Vec3T<S> candidate = reduce_to_closest_cold(trial, trial);
        const S candidate_sq = candidate.squaredNorm();
        if (candidate_sq < best_sq) {
          best_sq = candidate_sq;
          best_v = candidate;
          current ^= 1;  // the trial buffer becomes the simplex
        }
        if (best_sq < v_sq) break;
      }
      if (!(best_sq < v_sq)) {
        // Still stuck with the bounds apart: restart from a fresh simplex along v, which sheds
        // the crowded points; keep the best answer seen in case the restart does no better.
        if (restarts < kMaxRestarts && v_sq - vw > converged * std::sqrt(v_sq)) {
          ++restarts;
          if (v_sq < saved_sq) {
            saved = simplex;
            saved_v = v;
            saved_sq = v_sq;
          }
          simplex.size = 0;
          v_in_set = false;
          continue;
        }
        out.status = Status::Separated;
        break;
      }
      v = best_v;
      continue;
    }
    keep_vertices(simplex, kept, simplex);
    v = next;
    v_in_set = true;
  }
  if (saved_sq < std::numeric_limits<S>::infinity() &&
      (!v_in_set || !(v.squaredNorm() < saved_sq)) && out.status != Status::Intersecting) {
    buffers[current] = saved;
    v = saved_v;
    v_in_set = true;
  }
  const SimplexT<S>& simplex = buffers[current];
  out.simplex = simplex;
  out.v = v_in_set ? v : Vec3T<S>::Zero();
  if (v_in_set) out.upper = v.norm();
  if (!(out.upper <= std::numeric_limits<S>::max()) && v_in_set) out.status = Status::InvalidInput;
  if (out.status == Status::Separated && out.upper <= inside) out.status = Status::Intersecting;
  // Cores that meet have distance 0; cores apart but within the radii keep their bounds.
  if (out.status == Status::Intersecting && !(out.upper > touch)) out.lower = S(0);
  save_cache(
      cache, simplex.size, [&simplex](int i) { return simplex.vertices[i].dir; }, v);
  return out;
}

template <class S>
struct GjkBooleanOutcome {
  Status status = Status::Separated;
  S upper = std::numeric_limits<S>::infinity();  ///< upper bound on the core distance
  int iterations = 0;
  /// The loop stalled with its bounds on both sides of the touching range: `status` is
  /// IterationLimit, and the caller decides (intersect(): the distance loop and distance()'s rule).
  bool stalled = false;
};

/// GJK as a yes/no test: do the full shapes intersect (cores within `radius`, touching within
/// tolerance counts)? Same iteration as run_gjk_distance(), but it stops as soon as a bound
/// decides, and its simplex holds only the points of A - B and their directions: no witness points
/// or weights to carry, which is most of the cost of an iteration on cheap shapes. In the rare
/// case where the loop stalls with the bounds on both sides of `radius` (curved shapes, see the
/// recombination in run_gjk_distance(); needles, whose thin simplices round), it says so
/// (`stalled`) and the caller hands the question to run_gjk_distance(), which has the witness
/// points to get unstuck.
///
/// `first` (optional): a support point and its direction (the first phase's first, or a point
/// core's support plane, query/point_solid.hpp), already computed by the caller, who passes it only
/// when there is no usable cache; it counts as one iteration, and the first phase (radius 0) or
/// else the loop starts from it.
template <ConvexShape A, ConvexShape B>
GjkBooleanOutcome<typename A::Scalar> run_gjk_boolean(
    const CoreDifference<A, B>& diff, typename A::Scalar radius, typename A::Scalar size,
    const TolerancesT<typename A::Scalar>& tol, GjkCacheT<typename A::Scalar>* cache,
    const PointAndDirection<typename A::Scalar>* first = nullptr) {
  using S = typename A::Scalar;
  GjkBooleanOutcome<S> out;
  Vec3T<S> points[4], directions[4];
  int count = 0;
  const S touch = tol.relative * size;
  const S inside = radius + touch;

  // The closest point of points[0..n) to the origin; keeps only the sub-simplex that holds it.
  auto reduce = [&points, &directions, &count](const SubSimplex<S>& r, int n) {
    const KeptVertices<S> kept = vertices_to_keep(r, points, n);
    for (int j = 0; j < kept.count; ++j) {
      points[j] = points[kept.index[j]];
      directions[j] = directions[kept.index[j]];
    }
    count = kept.count;
    return kept.v;
  };

  const bool warm = cache_is_usable(cache);
  if (warm) first = nullptr;  // the cache's points come first (callers pass none then)
  if (radius == S(0) && !warm) {
    // Cores with no radius: the cheap first phase decides most pairs; the loop below takes the
    // rest (the origin near the boundary of A - B), from a fresh start.
    out.iterations = first ? 1 : 0;
    const EncloseVerdict verdict =
        enclose_origin(diff, inside, std::min(kEnclosePhaseSupports, tol.max_iterations),
                       out.iterations, directions, count, first);
    if (verdict != EncloseVerdict::Unsure) {
      out.status =
          verdict == EncloseVerdict::Intersecting ? Status::Intersecting : Status::Separated;
      out.upper =
          verdict == EncloseVerdict::Intersecting ? S(0) : std::numeric_limits<S>::infinity();
      save_cache(
          cache, count, [&directions](int i) { return directions[i]; }, Vec3T<S>(Vec3T<S>::Zero()));
      return out;
    }
    count = 0;
    first = nullptr;  // the phase took it
  }

  Vec3T<S> v;
  bool v_in_set = false;  // v is a point of A - B (so |v| bounds the distance from above)
  if (warm) {
    for (int i = 0; i < cache->size; ++i) {
      const Vec3T<S> w = diff.support_point(cache->directions[i]);
      ++out.iterations;
      bool duplicate = false;
      for (int k = 0; k < count; ++k) duplicate |= points[k] == w;
      if (duplicate) continue;
      points[count] = w;
      directions[count] = cache->directions[i];
      ++count;
    }
    v = reduce(closest_of_simplex(points, count), count);
    v_in_set = true;
  } else if (first) {
    v = -first->dir;  // the loop's first support call is the caller's
  } else {
    v = -diff.translation;  // along the line of centres
    if (!(v.squaredNorm() > S(0))) v = Vec3T<S>::UnitX();
  }

  bool stalled = false;
  while (true) {
    const S v_sq = v.squaredNorm();
    if (v_in_set && (count == 4 || length_at_most(v, v_sq, inside))) {
      out.status = Status::Intersecting;
      break;
    }
    if (v_in_set && out.iterations >= tol.max_iterations) {
      out.status = Status::IterationLimit;
      break;
    }
    const Vec3T<S> w = first ? first->w : diff.support_point(-v);
    first = nullptr;
    ++out.iterations;
    const S vw = v.dot(w);
    // A separating plane with room for the radii decides: the lower bound v.w / |v| exceeds
    // `inside`, squared so the common one-iteration exit needs no square root (by |v| where the
    // squares leave the range of doubles: shapes of 1e-145 were called apart when
    // inside^2 |v|^2 underflowed to 0).
    if (exceeds_times_length(vw, inside, v, v_sq)) {
      out.status = Status::Separated;
      break;
    }
    if (v_in_set) {
      // Converged with |v| > inside: separated (the same test as run_gjk_distance()).
      const S gap = v_sq - vw;
      // NaN (overflow) decides nothing here: the simplex's closest point reports it below.
      if (gap <= S(0) || (gap > S(0) && !exceeds_times_length(gap, touch, v, v_sq))) {
        out.status = Status::Separated;
        break;
      }
      bool duplicate = false;
      for (int k = 0; k < count; ++k) duplicate |= points[k] == w;
      if (duplicate) {
        stalled = true;
        break;
      }
    }
    // Append w past the end; points[0..count) stay as they were until progress is certain.
    points[count] = w;
    directions[count] = -v;
    const SubSimplex<S> closest = closest_of_simplex(points, count + 1);
    if (!(closest.dist_sq <= std::numeric_limits<S>::max())) {
      out.status = Status::InvalidInput;  // overflow, see run_gjk_distance()
      return out;
    }
    if (v_in_set && closest.dist_sq >= v_sq) {
      stalled = true;  // no progress: settled below
      break;
    }
    const Vec3T<S> next = reduce(closest, count + 1);
    v = next;
    v_in_set = true;
  }
  out.upper = v_in_set ? v.norm() : std::numeric_limits<S>::infinity();
  save_cache(
      cache, count, [&directions](int i) { return directions[i]; }, v);
  if (stalled) {
    // The bounds straddle `inside` and this simplex cannot tighten them: the distance loop, with
    // its recombination and restarts, decides (intersect()).
    out.status = Status::IterationLimit;
    out.stalled = true;
  }
  return out;
}

}  // namespace mink::detail

namespace mink::detail {

/// True when every entry of the pose is finite. Multiplying by zero maps finite values to 0 and
/// NaN or infinity to NaN, so one vectorised sum decides (allFinite() tests entry by entry).
template <class S>
[[gnu::always_inline]] inline bool pose_is_finite(const PoseT<S>& pose) {
  return (pose.rotation.array() * S(0)).sum() + (pose.translation.array() * S(0)).sum() == S(0);
}

/// Whether the sum of every entry of both poses is finite: true when every entry is finite,
/// except where the sum of finite entries overflows (translations near the largest S), which
/// pose_finiteness_error() sorts out. A NaN stays NaN in a sum, an infinity stays infinite or
/// meets the other sign's and makes NaN: one chain of additions, where testing each pose's
/// entries took twice the instructions.
template <class S>
[[gnu::always_inline]] inline bool poses_sum_finite(const PoseT<S>& pose_a,
                                                    const PoseT<S>& pose_b) {
  const S sum = (pose_a.rotation.array() + pose_b.rotation.array()).sum() +
                (pose_a.translation.array() + pose_b.translation.array()).sum();
  return sum - sum == S(0);
}

/// Which pose is not finite (pose_is_finite() of each), or nullptr: both are, and the sum of
/// their entries overflowed.
template <class S>
[[gnu::noinline, gnu::cold]] const char* pose_finiteness_error(const PoseT<S>& pose_a,
                                                               const PoseT<S>& pose_b) {
  if (!pose_is_finite(pose_a)) return "pose of A is not finite";
  if (!pose_is_finite(pose_b)) return "pose of B is not finite";
  return nullptr;
}

/// Why a query cannot run, or nullptr, shape by shape and entry by entry, in the order of the
/// messages; for query_input_error(), out of line, where its quick checks fail.
template <ConvexShape A, ConvexShape B>
[[gnu::noinline, gnu::cold]] const char* query_input_error_in_full(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b) {
  if (const char* e = a.error()) return e;
  if (const char* e = b.error()) return e;
  return pose_finiteness_error(pose_a, pose_b);
}

/// For two shapes made of lengths alone (shape_lengths.hpp): every pose entry and length finite
/// and every length >= 0, from one sum of them all (finite unless an entry is not, or the sum of
/// finite ones overflows: as poses_sum_finite()) and one minimum of the lengths, with one branch.
/// Shape by shape, the checks took 72 of the 378 instructions of a box pair's boolean test apart,
/// a fifth of its time: the test runs near the machine's instruction throughput.
template <ConvexShape A, ConvexShape B>
[[gnu::always_inline]] inline bool lengths_and_poses_valid(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b) {
  using S = typename A::Scalar;
  const auto lengths_a = ShapeLengths<A>::of(a);
  const auto lengths_b = ShapeLengths<B>::of(b);
  const S sum = (pose_a.rotation.array() + pose_b.rotation.array()).sum() +
                (pose_a.translation.array() + pose_b.translation.array()).sum() +
                (lengths_a.sum() + lengths_b.sum());
  const S least = std::min(lengths_a.minCoeff(), lengths_b.minCoeff());
  return int(sum - sum == S(0)) & int(least >= S(0));
}

/// Why a query cannot run, or nullptr. Poses are checked for finiteness only: an orthonormal
/// rotation is the caller's contract (pose_error() checks it in full, the JSON front end does).
/// Always inlined: every query starts with it, and whether GCC inlines it otherwise changes with
/// the size of the query around it (3-5 % of a capsule query).
template <ConvexShape A, ConvexShape B>
[[gnu::always_inline]] inline const char* query_input_error(
    const A& a, const PoseT<typename A::Scalar>& pose_a, const B& b,
    const PoseT<typename A::Scalar>& pose_b) {
  if constexpr (kLengthPair<A, B>) {
    if (lengths_and_poses_valid(a, pose_a, b, pose_b)) [[likely]]
      return nullptr;
    return query_input_error_in_full(a, pose_a, b, pose_b);
  } else {
    if (a.error() || b.error() || !poses_sum_finite(pose_a, pose_b)) [[unlikely]]
      return query_input_error_in_full(a, pose_a, b, pose_b);
    return nullptr;
  }
}

/// For distance() and contact(), whose GJK and EPA call B's support several times: when B's core
/// is a polytope of at most FramedPointsT::kMaxPoints points, moves them into `framed` (A's frame,
/// by the same product as CoreDifference::support() moves its answer) and has `diff` scan them.
/// Not for the boolean test, most of whose pairs one support call decides: the move cost more
/// than that call (polytope8 pairs apart, +30 ns when stop 34 tried it; docs/benchmarks.md).
/// `framed` must outlive `diff`'s use.
template <ConvexShape A, ConvexShape B>
[[gnu::always_inline]] inline void frame_points_of_b(CoreDifference<A, B>& diff,
                                                     FramedPointsT<typename A::Scalar>& framed) {
  using S = typename A::Scalar;
  if constexpr (PolytopeCore<B>::value) {
    const auto& polytope = PolytopeCore<B>::of(diff.b);
    const std::size_t n = polytope.size();
    if (n > FramedPointsT<S>::kMaxPoints) return;
    // The expression support() moves its answer by: the same point, bit for bit.
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3T<S> p = diff.rotation * polytope.point(i) + diff.translation;
      framed.x[i] = p.x();
      framed.y[i] = p.y();
      framed.z[i] = p.z();
    }
    framed.size = n;
    diff.b_points = &framed;
  }
}

template <ConvexShape A, ConvexShape B>
CoreDifference<A, B> make_core_difference(const A& a, const PoseT<typename A::Scalar>& pose_a,
                                          const B& b, const PoseT<typename A::Scalar>& pose_b) {
  CoreDifference<A, B> diff{a, b, {}, {}, nullptr};
  pose_a.relative(pose_b, diff.rotation, diff.translation);
  return diff;
}

}  // namespace mink::detail
