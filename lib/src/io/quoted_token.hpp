// A token quoted for an error message: at most 60 bytes, and every byte
// outside printable ASCII written as \xNN, so that binary garbage in a scene
// or certificate file never reaches the terminal as it is.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace orthoray::io {

inline std::string quoted_token(std::string_view text) {
    std::string out = "'";
    for (unsigned char c : text.substr(0, 60)) {
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", c);
            out += buf;
        }
    }
    return out + (text.size() > 60 ? "...'" : "'");
}

} // namespace orthoray::io
