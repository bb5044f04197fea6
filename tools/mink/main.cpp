// The `mink` command-line tool: one subcommand per file (cmd_*.cpp), JSON lines in and out.
#include <string>

#include "commands.hpp"
#include "mink/config.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mink: convex collision detection on the command line (JSON lines in and out)",
               "mink"};
  app.set_version_flag("--version", std::string("mink ") + mink::kVersion);
  app.require_subcommand(1);
  int exit_code = 0;
  mink::cli::add_query_command(app, exit_code);
  mink::cli::add_hull_command(app, exit_code);
  mink::cli::add_view_command(app, exit_code);
  CLI11_PARSE(app, argc, argv);
  return exit_code;
}
