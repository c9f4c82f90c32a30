#include "support/xml_check.hpp"

#include <cctype>

namespace orthoray::test {
namespace {

bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' ||
           c == '.';
}

class Reader {
public:
    explicit Reader(const std::string& text) : text_(text) {}

    XmlDocument read() {
        XmlDocument doc;
        try {
            if (text_.compare(0, 5, "<?xml") == 0) {
                const std::size_t end = text_.find("?>");
                if (end == std::string::npos) fail("unterminated XML declaration");
                at_ = end + 2;
            }
            bool root_seen = false;
            while (at_ < text_.size()) {
                if (text_[at_] != '<') {
                    const std::size_t next = text_.find('<', at_);
                    const std::string data = text_.substr(at_, next - at_);
                    check_entities(data);
                    if (stack_.empty()) {
                        for (char c : data)
                            if (!std::isspace(static_cast<unsigned char>(c)))
                                fail("text outside the root element");
                    } else {
                        doc.elements[stack_.back()].text += data;
                    }
                    at_ = next == std::string::npos ? text_.size() : next;
                    continue;
                }
                if (text_.compare(at_, 2, "</") == 0) {
                    at_ += 2;
                    const std::string name = read_name();
                    skip_space();
                    expect('>');
                    if (stack_.empty() || doc.elements[stack_.back()].name != name)
                        fail("closing tag </" + name + "> does not match");
                    stack_.pop_back();
                    continue;
                }
                ++at_;
                if (stack_.empty() && root_seen) fail("a second root element");
                root_seen = true;
                XmlElement element;
                element.name = read_name();
                while (true) {
                    skip_space();
                    if (at_ >= text_.size()) fail("unterminated tag");
                    if (text_[at_] == '/' || text_[at_] == '>') break;
                    const std::string key = read_name();
                    skip_space();
                    expect('=');
                    skip_space();
                    const char quote = at_ < text_.size() ? text_[at_] : 0;
                    if (quote != '"' && quote != '\'') fail("unquoted attribute " + key);
                    const std::size_t end = text_.find(quote, at_ + 1);
                    if (end == std::string::npos) fail("unterminated attribute " + key);
                    const std::string value = text_.substr(at_ + 1, end - at_ - 1);
                    if (value.find('<') != std::string::npos) fail("'<' in attribute " + key);
                    check_entities(value);
                    if (!element.attributes.emplace(key, value).second)
                        fail("repeated attribute " + key);
                    at_ = end + 1;
                }
                doc.elements.push_back(element);
                if (text_[at_] == '/') {
                    ++at_;
                    expect('>');
                } else {
                    ++at_;
                    stack_.push_back(doc.elements.size() - 1);
                }
            }
            if (!stack_.empty()) fail("unclosed <" + doc.elements[stack_.back()].name + ">");
            if (!root_seen) fail("no root element");
            doc.well_formed = true;
        } catch (const std::string& error) {
            doc.error = error;
        }
        return doc;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw what + " at byte " + std::to_string(at_);
    }
    void skip_space() {
        while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    }
    void expect(char c) {
        if (at_ >= text_.size() || text_[at_] != c) fail(std::string("expected '") + c + "'");
        ++at_;
    }
    std::string read_name() {
        const std::size_t start = at_;
        while (at_ < text_.size() && name_char(text_[at_])) ++at_;
        if (at_ == start) fail("expected a name");
        return text_.substr(start, at_ - start);
    }
    void check_entities(const std::string& data) const {
        for (std::size_t i = data.find('&'); i != std::string::npos; i = data.find('&', i + 1)) {
            bool known = false;
            for (const char* entity : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"})
                known = known || data.compare(i, std::string(entity).size(), entity) == 0;
            if (!known) fail("unknown entity");
        }
        for (unsigned char c : data)
            if (c < 0x20 && c != '\n' && c != '\t' && c != '\r') fail("control byte");
    }

    const std::string& text_;
    std::size_t at_ = 0;
    std::vector<std::size_t> stack_;
};

} // namespace

XmlDocument read_xml(const std::string& text) {
    return Reader(text).read();
}

} // namespace orthoray::test
