// The .scene reader on malformed files: each gives exactly one InputError
// that names the file, the line, the column, what was found and what was
// expected; binary garbage and mutated valid files never give anything
// else, and a 50,000-line file parses with its line numbers right.
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

using orthoray::Element;
using orthoray::ElementKind;
using orthoray::InputError;
using orthoray::Rational;
using orthoray::read_scene;
using orthoray::Scene;
using orthoray::Vector;

namespace {

// Does the text contain any byte a terminal would not print as is?
bool has_raw_control_bytes(const std::string& text) {
    for (unsigned char c : text)
        if (c < 0x20 || c >= 0x7f) return true;
    return false;
}

// Reads text that must be malformed and returns its one error.
InputError error_of(const std::string& text, const std::string& file = "t.scene") {
    try {
        read_scene(text, file);
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError for:\n" << text);
    return InputError(file, 0, 0, "unreachable");
}

} // namespace

TEST_CASE("the error message names the file, line and column", "[reader]") {
    const InputError e = error_of("dim 2\nmirror x 0 y 0 1 2\n", "dir/my file.scene");
    CHECK(e.file() == "dir/my file.scene");
    CHECK(e.line() == 2);
    CHECK(e.column() == 18);
    CHECK(e.message() == "found '2', expected end of line");
    CHECK(std::string(e.what()) == "dir/my file.scene:2:18: found '2', expected end of line");
    // The default file name.
    try {
        read_scene("dim 5\n");
        FAIL("no error");
    } catch (const InputError& err) {
        CHECK(std::string(err.what()) == "<input>:1:5: found '5', expected the dimension 2 or 3");
    }
}

namespace {

struct Malformed {
    const char* what; // the case, for the report
    std::string text;
    int line, column;
    std::string message;
};

const std::string ok_ray = "ray 0 0 1 1\n";
const std::string ok_target = "target 1 1\n";
const std::string number_forms = "a number (integer, fraction like 7/2, or decimal like 0.125)";

std::vector<Malformed> malformed_cases() {
    using namespace std::string_literals;
    return {
        // dim: missing, late, malformed, duplicated.
        {"empty file", "", 1, 1,
         "found end of file, expected 'dim 2' or 'dim 3' as the first statement"},
        {"only comments and blank lines", "# nothing\n\n   \n", 4, 1,
         "found end of file, expected 'dim 2' or 'dim 3' as the first statement"},
        {"missing dim", "mirror x 0 y 0 1\n" + ok_ray + ok_target, 1, 1,
         "found 'mirror', expected 'dim 2' or 'dim 3' as the first statement"},
        {"late dim", "# header\n  ray 0 0 1 1\ndim 2\n" + ok_target, 2, 3,
         "found 'ray', expected 'dim 2' or 'dim 3' as the first statement"},
        {"dim without a value", "dim\n", 1, 4, "found end of line, expected the dimension 2 or 3"},
        {"dim 4", "dim 4\n", 1, 5, "found '4', expected the dimension 2 or 3"},
        {"dim 1", "dim\t1\n", 1, 5, "found '1', expected the dimension 2 or 3"},
        {"dim 2.0", "dim 2.0\n", 1, 5, "found '2.0', expected the dimension 2 or 3"},
        {"dim with a trailing token", "dim 2 3\n", 1, 7, "found '3', expected end of line"},
        {"duplicate dim", "dim 2\n" + ok_ray + "dim 2\n" + ok_target, 3, 1,
         "found a second 'dim' (the first is on line 1), expected one 'dim' statement"},
        {"upper-case keyword", "DIM 2\n", 1, 1,
         "found 'DIM', expected 'dim 2' or 'dim 3' as the first statement"},

        // Unknown statements.
        {"unknown statement", "dim 2\nlens x 0 y 0 1\n", 2, 1,
         "found 'lens', expected a statement: dim, mirror, absorber, splitter, ray or target"},
        {"misspelt mirror", "dim 2\n" + ok_ray + "  mirorr x 0 y 0 1\n", 3, 3,
         "found 'mirorr', expected a statement: dim, mirror, absorber, splitter, ray or target"},
        {"a number as a statement", "dim 3\n1 2 3\n", 2, 1,
         "found '1', expected a statement: dim, mirror, absorber, splitter, ray or target"},

        // Mirrors and absorbers: arity.
        {"mirror with nothing", "dim 2\nmirror\n", 2, 7,
         "found end of line, expected the normal axis (x or y) or a diagonal (/ or \\)"},

        // Diagonal elements (docs/octagonal.md).
        {"a diagonal in 3D", "dim 3\nmirror / 0 0 1 1\n", 2, 8,
         "found '/' in a 3D scene, expected the normal axis (x, y or z): diagonal elements are "
         "2D only"},
        {"a sign on a diagonal", "dim 2\nsplitter \\- 0 1 1 0\n", 2, 10,
         "found '\\-', expected '/' or '\\' alone: diagonal elements are two-sided, with no "
         "sign"},
        {"a doubled diagonal", "dim 2\nmirror // 0 0 1 1\n", 2, 8,
         "found '//', expected '/' or '\\' alone"},
        {"a diagonal off its slope", "dim 2\nmirror / 0 0 2 3\n", 2, 16,
         "found '3' as the second endpoint's y, expected 2 (a segment of slope +1)"},
        {"a falling diagonal written rising", "dim 2\nabsorber \\ 0 0 1 1\n", 2, 18,
         "found '1' as the second endpoint's y, expected -1 (a segment of slope -1)"},
        {"a diagonal with X0 = X1", "dim 2\nmirror / 1 0 1 0\n", 2, 14,
         "found '1' as the second endpoint's x, expected a number greater than 1 (the first "
         "endpoint's x)"},
        {"a diagonal short of an endpoint", "dim 2\nmirror / 0 0 1\n", 2, 15,
         "found end of line, expected the second endpoint's y"},
        {"mirror without an offset", "dim 2\nmirror x\n", 2, 9,
         "found end of line, expected the offset x = c"},
        {"mirror without an extent", "dim 2\nmirror x 0 # no extent\n", 2, 12,
         "found end of line, expected 'y' and its extent"},
        {"mirror without the lower end", "dim 2\nmirror x 0 y\n", 2, 13,
         "found end of line, expected the lower end of the y extent"},
        {"mirror without the upper end", "dim 2\r\nmirror x 0 y 0\r\n", 2, 15,
         "found end of line, expected the upper end of the y extent"},
        {"3D mirror with one extent", "dim 3\nmirror z 0 x 0 1\n", 2, 17,
         "found end of line, expected 'y' and its extent"},
        {"mirror with a trailing token", "dim 2\nmirror x 0 y 0 1 2\n", 2, 18,
         "found '2', expected end of line"},
        {"absorber with a 3D extent in 2D", "dim 2\nabsorber y 0 x 0 1 z 0 1\n", 2, 20,
         "found 'z', expected end of line"},

        // Axis letters.
        {"normal axis out of range in 2D", "dim 2\nmirror z 0 x 0 1\n", 2, 8,
         "found 'z', expected the normal axis (x or y) of a 2D scene"},
        {"normal axis out of range in 3D", "dim 3\nmirror w 0 x 0 1 y 0 1\n", 2, 8,
         "found 'w', expected the normal axis (x, y or z) of a 3D scene"},
        {"normal axis upper case", "dim 2\nabsorber X 0 y 0 1\n", 2, 10,
         "found 'X', expected the normal axis (x or y) of a 2D scene"},
        {"normal axis as a number", "dim 2\nmirror 0 x 0 1\n", 2, 8,
         "found '0', expected the normal axis (x or y) of a 2D scene"},
        {"extent axis repeats the normal", "dim 2\nmirror x 0 x 0 1\n", 2, 12,
         "found 'x', expected 'y' (the other axes, in the order x, y, z)"},
        {"3D extent axes out of order", "dim 3\nmirror z 0 y 0 1 x 0 1\n", 2, 12,
         "found 'y', expected 'x' (the other axes, in the order x, y, z)"},
        {"3D extent axis out of range", "dim 3\nmirror x 0 y 0 1 w 0 1\n", 2, 18,
         "found 'w', expected 'z' (the other axes, in the order x, y, z)"},
        {"extent axis missing, number instead", "dim 2\nmirror y 1 0 1\n", 2, 12,
         "found '0', expected 'x' (the other axes, in the order x, y, z)"},

        // Extents.
        {"empty extent", "dim 2\nmirror x 0 y 1 1\n", 2, 16,
         "found '1' as the upper end of the y extent, expected a number greater than 1"},
        {"reversed extent", "dim 3\nmirror y 0 x 0 1 z 5/2 2.5\n", 2, 24,
         "found '2.5' as the upper end of the z extent, expected a number greater than 5/2"},
        {"inverted extent", "dim 2\nabsorber y 0 x 3 -3\n", 2, 18,
         "found '-3' as the upper end of the x extent, expected a number greater than 3"},

        // Numbers.
        {"1/0 as an offset", "dim 2\nmirror x 1/0 y 0 1\n", 2, 10,
         "found '1/0', expected the offset x = c with a nonzero denominator"},
        {"0/0 in an extent", "dim 2\nmirror x 1 y 0/0 1\n", 2, 14,
         "found '0/0', expected the lower end of the y extent with a nonzero denominator"},
        {"1/0 in the ray", "dim 2\nray 0 0 1/0 1\n", 2, 9,
         "found '1/0', expected the direction's x with a nonzero denominator"},
        {"exponent notation", "dim 2\n" + ok_ray + "target 1e3 1\n", 3, 8,
         "found '1e3', expected the target x: " + number_forms},
        {"two slashes", "dim 2\nmirror x 1/2/3 y 0 1\n", 2, 10,
         "found '1/2/3', expected the offset x = c: " + number_forms},
        {"double sign", "dim 2\nray --1 0 1 1\n", 2, 5,
         "found '--1', expected the start x: " + number_forms},
        {"signed denominator", "dim 2\nray 0 1/-2 1 1\n", 2, 7,
         "found '1/-2', expected the start y: " + number_forms},
        {"a lone point", "dim 3\nray 0 0 0 1 . 1\n", 2, 13,
         "found '.', expected the direction's y: " + number_forms},
        {"a word for a number", "dim 2\n" + ok_ray + "target 1 one\n", 3, 10,
         "found 'one', expected the target y: " + number_forms},
        {"a comma in a number", "dim 2\nmirror x 1,5 y 0 1\n", 2, 10,
         "found '1,5', expected the offset x = c: " + number_forms},
        {"a very long bad token is shortened",
         std::string("dim 2\nray ").append(100, '9') + "x 0 1 1\n", 2, 5,
         std::string("found '").append(60, '9') + "...', expected the start x: " + number_forms},

        // The ray.
        {"zero direction", "dim 2\nray 1 2 0 0\n", 2, 9,
         "found the direction 0, expected a nonzero direction"},
        {"zero direction written as fractions", "dim 3\nray 1 2 3 0/7 -0 0.000\n", 2, 11,
         "found the direction 0, expected a nonzero direction"},
        {"ray too short", "dim 2\nray 0 0 1\n", 2, 10,
         "found end of line, expected the direction's y"},
        {"ray with only a start", "dim 3\nray 0 0 0   # start only\n", 2, 13,
         "found end of line, expected the direction's x"},
        {"ray too long", "dim 2\nray 0 0 1 1 1\n", 2, 13, "found '1', expected end of line"},
        {"3D ray in 2D", "dim 2\nray 0 0 0 1 1 1\n", 2, 13, "found '1', expected end of line"},
        {"missing ray", "dim 2\n" + ok_target, 3, 1,
         "found end of file, expected a 'ray' statement"},

        // The target.
        {"2D ray in a 3D scene", "dim 3\n" + ok_ray + "target 1 2\n", 2, 12,
         "found end of line, expected the direction's y"},
        {"target too short (3D)", "dim 3\nray 0 0 0 1 1 1\ntarget 1 2\n", 3, 11,
         "found end of line, expected the target z"},
        {"target too long", "dim 2\n" + ok_ray + "target 1 1 1\n", 3, 12,
         "found '1', expected end of line"},
        {"missing target", "dim 2\n" + ok_ray, 3, 1,
         "found end of file, expected a 'target' statement"},
        {"missing target, no final newline", "dim 2\nray 0 0 1 1", 2, 12,
         "found end of file, expected a 'target' statement"},
        {"missing target, CRLF file", "dim 2\r\nray 0 0 1 1\r\n", 3, 1,
         "found end of file, expected a 'target' statement"},
        {"missing target, lone CR at the end", "dim 2\r\nray 0 0 1 1\r", 2, 12,
         "found end of file, expected a 'target' statement"},

        // Bytes that are not plain text.
        {"NUL byte", "dim 2\nray 0 \0 1 1\n"s, 2, 7,
         "found byte 0x00, expected printable ASCII text"},
        {"NUL byte in a comment", "dim 2 # \0\n"s, 1, 9,
         "found byte 0x00, expected printable ASCII text"},
        {"control byte", "dim 2\n\x01\x02\n", 2, 1,
         "found byte 0x01, expected printable ASCII text"},
        {"DEL byte", "dim 2\nmirror x 0 y 0 1\x7f\n", 2, 17,
         "found byte 0x7F, expected printable ASCII text"},
        {"stray CR inside a line", "dim 2\rray 0 0 1 1\n", 1, 6,
         "found byte 0x0D, expected printable ASCII text"},
        {"form feed", "dim 2\n\f\n", 2, 1, "found byte 0x0C, expected printable ASCII text"},
        {"UTF-8 outside a comment", "dim 2\nray 0 0 1 1 \xC3\xA9\n", 2, 13,
         "found byte 0xC3, expected printable ASCII text"},
        {"UTF-8 byte order mark past the first line's start", "dim 2\n\xEF\xBB\xBFray 0 0 1 1\n", 2,
         1, "found byte 0xEF, expected printable ASCII text"},
        {"UTF-8 byte order mark, then a bad byte: columns count the mark's bytes",
         "\xEF\xBB\xBF"
         "dim 2 \x01\n",
         1, 10, "found byte 0x01, expected printable ASCII text"},
        {"binary header",
         "\x7F"
         "ELF\x02\x01\x01",
         1, 1, "found byte 0x7F, expected printable ASCII text"},
    };
}

} // namespace

TEST_CASE("malformed files give one exact InputError", "[reader]") {
    const std::vector<Malformed> cases = malformed_cases();
    REQUIRE(cases.size() >= 30);
    for (const Malformed& c : cases) {
        INFO("case: " << c.what);
        const InputError e = error_of(c.text);
        CHECK(e.file() == "t.scene");
        CHECK(e.line() == c.line);
        CHECK(e.column() == c.column);
        CHECK(e.message() == c.message);
        // Every message says what was found and what was expected, on one
        // printable line.
        CHECK(e.message().rfind("found ", 0) == 0);
        CHECK(e.message().find(", expected ") != std::string::npos);
        CHECK_FALSE(has_raw_control_bytes(e.what()));
        CHECK(std::string(e.what()) == "t.scene:" + std::to_string(c.line) + ":" +
                                           std::to_string(c.column) + ": " + c.message);
    }
}

TEST_CASE("the first error in the file is the one reported", "[reader]") {
    // Line 2 has two problems and line 4 another; the first token wins.
    const InputError e = error_of("dim 2\nmirror q 1/0 y 0 1\nray 0 0 0 0\ntarget\n");
    CHECK(e.line() == 2);
    CHECK(e.column() == 8);
}

TEST_CASE("binary garbage gives an InputError and nothing else", "[reader]") {
    for (std::uint64_t seed : {1u, 2u, 3u, 42u, 1234u, 99991u}) {
        std::mt19937_64 rng(seed);
        for (std::size_t length : {1u, 7u, 64u, 1000u, 20000u}) {
            std::string bytes(length, '\0');
            for (char& c : bytes) c = static_cast<char>(rng() & 0xff);
            for (const std::string& text : {bytes, "dim 2\n" + bytes, "dim 3\n# " + bytes}) {
                INFO("seed " << seed << ", " << text.size() << " bytes");
                bool input_error = false;
                try {
                    read_scene(text, "garbage.bin");
                } catch (const InputError& e) {
                    input_error = true;
                    CHECK(e.line() >= 1);
                    CHECK(e.column() >= 1);
                    CHECK_FALSE(has_raw_control_bytes(e.what()));
                }
                CHECK(input_error);
            }
        }
        // Printable garbage: random words and punctuation, no control bytes.
        std::string words;
        const std::string alphabet = "dimrotaygexbsz0123456789./-+# \t\n";
        for (int i = 0; i < 5000; ++i) words += alphabet[rng() % alphabet.size()];
        bool input_error = false;
        try {
            read_scene(words, "words.txt");
        } catch (const InputError& e) {
            input_error = true;
            CHECK_FALSE(has_raw_control_bytes(e.what()));
        }
        CHECK(input_error);
    }
}

TEST_CASE("mutated valid files give a Scene or a well-placed InputError", "[reader]") {
    const std::string base = "# mutation base\r\n"
                             "dim 3\n"
                             "mirror z 0 x 0 4 y 0 4\n"
                             "absorber x -1/2 y 0 1 z -2.5 2\t# comment\n"
                             "ray 1 2 3 -1 0 1/3\n"
                             "target 1 1 1\n";
    const std::string pieces[] = {" ",
                                  "\t",
                                  "\n",
                                  "#",
                                  "/",
                                  ".",
                                  "-",
                                  "0",
                                  "1/0",
                                  "x",
                                  "y",
                                  "z",
                                  "w",
                                  "ray 0 0 0 1 1 1",
                                  "dim 2",
                                  "\r",
                                  "\0",
                                  "\xff",
                                  "9999999999999999999999"};
    std::mt19937 rng(5);
    int errors = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string text = base;
        const int edits = 1 + static_cast<int>(rng() % 3);
        for (int k = 0; k < edits; ++k) {
            const std::size_t at = rng() % (text.size() + 1);
            switch (rng() % 3) {
            case 0: // delete a few bytes
                text.erase(at, rng() % 4);
                break;
            case 1: { // insert a piece
                const std::string& piece = pieces[rng() % std::size(pieces)];
                text.insert(at, piece == "\0" ? std::string(1, '\0') : piece);
                break;
            }
            default: // overwrite one byte
                if (at < text.size()) text[at] = static_cast<char>(rng() & 0xff);
            }
        }
        INFO("round " << round);
        try {
            read_scene(text, "m.scene");
        } catch (const InputError& e) {
            ++errors;
            // The line exists (or is the one just past the last newline) and
            // the column is inside it or just past its end.
            std::vector<std::string> lines;
            std::size_t begin = 0;
            for (std::size_t end; (end = text.find('\n', begin)) != std::string::npos;
                 begin = end + 1)
                lines.push_back(text.substr(begin, end - begin));
            lines.push_back(text.substr(begin));
            REQUIRE(e.line() >= 1);
            REQUIRE(e.line() <= static_cast<int>(lines.size()));
            CHECK(e.column() >= 1);
            CHECK(e.column() <= static_cast<int>(lines[e.line() - 1].size()) + 1);
            CHECK(e.message().rfind("found ", 0) == 0);
            CHECK(e.message().find(", expected ") != std::string::npos);
            CHECK_FALSE(has_raw_control_bytes(e.what()));
        }
    }
    CHECK(errors > 1000); // most mutations break the file
}

