#include "mink/io/mesh.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <system_error>

namespace mink {

namespace {

// ---------------------------------------------------------------------------------------------
// Text helpers shared by OBJ and ASCII STL.

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// Splits a line into whitespace-separated tokens; `tokens` is reused from line to line.
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t begin = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > begin) tokens.push_back(line.substr(begin, i - begin));
  }
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

/// A token from the file in quotes, cut short: it is echoed into an error message.
std::string quoted(std::string_view token) {
  constexpr std::size_t kMaxLength = 32;
  std::string out = "'";
  out += token.substr(0, kMaxLength);
  if (token.size() > kMaxLength) out += "...";
  out += '\'';
  return out;
}

enum class NumberStatus { Ok, Malformed, OutOfRange, NotFinite };

/// Parses a whole token as a decimal floating-point number. std::from_chars is locale-free and
/// exact (correctly rounded), unlike strtod under a user's locale; it rejects a leading '+',
/// which OBJ writers sometimes emit, so one is skipped here.
NumberStatus parse_number(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && (token.front() == '+' || token.front() == '-'))
      return NumberStatus::Malformed;
  }
  if (token.empty()) return NumberStatus::Malformed;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range && ptr == end) return NumberStatus::OutOfRange;
  if (ec != std::errc() || ptr != end) return NumberStatus::Malformed;
  // from_chars also reads "nan" and "inf"; a mesh coordinate must be a real position.
  if (!std::isfinite(value)) return NumberStatus::NotFinite;
  return NumberStatus::Ok;
}

/// Builds "name:line: what" messages.
class TextErrors {
 public:
  explicit TextErrors(std::string_view name) : name_(name) {}
  std::int64_t line = 0;

  /// "name: what", for problems of the whole file.
  std::string at_file(std::string_view what) const {
    std::string out(name_);
    out += ": ";
    out += what;
    return out;
  }

  std::string at_line(std::string_view what) const {
    std::string out(name_);
    out += ':';
    out += std::to_string(line);
    out += ": ";
    out += what;
    return out;
  }

  /// The message for a number token that did not parse; `what` names the field.
  std::string number(NumberStatus status, std::string_view token, std::string_view what) const {
    std::string text(what);
    text += ' ';
    text += quoted(token);
    switch (status) {
      case NumberStatus::Malformed:
        text += " is not a number";
        break;
      case NumberStatus::OutOfRange:
        text += " is out of the range of a double";
        break;
      case NumberStatus::NotFinite:
        text += " is not finite (NaN or infinity)";
        break;
      case NumberStatus::Ok:
        break;
    }
    return at_line(text);
  }

 private:
  std::string_view name_;
};

