// `mink view`: answers query lines exactly as `mink query` does and writes one self-contained HTML
// page that draws them (viewer/ holds the page; docs/viewer.md describes it).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <simdjson.h>

#include "commands.hpp"
#include "json_writer.hpp"
#include "mink/config.hpp"
#include "query_stream.hpp"
#include "viewer_page.hpp"

namespace mink::cli {

namespace {

struct ViewCommandOptions {
  std::vector<std::string> files;
  std::string output;
  std::size_t max_queries = 1000;
};

/// One query line and the answer `mink query` gives it.
struct ViewItem {
  std::string file;
  std::int64_t line = 0;
  std::string_view query;
  std::string_view answer;
};

bool read_all(std::FILE* in, std::string& text) {
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, in);
    text.append(buffer, n);
    if (n < sizeof buffer) return std::ferror(in) == 0;
  }
}

bool is_blank(std::string_view line) {
  for (const char c : line)
    if (c != ' ' && c != '\t' && c != '\r') return false;
  return true;
}

/// Splits `text` into lines the way QueryStream does (a trailing "\r" dropped, a last line without
/// a newline kept) and calls `f(line_number, line)` for each line that is not blank, so that the
/// n-th call belongs to the n-th answer line.
template <class F>
void for_each_query_line(std::string_view text, F&& f) {
  std::int64_t number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!is_blank(line)) f(number, line);
  }
}

/// Length of the valid UTF-8 sequence at s[i], or 0 when the bytes there are not one.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  std::size_t n = 0;
  unsigned min = 0;
  unsigned code = 0;
  if (c >= 0xc2 && c <= 0xdf)
    n = 2, min = 0x80, code = c & 0x1fu;
  else if (c >= 0xe0 && c <= 0xef)
    n = 3, min = 0x800, code = c & 0x0fu;
  else if (c >= 0xf0 && c <= 0xf4)
    n = 4, min = 0x10000, code = c & 0x07u;
  else
    return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0u) != 0x80u) return 0;
    code = (code << 6) | (byte(i + k) & 0x3fu);
  }
  if (code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

/// Appends `text` as a JSON string that is safe inside an HTML <script> element: '<', '>' and '&'
/// are escaped (no "</script>" can end the element early) and bytes that are not valid UTF-8 (a
/// malformed input line may hold any) become U+FFFD, so that the page always parses.
void append_html_json_string(std::string& out, std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '"';
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::size_t n = utf8_length(text, i);
      if (n == 0) {
        out += "\\ufffd";
        ++i;
      } else {
        out.append(text.substr(i, n));
        i += n;
      }
      continue;
    }
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == '<' || c == '>' || c == '&' || c == 0x7f) {
      out += "\\u00";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
    ++i;
  }
  out += '"';
}

/// The error message of an error answer line; empty when the line is not one.
std::string error_of(simdjson::dom::parser& parser, std::string_view answer) {
  simdjson::dom::element line;
  if (parser.parse(answer.data(), answer.size()).get(line)) return "unreadable answer";
  std::string_view status, error;
  if (line["status"].get(status) || status != "error") return {};
  if (line["error"].get(error)) return "error";
  return std::string(error);
}

