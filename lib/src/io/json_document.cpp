// Builds the positioned JSON tree with nlohmann-json's SAX parser. The SAX
// callbacks do not say where a value is, so the input is read through an
// iterator that remembers the furthest byte the lexer has looked at: when a
// callback fires, that byte ends the value just read (or is the one byte of
// look-ahead after a number), and the value's start is found from there.
#include "io/json_document.hpp"

#include "io/quoted_token.hpp"
#include "orthoray/parse.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <cstddef>
#include <iterator>

namespace orthoray::io {
namespace {

// A char iterator that records the furthest position ever dereferenced.
class TrackingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    TrackingIterator(const char* at, const char** furthest) : at_(at), furthest_(furthest) {}
    reference operator*() const {
        if (at_ > *furthest_) *furthest_ = at_;
        return *at_;
    }
    TrackingIterator& operator++() {
        ++at_;
        return *this;
    }
    TrackingIterator operator++(int) {
        TrackingIterator before = *this;
        ++at_;
        return before;
    }
    bool operator==(const TrackingIterator& other) const { return at_ == other.at_; }
    bool operator!=(const TrackingIterator& other) const { return at_ != other.at_; }

private:
    const char* at_;
    const char** furthest_;
};

// Deeper nesting is never a scene or a certificate; the cap also keeps the
// tree's recursive destructor off the end of the stack.
constexpr std::size_t max_depth = 64;

class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
public:
    TreeBuilder(std::string_view text, const std::string& file, int first_line)
        : text_(text), file_(file), first_line_(first_line), furthest_(text.data()) {
        line_starts_.push_back(0);
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') line_starts_.push_back(i + 1);
    }

    const char** furthest() { return &furthest_; }
    JsonValue take_root() { return std::move(root_); }

    bool null() override { return scalar(JsonValue::Type::null, "null", literal_start(4)); }
    bool boolean(bool value) override {
        return scalar(JsonValue::Type::boolean, value ? "true" : "false",
                      literal_start(value ? 4 : 5));
    }
    bool number_integer(number_integer_t) override { return number(); }
    bool number_unsigned(number_unsigned_t) override { return number(); }
    bool number_float(number_float_t, const string_t&) override { return number(); }
    bool string(string_t& value) override {
        return scalar(JsonValue::Type::string, std::move(value), string_start());
    }
    bool binary(binary_t&) override { return true; } // never produced by JSON text

    bool start_object(std::size_t) override { return open(JsonValue::Type::object); }
    bool start_array(std::size_t) override { return open(JsonValue::Type::array); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& name) override {
        JsonValue& object = *stack_.back();
        const std::size_t start = string_start();
        object.keys.push_back(std::move(name));
        object.key_lines.push_back(line_of(start));
        object.key_columns.push_back(column_of(start));
        return true;
    }

    bool parse_error(std::size_t, const std::string& last_token,
                     const nlohmann::detail::exception& error) override {
        // nlohmann's message is either "... - unexpected '}'; expected string
        // literal" (a token in the wrong place: the parser names the token
        // and what it wanted) or "... - invalid literal; last read: 'tru'"
        // (a token that is not JSON at all).
        const std::string what = error.what();
        const std::size_t dash = what.find(" - ");
        const std::size_t semicolon = what.find(';', dash);
        const std::string problem = dash == std::string::npos
                                        ? "syntax error"
                                        : what.substr(dash + 3, semicolon - dash - 3);
        const std::size_t end = end_offset();
        std::size_t offset = text_.size();
        std::string found = "end of file", expected;
        if (what.find("number overflow") != std::string::npos) {
            // nlohmann gives up on a number no double holds (1e999); we
            // never convert numbers, but the parse has stopped.
            offset = number_start();
            found = quoted_token(text_.substr(offset, number_end(offset) - offset));
            expected = "a number a double can hold (write exact numbers as strings)";
        } else if (problem.rfind("unexpected ", 0) == 0) {
            const std::string token = problem.substr(11);
            const std::size_t expected_at = what.find("; expected ");
            expected =
                expected_at == std::string::npos ? "valid JSON" : what.substr(expected_at + 11);
            if (token != "end of input") {
                if (token == "string literal")
                    offset = string_start();
                else if (token == "number literal")
                    offset = number_start();
                else if (token.size() > 8 && token.ends_with(" literal"))
                    offset = literal_start(token.size() - 8); // true, false, null
                else
                    offset = end;       // a one-character token: [ ] { } : ,
                std::size_t last = end; // a number's look-ahead is not part of it
                if (token == "number literal") last = number_end(offset) - 1;
                found = token.front() == '\''
                            ? token
                            : quoted_token(text_.substr(offset, last + 1 - offset));
            }
        } else {
            expected = "valid JSON (" + problem + ")";
            // The lexer's "last read" runs from the start of the bad token,
            // except for literals, where it may begin at earlier tokens.
            std::string token = last_token;
            if (problem == "invalid literal" && token.size() > 1) {
                const std::size_t cut =
                    token.substr(0, token.size() - 1).find_last_of(",:[]{} \t\r\n");
                if (cut != std::string::npos) token = token.substr(cut + 1);
            }
            if (!token.empty() && token != "<end of input>" && end < text_.size()) {
                found = quoted_token(token);
                // nlohmann spells control characters as <U+XXXX>, so the
                // token may look longer than it is.
                offset = end + 1 >= token.size() ? end + 1 - token.size() : 0;
                while (offset < end && text_[offset] != token.front()) ++offset;
            }
        }
        throw InputError(file_, line_of(offset), column_of(offset),
                         "found " + found + ", expected " + expected);
    }

private:
    std::size_t end_offset() const { return static_cast<std::size_t>(furthest_ - text_.data()); }