TEST_CASE("a 50,000-line file parses", "[reader][slow]") {
    std::string text = "# generated\ndim 2\n";
    const int mirrors = 49'996;
    text.reserve(static_cast<std::size_t>(mirrors) * 32);
    for (int i = 0; i < mirrors; ++i)
        text += (i % 2 ? "mirror x " : "absorber y ") + std::to_string(i) + " " +
                (i % 2 ? "y" : "x") + " -" + std::to_string(i + 1) + "/2 " + std::to_string(i + 1) +
                ".5\n";
    text += "ray 0 0 1 1\ntarget 3 4\n";
    std::size_t lines = 0;
    for (char c : text) lines += c == '\n';
    REQUIRE(lines == 50'000);

    const Scene s = read_scene(text);
    REQUIRE(s.elements.size() == static_cast<std::size_t>(mirrors));
    const Element& last = s.elements.back();
    CHECK(last.kind == ElementKind::mirror);
    CHECK(last.axis == 0);
    CHECK(last.offset() == mirrors - 1);
    CHECK(last.lo[1] == Rational(-mirrors) / 2);
    CHECK(last.hi[1] == Rational(2 * mirrors + 1) / 2);
    CHECK(last.line == mirrors + 2);
    CHECK(s.target() == Vector{3, 4, 0});

    // An error on the very last line still has the right line number.
    const InputError e = error_of(text + "target 5\n");
    CHECK(e.line() == 50'001);
    CHECK(e.column() == 9);
}