/// Calls `on_line(line)` for every line of `text` (without its newline and trailing '\r') and
/// stops at the first that returns false; returns whether all succeeded.
template <class OnLine>
bool for_each_line(std::string_view text, TextErrors& errors, OnLine&& on_line) {
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++errors.line;
    if (!on_line(line)) return false;
    begin = end + 1;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// OBJ

/// Statements of the OBJ specification that carry nothing a hull needs (grouping, materials,
/// smoothing, free-form curves and surfaces, display attributes). Their contents are skipped.
constexpr std::array<std::string_view, 33> kObjSkipped = {
    "o",      "g",     "s",      "mg",       "usemtl",   "mtllib",     "usemap",
    "maplib", "lod",   "bevel",  "c_interp", "d_interp", "shadow_obj", "trace_obj",
    "ctech",  "stech", "cstype", "deg",      "bmat",     "step",       "curv",
    "curv2",  "surf",  "parm",   "trim",     "hole",     "scrv",       "sp",
    "end",    "con",   "call",   "scmp",     "csh"};

/// One kind of indexed element (v, vt or vn): how many the file has defined so far, and the
/// largest positive reference seen, checked once the whole file has been read because a
/// positive index may legally point past the vertices read so far in some writers' output.
struct ObjIndexKind {
  std::string_view name;
  std::int64_t count = 0;
  std::int64_t max_reference = 0;
  std::int64_t max_reference_line = 0;
};

class ObjReader {
 public:
  explicit ObjReader(std::string_view name) : errors_(name) {}

  Expected<std::vector<Vec3>> read(std::string_view text) {
    // A UTF-8 byte order mark is harmless; skip it rather than call it an unknown statement.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    const bool ok =
        for_each_line(text, errors_, [&](std::string_view line) { return read_line(line); });
    if (!ok) return Expected<std::vector<Vec3>>::failure(std::move(error_));
    for (const ObjIndexKind* kind : {&vertices_, &texture_coords_, &normals_}) {
      if (kind->max_reference > kind->count) {
        errors_.line = kind->max_reference_line;
        return Expected<std::vector<Vec3>>::failure(errors_.at_line(
            "refers to " + std::string(kind->name) + " " + std::to_string(kind->max_reference) +
            ", but the file defines " + std::to_string(kind->count)));
      }
    }
    if (points_.empty()) {
      return Expected<std::vector<Vec3>>::failure(
          errors_.at_file("no vertices (an OBJ file needs 'v' lines)"));
    }
    return std::move(points_);
  }

 private:
  bool fail(std::string message) {
    error_ = std::move(message);
    return false;
  }

  bool read_line(std::string_view line) {
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    split_tokens(line, tokens_);
    if (tokens_.empty()) return true;
    if (tokens_.back().back() == '\\')
      return fail(
          errors_.at_line("line continuation ('\\' at the end of a line) is not supported"));
    const std::string_view keyword = tokens_.front();
    if (keyword == "v") return read_vertex();
    if (keyword == "vt") return read_numbers("vt", 1, 3, texture_coords_);
    if (keyword == "vn") return read_numbers("vn", 3, 3, normals_);
    if (keyword == "vp") return read_numbers("vp", 1, 3, parameter_points_);
    if (keyword == "f") return read_element("f", 3);
    if (keyword == "l") return read_element("l", 2);
    if (keyword == "p") return read_element("p", 1);
    if (std::find(kObjSkipped.begin(), kObjSkipped.end(), keyword) != kObjSkipped.end())
      return true;
    return fail(errors_.at_line("unknown statement " + quoted(keyword)));
  }

  bool read_vertex() {
    // x y z, optionally a weight w (x y z w) or a vertex colour (x y z r g b [a]).
    const std::size_t count = tokens_.size() - 1;
    if (count != 3 && count != 4 && count != 6 && count != 7)
      return fail(errors_.at_line("v needs x y z (optionally w, or a colour r g b), found " +
                                  std::to_string(count) + (count == 1 ? " number" : " numbers")));
    Vec3 p;
    for (std::size_t i = 0; i < count; ++i) {
      double value;
      const NumberStatus status = parse_number(tokens_[i + 1], value);
      if (status != NumberStatus::Ok)
        return fail(errors_.number(
            status, tokens_[i + 1],
            i < 3 ? std::string("v coordinate ") + "xyz"[i] : "v value " + std::to_string(i + 1)));
      if (i < 3) p[static_cast<Eigen::Index>(i)] = value;
    }
    points_.push_back(p);
    ++vertices_.count;
    return true;
  }

  bool read_numbers(std::string_view keyword, std::size_t min_count, std::size_t max_count,
                    ObjIndexKind& kind) {
    const std::size_t count = tokens_.size() - 1;
    if (count < min_count || count > max_count)
      return fail(
          errors_.at_line(std::string(keyword) + " needs " + std::to_string(min_count) +
                          (min_count == max_count ? "" : " to " + std::to_string(max_count)) +
                          " numbers, found " + std::to_string(count)));
    for (std::size_t i = 1; i <= count; ++i) {
      double value;
      const NumberStatus status = parse_number(tokens_[i], value);
      if (status != NumberStatus::Ok)
        return fail(errors_.number(status, tokens_[i],
                                   std::string(keyword) + " value " + std::to_string(i)));
    }
    ++kind.count;
    return true;
  }

  /// Checks one index of a reference: 1-based, or negative relative to the elements so far.
  bool check_index(std::string_view token, std::string_view reference, ObjIndexKind& kind) {
    std::int64_t index = 0;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, index);
    if (ec != std::errc() || ptr != end)
      return fail(errors_.at_line("index " + quoted(token) + " in " + quoted(reference) +
                                  " is not an integer"));
    if (index == 0)
      return fail(errors_.at_line("index 0 in " + quoted(reference) +
                                  " (OBJ indices start at 1; negative ones count back)"));
    if (index < 0) {
      if (-index > kind.count)
        return fail(errors_.at_line("index " + std::to_string(index) + " in " + quoted(reference) +
                                    " reaches before the first of the " +
                                    std::to_string(kind.count) + " " + std::string(kind.name) +
                                    " defined so far"));
      return true;
    }
    if (index > kind.max_reference) {
      kind.max_reference = index;
      kind.max_reference_line = errors_.line;
    }
    return true;
  }

  bool read_element(std::string_view keyword, std::size_t min_references) {
    const std::size_t count = tokens_.size() - 1;
    if (count < min_references)
      return fail(errors_.at_line(std::string(keyword) + " needs at least " +
                                  std::to_string(min_references) + " vertices, found " +
                                  std::to_string(count)));
    for (std::size_t i = 1; i <= count; ++i) {
      // v, v/vt, v//vn or v/vt/vn.
      const std::string_view reference = tokens_[i];
      std::array<std::string_view, 3> parts;
      std::size_t part_count = 0;
      std::size_t begin = 0;
      for (;;) {
        const std::size_t slash = reference.find('/', begin);
        if (part_count == parts.size())
          return fail(errors_.at_line("vertex reference " + quoted(reference) +
                                      " has more than three parts (v/vt/vn)"));
        parts[part_count++] = reference.substr(begin, slash - begin);
        if (slash == std::string_view::npos) break;
        begin = slash + 1;
      }
      if (!check_index(parts[0], reference, vertices_)) return false;
      // "v//vn" leaves the middle part empty; an empty last part ("1/") is malformed.
      if (part_count >= 2 && !(part_count == 3 && parts[1].empty()) &&
          !check_index(parts[1], reference, texture_coords_))
        return false;
      if (part_count == 3 && !check_index(parts[2], reference, normals_)) return false;
    }
    return true;
  }

  TextErrors errors_;
  std::string error_;
  std::vector<std::string_view> tokens_;
  std::vector<Vec3> points_;
  ObjIndexKind vertices_{"vertex"};
  ObjIndexKind texture_coords_{"texture coordinate"};
  ObjIndexKind normals_{"normal"};
  ObjIndexKind parameter_points_{"parameter point"};
};

