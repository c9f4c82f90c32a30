// parse_json: the positioned JSON tree the JSON readers report errors from.
#include "io/json_document.hpp"
#include "orthoray/parse.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <tuple>

using orthoray::InputError;
using orthoray::io::JsonValue;
using orthoray::io::parse_json;

TEST_CASE("parse_json gives every value and key its line and column", "[json]") {
    // Values on one line and on many, nested, after blank lines; columns
    // are 1-based bytes.
    const std::string text = "{\"a\": [1, \"two\",\n"
                             "        {\"b\": null}],\n"
                             "\n"
                             "   \"c\": true, \"d\":\n"
                             "\"x\"}\n";
    const JsonValue root = parse_json(text, "t.json", 10);
    CHECK(root.line == 10);
    CHECK(root.column == 1);
    REQUIRE(root.keys.size() == 3);
    CHECK(root.key_lines[0] == 10);
    CHECK(root.key_columns[0] == 2);
    const JsonValue& a = root.items[0];
    CHECK(a.line == 10);
    CHECK(a.column == 7);
    REQUIRE(a.items.size() == 3);
    CHECK(a.items[0].column == 8);
    CHECK(a.items[1].text == "two");
    CHECK(a.items[1].column == 11);
    CHECK(a.items[2].line == 11);
    CHECK(a.items[2].column == 9);
    CHECK(a.items[2].key_lines[0] == 11);
    CHECK(a.items[2].key_columns[0] == 10);
    CHECK(a.items[2].items[0].column == 15);
    CHECK(root.key_lines[1] == 13);
    CHECK(root.key_columns[1] == 4);
    CHECK(root.items[1].column == 9);
    CHECK(root.key_columns[2] == 15);
    CHECK(root.items[2].line == 14);
    CHECK(root.items[2].column == 1);
}

TEST_CASE("parse_json places a syntax error at its token", "[json]") {
    const std::string text = "[1,\n 2,\n\n  tru]\n";
    try {
        parse_json(text, "t.json");
        FAIL("parsed");
    } catch (const InputError& error) {
        CHECK(error.line() == 4);
        CHECK(error.column() == 3);
    }
}

TEST_CASE("parse_json refuses a NUL byte where it stands, not as the end of the text", "[json]") {
    // nlohmann's lexer ends the input at a NUL: a valid document followed
    // by a NUL and garbage would read as whole, and a NUL inside one would
    // be reported as an early end.
    using namespace std::string_literals;
    for (const auto& [text, line, column] :
         {std::tuple{"{\"a\": 1}\0 not json {{"s, 5, 9}, std::tuple{"[1,\n 2\0, 3]"s, 6, 3},
          std::tuple{"\0"s, 5, 1}}) {
        INFO(line << ":" << column);
        try {
            parse_json(text, "t.json", 5);
            FAIL("parsed");
        } catch (const InputError& error) {
            CHECK(error.line() == line);
            CHECK(error.column() == column);
            CHECK(std::string(error.what()) == "t.json:" + std::to_string(line) + ":" +
                                                   std::to_string(column) +
                                                   ": found byte 0x00, expected JSON text");
        }
    }
}
