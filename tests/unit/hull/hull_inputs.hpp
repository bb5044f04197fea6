// Point sets for the hull tests: random distributions, degenerate and nearly degenerate sets
// modelled on Qhull's rbox test options, and regression inputs from other libraries' issues
// (docs: ../shared/research/hull-anchors.md, section 5).
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mink/math/vec.hpp"

namespace hull_inputs {

using mink::Vec3;

struct Input {
  std::string name;
  std::vector<Vec3> points;
};

inline std::mt19937_64 rng(unsigned seed) {
  return std::mt19937_64(seed);
}

inline Vec3 unit_vector(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  for (;;) {
    const Vec3 v(n(g), n(g), n(g));
    if (v.norm() > 1e-3) return v.normalized();
  }
}

inline std::vector<Vec3> in_ball(int n, unsigned seed) {
  auto g = rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back(unit_vector(g) * std::cbrt(u(g)));
  return p;
}

inline std::vector<Vec3> in_cube(int n, unsigned seed) {
  auto g = rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.emplace_back(u(g), u(g), u(g));
  return p;
}

inline std::vector<Vec3> on_sphere(int n, unsigned seed) {
  auto g = rng(seed);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back(unit_vector(g));
  return p;
}

/// Points on the surface of [-1, 1]^3 (rbox W0), with the corners when asked; every face then
/// holds many exactly coplanar points.
inline std::vector<Vec3> on_cube_surface(int n, unsigned seed, bool corners, double fuzz = 0) {
  auto g = rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> face(0, 5);
  std::vector<Vec3> p;
  if (corners) {
    for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  }
  for (int i = 0; i < n; ++i) {
    Vec3 v(u(g), u(g), u(g));
    const int f = face(g);
    v[f / 2] = (f % 2 ? 1 : -1) * (1 + fuzz * u(g));
    p.push_back(v);
  }
  return p;
}

/// An integer lattice k x k x k, optionally mapped by the integer matrix of rbox M3,4,5.
inline std::vector<Vec3> lattice(int k, bool rotated) {
  std::vector<Vec3> p;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l) {
        if (rotated)
          p.emplace_back(3 * i - 4 * j, 4 * i + 3 * j, 5 * l);
        else
          p.emplace_back(i, j, l);
      }
  return p;
}

/// Points rotated by a random rotation (rounded, so coplanar sets become nearly coplanar).
inline std::vector<Vec3> rotated(std::vector<Vec3> p, unsigned seed) {
  auto g = rng(seed);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.0 + seed % 7, unit_vector(g)));
  const mink::Mat3 m = q.toRotationMatrix();
  for (Vec3& v : p) v = m * v;
  return p;
}

/// Pairs of nearly coincident points on a sphere (rbox C1,1e-13 style).
inline std::vector<Vec3> near_pairs(int n, double gap, unsigned seed) {
  auto g = rng(seed);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const Vec3 v = unit_vector(g);
    p.push_back(v);
    p.push_back(v + gap * unit_vector(g));
  }
  return p;
}

/// A narrow lens: the intersection of two balls of radius r whose circle of intersection has
/// radius 1 (rbox L), points on its surface; thickness about 1 / r.
inline std::vector<Vec3> lens(int n, double r, unsigned seed) {
  auto g = rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double h = std::sqrt(r * r - 1);
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double rho = std::sqrt(u(g)), phi = 2 * M_PI * u(g);
    const double x = rho * std::cos(phi), y = rho * std::sin(phi);
    const double z = std::sqrt(r * r - rho * rho) - h;
    p.emplace_back(x, y, i % 2 ? z : -z);
  }
  return p;
}

/// A cone of nearly cocircular points: an apex above a circle whose points are off by `fuzz`
/// radially (rbox s Z1 G1e-13 style).
inline std::vector<Vec3> cocircular_cone(int n, double fuzz, unsigned seed) {
  auto g = rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> p{Vec3(0, 0, 1)};
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * M_PI * i / n, r = 1 + fuzz * u(g);
    p.emplace_back(r * std::cos(phi), r * std::sin(phi), 0);
  }
  return p;
}

/// The vertex cloud of cylinder(r = 3.5, h = 10, 32 segments) + sphere(r = 2, 32 segments):
/// the Minkowski-sum input of manifold#1785 (large exactly coplanar clusters).
inline std::vector<Vec3> minkowski_cylinder_sphere() {
  std::vector<Vec3> cyl, sph, p;
  for (int i = 0; i < 32; ++i) {
    const double a = 2 * M_PI * i / 32;
    cyl.emplace_back(3.5 * std::cos(a), 3.5 * std::sin(a), -5);
    cyl.emplace_back(3.5 * std::cos(a), 3.5 * std::sin(a), 5);
  }
  sph.emplace_back(0, 0, 2);
  sph.emplace_back(0, 0, -2);
  for (int ring = 1; ring < 16; ++ring) {
    const double t = M_PI * ring / 16;
    for (int i = 0; i < 32; ++i) {
      const double a = 2 * M_PI * i / 32;
      sph.emplace_back(2 * std::sin(t) * std::cos(a), 2 * std::sin(t) * std::sin(a),
                       2 * std::cos(t));
    }
  }
  for (const Vec3& a : cyl)
    for (const Vec3& b : sph) p.push_back(a + b);
  return p;
}

