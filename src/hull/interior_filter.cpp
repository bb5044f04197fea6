// Interior filter: most points of a solid cloud (in a ball, in a cube) are deep inside its hull,
// and Quickhull spends most of its time handing them from face to face until no face sees them.
// A ball and a box inscribed in the exact hull of every 16th point (itself filtered the same way,
// recursively) reject them with one test each. Why a rejected point is never needed: see
// hull_candidates in interior_filter.hpp and the margin below.
#include "interior_filter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "mink/hull/predicates.hpp"
#include "triangle_hull.hpp"

namespace mink::detail {
namespace {

constexpr std::size_t kMinFilter = 4096;  // smaller inputs: Quickhull alone is as fast
constexpr std::size_t kSampleStride = 16;
constexpr int kMaxDepth = 6;

/// Four points of s spanning a solid (extremes along the widest axis, farthest from their line,
/// farthest from that plane), or false when s looks flat.
bool find_simplex(const std::vector<Vec3>& s, int simplex[4]) {
  Vec3 lo = s[0], hi = s[0];
  for (const Vec3& x : s) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (hi[i] - lo[i] > hi[axis] - lo[axis]) axis = i;
  }
  int a = 0, b = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i][axis] < s[static_cast<std::size_t>(a)][axis]) a = static_cast<int>(i);
    if (s[i][axis] > s[static_cast<std::size_t>(b)][axis]) b = static_cast<int>(i);
  }
  const Vec3 qa = s[static_cast<std::size_t>(a)], ab = s[static_cast<std::size_t>(b)] - qa;
  int c = a;
  double best = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double d2 = (s[i] - qa).cross(ab).squaredNorm();
    if (d2 > best) {
      best = d2;
      c = static_cast<int>(i);
    }
  }
  const Vec3 n = ab.cross(s[static_cast<std::size_t>(c)] - qa);
  int d = a;
  best = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double h = std::fabs(n.dot(s[i] - qa));
    if (h > best) {
      best = h;
      d = static_cast<int>(i);
    }
  }
  simplex[0] = a;
  simplex[1] = b;
  simplex[2] = c;
  simplex[3] = d;
  return exact::orient3d(
             s[static_cast<std::size_t>(a)].data(), s[static_cast<std::size_t>(b)].data(),
             s[static_cast<std::size_t>(c)].data(), s[static_cast<std::size_t>(d)].data()) != 0;
}

