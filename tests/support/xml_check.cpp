#include "support/xml_check.hpp"

#include <pugixml.hpp>

namespace orthoray::test {
namespace {

// pugixml keeps an unknown entity such as &nbsp; as plain text and accepts
// control bytes, so these two rules of XML 1.0 (section 4.6 and the Char
// production, section 2.2) are checked here, on the still escaped text.
std::string bad_character_data(const std::string& data) {
    for (std::size_t i = data.find('&'); i != std::string::npos; i = data.find('&', i + 1)) {
        bool known = data.compare(i, 2, "&#") == 0;
        for (const char* entity : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"})
            known = known || data.compare(i, std::string(entity).size(), entity) == 0;
        if (!known) return "unknown entity in \"" + data + "\"";
    }
    for (unsigned char c : data)
        if (c < 0x20 && c != '\n' && c != '\t' && c != '\r') return "control byte";
    return {};
}

// Lists `node` and the elements below it in document order; returns the
// first broken piece of character data, or an empty string.
std::string collect(const pugi::xml_node& node, std::vector<XmlElement>& elements) {
    XmlElement element;
    element.name = node.name();
    for (const pugi::xml_attribute& a : node.attributes()) {
        if (std::string why = bad_character_data(a.value()); !why.empty()) return why;
        element.attributes.emplace(a.name(), a.value());
    }
    const std::size_t at = elements.size();
    elements.push_back(element);
    for (const pugi::xml_node& child : node.children()) {
        if (child.type() == pugi::node_pcdata) {
            if (std::string why = bad_character_data(child.value()); !why.empty()) return why;
            elements[at].text += child.value();
        } else if (child.type() == pugi::node_cdata) {
            elements[at].text += child.value();
        } else if (child.type() == pugi::node_element) {
            if (std::string why = collect(child, elements); !why.empty()) return why;
        }
    }
    return {};
}

} // namespace

XmlDocument read_xml(const std::string& text) {
    XmlDocument doc;
    pugi::xml_document parsed;
    // Without parse_escapes the values stay escaped for the entity check;
    // parse_ws_pcdata keeps the whitespace a caption may hold; parse_fragment
    // keeps text outside the root, which a document must not have.
    const unsigned options = (pugi::parse_default & ~pugi::parse_escapes) | pugi::parse_ws_pcdata |
                             pugi::parse_declaration | pugi::parse_fragment;
    const pugi::xml_parse_result result = parsed.load_buffer(text.data(), text.size(), options);
    if (!result) {
        doc.error = std::string(result.description()) + " at byte " + std::to_string(result.offset);
        return doc;
    }
    pugi::xml_node root;
    for (const pugi::xml_node& top : parsed.children()) {
        if (top.type() == pugi::node_element) {
            if (root) {
                doc.error = "a second root element <" + std::string(top.name()) + ">";
                return doc;
            }
            root = top;
        } else if (top.type() == pugi::node_pcdata) {
            for (const char* c = top.value(); *c != 0; ++c)
                if (*c != ' ' && *c != '\n' && *c != '\t' && *c != '\r') {
                    doc.error = "text outside the root element";
                    return doc;
                }
        }
    }
    if (!root) {
        doc.error = "no root element";
        return doc;
    }
    doc.error = collect(root, doc.elements);
    doc.well_formed = doc.error.empty();
    return doc;
}

std::vector<const XmlElement*> with_class(const XmlDocument& doc, const std::string& name,
                                          const std::string& cls) {
    std::vector<const XmlElement*> found;
    for (const XmlElement& e : doc.elements) {
        const auto it = e.attributes.find("class");
        if (e.name == name && it != e.attributes.end() && it->second == cls) found.push_back(&e);
    }
    return found;
}

} // namespace orthoray::test
