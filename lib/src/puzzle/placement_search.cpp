#include "puzzle/placement_search.hpp"

#include <stdexcept>
#include <string>

namespace orthoray::puzzle {

void Board::apply(const Decision& d) {
    cells[d.cell] = d.content;
    --undecided_cells;
    if (d.content != empty) --remaining[d.content - 1];
}

void Board::undo(const Decision& d) {
    if (d.content != empty) ++remaining[d.content - 1];
    ++undecided_cells;
    cells[d.cell] = Content::undecided;
}

Board initial_board(const LazorLevel& level) {
    Board board;
    for (const LazorCell cell : level.cells) {
        board.cells.push_back(content_of(cell));
        if (board.cells.back() == undecided) ++board.undecided_cells;
    }
    board.remaining = level.blocks;
    return board;
}

Integer arrangements(const Board& board) {
    // Choose the reflect cells among the undecided ones, then the opaque
    // ones among the rest, then the refract ones: a multinomial.
    Integer ways = 1, choose;
    unsigned long cells = static_cast<unsigned long>(board.undecided_cells);
    for (const int count : board.remaining) {
        if (static_cast<unsigned long>(count) > cells) return 0;
        mpz_bin_uiui(choose.get_mpz_t(), cells, static_cast<unsigned long>(count));
        ways *= choose;
        cells -= static_cast<unsigned long>(count);
    }
    return ways;
}

std::string board_text(const Board& board) {
    std::string out;
    for (const Content c : board.cells) out += static_cast<char>('0' + c);
    for (const int count : board.remaining) out += '/' + std::to_string(count);
    return out + '/' + std::to_string(board.undecided_cells);
}

Board board_from_text(std::string_view text) {
    Board board;
    std::size_t at = 0;
    for (; at < text.size() && text[at] != '/'; ++at) {
        if (text[at] < '0' || text[at] > '0' + undecided)
            throw std::invalid_argument("a board's text holds a bad cell");
        board.cells.push_back(static_cast<Content>(text[at] - '0'));
    }
    std::array<int, 4> counts{};
    for (int& count : counts) {
        if (at >= text.size() || text[at] != '/')
            throw std::invalid_argument("a board's text lacks its counts");
        const std::size_t end = std::min(text.find('/', at + 1), text.size());
        count = std::stoi(std::string(text.substr(at + 1, end - at - 1)));
        at = end;
    }
    board.remaining = {counts[0], counts[1], counts[2]};
    board.undecided_cells = counts[3];
    return board;
}

PlacementSearch::PlacementSearch(const LazorLevel& level, bool count_all,
                                 std::function<bool()> stop)
    : level_(level), count_all_(count_all), stop_(std::move(stop)), walk_(level),
      board_(initial_board(level)) {}

PlacementSearch::Branches PlacementSearch::expand() {
    Branches out;
    const int cell = walk_.walk(board_.cells);
    if (cell < 0 || board_.remaining_total() == 0) {
        // Nothing can change the beams any more: a block on a cell no branch
        // enters does nothing, since only the block a branch enters acts.
        out.solution = walk_.all_lit() && board_.remaining_total() <= board_.undecided_cells;
        return out;
    }
    if (!walk_.all_lit()) {
        unsigned can_place = 0;
        for (int k = 0; k < 3; ++k)
            if (board_.remaining[k] > 0) can_place |= 1u << (k + 1);
        if (!walk_.may_light_all(board_.cells, can_place)) return out;
    }
    for (int k = 0; k < 3; ++k)
        if (board_.remaining[k] > 0)
            out.decisions[out.count++] = Decision{cell, static_cast<Content>(k + 1)};
    // Empty for good, if the blocks left still fit on the other cells.
    if (board_.undecided_cells - 1 >= board_.remaining_total())
        out.decisions[out.count++] = Decision{cell, empty};
    return out;
}

void PlacementSearch::explore() {
    if (stopped_ || stop_()) {
        stopped_ = true;
        return;
    }
    ++result_.nodes;
    const Branches branches = expand();
    if (branches.solution) {
        if (skip_ && skip_(board_)) return;
        if (!result_.first) result_.first = board_;
        if (count_all_) result_.solutions += arrangements(board_);
        return;
    }
    for (int i = 0; i < branches.count; ++i) {
        board_.apply(branches.decisions[i]);
        explore();
        board_.undo(branches.decisions[i]);
        if (stopped_ || (!count_all_ && result_.first)) return;
    }
}

std::vector<Decision> PlacementSearch::children(const std::vector<Decision>& path) {
    board_ = initial_board(level_);
    for (const Decision& d : path) board_.apply(d);
    const Branches branches = expand();
    return {branches.decisions.begin(), branches.decisions.begin() + branches.count};
}

SubtreeResult PlacementSearch::search(const std::vector<Decision>& path) {
    board_ = initial_board(level_);
    for (const Decision& d : path) board_.apply(d);
    result_ = SubtreeResult{};
    stopped_ = false;
    explore();
    result_.complete = !stopped_;
    return std::move(result_);
}

} // namespace orthoray::puzzle
