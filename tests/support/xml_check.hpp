// XML checks for tests of the SVG output: pugixml parses the text (every tag
// closed in order, attributes quoted); on top of that we require one root
// element, only the five predefined entities or character references, and no
// control bytes, since renderers such as rsvg-convert refuse those. The
// elements are listed with their attributes.
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
    std::string error;                // why not, with the byte offset when known
    std::vector<XmlElement> elements; // in document order
};

XmlDocument read_xml(const std::string& text);

// The elements `name` of class `cls` (the whole attribute), in document order.
std::vector<const XmlElement*> with_class(const XmlDocument& doc, const std::string& name,
                                          const std::string& cls);

} // namespace orthoray::test
