#include "render/viewer_html.hpp"

#include "render/svg_writer.hpp"
#include "render/viewer_assets.hpp"

namespace orthoray::render {
namespace {

// JSON inside <script> ends at the first "</script", whatever the JSON
// says: every '<' (only ever inside a JSON string) is written as the
// escape \u003c, which a JSON reader turns back into '<'.
std::string script_safe(const std::string& json) {
    std::string safe;
    safe.reserve(json.size());
    for (const char c : json) {
        if (c == '<')
            safe += "\\u003c";
        else
            safe += c;
    }
    return safe;
}

} // namespace

void write_viewer_html(std::ostream& out, const std::string& title, const std::string& json) {
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
        << "<title>" << escape_xml(title) << "</title>\n<style>\n"
        << assets::viewer_css << "</style>\n</head>\n<body>\n"
        << "<header><h1 id=\"title\">" << escape_xml(title) << "</h1>\n"
        << "<p id=\"answer\"></p>\n<div id=\"caption\"></div></header>\n"
        << "<div id=\"controls\">\n"
        << "<button id=\"play\" type=\"button\">play</button>\n"
        << "<input id=\"step\" type=\"range\" min=\"0\" max=\"0\" value=\"0\" "
           "aria-label=\"segments shown\">\n"
        << "<span id=\"step-label\"></span>\n"
        << "<button id=\"reset-view\" type=\"button\">reset view</button>\n"
        << "</div>\n"
        << "<div id=\"stage\"></div>\n"
        << "<p id=\"readout\">hover over a point, an element, a start or a target to read "
           "its exact coordinates</p>\n"
        << "<p id=\"help\"></p>\n"
        << "<script type=\"application/json\" id=\"viewer-data\">" << script_safe(json)
        << "</script>\n<script>\n"
        << assets::viewer_js << "</script>\n</body>\n</html>\n";
}

} // namespace orthoray::render
