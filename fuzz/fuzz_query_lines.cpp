// Fuzz target: any bytes as the input of `mink query`. Every non-blank input line must get exactly
// one answer line, and every answer line must be a JSON object with an "id" and a "status" (an
// error line says why); nothing may crash, read out of bounds (sanitizers) or hang.
#include <simdjson.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "query_stream.hpp"

namespace {

[[noreturn]] void fail(const char* what, std::string_view line) {
  std::fprintf(stderr, "fuzz_query_lines: %s: %.*s\n", what, static_cast<int>(line.size()),
               line.data());
  std::abort();
}

/// Lines as line_stream.hpp counts them: split at '\n'; blank when only spaces, tabs and '\r'.
int non_blank_lines(std::string_view text) {
  int count = 0;
  bool blank = true;
  for (char c : text) {
    if (c == '\n') {
      count += !blank;
      blank = true;
    } else if (c != ' ' && c != '\t' && c != '\r') {
      blank = false;
    }
  }
  return count + !blank;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static mink::cli::QueryStream stream;
  static simdjson::dom::parser parser;
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::string output = stream.answer_text(input);
  int answers = 0;
  std::size_t start = 0;
  while (start < output.size()) {
    std::size_t end = output.find('\n', start);
    if (end == std::string::npos) fail("answer without a newline", output.substr(start));
    const std::string_view line(output.data() + start, end - start);
    ++answers;
    simdjson::dom::object object;
    if (parser.parse(line).get(object)) fail("answer is not a JSON object", line);
    bool has_id = false, has_status = false;
    for (const auto field : object) {
      has_id |= field.key == "id";
      has_status |= field.key == "status";
    }
    if (!has_id || !has_status) fail("answer without id or status", line);
    start = end + 1;
  }
  if (answers != non_blank_lines(input)) fail("not one answer per non-blank line", input);
  return 0;
}