// ---------------------------------------------------------------------------------------------
// STL

constexpr std::size_t kStlHeaderSize = 80;
constexpr std::size_t kStlPrefixSize = kStlHeaderSize + 4;
constexpr std::size_t kStlRecordSize = 50;

std::uint32_t read_le32(const unsigned char* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
         std::uint32_t(p[3]) << 24;
}

float read_le_float(const unsigned char* p) {
  const std::uint32_t bits = read_le32(p);
  float value;
  static_assert(sizeof(value) == sizeof(bits));
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

/// True when the bytes have exactly the size a binary STL with the triangle count of its header
/// would have: 84 + 50 n. An ASCII file cannot pass by accident in practice: its bytes 80..83
/// are text, which makes n at least 0x09090909 (150 million triangles, a 7.5 GB file).
bool has_binary_stl_size(std::string_view bytes) {
  if (bytes.size() < kStlPrefixSize) return false;
  const std::uint64_t n =
      read_le32(reinterpret_cast<const unsigned char*>(bytes.data()) + kStlHeaderSize);
  return bytes.size() == kStlPrefixSize + kStlRecordSize * n;
}

bool begins_with_solid(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && (is_space(bytes[i]) || bytes[i] == '\n')) ++i;
  return bytes.size() - i >= 5 && equals_ignoring_case(bytes.substr(i, 5), "solid") &&
         (bytes.size() - i == 5 || is_space(bytes[i + 5]) || bytes[i + 5] == '\n');
}

