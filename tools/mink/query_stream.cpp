#include "query_stream.hpp"

namespace mink::cli {

void QueryStream::answer_line(std::string_view line, std::int64_t line_number, std::string& out) {
  if (parser_.parse(line, line_number, query_))
    write_answer(query_, options_, out);
  else
    write_error(query_.id, parser_.error(), out);
}

LineHandler QueryStream::handler() {
  return [this](std::string_view line, std::int64_t line_number, std::string& out) {
    answer_line(line, line_number, out);
  };
}

bool QueryStream::run(int fd, std::FILE* out, std::string& error) {
  return run_lines(fd, out, handler(), error);
}

std::string QueryStream::answer_text(std::string_view text) {
  return run_lines_on_text(text, handler());
}

}  // namespace mink::cli
