/// @file hull_json.hpp
/// `mink hull` without the command line: reading a hull request line, writing a hull as a JSON
/// answer line, and as Wavefront OBJ (docs/protocol.md, "mink hull").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "json_io.hpp"
#include "mink/hull/convex_hull.hpp"

namespace mink::cli {

/// One request line, parsed: `{"id": .., "points": [[x,y,z], ...], "max_vertices": N,
/// "relative_tolerance": r}`. The two options are optional; when absent the command line's
/// defaults apply.
struct HullRequest {
  std::string id;  ///< as JSON text (quoted string or number), else the 1-based line number
  std::vector<Vec3> points;
  std::optional<std::size_t> max_vertices;
  std::optional<double> relative_tolerance;
};

/// Parses request lines. Every field is checked, with `mink query`'s reader (json_io.hpp): unknown
/// or duplicate fields, wrong types, empty or malformed point lists, numbers that are not finite
/// or beyond 1e50 in magnitude, max_vertices that is not 0 or an integer >= 4, a relative
/// tolerance outside [0, 1e-2]. Keep one and reuse it: the parser's buffers are allocated once.
class HullRequestParser : public JsonLineReader {
 public:
  /// Parses `line`, which must be followed by simdjson::SIMDJSON_PADDING readable bytes (see
  /// line_stream.hpp). Returns false when the line is malformed; error() then says why. In both
  /// cases `request.id` is set: from the line when its id is valid, else to `line_number`.
  bool parse(std::string_view line, std::int64_t line_number, HullRequest& request);
};

/// Appends the answer line for `hull`, newline included:
/// {"id", "status" (full | flat | segment | point), "vertices" [[x,y,z]...], "input_indices",
/// "faces" [[v...]...], "normals", "offsets", "vertex_neighbors" [[v...]...], "face_neighbors"
/// [[f...]...] (the face across each edge of the loop: edge k goes from vertex k to k+1),
/// "volume", "area", "tolerance", "complete", "max_outside"}.
void write_hull(std::string_view id_json, const ConvexHull& hull, std::string& out);

/// Appends `hull` as an OBJ object named `name`: `o`, one `v` per vertex, then `f` per face (a
/// flat hull's two faces are both written), `l` for a segment, `p` for a point. OBJ indices are
/// global: `vertex_base` is the number of `v` lines already written to the same file.
void write_hull_obj(std::string_view name, const ConvexHull& hull, std::size_t vertex_base,
                    std::string& out);

}  // namespace mink::cli
