// `mink hull`: convex hulls of point sets given as JSON lines or of mesh files (docs/protocol.md).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "answer.hpp"
#include "commands.hpp"
#include "hull_json.hpp"
#include "json_writer.hpp"
#include "line_stream.hpp"
#include "mink/io/mesh.hpp"

namespace mink::cli {

namespace {

struct HullCommandOptions {
  std::vector<std::string> meshes;
  std::vector<std::string> files;
  std::size_t max_vertices = 0;
  double relative_tolerance = HullOptions{}.relative_tolerance;
  std::string obj_path;
};

/// Builds hulls and writes their answer lines; remembers them as OBJ text when asked.
class HullRunner {
 public:
  explicit HullRunner(const HullCommandOptions& options) : options_(options) {}

  void answer(std::string_view id_json, std::span<const Vec3> points, const HullOptions& options,
              std::string& out) {
    const Expected<ConvexHull> hull = build_convex_hull(points, options);
    if (!hull) {
      write_error(id_json, hull.error(), out);
      return;
    }
    write_hull(id_json, *hull, out);
    if (!options_.obj_path.empty()) {
      // The object is named after the id, without the quotes of a string id.
      std::string_view name = id_json;
      if (name.size() >= 2 && name.front() == '"') name = name.substr(1, name.size() - 2);
      write_hull_obj(name, *hull, obj_vertex_count_, obj_);
      obj_vertex_count_ += hull->vertices.size();
    }
  }

  void answer_line(std::string_view line, std::int64_t line_number, std::string& out) {
    if (!parser_.parse(line, line_number, request_)) {
      write_error(request_.id, parser_.error(), out);
      return;
    }
    HullOptions options = defaults();
    if (request_.max_vertices) options.max_vertices = *request_.max_vertices;
    if (request_.relative_tolerance) options.relative_tolerance = *request_.relative_tolerance;
    answer(request_.id, request_.points, options, out);
  }

  HullOptions defaults() const {
    HullOptions options;
    options.max_vertices = options_.max_vertices;
    options.relative_tolerance = options_.relative_tolerance;
    return options;
  }

  const std::string& obj() const { return obj_; }

 private:
  const HullCommandOptions& options_;
  HullRequestParser parser_;
  HullRequest request_;
  std::string obj_ = "# convex hulls written by mink hull\n";
  std::size_t obj_vertex_count_ = 0;
};

bool write_text(const std::string& text, std::FILE* out) {
  return std::fwrite(text.data(), 1, text.size(), out) == text.size() && std::fflush(out) == 0;
}

/// Meshes first (each answered under its path as id), then the JSON-lines files (standard input
/// when there is no file and no mesh). A mesh or file that cannot be read is an error line or a
/// message on stderr, and the exit code is 1; malformed lines are error lines only.
int run_hull(const HullCommandOptions& options) {
  if (options.max_vertices > 0 && options.max_vertices < 4) {
    std::fprintf(stderr, "mink hull: --max-vertices must be 0 (no limit) or at least 4\n");
    return 2;
  }
  HullRunner runner(options);
  int exit_code = 0;
  for (const std::string& path : options.meshes) {
    std::string id, out;
    append_string(id, path);
    const Expected<std::vector<Vec3>> points = read_mesh_points(path);
    if (points)
      runner.answer(id, *points, runner.defaults(), out);
    else
      write_error(id, points.error(), out);
    if (!points) {
      std::fprintf(stderr, "mink hull: %s\n", points.error().c_str());
      exit_code = 1;
    }
    if (!write_text(out, stdout)) {
      std::fprintf(stderr, "mink hull: cannot write the answers: %s\n", std::strerror(errno));
      return 1;
    }
  }
  std::vector<std::string> files = options.files;
  if (files.empty() && options.meshes.empty()) files.push_back("-");
  const LineHandler handler = [&runner](std::string_view line, std::int64_t line_number,
                                        std::string& out) {
    runner.answer_line(line, line_number, out);
  };
  if (run_on_files(files, "mink hull", [&handler](int fd, std::string& error) {
        return run_lines(fd, stdout, handler, error);
      }) != 0)
    exit_code = 1;
  if (!options.obj_path.empty()) {
    std::FILE* obj = std::fopen(options.obj_path.c_str(), "wb");
    const bool written = obj && write_text(runner.obj(), obj);
    const int write_errno = errno;
    if (obj && std::fclose(obj) != 0 && written) {
      std::fprintf(stderr, "mink hull: cannot write %s: %s\n", options.obj_path.c_str(),
                   std::strerror(errno));
      return 1;
    }
    if (!written) {
      std::fprintf(stderr, "mink hull: cannot write %s: %s\n", options.obj_path.c_str(),
                   std::strerror(write_errno));
      return 1;
    }
  }
  return exit_code;
}

}  // namespace

void add_hull_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<HullCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "hull",
      "Convex hulls: one answer line (vertices, faces, normals, adjacency, volume, area, status) "
      "per input.\nInput lines: {\"id\": .., \"points\": [[x,y,z], ...], \"max_vertices\": N, "
      "\"relative_tolerance\": r}; or --mesh FILE (OBJ, STL ASCII or binary)");
  command->add_option("--mesh", options->meshes,
                      "A mesh file (.obj, .stl) whose vertices make one hull; repeatable. "
                      "Answered before any JSON-lines input, with the path as id");
  command
      ->add_option("--max-vertices", options->max_vertices,
                   "Stop at this many hull vertices (furthest points first; 0: no limit, "
                   "else >= 4); a line's max_vertices overrides it")
      ->check(CLI::NonNegativeNumber);
  command
      ->add_option("--relative-tolerance", options->relative_tolerance,
                   "Flatness tolerance relative to the bounding-box diagonal (default 1e-10); "
                   "a line's relative_tolerance overrides it")
      ->check(CLI::Range(0.0, 1e-2));
  command->add_option("--obj", options->obj_path,
                      "Also write every hull to this Wavefront OBJ file, one object each");
  command->add_option("files", options->files,
                      "Files of hull lines, answered in order; none or \"-\": standard input "
                      "(not read when --mesh is given without files)");
  command->callback([options, &exit_code] { exit_code = run_hull(*options); });
}

}  // namespace mink::cli
