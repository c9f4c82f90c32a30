// LazorSearchPieces (orthoray/puzzle_pieces.hpp): the split of the placement
// search into subtrees, the search of one, and the merge in search order
// that gives what a one-thread search gives (docs/puzzles.md, "The search,
// in pieces").
#include "orthoray/puzzle_pieces.hpp"

#include "puzzle/other_solution.hpp"
#include "puzzle/placement_search.hpp"

#include <algorithm>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace orthoray {
namespace {

using puzzle::Board;
using puzzle::Decision;
using puzzle::PlacementSearch;

// Enough pieces to keep every core (or rank) busy while one runs long; the
// split depends only on the level, never on who searches the pieces.
constexpr std::size_t split_target = 64;

// Breadth first, a level of the tree at a time, until there are enough
// pieces: the pieces stay in search (depth-first) order.
std::vector<std::vector<Decision>> split(PlacementSearch& search) {
    std::vector<std::vector<Decision>> pieces{{}};
    while (pieces.size() < split_target) {
        std::vector<std::vector<Decision>> next;
        bool expanded = false;
        for (const std::vector<Decision>& path : pieces) {
            const std::vector<Decision> children = search.children(path);
            if (children.empty()) {
                next.push_back(path); // a leaf or pruned: searched as it is
                continue;
            }
            expanded = true;
            for (const Decision& d : children) {
                next.push_back(path);
                next.back().push_back(d);
            }
        }
        pieces = std::move(next);
        if (!expanded) break;
    }
    return pieces;
}

// The nodes above the split that a depth-first search enters before each
// piece's root, counted up to each piece: a piece's ancestors not shared
// with the piece before it are new (depth-first order keeps shared
// ancestors on a common prefix).
std::vector<std::uint64_t> nodes_above(const std::vector<std::vector<Decision>>& pieces) {
    std::vector<std::uint64_t> out;
    std::uint64_t entered = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        std::size_t shared = 0; // common prefix with the piece before, plus the root
        if (k > 0) {
            const std::vector<Decision>&a = pieces[k - 1], &b = pieces[k];
            std::size_t common = 0;
            while (common < a.size() && common < b.size() && a[common].cell == b[common].cell &&
                   a[common].content == b[common].content)
                ++common;
            shared = std::min(common + 1, b.size());
        }
        entered += pieces[k].size() - shared;
        out.push_back(entered);
    }
    return out;
}

} // namespace

LazorSearchPieces::LazorSearchPieces(LazorLevel level, bool all,
                                     std::optional<std::uint64_t> max_nodes)
    : LazorSearchPieces(std::move(level), all ? Mode::all : Mode::first, max_nodes, std::nullopt) {}

LazorSearchPieces LazorSearchPieces::other_than(LazorLevel level, LazorLevel intended,
                                                std::uint64_t max_nodes) {
    return LazorSearchPieces(std::move(level), Mode::other, max_nodes, std::move(intended));
}

LazorSearchPieces::LazorSearchPieces(LazorLevel level, Mode mode,
                                     std::optional<std::uint64_t> max_nodes,
                                     std::optional<LazorLevel> intended)
    : level_(std::move(level)), mode_(mode), max_nodes_(max_nodes), intended_(std::move(intended)) {
    PlacementSearch splitter(level_, mode_ == Mode::all, [] { return false; });
    const std::vector<std::vector<Decision>> pieces = split(splitter);
    nodes_above_ = nodes_above(pieces);
    for (const std::vector<Decision>& path : pieces) {
        pieces_.emplace_back();
        for (const Decision& d : path) pieces_.back().emplace_back(d.cell, d.content);
    }
}

LazorPieceResult LazorSearchPieces::search(std::size_t index, const std::function<bool()>& stop,
                                           std::atomic<std::uint64_t>* progress) const {
    // The generator's one-pass search counts the nodes above the split too.
    const std::uint64_t above = mode_ == Mode::other ? nodes_above_.at(index) : 0;
    const std::uint64_t budget =
        max_nodes_ ? *max_nodes_ - std::min(*max_nodes_, above) : std::uint64_t{0};
    std::uint64_t visited = 0;
    bool over = false;
    PlacementSearch search(level_, mode_ == Mode::all, [&] {
        if (stop && stop()) return true;
        if (max_nodes_ && visited >= budget) return over = true;
        ++visited;
        if (progress) progress->fetch_add(1, std::memory_order_relaxed);
        return false;
    });
    if (mode_ == Mode::other)
        search.skip_solutions(
            [this](const Board& leaf) { return puzzle::only_intended(level_, *intended_, leaf); });
    std::vector<Decision> path;
    for (const auto& [cell, content] : pieces_.at(index))
        path.push_back(Decision{cell, static_cast<puzzle::Content>(content)});
    const puzzle::SubtreeResult found = search.search(path);
    LazorPieceResult out;
    out.end = found.complete ? LazorPieceResult::End::complete
              : over         ? LazorPieceResult::End::budget
                             : LazorPieceResult::End::stopped;
    out.nodes = found.nodes;
    if (mode_ == Mode::all) out.solutions = found.solutions.get_str();
    if (found.first) out.first = puzzle::board_text(*found.first);
    return out;
}

