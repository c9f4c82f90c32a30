// A small SVG writer: elements with attributes, text content escaped for
// XML, numbers to one decimal (a tenth of a pixel is below what any
// rasteriser shows, and it keeps pictures byte-for-byte reproducible).
#pragma once

#include <initializer_list>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>

namespace orthoray::render {

// A number as an attribute value: one decimal.
std::string number_text(double value);

// Text for XML content or an attribute value: the five special characters
// escaped, control bytes (not allowed in XML 1.0) dropped.
std::string escape_xml(std::string_view text);

// SVG path data from moves and lines, numbers as number_text writes them.
class PathData {
public:
    PathData& move(double x, double y) { return add('M', x, y); }
    PathData& line(double x, double y) { return add('L', x, y); }
    const std::string& text() const { return text_; }

private:
    PathData& add(char command, double x, double y);
    std::string text_;
};

using Attributes = std::initializer_list<std::pair<std::string_view, std::string>>;

class SvgWriter {
public:
    explicit SvgWriter(std::ostream& out) : out_(out) {}

    // <name a="v" ...>, left open for children.
    void open(std::string_view name, Attributes attributes = {});
    void close(std::string_view name);
    // <name a="v" .../>
    void empty(std::string_view name, Attributes attributes);
    // <name a="v" ...>text</name>
    void text(std::string_view name, Attributes attributes, std::string_view content);
    // Verbatim, for the style sheet.
    void raw(std::string_view text) { out_ << text; }

private:
    void start_tag(std::string_view name, Attributes attributes);
    std::ostream& out_;
};

} // namespace orthoray::render
