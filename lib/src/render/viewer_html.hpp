// The interactive viewer as one self-contained HTML page: the viewer's
// script and style sheet (viewer.js, viewer.css, compiled in) and the
// scene's data as JSON, with no reference to anything outside the file.
#pragma once

#include <ostream>
#include <string>

namespace orthoray::render {

// `title` is the page's title; `json` is ViewerRecord::to_json().
void write_viewer_html(std::ostream& out, const std::string& title, const std::string& json);

} // namespace orthoray::render
