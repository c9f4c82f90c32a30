// Certificates as lines of text, for tests that take them apart: split
// and join lines, read a line's keyword and numbers, change one number, and
// find the lines of one kind. Numbers are exact (Rational), as in the format.
#pragma once

#include "orthoray/number.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace orthoray::test {

using Lines = std::vector<std::string>;

inline Lines split_lines(const std::string& text) {
    Lines lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

inline std::string join(const Lines& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + '\n';
    return text;
}

inline std::vector<std::string> tokens(const std::string& line) {
    std::vector<std::string> result;
    std::istringstream in(line);
    for (std::string token; in >> token;) result.push_back(token);
    return result;
}

inline std::string keyword(const std::string& line) {
    const auto t = tokens(line);
    return t.empty() ? std::string() : t[0];
}

inline std::string untokens(const std::vector<std::string>& t) {
    std::string line;
    for (std::size_t i = 0; i < t.size(); ++i) line += (i ? " " : "") + t[i];
    return line;
}

inline Rational number(const std::string& token) {
    const NumberToken n = read_number(token);
    REQUIRE(n.status == NumberToken::Status::ok);
    return n.value;
}

// The line with token `index` (1-based after the keyword) changed by `f`.
template <class F>
std::string with_number(const std::string& line, std::size_t index, F f) {
    auto t = tokens(line);
    REQUIRE(index < t.size());
    t[index] = to_string(f(number(t[index])));
    return untokens(t);
}

inline std::vector<std::size_t> lines_with(const Lines& lines, const std::string& word) {
    std::vector<std::size_t> result;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (keyword(lines[i]) == word) result.push_back(i);
    return result;
}

inline std::size_t line_with(const Lines& lines, const std::string& word) {
    const auto all = lines_with(lines, word);
    REQUIRE(all.size() == 1);
    return all[0];
}

// `text` with the first occurrence of `from` (which must be there) replaced
// by `to`: a tampering written as the change it makes.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace orthoray::test
