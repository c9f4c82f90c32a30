// Checks for numeric options, so that every command rejects the same
// out-of-range values with the same one-line message (exit 2) instead of
// CLI11 clamping or wrapping them.
#pragma once

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace orthoray::cli {

// CLI11 reads an integer option with strtoull(text, base 0), so "010" would
// be octal 8 and "08" would not convert. The numeric validators below
// therefore rewrite the text they accept to plain decimal without leading
// zeros, and must be added with Option::transform: Option::check makes a
// validator read-only.

// `text` without the leading zeros of its digits (a lone "0" kept), from
// position `from` on, or "" when it holds anything but digits there.
inline std::string decimal_digits(const std::string& text, std::size_t from = 0) {
    if (text.size() <= from || text.find_first_not_of("0123456789", from) != std::string::npos)
        return {};
    const std::size_t first = text.find_first_not_of('0', from);
    return first == std::string::npos ? "0" : text.substr(first);
}

// A whole number from `least` to `most`, in decimal digits. (CLI11's Range
// says "Value X not in range", where every other option says what it found
// and what it expected.)
inline CLI::Validator whole_number_in(std::uint64_t least, std::uint64_t most) {
    return CLI::Validator(
        [least, most](std::string& text) -> std::string {
            const std::string digits = decimal_digits(text);
            const bool fits = !digits.empty() && digits.size() <= 20;
            errno = 0;
            const unsigned long long value = fits ? std::strtoull(digits.c_str(), nullptr, 10) : 0;
            if (fits && errno == 0 && value >= least && value <= most) {
                text = digits;
                return {};
            }
            return "found '" + text + "', expected a whole number from " + std::to_string(least) +
                   " to " + std::to_string(most);
        },
        std::to_string(least) + ".." + std::to_string(most));
}

// Any whole number a 64-bit unsigned integer holds.
inline CLI::Validator whole_number_u64() {
    return whole_number_in(0, std::numeric_limits<std::uint64_t>::max());
}

// One of `names`, spelled exactly.
inline CLI::Validator one_of(std::vector<std::string> names) {
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    return CLI::Validator(
        [names, list](const std::string& text) -> std::string {
            for (const std::string& name : names)
                if (text == name) return {};
            return "found '" + text + "', expected one of " + list;
        },
        "{" + list + "}");
}

// Seconds for --timeout: a finite decimal above 0 and at most 10^9 (31
// years; beyond, the deadline would overflow the clock). 0 is refused rather
// than read as "no timeout" or "stop at once": leaving the option out means
// no timeout.
inline CLI::Validator timeout_seconds() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            // strtod alone would also take hex floats, "inf" spelled out and
            // leading blanks: only decimal notation is documented.
            const bool decimal = text.find_first_not_of("0123456789.eE+-") == std::string::npos;
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            const bool parsed = decimal && !text.empty() && end == text.c_str() + text.size();
            if (parsed && std::isfinite(value) && value > 0 && value <= 1e9) return {};
            return "found '" + text + "', expected a number of seconds above 0 and at most 10^9";
        },
        "SECONDS");
}

// A value that must not be empty: a file name, a number. Without this an
// empty value would read as the option left out (standard output instead
// of a file, no threshold instead of one), silently.
inline CLI::Validator not_empty(const std::string& expected) {
    return CLI::Validator(
        [expected](const std::string& text) -> std::string {
            return text.empty() ? "found an empty value, expected " + expected : std::string{};
        },
        "");
}

} // namespace orthoray::cli
