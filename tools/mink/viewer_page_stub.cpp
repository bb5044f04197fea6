// The tool built without the viewer (npm was not found at configure time): `mink view` reports it.
#include "viewer_page.hpp"

namespace mink::cli {

bool viewer_available() {
  return false;
}

std::string viewer_page_template() {
  return {};
}

std::string_view viewer_three_version() {
  return {};
}

}  // namespace mink::cli