Expected<std::vector<Vec3>> read_binary_stl(std::string_view bytes, std::string_view name) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint64_t n = read_le32(data + kStlHeaderSize);
  const std::string prefix = std::string(name) + ": ";
  if (bytes.size() != kStlPrefixSize + kStlRecordSize * n)
    return Expected<std::vector<Vec3>>::failure(
        prefix + "binary STL of " + std::to_string(n) + " triangles should have 84 + 50 * " +
        std::to_string(n) + " = " + std::to_string(kStlPrefixSize + kStlRecordSize * n) +
        " bytes, but has " + std::to_string(bytes.size()) +
        (bytes.size() < kStlPrefixSize + kStlRecordSize * n ? " (truncated)" : ""));
  if (n == 0)
    return Expected<std::vector<Vec3>>::failure(prefix + "no vertices (binary STL of 0 triangles)");
  std::vector<Vec3> points;
  points.reserve(3 * n);
  for (std::uint64_t t = 0; t < n; ++t) {
    // Record: normal (3 floats, not used), three vertices (3 floats each), 2 attribute bytes.
    const unsigned char* record = data + kStlPrefixSize + kStlRecordSize * t;
    for (int v = 0; v < 3; ++v) {
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = read_le_float(record + 12 + 12 * v + 4 * k);
      if (!is_finite(p))
        return Expected<std::vector<Vec3>>::failure(
            prefix + "triangle " + std::to_string(t + 1) + " (byte " +
            std::to_string(kStlPrefixSize + kStlRecordSize * t) + "): vertex " +
            std::to_string(v + 1) + " has a NaN or infinite coordinate");
      points.push_back(p);
    }
  }
  return points;
}

class AsciiStlReader {
 public:
  explicit AsciiStlReader(std::string_view name) : errors_(name) {}

  Expected<std::vector<Vec3>> read(std::string_view text) {
    const bool ok =
        for_each_line(text, errors_, [&](std::string_view line) { return read_line(line); });
    if (!ok) return Expected<std::vector<Vec3>>::failure(std::move(error_));
    if (state_ != State::AfterSolid)
      return Expected<std::vector<Vec3>>::failure(
          errors_.at_line(std::string("unexpected end of file: expected ") + expected() +
                          " (truncated ASCII STL?)"));
    if (points_.empty())
      return Expected<std::vector<Vec3>>::failure(
          errors_.at_file("no vertices (ASCII STL without facets)"));
    return std::move(points_);
  }

 private:
  enum class State { BeforeSolid, InSolid, InFacet, InLoop, AfterLoop, AfterSolid };

  const char* expected() const {
    switch (state_) {
      case State::BeforeSolid:
        return "'solid'";
      case State::InSolid:
        return "'facet normal' or 'endsolid'";
      case State::InFacet:
        return "'outer loop'";
      case State::InLoop:
        return loop_vertices_ < 3 ? "'vertex'" : "'endloop'";
      case State::AfterLoop:
        return "'endfacet'";
      case State::AfterSolid:
        return "'solid' or the end of the file";
    }
    return "";
  }

  bool fail(std::string message) {
    error_ = std::move(message);
    return false;
  }

  bool unexpected() {
    return fail(errors_.at_line("expected " + std::string(expected()) + ", found " +
                                quoted(tokens_.front())));
  }

  bool is(std::size_t i, std::string_view keyword) const {
    return i < tokens_.size() && equals_ignoring_case(tokens_[i], keyword);
  }

  /// Reads tokens_[first..first+2] as three numbers; `finite` demands finite values.
  bool read_triple(std::size_t first, std::string_view what, bool finite, Vec3& v) {
    if (tokens_.size() != first + 3)
      return fail(errors_.at_line(std::string(what) + " needs 3 numbers, found " +
                                  std::to_string(tokens_.size() - first)));
    for (std::size_t k = 0; k < 3; ++k) {
      double value;
      NumberStatus status = parse_number(tokens_[first + k], value);
      // A facet normal is not used: exporters write NaN for degenerate facets, accept it.
      if (status == NumberStatus::NotFinite && !finite) status = NumberStatus::Ok;
      if (status != NumberStatus::Ok)
        return fail(errors_.number(status, tokens_[first + k],
                                   std::string(what) + " coordinate " + "xyz"[k]));
      v[static_cast<Eigen::Index>(k)] = value;
    }
    return true;
  }

