#include "query_stream.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace mink::cli {

namespace {

/// Input is read this much at a time, and the answers to it are written together.
constexpr std::size_t kChunk = std::size_t(1) << 20;

bool is_blank(std::string_view line) {
  for (const char c : line)
    if (c != ' ' && c != '\t' && c != '\r') return false;
  return true;
}

bool write_all(std::string& text, std::FILE* out, std::string& error) {
  if (!text.empty() && std::fwrite(text.data(), 1, text.size(), out) != text.size()) {
    error = std::string("cannot write the answers: ") + std::strerror(errno);
    return false;
  }
  text.clear();
  if (std::fflush(out) != 0) {
    error = std::string("cannot write the answers: ") + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace

void QueryStream::answer_line(std::string_view line, std::string& out) {
  ++line_number_;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (is_blank(line)) return;
  if (parser_.parse(line, line_number_, query_))
    write_answer(query_, options_, out);
  else
    write_error(query_.id, parser_.error(), out);
}

std::size_t QueryStream::answer_lines(const char* begin, const char* end, std::string& out) {
  const char* p = begin;
  while (const void* found = std::memchr(p, '\n', static_cast<std::size_t>(end - p))) {
    const char* newline = static_cast<const char*>(found);
    answer_line({p, static_cast<std::size_t>(newline - p)}, out);
    p = newline + 1;
  }
  return static_cast<std::size_t>(p - begin);
}

bool QueryStream::run(int fd, std::FILE* out, std::string& error) {
  line_number_ = 0;
  constexpr std::size_t kPadding = simdjson::SIMDJSON_PADDING;
  // [begin, end) is input not answered yet: the start of a line whose newline has not come.
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
      error = std::string("cannot read the queries: ") + std::strerror(errno);
      return false;
    }
    if (n == 0) break;
    end += static_cast<std::size_t>(n);
    begin += answer_lines(buffer.data() + begin, buffer.data() + end, answers);
    if (!write_all(answers, out, error)) return false;
  }
  // The last line may lack its newline.
  if (begin < end) answer_line({buffer.data() + begin, end - begin}, answers);
  return write_all(answers, out, error);
}

std::string QueryStream::answer_text(std::string_view text) {
  line_number_ = 0;
  const simdjson::padded_string padded(text);
  std::string answers;
  const std::size_t used = answer_lines(padded.data(), padded.data() + padded.size(), answers);
  if (used < padded.size()) answer_line({padded.data() + used, padded.size() - used}, answers);
  return answers;
}

}  // namespace mink::cli
