/// @file query_stream.hpp
/// `mink query` without the command line: answering each line of the input (split into lines
/// and written in large chunks by line_stream.hpp).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "answer.hpp"
#include "json_io.hpp"
#include "line_stream.hpp"

namespace mink::cli {

/// Answers query lines in order, one answer line per non-blank input line. Blank lines are
/// skipped but counted, so that a line without an id is answered with its 1-based line number in
/// its own input. A trailing "\r" (CRLF files) is ignored (line_stream.hpp). One per thread;
/// reuse it.
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
  void answer_line(std::string_view line, std::int64_t line_number, std::string& out);
  /// answer_line() on this stream, for run_lines().
  LineHandler handler();

  AnswerOptions options_;
  QueryParser parser_;
  Query query_;
};

}  // namespace mink::cli
