// The .bff reader (docs/puzzles.md). It reads the dialects the public level
// files use: cells separated by spaces or not, keywords in either case,
// block counts in any order, `#` comments anywhere, blank lines, CRLF. The
// grid comes first; every later line is a count, a laser or a point. The
// first problem becomes the one InputError, at the offending token.
#include "orthoray/parse.hpp"
#include "orthoray/puzzle.hpp"

#include "io/quoted_token.hpp"
#include "io/text_line.hpp"

#include <cctype>
#include <charconv>
#include <cstdio>

namespace orthoray {
namespace {

using io::Token;

std::string quoted(std::string_view text) {
    return io::quoted_token(text);
}

bool same_word(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) != b[i]) return false;
    return true;
}

std::optional<LazorCell> cell_of(char c) {
    switch (std::tolower(static_cast<unsigned char>(c))) {
    case 'o':
        return LazorCell::open;
    case 'x':
        return LazorCell::blocked;
    case 'a':
        return LazorCell::reflect;
    case 'b':
        return LazorCell::opaque;
    case 'c':
        return LazorCell::refract;
    default:
        return std::nullopt;
    }
}

constexpr const char* cell_forms =
    "a cell: o (open), x (no block), A (reflect), B (opaque) or C (refract)";
constexpr const char* statement_forms =
    "a block count (A n, B n, C n), a laser (L x y vx vy) or a point (P x y)";

std::string ordinal(int n) {
    const char* suffix = (n % 100 >= 11 && n % 100 <= 13) ? "th"
                         : n % 10 == 1                    ? "st"
                         : n % 10 == 2                    ? "nd"
                         : n % 10 == 3                    ? "rd"
                                                          : "th";
    return std::to_string(n) + suffix;
}

class LazorReader {
public:
    LazorReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    LazorLevel read() {
        const io::TextEnd end = io::for_each_line(
            text_, [&](std::string_view line, int number) { read_line(line, number); });
        eof_line_ = end.line;
        eof_column_ = end.column;
        if (grid_line_ == 0)
            fail_at_eof("a grid: GRID START, rows of cells (o x A B C), GRID STOP");
        if (in_grid_)
            fail_at_eof("GRID STOP (the grid starts on line " + std::to_string(grid_line_) + ")");
        if (level_.lasers.empty()) fail_at_eof("at least one laser 'L x y vx vy'");
        if (level_.points.empty()) fail_at_eof("at least one point 'P x y'");
        return std::move(level_);
    }

private:
    std::string_view text_;
    const std::string& file_;
    LazorLevel level_;
    int eof_line_ = 0, eof_column_ = 0;
    int grid_line_ = 0, first_row_line_ = 0;
    bool in_grid_ = false;
    std::array<int, 3> count_line_{};
    int open_cells_ = 0, counted_ = 0;

    std::vector<Token> tokens_;
    std::size_t next_ = 0;
    int line_ = 0, end_column_ = 0;

    [[noreturn]] void fail(int column, const std::string& message) const {
        throw InputError(file_, line_, column, message);
    }
    [[noreturn]] void fail_at_eof(const std::string& expected) const {
        throw InputError(file_, eof_line_, eof_column_, "found end of file, expected " + expected);
    }

    void read_line(std::string_view line, int line_number) {
        line_ = line_number;
        const std::size_t comment = line.find('#');
        if (const std::optional<io::BadByte> bad = io::find_bad_byte(line, comment))
            fail(bad->column, bad->message);
        const std::string_view code = line.substr(0, comment);
        io::split_tokens(code, tokens_);
        next_ = 0;
        end_column_ = static_cast<int>(code.size()) + 1;
        if (tokens_.empty()) return;
        if (in_grid_)
            read_grid_line();
        else
            read_statement();
    }

    bool is_grid_keyword(std::string_view second) const {
        return tokens_.size() >= 2 && same_word(tokens_[0].text, "GRID") &&
               same_word(tokens_[1].text, second);
    }

    void expect_end_of_line() {
        if (next_ < tokens_.size())
            fail(tokens_[next_].column,
                 "found " + quoted(tokens_[next_].text) + ", expected end of line");
    }

    void read_grid_line() {
        if (is_grid_keyword("STOP")) {
            next_ = 2;
            expect_end_of_line();
            if (level_.height == 0)
                fail(tokens_[0].column, "found GRID STOP, expected at least one row of cells");
            in_grid_ = false;
            return;
        }
        if (level_.height == lazor_max_side)
            fail(tokens_[0].column, "found a " + ordinal(lazor_max_side + 1) +
                                        " row, expected at most " + std::to_string(lazor_max_side) +
                                        " rows, then GRID STOP");
        int cells = 0;
        for (const Token& token : tokens_) {
            for (std::size_t i = 0; i < token.text.size(); ++i) {
                const int column = token.column + static_cast<int>(i);
                const char c = token.text[i];
                const std::optional<LazorCell> cell = cell_of(c);
                if (!cell) {
                    if (std::isdigit(static_cast<unsigned char>(c)) || c == '-')
                        fail(column, "found " + quoted(token.text.substr(i, 1)) +
                                         " in the grid, expected " + cell_forms +
                                         ", or GRID STOP to end the grid before the counts");
                    fail(column,
                         "found " + quoted(token.text.substr(i, 1)) + ", expected " + cell_forms);
                }
                ++cells;
                const int limit = level_.height == 0 ? lazor_max_side : level_.width;
                if (cells > limit)
                    fail(column,
                         "found a " + ordinal(cells) + " cell, expected " +
                             (level_.height == 0
                                  ? "at most " + std::to_string(lazor_max_side) + " cells a row"
                                  : std::to_string(level_.width) +
                                        " cells like the first row (line " +
                                        std::to_string(first_row_line_) + ")"));
                level_.cells.push_back(*cell);
                level_.cell_positions.emplace_back(line_, column);
                if (*cell == LazorCell::open) ++open_cells_;
            }
        }
        if (level_.height == 0) {
            level_.width = cells;
            first_row_line_ = line_;
        } else if (cells < level_.width) {
            fail(end_column_, "found the end of the row after " + std::to_string(cells) +
                                  " cells, expected " + std::to_string(level_.width) +
                                  " cells like the first row (line " +
                                  std::to_string(first_row_line_) + ")");
        }
        ++level_.height;
    }

