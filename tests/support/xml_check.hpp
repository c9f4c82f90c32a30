// A small XML reader for tests of the SVG output: it checks that the text
// is well-formed (every tag closed in order, attributes quoted, only the
// five predefined entities) and lists the elements with their attributes.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace orthoray::test {

struct XmlElement {
    std::string name;
    std::map<std::string, std::string> attributes; // values with entities still escaped
    std::string text;                              // character data directly inside
};

struct XmlDocument {
    bool well_formed = false;
    std::string error;                // why not, with the byte offset
    std::vector<XmlElement> elements; // in document order
};

XmlDocument read_xml(const std::string& text);

} // namespace orthoray::test
