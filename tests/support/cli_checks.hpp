// What every command-line test checks of a run's output: one line, nothing
// a terminal would not print, and bad input as status 2 with one message.
#pragma once

#include "support/run_cli.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

namespace orthoray::test {

inline bool is_one_line(const std::string& s) {
    return !s.empty() && s.back() == '\n' && std::count(s.begin(), s.end(), '\n') == 1;
}

// A byte other than a newline that a terminal would not print as is.
inline bool has_raw_control_bytes(const std::string& s) {
    for (unsigned char c : s)
        if ((c < 0x20 && c != '\n') || c >= 0x7f) return true;
    return false;
}

// Bad input: status 2, nothing on stdout, exactly one printable line on stderr.
inline void require_bad_input(const CliResult& r) {
    INFO("stdout: " << r.out);
    INFO("stderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(is_one_line(r.err));
    CHECK_FALSE(has_raw_control_bytes(r.err));
}

// stdout as one line of JSON holding an object; fails the test otherwise.
inline nlohmann::json parse_json(const std::string& out) {
    INFO("stdout: " << out);
    REQUIRE(is_one_line(out));
    nlohmann::json j = nlohmann::json::parse(out); // throws (and fails the test) if not JSON
    REQUIRE(j.is_object());
    return j;
}

} // namespace orthoray::test