    void read_statement() {
        const Token& head = tokens_[next_++];
        if (same_word(head.text, "GRID")) return read_grid_start(head);
        if (grid_line_ == 0)
            fail(head.column,
                 "found " + quoted(head.text) + ", expected GRID START: the grid comes first");
        if (head.text.size() == 1) {
            const char letter =
                static_cast<char>(std::toupper(static_cast<unsigned char>(head.text[0])));
            if (letter >= 'A' && letter <= 'C') return read_count(letter - 'A', letter);
            if (letter == 'L') return read_laser();
            if (letter == 'P') return read_point();
        }
        fail(head.column, "found " + quoted(head.text) + ", expected " + statement_forms);
    }

    void read_grid_start(const Token& head) {
        if (next_ == tokens_.size())
            fail(end_column_, "found end of line, expected 'START' after 'GRID'");
        const Token& word = tokens_[next_++];
        if (!same_word(word.text, "START"))
            fail(word.column, "found " + quoted(word.text) + ", expected 'START' after 'GRID'" +
                                  (same_word(word.text, "STOP") ? " (no grid is open)" : ""));
        if (grid_line_ != 0)
            fail(head.column, "found a second GRID START (the grid starts on line " +
                                  std::to_string(grid_line_) + "), expected one grid");
        expect_end_of_line();
        grid_line_ = line_;
        in_grid_ = true;
    }

    // An integer token; `what` names it in the message.
    std::pair<int, int> take_integer(const std::string& what) {
        if (next_ == tokens_.size()) fail(end_column_, "found end of line, expected " + what);
        const Token& t = tokens_[next_++];
        int value = 0;
        const char* first = t.text.data();
        const char* last = first + t.text.size();
        if (first != last && *first == '+') ++first;
        const auto [end, error] = std::from_chars(first, last, value);
        if (error != std::errc() || end != last || first == last)
            fail(t.column, "found " + quoted(t.text) + ", expected " + what + " (an integer)");
        return {value, t.column};
    }

    void read_count(int kind, char letter) {
        const std::string name(1, letter);
        if (count_line_[kind] != 0)
            fail(tokens_[0].column,
                 "found a second count of " + name + " blocks (the first is on line " +
                     std::to_string(count_line_[kind]) + "), expected one count a block type");
        const auto [count, column] = take_integer("the number of " + name + " blocks to place");
        const int room = open_cells_ - counted_;
        if (count < 0 || count > room)
            fail(column, "found " + std::to_string(count) + ", expected a number of " + name +
                             " blocks from 0 to " + std::to_string(room) + " (the open cells" +
                             (counted_ > 0 ? " left by the other counts)" : ")"));
        expect_end_of_line();
        level_.blocks[kind] = count;
        counted_ += count;
        count_line_[kind] = line_;
    }

    // A coordinate in half-block units within the grid, 0 to `size`.
    std::pair<int, int> take_coordinate(const std::string& what, char axis) {
        const int size = axis == 'x' ? 2 * level_.width : 2 * level_.height;
        const auto [value, column] = take_integer(what);
        if (value < 0 || value > size)
            fail(column, "found " + std::to_string(value) + ", expected " + what + " from 0 to " +
                             std::to_string(size) + " (the grid is " +
                             std::to_string(level_.width) + " x " + std::to_string(level_.height) +
                             " blocks, in half-block units)");
        return {value, column};
    }

    int take_direction(const std::string& what) {
        const auto [value, column] = take_integer(what);
        if (value != 1 && value != -1)
            fail(column, "found " + std::to_string(value) + ", expected " + what +
                             ": 1 or -1 (lasers move diagonally)");
        return value;
    }

    void read_laser() {
        LazorLaser laser;
        laser.line = line_;
        const auto [x, x_column] = take_coordinate("the laser's x", 'x');
        const int y = take_coordinate("the laser's y", 'y').first;
        if ((x + y) % 2 == 0)
            fail(x_column, "found the laser at (" + std::to_string(x) + ", " + std::to_string(y) +
                               "), " + (x % 2 == 0 ? "a block corner" : "a block centre") +
                               ", expected the midpoint of a cell edge (x + y odd)");
        laser.x = x;
        laser.y = y;
        laser.dx = take_direction("the direction's x");
        laser.dy = take_direction("the direction's y");
        expect_end_of_line();
        level_.lasers.push_back(laser);
    }

    void read_point() {
        LazorPoint point;
        point.line = line_;
        point.x = take_coordinate("the point's x", 'x').first;
        point.y = take_coordinate("the point's y", 'y').first;
        expect_end_of_line();
        level_.points.push_back(point);
    }
};

} // namespace

char lazor_letter(LazorCell cell) {
    switch (cell) {
    case LazorCell::open:
        return 'o';
    case LazorCell::blocked:
        return 'x';
    case LazorCell::reflect:
        return 'A';
    case LazorCell::opaque:
        return 'B';
    case LazorCell::refract:
        return 'C';
    }
    return '?';
}

LazorLevel read_lazor_level(std::string_view text, const std::string& file) {
    return LazorReader(text, file).read();
}

LazorLevel load_lazor_level(const std::string& path) {
    return read_lazor_level(read_file(path), path);
}

} // namespace orthoray
