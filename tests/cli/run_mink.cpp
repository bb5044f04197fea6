#include "run_mink.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace mink::cli::test {

ProcessResult run_mink(const std::string& arguments) {
  ProcessResult r;
  const std::string err_path =
      ::testing::TempDir() + "mink_stderr_" + std::to_string(::getpid()) + ".txt";
  const std::string command =
      shell_quoted(MINK_EXE) + " " + arguments + " 2>" + shell_quoted(err_path);
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ostringstream err;
  err << std::ifstream(err_path, std::ios::binary).rdbuf();
  r.err = err.str();
  std::remove(err_path.c_str());
  return r;
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string shell_quoted(const std::string& text) {
  return "'" + text + "'";
}

}  // namespace mink::cli::test