    // The value that just ended started `length` bytes before its last byte.
    std::size_t literal_start(std::size_t length) const { return end_offset() + 1 - length; }

    // The lexer stops on the closing quote; walk back to the opening one (a
    // quote is escaped when an odd number of backslashes precede it).
    std::size_t string_start() const {
        std::size_t i = end_offset();
        while (i > 0) {
            --i;
            if (text_[i] != '"') continue;
            std::size_t slashes = 0;
            while (slashes < i && text_[i - 1 - slashes] == '\\') ++slashes;
            if (slashes % 2 == 0) return i;
        }
        return 0;
    }

    // A number ends one byte before the look-ahead that ended it (or at the
    // end of the text); walk back over the number's characters.
    std::size_t number_start() const {
        static constexpr std::string_view number_chars = "0123456789+-.eE";
        std::size_t end = end_offset();
        if (end >= text_.size() || number_chars.find(text_[end]) == std::string_view::npos) --end;
        std::size_t i = end;
        while (i > 0 && number_chars.find(text_[i - 1]) != std::string_view::npos) --i;
        return i;
    }

    // One past the last character of the number that starts at `start`.
    std::size_t number_end(std::size_t start) const {
        static constexpr std::string_view number_chars = "0123456789+-.eE";
        std::size_t end = start;
        while (end < text_.size() && number_chars.find(text_[end]) != std::string_view::npos) ++end;
        return end;
    }

    bool number() {
        const std::size_t start = number_start();
        return scalar(JsonValue::Type::number,
                      std::string(text_.substr(start, number_end(start) - start)), start);
    }

    // The index of the line holding `offset`, found by moving on from the
    // line last asked about: values and keys start at rising offsets as the
    // parse goes on (a binary search for each was about a tenth of the time
    // to read a large JSON scene, measured).
    std::size_t line_index(std::size_t offset) const {
        while (offset < line_starts_[last_line_]) --last_line_;
        while (last_line_ + 1 < line_starts_.size() && line_starts_[last_line_ + 1] <= offset)
            ++last_line_;
        return last_line_;
    }
    int line_of(std::size_t offset) const {
        const auto index = static_cast<long long>(line_index(offset));
        return static_cast<int>(std::min<long long>(index + first_line_, INT_MAX));
    }
    int column_of(std::size_t offset) const {
        return static_cast<int>(
            std::min<std::size_t>(offset - line_starts_[line_index(offset)] + 1, INT_MAX));
    }

    // Places a new value in its parent (or as the root) and returns it.
    JsonValue& place(JsonValue::Type type, std::size_t start) {
        JsonValue* slot = &root_;
        if (!stack_.empty()) slot = &stack_.back()->items.emplace_back();
        slot->type = type;
        slot->line = line_of(start);
        slot->column = column_of(start);
        return *slot;
    }

    bool scalar(JsonValue::Type type, std::string text, std::size_t start) {
        place(type, start).text = std::move(text);
        return true;
    }

    bool open(JsonValue::Type type) {
        const std::size_t start = end_offset();
        if (stack_.size() == max_depth)
            throw InputError(file_, line_of(start), column_of(start),
                             "found JSON nested more than " + std::to_string(max_depth) +
                                 " levels deep, expected a flatter document");
        stack_.push_back(&place(type, start));
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    std::string_view text_;
    const std::string& file_;
    int first_line_;
    const char* furthest_;
    std::vector<std::size_t> line_starts_;
    mutable std::size_t last_line_ = 0; // line_index's cursor
    JsonValue root_;
    // Open arrays and objects. Pointers stay valid: a parent's items only
    // grow while its last child is closed.
    std::vector<JsonValue*> stack_;
};

} // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
        if (keys[i] == key) return &items[i];
    return nullptr;
}

JsonValue parse_json(std::string_view text, const std::string& file, int first_line) {
    // nlohmann's lexer takes a NUL byte for the end of the input, so text
    // after one would be ignored, a document that goes on after it read as
    // whole. A NUL is never JSON: refuse it where it stands.
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        const std::string_view before = text.substr(0, nul);
        const std::size_t breaks =
            static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
        const std::size_t line_start = breaks == 0 ? 0 : before.rfind('\n') + 1;
        throw InputError(file,
                         static_cast<int>(std::min<std::size_t>(
                             static_cast<std::size_t>(first_line) + breaks, INT_MAX)),
                         static_cast<int>(std::min<std::size_t>(nul - line_start + 1, INT_MAX)),
                         "found byte 0x00, expected JSON text");
    }
    TreeBuilder builder(text, file, first_line);
    const char* begin = text.data();
    const char* end = begin + text.size();
    nlohmann::json::sax_parse(TrackingIterator(begin, builder.furthest()),
                              TrackingIterator(end, builder.furthest()), &builder);
    return builder.take_root();
}

std::string json_quoted(std::string_view text) {
    // ASCII only, and a string cut inside a UTF-8 sequence stays printable.
    return nlohmann::json(std::string(text.substr(0, 60)))
        .dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
}

std::string describe(const JsonValue& value) {
    switch (value.type) {
    case JsonValue::Type::string:
        return "the string " + json_quoted(value.text);
    case JsonValue::Type::number:
        return "the number " + value.text.substr(0, 60);
    case JsonValue::Type::array:
        return "an array";
    case JsonValue::Type::object:
        return "an object";
    default:
        return value.text;
    }
}

} // namespace orthoray::io
