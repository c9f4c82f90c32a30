// The .grid reader (docs/grid-mazes.md). Statements come first, one a line,
// `#` starting a comment: `beam SIDE INDEX`, `target ROW COLUMN`,
// `exit SIDE INDEX`. A line `grid` ends them; every later line is a row of
// cells, where `#` is a block, so no comments there. The first problem
// becomes the one InputError, at the offending byte or token.
#include "orthoray/grid.hpp"
#include "orthoray/parse.hpp"

#include "io/quoted_token.hpp"
#include "io/text_line.hpp"

#include <cstdio>
#include <optional>

namespace orthoray {
namespace {

using io::Token;

std::string quoted(std::string_view text) {
    return io::quoted_token(text);
}

constexpr const char* cell_forms = "a cell: . (empty), / or \\ (mirrors), # (block)";
constexpr const char* statement_forms =
    "a statement: beam SIDE INDEX, target ROW COLUMN, exit SIDE INDEX, or grid";

std::optional<GridCell> cell_of(char c) {
    switch (c) {
    case '.':
        return GridCell::empty;
    case '/':
        return GridCell::rising;
    case '\\':
        return GridCell::falling;
    case '#':
        return GridCell::block;
    default:
        return std::nullopt;
    }
}

std::optional<GridSide> side_named(std::string_view word) {
    for (GridSide side : {GridSide::left, GridSide::right, GridSide::top, GridSide::bottom})
        if (word == to_string(side)) return side;
    return std::nullopt;
}

// A beam or exit enters through a row (left, right) or a column (top, bottom).
bool names_row(GridSide side) {
    return side == GridSide::left || side == GridSide::right;
}

// A number that must lie in [0, count) once the grid is known: where it
// was written, for the message then.
struct PendingIndex {
    int line, column;
    int value;
    bool row; // a row number, else a column number
};

class GridReader {
public:
    GridReader(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    GridMaze read() {
        const io::TextEnd end = io::for_each_line(text_, [&](std::string_view line, int number) {
            line_ = number;
            if (in_grid_)
                read_row(line);
            else
                read_statement_line(line);
        });
        eof_line_ = end.line;
        eof_column_ = end.column;
        if (!in_grid_) fail_at_eof("a line 'grid' followed by the rows of the maze");
        if (maze_.height == 0) fail_at_eof("a row of cells after 'grid'");
        for (const PendingIndex& index : pending_) check_range(index);
        return std::move(maze_);
    }

private:
    std::string_view text_;
    const std::string& file_;
    GridMaze maze_;
    int eof_line_ = 0, eof_column_ = 0;
    int line_ = 0;
    bool in_grid_ = false;
    int filled_ = 0;
    // Empty lines seen since the last row: trailing ones end the file
    // harmlessly, one followed by a row is a row with no cells.
    int blank_rows_ = 0, first_blank_line_ = 0;
    std::vector<PendingIndex> pending_;

    std::vector<Token> tokens_;
    std::size_t next_ = 0;
    int end_column_ = 0;

    [[noreturn]] void fail(int column, const std::string& message) const {
        throw InputError(file_, line_, column, message);
    }
    [[noreturn]] void fail_at_eof(const std::string& expected) const {
        throw InputError(file_, eof_line_, eof_column_, "found end of file, expected " + expected);
    }

    // Only printable ASCII and tabs, outside comments.
    void check_bytes(std::string_view line, std::size_t comment) const {
        if (const std::optional<io::BadByte> bad = io::find_bad_byte(line, comment))
            fail(bad->column, bad->message);
    }

    void read_statement_line(std::string_view line) {
        const std::size_t comment = line.find('#');
        check_bytes(line, comment);
        const std::string_view code = line.substr(0, comment);
        io::split_tokens(code, tokens_);
        next_ = 0;
        end_column_ = static_cast<int>(code.size()) + 1;
        if (tokens_.empty()) return;
        const Token& word = tokens_[next_++];
        if (word.text == "beam") {
            GridBeam beam;
            beam.line = line_;
            beam.side = take_side();
            beam.index = take_index(names_row(beam.side));
            maze_.beams.push_back(beam);
        } else if (word.text == "exit") {
            GridTarget target;
            target.kind = GridTarget::Kind::exit;
            target.line = line_;
            target.side = take_side();
            target.index = take_index(names_row(target.side));
            maze_.targets.push_back(target);
        } else if (word.text == "target") {
            GridTarget target;
            target.line = line_;
            target.row = take_index(true);
            target.column = take_index(false);
            maze_.targets.push_back(target);
        } else if (word.text == "grid") {
            if (maze_.beams.empty())
                fail(word.column, "found 'grid', expected a 'beam SIDE INDEX' statement first");
            in_grid_ = true;
        } else {
            fail(word.column, "found " + quoted(word.text) + ", expected " + statement_forms);
        }
        if (next_ < tokens_.size())
            fail(tokens_[next_].column,
                 "found " + quoted(tokens_[next_].text) + ", expected end of line");
    }

    const Token* take(const std::string& expected) {
        if (next_ == tokens_.size()) fail(end_column_, "found end of line, expected " + expected);
        return &tokens_[next_++];
    }

    GridSide take_side() {
        constexpr const char* forms = "a side: left, right, top or bottom";
        const Token* token = take(forms);
        const std::optional<GridSide> side = side_named(token->text);
        if (!side) fail(token->column, "found " + quoted(token->text) + ", expected " + forms);
        return *side;
    }

    int take_index(bool row) {
        const std::string forms =
            row ? "a row number (0 for the top row)" : "a column number (0 for the left column)";
        const Token* token = take(forms);
        // At most 9 digits: the value fits an int; the range is checked once
        // the grid's size is known.
        const bool digits = !token->text.empty() && token->text.size() <= 9 &&
                            token->text.find_first_not_of("0123456789") == std::string_view::npos;
        if (!digits) fail(token->column, "found " + quoted(token->text) + ", expected " + forms);
        const int value = std::stoi(std::string(token->text));
        pending_.push_back({line_, token->column, value, row});
        return value;
    }

    void check_range(const PendingIndex& index) const {
        const int count = index.row ? maze_.height : maze_.width;
        if (index.value < count) return;
        const std::string what = index.row ? "row" : "column";
        throw InputError(file_, index.line, index.column,
                         "found " + what + " " + std::to_string(index.value) + ", expected a " +
                             what + " from 0 to " + std::to_string(count - 1) + " (the grid has " +
                             std::to_string(count) + " " + what + (count == 1 ? ")" : "s)"));
    }

    void read_row(std::string_view line) {
        if (line.empty()) {
            if (blank_rows_++ == 0) first_blank_line_ = line_;
            return;
        }
        if (blank_rows_ > 0) {
            // A row with no cells, since more rows follow.
            throw InputError(file_, first_blank_line_, 1,
                             "found an empty line inside the grid, expected " +
                                 std::string(cell_forms));
        }
        const bool first = maze_.height == 0;
        if (first) {
            maze_.first_row_line = line_;
            maze_.width = static_cast<int>(line.size());
        }
        for (std::size_t i = 0; i < line.size(); ++i) {
            const int column = static_cast<int>(i) + 1;
            if (!first && column > maze_.width)
                fail(column, "found " + quoted(line.substr(i, 1)) +
                                 ", expected the end of the row (" + std::to_string(maze_.width) +
                                 " cells, as in the first row on line " +
                                 std::to_string(maze_.first_row_line) + ")");
            const std::optional<GridCell> cell = cell_of(line[i]);
            if (!cell) fail_cell(line, i);
            if (*cell != GridCell::empty && ++filled_ > grid_max_filled_cells)
                fail(column, "found mirror or block number " + std::to_string(filled_) +
                                 ", expected at most " + std::to_string(grid_max_filled_cells) +
                                 " (docs/grid-mazes.md)");
            maze_.cells.push_back(*cell);
        }
        if (static_cast<int>(line.size()) < maze_.width)
            fail(static_cast<int>(line.size()) + 1,
                 "found end of line, expected " + std::to_string(maze_.width) +
                     " cells, as in the first row on line " + std::to_string(maze_.first_row_line));
        ++maze_.height;
    }

    [[noreturn]] void fail_cell(std::string_view line, std::size_t i) const {
        const int column = static_cast<int>(i) + 1;
        const auto c = static_cast<unsigned char>(line[i]);
        if (c < 0x20 || c >= 0x7f) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "found byte 0x%02X", c);
            fail(column, std::string(buf) + ", expected " + cell_forms);
        }
        // Puzzle splitters send a beam both ways at once, which no optical
        // element does: refused by name rather than read as something else.
        if (c == '|' || c == '-')
            fail(column, "found " + quoted(line.substr(i, 1)) +
                             ", a puzzle splitter that sends a beam both ways (not optics, "
                             "docs/grid-mazes.md), expected " +
                             cell_forms);
        fail(column, "found " + quoted(line.substr(i, 1)) + ", expected " + cell_forms);
    }
};

} // namespace

const char* to_string(GridSide side) {
    switch (side) {
    case GridSide::left:
        return "left";
    case GridSide::right:
        return "right";
    case GridSide::top:
        return "top";
    case GridSide::bottom:
        return "bottom";
    }
    return "";
}

GridMaze read_grid_maze(std::string_view text, const std::string& file) {
    return GridReader(text, file).read();
}

} // namespace orthoray
