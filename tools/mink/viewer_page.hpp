/// @file viewer_page.hpp
/// The page `mink view` writes (viewer/: template.html, viewer.js and three.js), compiled into the
/// tool. The build generates its definition from viewer/ with node (viewer/embed.mjs) when npm is
/// found; without npm it compiles viewer_page_stub.cpp and `mink view` says so.
#pragma once

#include <string>
#include <string_view>

namespace mink::cli {

/// Stands in the template where the JSON of the queries and answers goes.
inline constexpr std::string_view kViewerDataMarker = "@@MINK_VIEW_DATA@@";

/// False when the tool was built without the viewer (npm was not found).
bool viewer_available();

/// The whole page with kViewerDataMarker once in it, inside a
/// `<script type="application/json">` element; empty without the viewer.
std::string viewer_page_template();

/// The version of three.js inside the page; empty without the viewer.
std::string_view viewer_three_version();

}  // namespace mink::cli