int run_view(const ViewCommandOptions& options) {
  if (!viewer_available()) {
    std::fprintf(stderr,
                 "mink view: this mink was built without the viewer (npm was not found when it was "
                 "configured); install npm (scripts/deps.sh) and build again\n");
    return 1;
  }
  std::vector<std::string> files = options.files;
  if (files.empty()) files.push_back("-");
  int exit_code = 0;

  // Every input's text and answers stay alive until the page is written: items point into them.
  std::vector<std::unique_ptr<std::string>> texts, answers;
  std::vector<ViewItem> items;
  std::size_t dropped = 0;
  QueryStream stream;
  for (const std::string& file : files) {
    const bool is_stdin = file == "-";
    std::FILE* in = is_stdin ? stdin : std::fopen(file.c_str(), "rb");
    if (in == nullptr) {
      std::fprintf(stderr, "mink view: cannot open %s: %s\n", file.c_str(), std::strerror(errno));
      exit_code = 1;
      continue;
    }
    auto text = std::make_unique<std::string>();
    const bool ok = read_all(in, *text);
    if (!is_stdin) std::fclose(in);
    if (!ok) {
      std::fprintf(stderr, "mink view: cannot read %s\n", file.c_str());
      exit_code = 1;
      continue;
    }
    // The same answering path as `mink query`: one answer line per non-blank query line.
    auto answered = std::make_unique<std::string>(stream.answer_text(*text));
    std::string_view rest = *answered;
    const std::string name = is_stdin ? "stdin" : file;
    for_each_query_line(*text, [&](std::int64_t number, std::string_view line) {
      const std::size_t end = rest.find('\n');
      const std::string_view answer = rest.substr(0, end);
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
      if (items.size() >= options.max_queries) {
        ++dropped;
        return;
      }
      items.push_back({name, number, line, answer});
    });
    texts.push_back(std::move(text));
    answers.push_back(std::move(answered));
  }

  std::size_t errors = 0;
  simdjson::dom::parser parser;
  for (const ViewItem& item : items) {
    const std::string error = error_of(parser, item.answer);
    if (error.empty()) continue;
    ++errors;
    std::fprintf(stderr, "mink view: %s:%lld: %s\n", item.file.c_str(),
                 static_cast<long long>(item.line), error.c_str());
  }
  if (dropped > 0)
    std::fprintf(stderr,
                 "mink view: only the first %zu queries are in the page (%zu more left out; "
                 "see --max-queries)\n",
                 options.max_queries, dropped);

  std::string data = "{\"mink\":";
  append_string(data, kVersion);
  data += ",\"three\":";
  append_string(data, viewer_three_version());
  data += ",\"sources\":[";
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (i > 0) data += ',';
    append_html_json_string(data, files[i] == "-" ? "stdin" : files[i]);
  }
  data += "],\"items\":[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const ViewItem& item = items[i];
    if (i > 0) data += ",\n";
    data += "{\"file\":";
    append_html_json_string(data, item.file);
    data += ",\"line\":";
    append_integer(data, item.line);
    data += ",\"query\":";
    append_html_json_string(data, item.query);
    data += ",\"answer\":";
    append_html_json_string(data, item.answer);
    data += '}';
  }
  data += "]}";

  std::string page = viewer_page_template();
  const std::size_t marker = page.find(kViewerDataMarker);
  if (marker == std::string::npos) {
    std::fprintf(stderr, "mink view: the built-in page has no data marker (a build bug)\n");
    return 1;
  }
  page.replace(marker, kViewerDataMarker.size(), data);

  const bool to_stdout = options.output == "-";
  std::FILE* out = to_stdout ? stdout : std::fopen(options.output.c_str(), "wb");
  if (out == nullptr) {
    std::fprintf(stderr, "mink view: cannot write %s: %s\n", options.output.c_str(),
                 std::strerror(errno));
    return 1;
  }
  const bool written = std::fwrite(page.data(), 1, page.size(), out) == page.size();
  const bool closed = to_stdout ? std::fflush(out) == 0 : std::fclose(out) == 0;
  if (!written || !closed) {
    std::fprintf(stderr, "mink view: cannot write %s: %s\n", options.output.c_str(),
                 std::strerror(errno));
    return 1;
  }
  std::fprintf(stderr, "mink view: %zu queries (%zu with errors) drawn in %s\n", items.size(),
               errors, to_stdout ? "stdout" : options.output.c_str());
  return exit_code;
}

}  // namespace

void add_view_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ViewCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "view",
      "Answer query lines as `mink query` does and write one self-contained HTML page (three.js "
      "inside, opens offline) that draws the shapes, witness points, normals and manifolds, with "
      "the answers listed beside the picture. Malformed lines are listed as errors in the page "
      "and on stderr.");
  command->add_option("files", options->files,
                      "Files of query lines, in order; none or \"-\": standard input");
  command->add_option("-o,--output", options->output, "The page to write (\"-\": standard output)")
      ->required();
  command
      ->add_option("--max-queries", options->max_queries,
                   "Put at most this many queries in the page (a browser draws a few thousand "
                   "shapes smoothly, not millions)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->callback([options, &exit_code] { exit_code = run_view(*options); });
}

}  // namespace mink::cli
