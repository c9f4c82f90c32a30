// The octagonal exchange's builder (octagonal_exchange.hpp): the scene's
// lines cut at every vertex into transversals (slots), and the step of a
// state. octagonal_builder.cpp holds that geometry; octagonal_layout.cpp
// assembles the pieces, collisions and hits into an OctagonalLayout.
#pragma once

#include "induction/octagonal_exchange.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <type_traits>
#include <utility>
#include <vector>

namespace orthoray::induction::octagonal::detail {

using lattice::floor_mod;
using lattice::int128_t;
using lattice::to_integer;

constexpr std::size_t npos = ~std::size_t{0};

// Where a transversal lies: an open edge (a line and the interval between
// its cuts `interval` and `interval + 1`) or a vertex.
struct Slot {
    bool vertex = false;
    std::size_t line = 0, interval = 0; // for an edge; `line` is the vertex for a vertex
    int sheet = 0;
    Integer first, count, start; // least w of the class in it, how many, raw number of the first
    Integer w_at_cut, kappa;     // an edge's w at its first cut, and dw / d(position)
};

template <class Int>
class Builder {
public:
    Builder(const OctagonalScene<Int>& scene, const Point<Int>& x, int x_sheet)
        : s_(scene), w_x_(to_integer(scene.w(x, x_sheet))) {}

    std::optional<OctagonalLayout> build(const Point<Int>& x, int x_sheet, std::size_t max_pieces,
                                         BuildFailure& failure);
    std::optional<OctagonalLayout> build_all(const Point<Int>& x, int x_sheet,
                                             std::size_t max_pieces, BuildFailure& failure);
    void dump(std::ostream& out) const;
    void set_stop(const std::function<bool()>& stop) { stop_ = stop; }
    std::vector<RawPiece>& pieces() { return pieces_; }

private:
    struct Line {
        Orientation orientation;
        Int c;
        std::vector<Int> cuts;
        std::vector<std::uint8_t> mirror_only; // per interval between cuts
        std::vector<std::size_t> slot;         // interval * 8 + sheet -> slot or npos
    };

    // Thrown by poll() when stop_ says so; build() turns it into a failure.
    // On 128-bit integers a unit of work takes well under a microsecond, so
    // stop_ is asked every 4,096 units; on GMP integers a unit can take
    // milliseconds (numbers of 10^5 digits and more), so it is asked at
    // every unit, which the monitor's own clock keeps cheap.
    struct Stopped {};
    void poll() {
        constexpr unsigned mask = std::is_same_v<Int, Integer> ? 0u : 0xfffu;
        if (stop_ && (++polls_ & mask) == 0 && stop_()) throw Stopped{};
    }

    bool in_class(const Integer& w) const {
        return modulus_ == 0 ? w == w_x_ : floor_mod(w - w_x_, modulus_) == 0;
    }
    void find_vertices();
    void cut_lines();
    void make_slots();
    std::optional<std::size_t> line_of(Orientation o, const Int& c) const;
    std::optional<std::size_t> vertex_of(const Point<Int>& p) const;
    // The slot and w of lifted state (q, g), if it is a state of the class.
    std::optional<std::pair<std::size_t, Integer>> locate(const Point<Int>& q, int g) const;
    Integer raw(std::size_t slot, const Integer& w) const {
        const Slot& t = slots_[slot];
        return modulus_ == 0 ? t.start : Integer(t.start + (w - t.first) / modulus_);
    }
    Point<Int> point_of(const Slot& t, const Integer& w) const;
    // The other lift of (q, g), when two sheets share g's direction (a
    // double cover) and it is a state of the class; by raw number too.
    std::optional<std::pair<std::size_t, Integer>> twin_at(const Point<Int>& q, int g) const;
    std::optional<Integer> twin_of(const Integer& raw_state) const;
    // Where the state (slot, w) steps to.
    struct Step {
        PieceKind kind = PieceKind::reflect;
        std::size_t slot = 0;
        Integer w;
    };
    Step step(std::size_t slot, const Integer& w) const;
    void add_run(std::size_t slot, const Integer& first, const Integer& last);

    const OctagonalScene<Int>& s_;
    Integer w_x_, modulus_, size_;
    std::vector<Point<Int>> vertices_; // sorted
    std::vector<Line> lines_;          // sorted by (orientation, c)
    std::vector<Slot> slots_;
    std::vector<std::size_t> vertex_slot_; // vertex * 8 + sheet -> slot or npos
    std::vector<RawPiece> pieces_;
    std::function<bool()> stop_;
    std::uint64_t polls_ = 0;
};

} // namespace orthoray::induction::octagonal::detail
