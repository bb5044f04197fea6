// What the benchmark asks of each library: answer the pairs of one case, by index.
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "../cases.hpp"

namespace mink_bench {

enum class Query { Intersect, Distance, Contact };

/// The full answer of a contact query, in mink's conventions whatever the library's own (each
/// adapter converts): `normal` is unit, in the world frame, pointing from A towards B: when
/// separated, point_b - point_a = distance * normal; when penetrating, the direction in which B
/// must move by `depth` to separate, and point_b - point_a = -depth * normal (point_a is A's
/// deepest point inside B, point_b B's deepest point inside A).
struct ContactAnswer {
  bool intersect = false;                                      ///< penetrating or touching
  double distance = std::numeric_limits<double>::quiet_NaN();  ///< when separated
  double depth = std::numeric_limits<double>::quiet_NaN();     ///< when intersecting
  Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d point_a = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d point_b = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

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
  /// The full answer for pair i: verdict, distance or depth, normal and the two points. Only
  /// called when the Method says it has one (has_contact, has_separated_contact).
  virtual ContactAnswer contact(std::size_t i) const {
    (void)i;
    return {};
  }
  /// GJK (and EPA) iterations of the query on pair i, when the library reports them.
  virtual double iterations(std::size_t i, Query query) const {
    (void)i;
    (void)query;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

/// A library's method, with what it can answer.
struct Method {
  std::string name;  ///< column in the report, e.g. "fcl_ccd"
  bool has_intersect = true;
  bool has_distance = true;
  std::unique_ptr<PairQueries> queries;
  /// contact() answers penetrating pairs (depth, normal, points).
  bool has_contact = false;
  /// contact() also answers separated pairs (distance, normal, closest points).
  bool has_separated_contact = false;
};

std::vector<Method> make_mink_methods(const Case& c);
std::vector<Method> make_ccd_methods(const Case& c);
std::vector<Method> make_fcl_methods(const Case& c);
std::vector<Method> make_bullet_methods(const Case& c);

}  // namespace mink_bench
