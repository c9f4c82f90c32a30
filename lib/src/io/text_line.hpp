// What the line-based readers (.scene, .bff levels, .grid mazes) do alike:
// walk the text line by line, refuse bytes that are not plain text, and
// split the code before a comment into tokens with their 1-based byte
// columns.
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
// The message is the reader's "found byte 0x.., expected printable ASCII text".
struct BadByte {
    int column;
    std::string message;
};
std::optional<BadByte> find_bad_byte(std::string_view line, std::size_t comment);

// Where the text ends, for "found end of file" messages: the last line's
// number and the column just after it.
struct TextEnd {
    int line, column;
};

// Calls read(line, number) for every line of `text`, numbered from 1, each
// without its '\n' and without a CR before it (CRLF files, or a last line
// ending in CR). A UTF-8 byte order mark before the first line, which some
// editors write, reads as three blanks, so that columns stay byte columns
// of the file. Exceptions from `read` pass through.
template <class Read>
TextEnd for_each_line(std::string_view text, Read&& read) {
    constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
    std::string unmarked; // line 1 with the mark blanked, when it has one
    std::size_t begin = 0;
    for (int number = 1;; ++number) {
        const std::size_t end = text.find('\n', begin);
        std::string_view line = text.substr(
            begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (number == 1 && line.starts_with(byte_order_mark)) {
            unmarked = "   ";
            unmarked += line.substr(byte_order_mark.size());
            line = unmarked;
        }
        read(line, number);
        if (end == std::string_view::npos) return {number, static_cast<int>(line.size()) + 1};
        begin = end + 1;
    }
}

// The tokens of `code`, separated by spaces and tabs, into `out` (cleared).
void split_tokens(std::string_view code, std::vector<Token>& out);

} // namespace orthoray::io
