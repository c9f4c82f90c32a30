#include "render/svg_writer.hpp"

#include <cstdio>

namespace orthoray::render {

std::string number_text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", value);
    return buffer;
}

std::string escape_xml(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') out += c;
        }
    }
    return out;
}

PathData& PathData::add(char command, double x, double y) {
    text_ += command;
    text_ += number_text(x);
    text_ += ' ';
    text_ += number_text(y);
    return *this;
}

void SvgWriter::start_tag(std::string_view name, Attributes attributes) {
    out_ << '<' << name;
    for (const auto& [key, value] : attributes)
        out_ << ' ' << key << "=\"" << escape_xml(value) << '"';
}

void SvgWriter::open(std::string_view name, Attributes attributes) {
    start_tag(name, attributes);
    out_ << ">\n";
}

void SvgWriter::close(std::string_view name) {
    out_ << "</" << name << ">\n";
}

void SvgWriter::empty(std::string_view name, Attributes attributes) {
    start_tag(name, attributes);
    out_ << "/>\n";
}

void SvgWriter::text(std::string_view name, Attributes attributes, std::string_view content) {
    start_tag(name, attributes);
    out_ << '>' << escape_xml(content) << "</" << name << ">\n";
}

} // namespace orthoray::render
