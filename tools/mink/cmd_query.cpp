// `mink query`: the JSON-lines protocol of docs/protocol.md on files or stdin.
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "query_stream.hpp"

namespace mink::cli {

namespace {

struct QueryCommandOptions {
  bool timing = false;
  std::vector<std::string> files;
};

/// Answers every file in order ("-" or no file: standard input). A file that cannot be read is
/// reported on stderr and the others are still answered; the exit code is then 1. Malformed lines
/// are answered with error lines and do not change the exit code.
int run_query(const QueryCommandOptions& options) {
  QueryStream stream(AnswerOptions{options.timing});
  std::vector<std::string> files = options.files;
  if (files.empty()) files.push_back("-");
  return run_on_files(files, "mink query", [&stream](int fd, std::string& error) {
    return stream.run(fd, stdout, error);
  });
}

}  // namespace

void add_query_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<QueryCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "query",
      "Answer collision queries given as JSON lines, one answer line per query line, in order.\n"
      "Each line: {\"id\": .., \"a\": SHAPE, \"pa\": POSE, \"b\": SHAPE, \"pb\": POSE, \"want\": "
      "\"intersect|distance|contact|manifold\", \"margin\": m (manifold only)}");
  command->add_flag("--timing", options->timing,
                    "Add \"us\" to each answer: the median time of the query itself in "
                    "microseconds (parsing and printing excluded)");
  command->add_option("files", options->files,
                      "Files of query lines, answered in order; none or \"-\": standard input");
  command->callback([options, &exit_code] { exit_code = run_query(*options); });
}

}  // namespace mink::cli
