/// @file face_planes.hpp
/// The faces of a small convex polytope as planes and edge loops, for point queries in closed
/// form (query/point_solid.hpp): a point is inside when it is below every plane, and then the
/// nearest plane is the nearest part of the surface; outside, the nearest point lies on a face
/// whose plane the point is above, in the face or on one of its edges.
///
/// Built from the polytope's convex hull (hull/convex_hull.hpp) only when the answers are exact
/// to rounding: a solid hull, at most kMaxFaces faces (beyond that GJK's few support calls cost
/// less than the plane scan), and every face flat to rounding. A hull face is flat only within
/// the hull's tolerance (1e-10 of the points' extent), which would be the error of the answers;
/// nearly coplanar inputs therefore keep GJK, which works on the points themselves. Also none for
/// coordinates beyond 2^+-488 (2^+-40 in float), whose squares would overflow or underflow.
///
/// The arrays the scans read are held in the struct (5 KB), those of the edge search sized to the
/// hull: through a vector, the scans cost 10 % more on 8-point polytopes.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "mink/hull/convex_hull.hpp"
#include "mink/math/vec.hpp"

namespace mink {

template <class S>
struct FacePlanesT {
  /// At most this many faces (the hull of 34 points in general position has 64).
  static constexpr std::size_t kMaxFaces = 64;
  /// Half-edges: 2 E, and E <= 3 F - 6 (Euler's formula with at least 3 edges at every vertex).
  static constexpr std::size_t kMaxEdges = 6 * kMaxFaces - 12;
  /// Corners: V <= 2 F - 4 (the dual of F >= V / 2 + 2), a multiple of 4.
  static constexpr std::size_t kMaxCorners = 2 * kMaxFaces - 4;

  std::uint32_t face_count = 0;
  /// The largest coordinate of the points: the scale of the planes' rounding.
  S largest = S(0);
  /// Plane of face f: normal (nx, ny, nz)[f], unit and outward, and offset[f], the largest
  /// normal . x over the face's corners (the polytope's largest to rounding). Entries from
  /// face_count up to the next multiple of 4 are padding that is never the largest: normal 0,
  /// offset +inf.
  alignas(32) std::array<S, kMaxFaces> nx{}, ny{}, nz{}, offset{};
  /// Face f's edges are edge_begin[f] .. edge_begin[f + 1] - 1, counter-clockwise seen from
  /// outside: edge k runs from corner[k] to the next corner of the loop.
  std::array<std::uint16_t, kMaxFaces + 1> edge_begin{};
  std::vector<Vec3T<S>> corner;
  /// normal x (next corner - corner[k]): in the face's plane, pointing into the face.
  std::vector<Vec3T<S>> inward;
  /// The hull's vertices (cx, cy, cz)[i], for scans: entries from corner_count up to the next
  /// multiple of 4 repeat vertex 0.
  std::uint32_t corner_count = 0;
  alignas(32) std::array<S, kMaxCorners> cx{}, cy{}, cz{};

  /// Face planes of `hull`, or nothing when they would not give exact answers (see the file
  /// comment). `points` are the points the hull was built from: their largest coordinate sets the
  /// rounding the faces are held to.
  static std::optional<FacePlanesT> make(const ConvexHull& hull, std::span<const Vec3> points) {
    if (hull.status != HullStatus::Full || !hull.complete || hull.faces.size() > kMaxFaces)
      return std::nullopt;
    double largest = 0;
    for (const Vec3& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    // Squares of coordinates and edges must neither overflow nor underflow in S.
    constexpr int kRange = std::numeric_limits<S>::max_exponent / 2 - 24;
    if (!(largest <= double(detail::power_of_two<S>(kRange)) &&
          largest >= double(detail::power_of_two<S>(-kRange))))
      return std::nullopt;
    // The hull's offsets carry a margin of about 24 eps M, and n . x about 4 eps M of rounding
    // (hull/convex_hull.hpp); a face merged within the hull's tolerance shows 1e-10 of the extent.
    const double flat = 256 * std::numeric_limits<double>::epsilon() * largest;
    FacePlanesT planes;
    planes.face_count = std::uint32_t(hull.faces.size());
    planes.largest = S(largest);
    std::size_t edges = 0;
    for (std::size_t f = 0; f < hull.faces.size(); ++f) {
      const HullFace& face = hull.faces[f];
      if (edges + face.count > kMaxEdges) return std::nullopt;
      // Not the hull's offset, which is an upper bound with a margin of up to 24 eps M: a bias
      // of every distance from the face (4e-15 of the size on the benchmark's polytopes).
      double offset = -std::numeric_limits<double>::infinity();
      for (std::uint32_t k = 0; k < face.count; ++k) {
        const Vec3& here = hull.vertices[hull.face_vertex(f, k)].position;
        const Vec3& next = hull.vertices[hull.face_vertex(f, (k + 1) % face.count)].position;
        if (!(std::abs(face.normal.dot(here) - face.offset) <= flat)) return std::nullopt;
        offset = std::max(offset, face.normal.dot(here));
        planes.corner.push_back(here.template cast<S>());
        planes.inward.push_back(face.normal.cross(next - here).template cast<S>());
      }
      planes.nx[f] = S(face.normal.x());
      planes.ny[f] = S(face.normal.y());
      planes.nz[f] = S(face.normal.z());
      planes.offset[f] = S(offset);
      planes.edge_begin[f] = std::uint16_t(edges);
      edges += face.count;
    }
    planes.edge_begin[hull.faces.size()] = std::uint16_t(edges);
    if (hull.vertices.size() > kMaxCorners) return std::nullopt;  // not a polytope's hull
    planes.corner_count = std::uint32_t(hull.vertices.size());
    for (std::size_t i = 0; i < planes.corner_scan_count(); ++i) {
      const Vec3& v = hull.vertices[i < hull.vertices.size() ? i : 0].position;
      planes.cx[i] = S(v.x());
      planes.cy[i] = S(v.y());
      planes.cz[i] = S(v.z());
    }
    for (std::size_t f = hull.faces.size(); f < kMaxFaces; ++f)
      planes.offset[f] = std::numeric_limits<S>::infinity();
    return planes;
  }

  Vec3T<S> normal(std::size_t f) const { return {nx[f], ny[f], nz[f]}; }
  /// Faces rounded up to a multiple of 4, the padding included: the length of the plane scan.
  std::size_t scan_count() const {
    return std::min<std::size_t>((face_count + 3) & ~3u, kMaxFaces);
  }
  Vec3T<S> corner_point(std::size_t i) const { return {cx[i], cy[i], cz[i]}; }
  /// Corners rounded up to a multiple of 4, the padding included: the length of a corner scan.
  std::size_t corner_scan_count() const {
    return std::min<std::size_t>((corner_count + 3) & ~3u, kMaxCorners);
  }
};

using FacePlanes = FacePlanesT<double>;

}  // namespace mink
