// JSON text as a tree whose every value knows its line and column, so that a
// JSON scene or certificate that is valid JSON but not a valid scene can
// still be reported as `FILE:LINE:COL: found ..., expected ...`. Parsing is
// nlohmann-json's; this layer only records where each value starts.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace orthoray::io {

struct JsonValue {
    enum class Type { null, boolean, number, string, array, object };
    Type type = Type::null;
    // A string's content; a number's literal text as written (never
    // converted, so nothing is rounded); "true", "false" or "null".
    std::string text;
    std::vector<JsonValue> items;  // array elements, or object member values
    std::vector<std::string> keys; // object member names, parallel to items
    std::vector<int> key_columns, key_lines;
    int line = 0, column = 0; // where the value starts (1-based; byte column)

    // The member named `key`, or nullptr.
    const JsonValue* find(std::string_view key) const;
};

// Parses one JSON value (the whole of `text`, surrounding white space
// allowed). `first_line` numbers the first line of `text`, for JSON Lines
// files read a line at a time. A syntax error throws InputError naming
// `file`, the line and column of the offending token, what was found there
// and what JSON expects.
JsonValue parse_json(std::string_view text, const std::string& file, int first_line = 1);

// A short description of a value for "found ..." messages: the string "abc",
// the number 3, an array, an object, true, null.
std::string describe(const JsonValue& value);

// `text` as a JSON string literal, cut to 60 bytes, in ASCII.
std::string json_quoted(std::string_view text);

} // namespace orthoray::io
