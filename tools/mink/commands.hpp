/// @file commands.hpp
/// The subcommands of `mink`, one file each (cmd_*.cpp). Each registers itself on the app; its
/// callback runs after the command line was parsed and stores the process exit code.
#pragma once

#include <CLI/CLI.hpp>

namespace mink::cli {

/// `mink query [--timing] [files...]`: answer JSON-lines queries (cmd_query.cpp).
void add_query_command(CLI::App& app, int& exit_code);

/// `mink hull [--mesh FILE] [--max-vertices N] [--obj OUT] [files...]`: convex hulls of point
/// sets or meshes as JSON lines (cmd_hull.cpp).
void add_hull_command(CLI::App& app, int& exit_code);

/// `mink view [files...] -o page.html`: answer query lines and draw them in a page (cmd_view.cpp).
void add_view_command(CLI::App& app, int& exit_code);

}  // namespace mink::cli
