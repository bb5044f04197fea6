#include "json_writer.hpp"

#include <charconv>
#include <cmath>

namespace mink::cli {

void append_number(std::string& out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  // Adding +0 turns -0 into +0 and changes nothing else.
  value += 0.0;
  char buffer[32];  // the longest shortest-form double, "-2.2250738585072014e-308", has 24
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_integer(std::string& out, std::int64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_string(std::string& out, std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '"';
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      switch (c) {
        case '\n':
          out += "\\n";
          break;
        case '\r':
          out += "\\r";
          break;
        case '\t':
          out += "\\t";
          break;
        default:
          out += "\\u00";
          out += kHex[u >> 4];
          out += kHex[u & 0xf];
      }
    } else {
      out += c;
    }
  }
  out += '"';
}

void append_vec3(std::string& out, const Vec3& v) {
  out += '[';
  append_components(out, v, ',');
  out += ']';
}

void append_components(std::string& out, const Vec3& v, char separator) {
  append_number(out, v.x());
  out += separator;
  append_number(out, v.y());
  out += separator;
  append_number(out, v.z());
}

void append_field(std::string& out, std::string_view key) {
  out += ",\"";
  out += key;
  out += "\":";
}

}  // namespace mink::cli
