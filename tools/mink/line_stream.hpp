/// @file line_stream.hpp
/// Reading JSON lines in large chunks and writing the answers in large chunks, for every
/// subcommand (QueryStream for `mink query` and `mink view`, `mink hull`): the caller supplies
/// what to do with one line.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace mink::cli {

/// Called for each non-blank line (without its newline and trailing "\r"; a line of spaces, tabs
/// and carriage returns is blank) with its 1-based line number; appends its answer line(s) to
/// `out`. The memory after the line is readable for simdjson::SIMDJSON_PADDING bytes, so the line
/// can be parsed in place.
using LineHandler =
    std::function<void(std::string_view line, std::int64_t line_number, std::string& out)>;

/// Calls `handler` for every line readable from `fd` until its end and writes what it appends to
/// `out`, flushing after each read (a program that writes one line to a pipe and waits gets its
/// answer at once). Blank lines are skipped but counted. Returns false, with `error` set, when
/// reading or writing fails.
bool run_lines(int fd, std::FILE* out, const LineHandler& handler, std::string& error);

/// The same on text in memory; returns what the handler appended (tests, embedding).
std::string run_lines_on_text(std::string_view text, const LineHandler& handler);

/// Reads in order each of `files` ("-": standard input) through `run(fd, error)`. A file that
/// cannot be opened, or whose `run` returns false with `error` set, is reported on stderr as
/// "<command>: <file>: <reason>" and the others are still read. Returns 0 when every file was
/// read, else 1 (the exit code of `mink query` and `mink hull`).
int run_on_files(const std::vector<std::string>& files, const char* command,
                 const std::function<bool(int fd, std::string& error)>& run);

}  // namespace mink::cli
