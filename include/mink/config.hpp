/// @file config.hpp
/// Version and build-wide conventions of mink. See docs/conventions.md for frames, units and signs.
#pragma once

#define MINK_VERSION_MAJOR 0
#define MINK_VERSION_MINOR 1
#define MINK_VERSION_PATCH 0

namespace mink {

/// Version string, "major.minor.patch".
inline constexpr const char* kVersion = "0.1.0";

}  // namespace mink
