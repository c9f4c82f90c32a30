// What the line-based readers (.scene, .bff levels, .grid mazes) do alike
// with one line of text: refuse bytes that are not plain text, and split the
// code before a comment into tokens with their 1-based byte columns.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace orthoray::io {

struct Token {
    std::string_view text;
    int column; // 1-based byte column
};

// A byte that has no place in a text line: a control character other than
// a tab, DEL, or (before `comment`, where UTF-8 is fine) a non-ASCII byte.
// The message is the reader's "found byte 0x.., expected plain ASCII text".
struct BadByte {
    int column;
    std::string message;
};
std::optional<BadByte> find_bad_byte(std::string_view line, std::size_t comment);

// The tokens of `code`, separated by spaces and tabs, into `out` (cleared).
void split_tokens(std::string_view code, std::vector<Token>& out);

} // namespace orthoray::io
