#include "line_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include <simdjson.h>

namespace mink::cli {

namespace {

/// Input is read this much at a time, and the answers to it are written together.
constexpr std::size_t kChunk = std::size_t(1) << 20;
constexpr std::size_t kPadding = simdjson::SIMDJSON_PADDING;

/// Only spaces, tabs and carriage returns (JSON's white space, but for the newline).
bool is_blank(std::string_view line) {
  for (const char c : line)
    if (c != ' ' && c != '\t' && c != '\r') return false;
  return true;
}

struct LineSplitter {
  const LineHandler& handler;
  std::int64_t line_number = 0;

  void line(std::string_view text, std::string& out) {
    ++line_number;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    if (!is_blank(text)) handler(text, line_number, out);
  }

  /// Handles the complete lines in [begin, end); returns how many bytes they took.
  std::size_t lines(const char* begin, const char* end, std::string& out) {
    const char* p = begin;
    while (const void* found = std::memchr(p, '\n', static_cast<std::size_t>(end - p))) {
      const char* newline = static_cast<const char*>(found);
      line({p, static_cast<std::size_t>(newline - p)}, out);
      p = newline + 1;
    }
    return static_cast<std::size_t>(p - begin);
  }
};

bool write_all(std::string& text, std::FILE* out, std::string& error) {
  if ((!text.empty() && std::fwrite(text.data(), 1, text.size(), out) != text.size()) ||
      std::fflush(out) != 0) {
    error = std::string("cannot write the answers: ") + std::strerror(errno);
    return false;
  }
  text.clear();
  return true;
}

}  // namespace

bool run_lines(int fd, std::FILE* out, const LineHandler& handler, std::string& error) {
  LineSplitter splitter{handler};
  // [begin, end) is input not handled yet: the start of a line whose newline has not come.
  std::vector<char> buffer(kChunk + kPadding);
  std::size_t begin = 0, end = 0;
  std::string answers;
  answers.reserve(2 * kChunk);
  for (;;) {
    if (buffer.size() - kPadding - end < kChunk) {
      std::memmove(buffer.data(), buffer.data() + begin, end - begin);
      end -= begin;
      begin = 0;
      // A line longer than a chunk: grow, keeping the padding after the usable part.
      if (buffer.size() - kPadding - end < kChunk) buffer.resize(end + kChunk + kPadding);
    }
    const ssize_t n = ::read(fd, buffer.data() + end, buffer.size() - kPadding - end);
    if (n < 0) {
      if (errno == EINTR) continue;
      error = std::string("cannot read the input: ") + std::strerror(errno);
      return false;
    }
    if (n == 0) break;
    end += static_cast<std::size_t>(n);
    begin += splitter.lines(buffer.data() + begin, buffer.data() + end, answers);
    if (!write_all(answers, out, error)) return false;
  }
  // The last line may lack its newline.
  if (begin < end) splitter.line({buffer.data() + begin, end - begin}, answers);
  return write_all(answers, out, error);
}

std::string run_lines_on_text(std::string_view text, const LineHandler& handler) {
  LineSplitter splitter{handler};
  const simdjson::padded_string padded(text);
  std::string answers;
  const std::size_t used = splitter.lines(padded.data(), padded.data() + padded.size(), answers);
  if (used < padded.size()) splitter.line({padded.data() + used, padded.size() - used}, answers);
  return answers;
}

int run_on_files(const std::vector<std::string>& files, const char* command,
                 const std::function<bool(int fd, std::string& error)>& run) {
  int exit_code = 0;
  for (const std::string& file : files) {
    const bool is_stdin = file == "-";
    const int fd = is_stdin ? STDIN_FILENO : ::open(file.c_str(), O_RDONLY);
    if (fd < 0) {
      std::fprintf(stderr, "%s: cannot open %s: %s\n", command, file.c_str(), std::strerror(errno));
      exit_code = 1;
      continue;
    }
    std::string error;
    if (!run(fd, error)) {
      std::fprintf(stderr, "%s: %s: %s\n", command, is_stdin ? "stdin" : file.c_str(),
                   error.c_str());
      exit_code = 1;
    }
    if (!is_stdin) ::close(fd);
  }
  return exit_code;
}

}  // namespace mink::cli
