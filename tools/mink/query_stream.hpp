/// @file query_stream.hpp
/// `mink query` without the command line: splitting input into lines, answering each, and
/// writing the answers in large chunks.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "answer.hpp"
#include "json_io.hpp"

namespace mink::cli {

/// Answers query lines in order, one answer line per non-blank input line. Blank lines are
/// skipped but counted, so that a line without an id is answered with its 1-based line number in
/// its own input. A trailing "\r" (CRLF files) is ignored. One per thread; reuse it.
class QueryStream {
 public:
  explicit QueryStream(AnswerOptions options = {}) : options_(options) {}

  /// Answers every line readable from the file descriptor `fd` until its end and writes the
  /// answers to `out`. Line numbers start again at 1. Answers are flushed after each read, so a
  /// program that writes one line to a pipe and waits gets its answer at once, while a large file
  /// is written in chunks of about a megabyte. Returns false, with `error` set, when reading or
  /// writing fails; malformed lines are not failures (they get error lines).
  bool run(int fd, std::FILE* out, std::string& error);

  /// Answers every line of `text` and returns the answer lines (tests, embedding).
  std::string answer_text(std::string_view text);

 private:
  /// Answers the complete lines in [begin, end) and returns how many bytes they took; the bytes
  /// after `end` must be readable for simdjson::SIMDJSON_PADDING bytes.
  std::size_t answer_lines(const char* begin, const char* end, std::string& out);
  void answer_line(std::string_view line, std::string& out);

  AnswerOptions options_;
  QueryParser parser_;
  Query query_;
  std::int64_t line_number_ = 0;
};

}  // namespace mink::cli