std::optional<LazorSearchOutcome>
LazorSearchPieces::outcome(const std::vector<std::optional<LazorPieceResult>>& results) const {
    // At the node budget, one thread would have visited exactly the budget:
    // the pieces before the one that ran out complete within it, and that
    // one leaves none. (Each piece is given the whole budget, so pieces
    // searched beside it may have visited more; they are not counted.)
    auto out_of_nodes = [&] {
        LazorSearchOutcome o;
        o.limit = "nodes";
        o.nodes = *max_nodes_;
        return o;
    };
    // A stop request has no one-thread count: the nodes visited are reported.
    auto stopped = [&] {
        LazorSearchOutcome o;
        o.limit = "stop";
        for (const std::optional<LazorPieceResult>& r : results)
            if (r) o.nodes += r->nodes;
        return o;
    };
    // A one-thread search visits the pieces in order: its node count at the
    // end of piece i is the nodes of pieces 0..i (and, for the generator's
    // search, the nodes above the split entered so far).
    std::uint64_t nodes = 0;
    Integer count = 0;
    LazorSearchOutcome o;
    o.status = LazorSearchOutcome::Status::none;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        if (i >= results.size() || !results[i]) return std::nullopt;
        const LazorPieceResult& r = *results[i];
        if (r.end == LazorPieceResult::End::budget) return out_of_nodes();
        if (r.end == LazorPieceResult::End::stopped) return stopped();
        nodes += r.nodes;
        o.nodes = nodes + (mode_ == Mode::other ? nodes_above_[i] : 0);
        if (max_nodes_ && o.nodes > *max_nodes_) return out_of_nodes();
        if (mode_ == Mode::all) count += Integer(r.solutions);
        if (r.first.empty() || !o.first.empty()) continue;
        o.first = r.first;
        o.status = LazorSearchOutcome::Status::found;
        if (mode_ != Mode::all) return o;
    }
    if (mode_ == Mode::all) o.solutions = count.get_str();
    return o;
}

std::string LazorSearchPieces::to_text() const {
    const std::string level = write_lazor_level(level_);
    std::string out = "lazor-search ";
    out += static_cast<char>(mode_);
    out += ' ' + (max_nodes_ ? std::to_string(*max_nodes_) : std::string("-")) + ' ' +
           std::to_string(level.size()) + '\n' + level;
    if (intended_) out += write_lazor_level(*intended_);
    return out;
}

LazorSearchPieces LazorSearchPieces::from_text(std::string_view text) {
    const std::size_t line_end = text.find('\n');
    std::istringstream header(std::string(text.substr(0, line_end)));
    std::string word, max_text;
    char mode = 0;
    std::size_t length = 0;
    if (line_end == std::string_view::npos || !(header >> word >> mode >> max_text >> length) ||
        word != "lazor-search" || line_end + 1 + length > text.size())
        throw std::invalid_argument("not the text of a Lazor search");
    std::optional<std::uint64_t> max_nodes;
    if (max_text != "-") max_nodes = std::stoull(max_text);
    LazorLevel level = read_lazor_level(text.substr(line_end + 1, length), "<search>");
    std::optional<LazorLevel> intended;
    if (mode == static_cast<char>(Mode::other))
        intended = read_lazor_level(text.substr(line_end + 1 + length), "<search>");
    return LazorSearchPieces(std::move(level), static_cast<Mode>(mode), max_nodes,
                             std::move(intended));
}

std::string lazor_piece_text(const LazorPieceResult& result) {
    const char end = result.end == LazorPieceResult::End::complete ? 'c'
                     : result.end == LazorPieceResult::End::budget ? 'b'
                                                                   : 's';
    return std::string(1, end) + ' ' + std::to_string(result.nodes) + ' ' + result.solutions + ' ' +
           (result.first.empty() ? "-" : result.first);
}

LazorPieceResult lazor_piece_from_text(std::string_view text) {
    std::istringstream in{std::string(text)};
    char end = 0;
    LazorPieceResult out;
    std::string first;
    if (!(in >> end >> out.nodes >> out.solutions >> first))
        throw std::invalid_argument("not the text of a Lazor piece result");
    out.end = end == 'c'   ? LazorPieceResult::End::complete
              : end == 'b' ? LazorPieceResult::End::budget
                           : LazorPieceResult::End::stopped;
    if (first != "-") out.first = std::move(first);
    return out;
}

std::vector<std::optional<LazorPieceResult>>
run_lazor_pieces(const LazorSearchPieces& pieces, unsigned jobs, const std::atomic<bool>* stop,
                 std::atomic<std::uint64_t>* progress) {
    const unsigned threads = jobs > 0 ? jobs : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::optional<LazorPieceResult>> results(pieces.size());
    std::mutex mutex;
    std::size_t next = 0;
    // Once the results decide the answer, the pieces still running are
    // after the deciding one: they stop, and no more start.
    std::atomic<bool> decided{false};
    const std::function<bool()> halt = [&] {
        return decided.load(std::memory_order_relaxed) ||
               (stop && stop->load(std::memory_order_relaxed));
    };
    auto worker = [&] {
        for (;;) {
            std::size_t index = 0;
            {
                const std::lock_guard<std::mutex> lock(mutex);
                if (decided || next >= pieces.size()) return;
                index = next++;
            }
            LazorPieceResult result = pieces.search(index, halt, progress);
            const std::lock_guard<std::mutex> lock(mutex);
            results[index] = std::move(result);
            if (pieces.outcome(results)) decided = true;
        }
    };
    std::vector<std::thread> others;
    for (unsigned t = 1; t < std::min<std::size_t>(threads, pieces.size()); ++t)
        others.emplace_back(worker);
    worker();
    for (std::thread& t : others) t.join();
    return results;
}

} // namespace orthoray
