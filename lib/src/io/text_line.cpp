#include "io/text_line.hpp"

#include <cstdio>

namespace orthoray::io {

std::optional<BadByte> find_bad_byte(std::string_view line, std::size_t comment) {
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        const bool control = (c < 0x20 && c != '\t') || c == 0x7f;
        const bool foreign = c >= 0x80 && i < comment; // UTF-8 is fine inside comments
        if (control || foreign) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "found byte 0x%02X, expected printable ASCII text", c);
            return BadByte{static_cast<int>(i) + 1, buf};
        }
    }
    return std::nullopt;
}

void split_tokens(std::string_view code, std::vector<Token>& out) {
    out.clear();
    for (std::size_t i = 0; i < code.size();) {
        if (code[i] == ' ' || code[i] == '\t') {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < code.size() && code[j] != ' ' && code[j] != '\t') ++j;
        out.push_back({code.substr(i, j - i), static_cast<int>(i) + 1});
        i = j;
    }
}

} // namespace orthoray::io
