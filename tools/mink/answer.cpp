#include "answer.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "json_writer.hpp"
#include "mink/query/shape_queries.hpp"

namespace mink::cli {

namespace {

/// Median time of one call of `run`, in microseconds. Calls are timed in batches long enough
/// (>= 20 us) that the clock's resolution and overhead do not matter; the median of several
/// batches ignores the odd interruption by the system.
template <class Run>
double median_microseconds(Run&& run) {
  using Clock = std::chrono::steady_clock;
  constexpr auto kMinBatch = std::chrono::microseconds(20);
  constexpr long kMaxBatchSize = 1L << 20;
  constexpr int kBatches = 7;
  long batch_size = 1;
  // The smallest power of two whose batch takes at least kMinBatch; this also warms the caches.
  for (;;) {
    const auto start = Clock::now();
    for (long i = 0; i < batch_size; ++i) run();
    if (Clock::now() - start >= kMinBatch || batch_size >= kMaxBatchSize) break;
    batch_size *= 2;
  }
  std::array<double, kBatches> per_call;
  for (double& t : per_call) {
    const auto start = Clock::now();
    for (long i = 0; i < batch_size; ++i) run();
    const std::chrono::duration<double, std::micro> elapsed = Clock::now() - start;
    t = elapsed.count() / static_cast<double>(batch_size);
  }
  std::nth_element(per_call.begin(), per_call.begin() + kBatches / 2, per_call.end());
  return per_call[kBatches / 2];
}

/// Microseconds rounded to nanoseconds, so that the shortest form stays short.
double round_to_nanoseconds(double us) {
  return std::round(us * 1000.0) / 1000.0;
}

void end_answer(const AnswerOptions& options, double us, std::string& out) {
  if (options.timing) {
    append_field(out, "us");
    append_number(out, round_to_nanoseconds(us));
  }
  out += "}\n";
}

const char* status_name(Status status) {
  return status == Status::IterationLimit ? "iteration_limit" : "ok";
}

constexpr std::string_view kNotFinite =
    "the query produced a number that is not finite (a mink bug: please report this line)";

bool all_finite(const IntersectResult&) {
  return true;
}

bool all_finite(const DistanceResult& r) {
  return std::isfinite(r.distance) && std::isfinite(r.error_bound) && is_finite(r.normal) &&
         is_finite(r.point_a) && is_finite(r.point_b);
}

bool all_finite(const ContactResult& r) {
  return std::isfinite(r.distance) && std::isfinite(r.depth) && std::isfinite(r.error_bound) &&
         is_finite(r.normal) && is_finite(r.point_a) && is_finite(r.point_b);
}

bool all_finite(const ManifoldResult& r) {
  bool finite = std::isfinite(r.distance) && std::isfinite(r.depth) &&
                std::isfinite(r.error_bound) && is_finite(r.normal);
  for (int i = 0; i < r.count; ++i)
    finite = finite && is_finite(r.points[i].point_a) && is_finite(r.points[i].point_b) &&
             std::isfinite(r.points[i].depth);
  return finite;
}

/// The frame every answer shares: run the query, turn invalid input and non-finite results into
/// error lines, time it when asked, then the status, the fields `write_fields` adds, the
/// iteration count, the error bound when the iteration cap was hit, and the time.
template <class Run, class WriteFields>
void write_answer_of(const Query& query, const AnswerOptions& options, Run&& run,
                     WriteFields&& write_fields, std::string& out) {
  const auto r = run();
  if (r.status == Status::InvalidInput) return write_error(query.id, r.error, out);
  if (!all_finite(r)) return write_error(query.id, kNotFinite, out);
  double us = 0;
  if (options.timing) {
    volatile int sink = 0;
    us = median_microseconds([&] { sink = sink + run().iterations; });
  }
  begin_answer(query.id, status_name(r.status), out);
  append_field(out, "intersect");
  out += r.intersect ? "true" : "false";
  write_fields(r);
  append_field(out, "iterations");
  append_integer(out, r.iterations);
  if constexpr (requires { r.error_bound; }) {
    if (r.status == Status::IterationLimit) {
      append_field(out, "error_bound");
      append_number(out, r.error_bound);
    }
  }
  end_answer(options, us, out);
}

void write_intersect(const Query& query, const AnswerOptions& options, std::string& out) {
  write_answer_of(
      query, options, [&] { return intersect(query.a, query.pose_a, query.b, query.pose_b); },
      [](const IntersectResult&) {}, out);
}

/// `point_a` and `point_b`: a pair of world points, on A's surface and on B's.
void append_pair(std::string& out, const Vec3& point_a, const Vec3& point_b) {
  append_field(out, "point_a");
  append_vec3(out, point_a);
  append_field(out, "point_b");
  append_vec3(out, point_b);
}

/// The fields of a `contact` answer after `intersect`, shared by `manifold`: distance, depth,
/// normal, the pair point_a, point_b when `with_pair`, and normal_chosen when it is true.
template <class Result>
void append_contact_fields(const Result& r, bool with_pair, const Vec3& point_a,
                           const Vec3& point_b, std::string& out) {
  append_field(out, "distance");
  append_number(out, r.distance);
  append_field(out, "depth");
  append_number(out, r.depth);
  append_field(out, "normal");
  append_vec3(out, r.normal);
  if (with_pair) append_pair(out, point_a, point_b);
  if (r.normal_chosen) out += ",\"normal_chosen\":true";
}

void write_distance(const Query& query, const AnswerOptions& options, std::string& out) {
  const auto fields = [&out](const DistanceResult& r) {
    append_field(out, "distance");
    append_number(out, r.distance);
    // The normal and points are defined only for separated shapes; GJK leaves them zero
    // otherwise.
    if (!r.intersect && r.normal.squaredNorm() > 0) {
      append_field(out, "normal");
      append_vec3(out, r.normal);
      append_pair(out, r.point_a, r.point_b);
    }
  };
  write_answer_of(
      query, options, [&] { return distance(query.a, query.pose_a, query.b, query.pose_b); },
      fields, out);
}

void write_contact(const Query& query, const AnswerOptions& options, std::string& out) {
  const auto fields = [&out](const ContactResult& r) {
    append_contact_fields(r, true, r.point_a, r.point_b, out);
  };
  write_answer_of(
      query, options, [&] { return contact(query.a, query.pose_a, query.b, query.pose_b); }, fields,
      out);
}

/// The contact fields (point_a, point_b: the deepest manifold point's pair, omitted when the
/// manifold is empty) and the manifold: its normal and up to 4 points, each with its position
/// (the midpoint of the pair), depth (> 0 penetrating, < 0 a gap: separated shapes within the
/// query's margin) and the pair on A and on B.
void write_manifold(const Query& query, const AnswerOptions& options, std::string& out) {
  const auto fields = [&out](const ManifoldResult& r) {
    append_contact_fields(r, r.count > 0, r.points[0].point_a, r.points[0].point_b, out);
    append_field(out, "manifold");
    out += "{\"normal\":";
    append_vec3(out, r.normal);
    out += ",\"points\":[";
    for (int i = 0; i < r.count; ++i) {
      if (i > 0) out += ',';
      out += "{\"position\":";
      append_vec3(out, r.points[i].position());
      append_field(out, "depth");
      append_number(out, r.points[i].depth);
      append_pair(out, r.points[i].point_a, r.points[i].point_b);
      out += '}';
    }
    out += "]}";
  };
  ManifoldOptions manifold_options;
  manifold_options.margin = query.margin;
  write_answer_of(
      query, options,
      [&] { return manifold(query.a, query.pose_a, query.b, query.pose_b, manifold_options); },
      fields, out);
}

}  // namespace

void write_answer(const Query& query, const AnswerOptions& options, std::string& out) {
  if (query.want == Want::Intersect) return write_intersect(query, options, out);
  if (query.want == Want::Contact) return write_contact(query, options, out);
  if (query.want == Want::Manifold) return write_manifold(query, options, out);
  write_distance(query, options, out);
}

void begin_answer(std::string_view id_json, std::string_view status, std::string& out) {
  out += "{\"id\":";
  out += id_json;
  out += ",\"status\":\"";
  out += status;
  out += '"';
}

void write_error(std::string_view id_json, std::string_view message, std::string& out) {
  begin_answer(id_json, "error", out);
  append_field(out, "error");
  append_string(out, message);
  out += "}\n";
}

}  // namespace mink::cli
