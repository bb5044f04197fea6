// A main() for the fuzz targets where libFuzzer is not available (GCC, the CI build): runs the
// target on every file given on the command line (a corpus, or one crash to reproduce), then on
// `--random N` inputs of random bytes from a fixed seed (`--seed S` to explore others), so that
// CTest exercises the target and its checks under the sanitizers on every build. An input that
// aborts is written to fuzz-failure.bin in the working directory first, to be replayed with the
// same binary.
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

const std::uint8_t* g_input = nullptr;
std::size_t g_input_size = 0;

/// The input being run, kept so that on_abort() can write it out.
int run_one(const std::uint8_t* data, std::size_t size) {
  g_input = data;
  g_input_size = size;
  return LLVMFuzzerTestOneInput(data, size);
}

extern "C" void on_abort(int signal) {
  if (std::FILE* f = std::fopen("fuzz-failure.bin", "wb")) {
    std::fwrite(g_input, 1, g_input_size, f);
    std::fclose(f);
    std::fputs("the failing input is in fuzz-failure.bin\n", stderr);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGABRT, on_abort);
  long random_inputs = 0;
  std::uint64_t seed = 20261126;
  int files = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--random") == 0 && i + 1 < argc) {
      random_inputs = std::strtol(argv[++i], nullptr, 10);
      continue;
    }
    if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
      continue;
    }
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "cannot read %s\n", argv[i]);
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    run_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    ++files;
  }
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> bytes;
  for (long n = 0; n < random_inputs; ++n) {
    bytes.resize(rng() % 512);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
    run_one(bytes.data(), bytes.size());
  }
  std::printf("%d files and %ld random inputs: no failure\n", files, random_inputs);
  return 0;
}
