// The placement search of a Lazor level cut into independent pieces
// (docs/puzzles.md, "The search, in pieces"): the top of the search tree is
// split, the same way on every machine, into subtrees in search order; each
// piece is searched on its own (by a thread, or by another process that got
// the search as text), and merging the pieces' results in order gives the
// answer a one-thread search gives: the same first solution, the same
// count, the same nodes, the same limit. Nothing here knows about MPI: the
// command line's MPI glue only ships the texts below between ranks.
#pragma once

#include "orthoray/puzzle.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace orthoray {

// What the search of one piece found.
struct LazorPieceResult {
    // complete: searched to its end (or, unless counting, to its first
    // solution); budget: it needed more nodes than it was given; stopped:
    // the stop function said so.
    enum class End : std::uint8_t { complete, budget, stopped };
    End end = End::stopped;
    std::uint64_t nodes = 0;     // search nodes visited in the piece
    std::string solutions = "0"; // when counting: the placements found in it
    std::string first;           // its first solution leaf, encoded; empty for none
};

// The merged answer of a search's pieces.
struct LazorSearchOutcome {
    enum class Status { found, none, limit };
    Status status = Status::limit;
    std::string first;       // found: the first solution leaf, encoded
    std::string solutions;   // when counting and not limit: the total
    std::uint64_t nodes = 0; // a one-thread search's nodes (limit: all visited)
    std::string limit;       // limit: "nodes" or "stop"
};

class LazorSearchPieces {
public:
    // The search of solve_lazor(): its first solution, or with `all` the
    // count of every one. `max_nodes` bounds the nodes of the pieces, in
    // order, as one thread would visit them.
    LazorSearchPieces(LazorLevel level, bool all, std::optional<std::uint64_t> max_nodes);
    // The generator's search for a solution other than `intended` (the level
    // with its blocks placed), within `max_nodes` nodes counted from the
    // root, as the generator's one-pass search counts them.
    static LazorSearchPieces other_than(LazorLevel level, LazorLevel intended,
                                        std::uint64_t max_nodes);

    std::size_t size() const { return pieces_.size(); }
    const LazorLevel& level() const { return level_; }

    // Searches piece `index` (thread-safe: each call has its own search
    // state). `stop` is asked at every node; `progress`, when set, gets 1
    // (relaxed) a node.
    LazorPieceResult search(std::size_t index, const std::function<bool()>& stop = {},
                            std::atomic<std::uint64_t>* progress = nullptr) const;

    // The answer once the results known so far (results[i] for piece i)
    // decide it; nothing while a piece it depends on is missing. Pieces
    // after the deciding one are not looked at.
    std::optional<LazorSearchOutcome>
    outcome(const std::vector<std::optional<LazorPieceResult>>& results) const;

    // The search as text, for another process; from_text() gives it back.
    std::string to_text() const;
    static LazorSearchPieces from_text(std::string_view text);

private:
    enum class Mode : char { first = 'f', all = 'a', other = 'o' };
    LazorSearchPieces(LazorLevel level, Mode mode, std::optional<std::uint64_t> max_nodes,
                      std::optional<LazorLevel> intended);

    LazorLevel level_;
    Mode mode_;
    std::optional<std::uint64_t> max_nodes_;
    std::optional<LazorLevel> intended_;
    // Each piece's decisions from the root, as (cell, content) pairs, and
    // the search nodes above the split that a one-pass search enters up to
    // and including the piece's root's parent.
    std::vector<std::vector<std::pair<int, int>>> pieces_;
    std::vector<std::uint64_t> nodes_above_;
};

// A piece result as one line of text and back, for another process.
std::string lazor_piece_text(const LazorPieceResult& result);
LazorPieceResult lazor_piece_from_text(std::string_view text);

// Runs the pieces a search needs (in order, those after the deciding one
// are stopped or never started) and returns their results, results[i] for
// piece i. The default runner uses threads; the command line gives one that
// spreads the pieces over MPI ranks.
using LazorPieceRunner =
    std::function<std::vector<std::optional<LazorPieceResult>>(const LazorSearchPieces&)>;

// The pieces on `jobs` threads (0: one per core), which take them in order.
std::vector<std::optional<LazorPieceResult>>
run_lazor_pieces(const LazorSearchPieces& pieces, unsigned jobs,
                 const std::atomic<bool>* stop = nullptr,
                 std::atomic<std::uint64_t>* progress = nullptr);

} // namespace orthoray