/// Removes from idx the points strictly inside the inner ball or box of the hull of a sample of
/// idx. Returns the fraction removed, or -1 when it did not try (too few points).
double filter(std::span<const Vec3> q, std::vector<int>& idx, int depth) {
  if (idx.size() < kMinFilter || depth >= kMaxDepth) return -1;
  std::vector<int> sample;
  sample.reserve(idx.size() / kSampleStride + 1);
  for (std::size_t i = 0; i < idx.size(); i += kSampleStride) sample.push_back(idx[i]);
  // A sample whose own filter removed little says the cloud is hollow (points on a sphere):
  // stop before paying for its hull.
  const double sub = filter(q, sample, depth + 1);
  if (sub >= 0 && sub < 0.25) return 0;

  std::vector<Vec3> s(sample.size());
  for (std::size_t i = 0; i < sample.size(); ++i) s[i] = q[static_cast<std::size_t>(sample[i])];
  int simplex[4];
  if (!find_simplex(s, simplex)) return 0;
  TriangleHull hull;
  std::string error;
  if (!build_triangle_hull(s, simplex, 0, hull, error)) return 0;

  // Centre: the mean of the hull's vertices, an interior point of a solid hull.
  std::vector<char> is_vertex(s.size(), 0);
  Vec3 centre = Vec3::Zero();
  double magnitude = 0, count = 0;
  for (const HullTriangle& t : hull.triangles) {
    for (const int v : t.v) {
      if (is_vertex[static_cast<std::size_t>(v)]) continue;
      is_vertex[static_cast<std::size_t>(v)] = 1;
      centre += s[static_cast<std::size_t>(v)];
      magnitude = std::max(magnitude, s[static_cast<std::size_t>(v)].cwiseAbs().maxCoeff());
      ++count;
    }
  }
  centre /= count;
  Vec3 half = Vec3::Zero();  // of the vertices' box about the centre
  for (std::size_t v = 0; v < s.size(); ++v) {
    if (is_vertex[v]) half = half.cwiseMax((s[v] - centre).cwiseAbs());
  }
  // The inner ball has the smallest distance from the centre to a face plane; the inner box is
  // the vertices' box scaled about the centre until a corner reaches a face plane.
  double radius = HUGE_VAL, box_scale = HUGE_VAL;
  for (const HullTriangle& t : hull.triangles) {
    double c[3];
    const double* a = s[static_cast<std::size_t>(t.v[0])].data();
    exact::cross_rounded(a, s[static_cast<std::size_t>(t.v[1])].data(),
                         s[static_cast<std::size_t>(t.v[2])].data(), c);
    const Vec3 n = Vec3(c[0], c[1], c[2]);
    const double len = n.norm();
    if (!(len > 0)) return 0;
    const Vec3 u = n / len;
    const double depth_below = u.dot(s[static_cast<std::size_t>(t.v[0])] - centre);
    radius = std::min(radius, depth_below);
    box_scale = std::min(box_scale, depth_below / u.cwiseAbs().dot(half));
  }
  // Margin. Coordinates are at most `magnitude`; the unit normals are within about 10 u of the
  // exact face normals (rounded cross products, then normalised), and every dot product or
  // squared distance here is rounded by a few u, so each tested distance is within about
  // 100 u magnitude (< 1e-13 magnitude) of its exact value. A margin of 1e-9 magnitude
  // therefore keeps every rejected point strictly inside every face plane of the sample's hull.
  const double margin = 1e-9 * magnitude;
  const double r = radius - margin;
  const double r2 = r > 0 ? r * r : -1;
  Vec3 box = box_scale * half - Vec3::Constant(margin);
  if (!(box_scale > 0) || box.minCoeff() <= 0) box = Vec3::Constant(-1);

  std::size_t kept = 0;
  const std::size_t total = idx.size();
  for (std::size_t i = 0; i < total; ++i) {
    const Vec3& x = q[static_cast<std::size_t>(idx[i])];
    const double dx = x[0] - centre[0], dy = x[1] - centre[1], dz = x[2] - centre[2];
    const bool in_ball = dx * dx + dy * dy + dz * dz < r2;
    const bool in_box = std::fabs(dx) < box[0] && std::fabs(dy) < box[1] && std::fabs(dz) < box[2];
    if (!in_ball && !in_box) idx[kept++] = idx[i];
  }
  idx.resize(kept);
  return 1 - static_cast<double>(kept) / static_cast<double>(total);
}

/// Spreads the low 21 bits of x to every third bit.
std::uint64_t spread(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

}  // namespace

void sort_spatially(std::span<const Vec3> q, std::vector<int>& idx) {
  if (idx.size() < 2) return;
  Vec3 lo = q[static_cast<std::size_t>(idx[0])], hi = lo;
  for (const int i : idx) {
    lo = lo.cwiseMin(q[static_cast<std::size_t>(i)]);
    hi = hi.cwiseMax(q[static_cast<std::size_t>(i)]);
  }
  const double cells = 2097151;  // 2^21 - 1
  Vec3 to_cell;
  for (int k = 0; k < 3; ++k) to_cell[k] = hi[k] > lo[k] ? cells / (hi[k] - lo[k]) : 0;
  std::vector<std::pair<std::uint64_t, int>> keyed(idx.size());
  for (std::size_t j = 0; j < idx.size(); ++j) {
    const Vec3& x = q[static_cast<std::size_t>(idx[j])];
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k) {
      const double c = std::clamp((x[k] - lo[k]) * to_cell[k], 0.0, cells);
      code |= spread(static_cast<std::uint64_t>(c)) << k;
    }
    keyed[j] = {code, idx[j]};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t j = 0; j < idx.size(); ++j) idx[j] = keyed[j].second;
}

std::vector<int> hull_candidates(std::span<const Vec3> q) {
  std::vector<int> idx(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) idx[i] = static_cast<int>(i);
  filter(q, idx, 0);
  return idx;
}

}  // namespace mink::detail
