/// @file run_mink.hpp
/// Running the real `mink` binary (MINK_EXE) through the shell, for the end-to-end tests, and
/// writing their input files.
#pragma once

#include <string>

namespace mink::cli::test {

struct ProcessResult {
  std::string out;  ///< standard output
  std::string err;  ///< standard error
  int exit_code = -1;
};

/// Runs `mink <arguments>` (a shell command line: quote paths) and collects its output.
ProcessResult run_mink(const std::string& arguments);

/// Writes `text` to `name` in the test's temporary directory and returns the path. Names must be
/// unique per test: ctest may run the tests in parallel processes.
std::string write_temp(const std::string& name, const std::string& text);

/// `text` in single quotes for the shell (no single quote inside).
std::string shell_quoted(const std::string& text);

}  // namespace mink::cli::test