/// The regression inputs of hull-anchors.md section 5 whose points are published in the issue.
inline std::vector<Input> regressions() {
  std::vector<Input> r;
  // manifold#1785: two points of the 15-point reduction are published; the full cloud it was
  // reduced from is minkowski_cylinder_sphere().
  r.push_back({"manifold1785_cloud", minkowski_cylinder_sphere()});
  // manifold#781: the 18-point reduction as printed (6 significant digits).
  r.push_back({"manifold781",
               {{-18.2869, 31.6738, 2.175},
                {-17.6332, -17.342, 89.9628},
                {49.8656, -0, 55.5071},
                {-20.4426, -35.4077, 8.275},
                {-23.0164, 39.8656, 79.0839},
                {10.2294, -14.7178, 10.508},
                {-24.9832, 43.2722, 52.7107},
                {-18.6273, -39.5444, 55.5071},
                {13.2675, -19.98, 28.1179},
                {-24.9832, -40.2722, 52.7107},
                {11.1761, -22.3575, 45.2756},
                {-24.9492, 1.5, 54.5981},
                {-25, 21.8857, 49.9071},
                {18.4196, -18.2153, 52.4501},
                {-25, -12.7727, 49.9071},
                {-24.9832, -43.2722, 52.7107},
                {9.20583, -23.4785, 55.334},
                {-1.62324, -29.7942, 48.3949}}});
  // bullet3#262 (8 points; float literals in the report).
  r.push_back({"bullet262",
               {{2.0f, 3.535533905932738f, 3.535533905932737f},
                {4.0f, 2.0f, 0.0f},
                {0.0f, 2.0f, 0.0f},
                {1.0f, 0.0f, 0.0f},
                {4.0f, 1.414213562373095f, 1.414213562373095f},
                {0.0f, 1.414213562373095f, 1.414213562373095f},
                {3.0f, 0.0f, 0.0f},
                {2.0f, 5.0f, 0.0f}}});
  // turbulenz_engine#38 (9-point box with a roof).
  r.push_back({"turbulenz38",
               {{-1, -1, -2},
                {1, -1, -2},
                {-1, 1, -2},
                {1, 1, -2},
                {-1, -1, 1},
                {1, -1, 1},
                {-1, 1, 1},
                {1, 1, 1},
                {0, 0, 2}}});
  // karimnaaji/3d-quickhull#2: a box with points inside its bottom face, and an octagonal prism.
  r.push_back({"karimnaaji2_cube",
               {{0, 50, 0},
                {100, 100, 0},
                {0, 100, 0},
                {-100, 100, 0},
                {-100, 0, 0},
                {100, -100, 0},
                {0, -50, 0},
                {50, -50, 0},
                {-100, -100, 0},
                {0, -100, 0},
                {100, 0, 0},
                {100, 100, 200},
                {-100, 100, 200},
                {100, -100, 200},
                {-100, -100, 200}}});
  r.push_back({"karimnaaji2_octagon",
               {{40, 100, 0},
                {100, 40, 0},
                {100, -40, 0},
                {40, -100, 0},
                {-40, -100, 0},
                {-100, -40, 0},
                {-100, 40, 0},
                {-40, 100, 0},
                {40, 100, 100},
                {100, 40, 100},
                {100, -40, 100},
                {40, -100, 100},
                {-40, -100, 100},
                {-100, -40, 100},
                {-100, 40, 100},
                {-40, 100, 100}}});
  // leomccormack/convhull_3d#1: 3 x 3 stacked 64 x 64 x 1 boxes (pattern of the report).
  {
    std::vector<Vec3> p;
    for (const double x0 : {-808.0, -936.0, -1064.0})
      for (const double y0 : {3300.0, 3428.0, 3556.0})
        for (int c = 0; c < 8; ++c)
          p.emplace_back(x0 + (c & 1 ? 64 : 0), y0 + (c & 2 ? 64 : 0), c & 4 ? 7552 : 7551);
    r.push_back({"convhull3d1_boxes", p});
  }
  // Mugen87/yuka#11 (14 points).
  r.push_back({"yuka11",
               {{-55.53499860610813, 73.11029657847513, -63.59099818190188},
                {-55.7849986005202, 73.11029657847513, -69.34100186807655},
                {-58.53499853905291, 73.11029657847513, -68.84100187925242},
                {-58.03499855022878, 73.11029657847513, -63.59099818190188},
                {-55.53499860610813, 73.01029657847513, -63.59099818190188},
                {-55.7849986005202, 73.01029657847513, -69.34100186807655},
                {-58.53499853905291, 73.01029657847513, -68.84100187925242},
                {-58.03499855022878, 73.01029657847513, -63.59099818190188},
                {-9.78499962870032, 74.11029655612339, -64.84100196865938},
                {-10.034999623112384, 74.11029655612339, -64.09100198542319},
                {-9.034999645464126, 73.92279656031434, -63.59099818190188},
                {-9.78499962870032, 74.0102965561234, -64.84100196865938},
                {-10.034999623112384, 74.0102965561234, -64.09100198542319},
                {-9.034999645464126, 73.82279656031434, -63.59099818190188}}});
  // mauriciopoppe/quickhull3d#2 (7 points that hung a face merge).
  r.push_back({"quickhull3d2",
               {{104, 216, 53},
                {104, 217, 52},
                {105, 216, 52},
                {88, 187, 43},
                {89, 187, 44},
                {89, 188, 43},
                {90, 187, 43}}});
  // dimforge/parry#49 (4 points of magnitude 1e-23, f32).
  r.push_back({"parry49",
               {{0.000000000000000000000023624029f, 0.000000000000000000000013771984f,
                 0.0000000000000000000000022062083f},
                {0.000000000000000000000013807439f, 0.000000000000000000000018596945f,
                 -0.000000000000000000000001784406f},
                {0.000000000000000000000014174896f, -0.000000000000000000000003200329f,
                 0.000000000000000000000004664615f},
                {0.000000000000000000000013685897f, 0.0000000000000000000000046402988f,
                 0.0000000000000000000000022509113f}}});
  // reactphysics3d#385: a box given as 24 vertices (each corner once per face).
  {
    std::vector<Vec3> p;
    for (int f = 0; f < 3; ++f)
      for (int c = 0; c < 8; ++c) p.emplace_back(c & 1 ? 3 : -3, c & 2 ? 3 : -3, c & 4 ? 3 : -3);
    r.push_back({"reactphysics385_box24", p});
  }
  // Jolt ConvexHullTest: the nearly flat 23-point disc at y = 0.1571 (float literals).
  r.push_back(
      {"jolt_flat_disc",
       {{1.25793016f, 0.157113776f, 1.22066617f},    {1.92657053f, 0.157114446f, 0.240761176f},
        {1.40259242f, 0.157115221f, -0.834863901f},  {1.94086421f, 0.157113507f, -0.790734947f},
        {2.20533752f, 0.157113209f, -0.281754375f},  {0.0426187329f, 0.157113969f, -1.40533638f},
        {1.11055744f, 0.157113969f, -1.33626819f},   {0.180490851f, 0.157114655f, 1.16420007f},
        {-1.34696794f, 0.157110974f, -0.978962243f}, {-0.981223822f, 0.157110706f, -1.44589376f},
        {-1.8200444f, 0.157106474f, 1.05036092f},    {-0.376947045f, 0.15711388f, 1.13544536f},
        {-1.37966835f, 0.157109678f, 1.08289516f},   {-1.04599845f, 0.157108605f, 1.54891157f},
        {-0.597127378f, 0.157110557f, 1.57243586f},  {-2.09407234f, 0.157106325f, 0.560136259f},
        {-1.91857386f, 0.157108605f, 0.0392456949f}, {-2.08503342f, 0.157106936f, -0.506603181f},
        {-1.80278254f, 0.157107696f, -0.986931145f}, {0.434835076f, 0.157112151f, 1.62568307f},
        {0.917346299f, 0.157111734f, 1.65097046f},   {1.77710009f, 0.157112047f, 1.2388792f},
        {2.11432409f, 0.157112464f, 0.780689001f}}});
  // Jolt ConvexHullTest: a thin spike with a duplicated point (16 points).
  r.push_back({"jolt_spike",
               {{0.0212580804f, 1.29376173f, 0.0102035152f},
                {0.0225791596f, 1.05854928f, 0.0887729526f},
                {0.0596007220f, 0.984267414f, 0.0408750288f},
                {0.0722020790f, 0.980246127f, -0.0416274220f},
                {-0.00376634207f, -0.718282819f, 0.00411359267f},
                {-0.00188124576f, -0.718283117f, 0.00229378697f},
                {-0.00162511703f, -0.718282461f, 0.00753012672f},
                {-0.00118427153f, 1.36079276f, 0.00107491738f},
                {-6.78644137e-05f, -0.718282998f, 0.00426622201f},
                {0.00102991192f, 1.29927433f, 0.0230795704f},
                {0.00699944887f, 1.05855191f, 0.0887731761f},
                {-0.00603519706f, 1.04913890f, -0.102404378f},
                {-0.0212373994f, 1.31092644f, 0.00530112581f},
                {-0.0542707182f, 1.07623804f, 0.0403260253f},
                {-0.0946691483f, 1.07357991f, -0.0185115524f},
                {-0.0946691483f, 1.07357991f, -0.0185115524f}}});
  // Jolt ConvexHullTest: the first four shapes (flat quad, flat triangle with inner point,
  // square pyramid).
  r.push_back({"jolt_quad", {{-1, 0, -1}, {1, 0, -1}, {-1, 0, 1}, {1, 0, 1}}});
  r.push_back({"jolt_triangle", {{-1, 0, -1}, {1, 0, -1}, {-1, 0, 1}, {-0.5, 0, -0.5}}});
  r.push_back({"jolt_pyramid", {{-1, 0, -1}, {1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {0, 1, 0}}});
  return r;
}

}  // namespace hull_inputs