  bool read_line(std::string_view line) {
    split_tokens(line, tokens_);
    if (tokens_.empty()) return true;
    Vec3 v;
    switch (state_) {
      case State::BeforeSolid:
      case State::AfterSolid:
        if (!is(0, "solid")) return unexpected();
        state_ = State::InSolid;  // the rest of the line is the solid's name
        return true;
      case State::InSolid:
        if (is(0, "endsolid")) {
          state_ = State::AfterSolid;
          return true;
        }
        if (!is(0, "facet")) return unexpected();
        if (!is(1, "normal")) return fail(errors_.at_line("expected 'facet normal nx ny nz'"));
        if (!read_triple(2, "facet normal", false, v)) return false;
        state_ = State::InFacet;
        return true;
      case State::InFacet:
        if (!is(0, "outer")) return unexpected();
        if (!is(1, "loop") || tokens_.size() != 2)
          return fail(errors_.at_line("expected 'outer loop'"));
        state_ = State::InLoop;
        loop_vertices_ = 0;
        return true;
      case State::InLoop:
        if (is(0, "vertex")) {
          if (loop_vertices_ == 3) return fail(errors_.at_line("a facet has more than 3 vertices"));
          if (!read_triple(1, "vertex", true, v)) return false;
          points_.push_back(v);
          ++loop_vertices_;
          return true;
        }
        if (!is(0, "endloop")) return unexpected();
        if (loop_vertices_ != 3)
          return fail(errors_.at_line("a facet has " + std::to_string(loop_vertices_) +
                                      " vertices, STL needs 3"));
        state_ = State::AfterLoop;
        return true;
      case State::AfterLoop:
        if (!is(0, "endfacet")) return unexpected();
        state_ = State::InSolid;
        return true;
    }
    return unexpected();
  }

  TextErrors errors_;
  std::string error_;
  std::vector<std::string_view> tokens_;
  std::vector<Vec3> points_;
  State state_ = State::BeforeSolid;
  int loop_vertices_ = 0;
};

Expected<std::vector<Vec3>> read_stl(std::string_view bytes, std::string_view name) {
  if (has_binary_stl_size(bytes)) return read_binary_stl(bytes, name);
  // Text never holds a NUL byte; a binary file whose header begins with "solid" almost always
  // does (its counts and floats), so it is reported as the broken binary file it is.
  if (begins_with_solid(bytes) && bytes.find('\0') == std::string_view::npos)
    return AsciiStlReader(name).read(bytes);
  if (bytes.size() >= kStlPrefixSize) return read_binary_stl(bytes, name);
  return Expected<std::vector<Vec3>>::failure(
      std::string(name) + ": not an STL file: " + std::to_string(bytes.size()) +
      " bytes is too short for a binary STL (84 at least) and it does not begin with 'solid'");
}

}  // namespace

Expected<std::vector<Vec3>> parse_mesh_points(std::string_view bytes, MeshFormat format,
                                              std::string_view name) {
  if (format == MeshFormat::Auto)
    format =
        has_binary_stl_size(bytes) || begins_with_solid(bytes) ? MeshFormat::Stl : MeshFormat::Obj;
  if (format == MeshFormat::Stl) return read_stl(bytes, name);
  return ObjReader(name).read(bytes);
}

Expected<std::vector<Vec3>> read_mesh_points(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file)
    return Expected<std::vector<Vec3>>::failure(path + ": cannot open: " + std::strerror(errno));
  std::string bytes;
  std::array<char, 1 << 16> buffer;
  for (;;) {
    const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), file);
    bytes.append(buffer.data(), n);
    if (n < buffer.size()) break;
  }
  // fopen succeeds on a directory; reading it fails with EISDIR, reported here.
  const bool failed = std::ferror(file) != 0;
  const int read_errno = errno;
  std::fclose(file);
  if (failed)
    return Expected<std::vector<Vec3>>::failure(path +
                                                ": cannot read: " + std::strerror(read_errno));

  MeshFormat format = MeshFormat::Auto;
  const std::size_t dot = path.find_last_of("./");
  if (dot != std::string::npos && path[dot] == '.') {
    const std::string_view extension = std::string_view(path).substr(dot + 1);
    if (equals_ignoring_case(extension, "obj")) format = MeshFormat::Obj;
    if (equals_ignoring_case(extension, "stl")) format = MeshFormat::Stl;
  }
  return parse_mesh_points(bytes, format, path);
}

}  // namespace mink
