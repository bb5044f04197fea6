// Writes random query lines for measuring `mink query` throughput:
//   mink_gen_queries [count=100000] [seed=1] > big.jsonl
// Mixed primitives (spheres, boxes, capsules, cylinders, polytopes of 4-12 points) with random
// poses, placed so that about half of the pairs penetrate; wants are mostly the default
// (contact), some distance and intersect. Numbers are written in full double precision, the worst
// case for the parser.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

namespace {

std::mt19937_64 rng;

double uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

void number(std::string& out, double x) {
  char buffer[32];
  out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
}

void vec3(std::string& out, double lo, double hi) {
  out += '[';
  for (int i = 0; i < 3; ++i) {
    if (i) out += ',';
    number(out, uniform(lo, hi));
  }
  out += ']';
}

void shape(std::string& out) {
  switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
    case 0:
      out += "{\"type\":\"sphere\",\"radius\":";
      number(out, uniform(0.2, 1));
      break;
    case 1:
      out += "{\"type\":\"box\",\"half_extents\":";
      vec3(out, 0.2, 1);
      break;
    case 2:
    case 3:
      out += rng() % 2 ? "{\"type\":\"capsule\",\"radius\":" : "{\"type\":\"cylinder\",\"radius\":";
      number(out, uniform(0.1, 0.6));
      out += ",\"half_height\":";
      number(out, uniform(0.2, 1));
      break;
    default: {
      out += "{\"type\":\"polytope\",\"points\":[";
      const int n = std::uniform_int_distribution<int>(4, 12)(rng);
      for (int i = 0; i < n; ++i) {
        if (i) out += ',';
        vec3(out, -0.8, 0.8);
      }
      out += ']';
    }
  }
  out += '}';
}

void pose(std::string& out, double spread) {
  out += "{\"t\":";
  vec3(out, -spread, spread);
  double q[4], norm_sq = 0;
  std::normal_distribution<double> normal;
  for (double& c : q) {
    c = normal(rng);
    norm_sq += c * c;
  }
  out += ",\"q\":[";
  for (int i = 0; i < 4; ++i) {
    if (i) out += ',';
    number(out, q[i] / std::sqrt(norm_sq));
  }
  out += "]}";
}

}  // namespace

int main(int argc, char** argv) {
  const long count = argc > 1 ? std::atol(argv[1]) : 100000;
  rng.seed(argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1);
  std::string out;
  for (long i = 0; i < count; ++i) {
    out += "{\"id\":";
    number(out, static_cast<double>(i));
    out += ",\"a\":";
    shape(out);
    out += ",\"pa\":";
    pose(out, 0.8);
    out += ",\"b\":";
    shape(out);
    out += ",\"pb\":";
    pose(out, 0.8);
    const auto want = rng() % 10;
    out += want < 6 ? "}\n" : want < 8 ? ",\"want\":\"distance\"}\n" : ",\"want\":\"intersect\"}\n";
    if (out.size() > (1 << 20)) {
      std::fwrite(out.data(), 1, out.size(), stdout);
      out.clear();
    }
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}
