// Checks for numeric options, so that every command rejects the same
// out-of-range values with the same one-line message (exit 2) instead of
// CLI11 clamping or wrapping them.
#pragma once

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace orthoray::cli {

// A whole number from 0 to 2^64 - 1, in plain decimal digits.
inline CLI::Validator whole_number_u64() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            const std::string max = "18446744073709551615";
            const std::size_t first = text.find_first_not_of('0');
            const std::string digits = first == std::string::npos ? "0" : text.substr(first);
            const bool plain =
                !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
            if (plain &&
                (digits.size() < max.size() || (digits.size() == max.size() && digits <= max)))
                return {};
            return "found '" + text + "', expected a whole number from 0 to " + max;
        },
        "0..2^64-1");
}

// A whole number from `least` to `most`, in plain decimal digits: CLI11's
// Range says "Value X not in range", where every other option says what it
// found and what it expected.
inline CLI::Validator whole_number_in(std::uint64_t least, std::uint64_t most) {
    return CLI::Validator(
        [least, most](const std::string& text) -> std::string {
            const bool plain = !text.empty() && text.size() <= 20 &&
                               text.find_first_not_of("0123456789") == std::string::npos;
            errno = 0;
            const unsigned long long value = plain ? std::strtoull(text.c_str(), nullptr, 10) : 0;
            if (plain && errno == 0 && value >= least && value <= most) return {};
            return "found '" + text + "', expected a whole number from " + std::to_string(least) +
                   " to " + std::to_string(most);
        },
        std::to_string(least) + ".." + std::to_string(most));
}

// An integer in plain decimal digits, perhaps negative, that fits 64 bits;
// the range is the library's to check (its message names the bound). Without
// this CLI11 says "Could not convert: --mirrors = x".
inline CLI::Validator an_integer() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            const std::size_t digits = !text.empty() && text[0] == '-' ? 1 : 0;
            const bool plain = text.size() > digits &&
                               text.find_first_not_of("0123456789", digits) == std::string::npos;
            errno = 0;
            if (plain) std::strtoll(text.c_str(), nullptr, 10);
            return plain && errno == 0
                       ? std::string{}
                       : "found '" + text + "', expected a whole number from -2^63 to 2^63 - 1";
        },
        "");
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
