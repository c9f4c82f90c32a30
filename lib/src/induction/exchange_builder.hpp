// From a 2D lattice scene and its piece tables to the integer interval
// exchange of interval_exchange.hpp (docs/induction.md, "Building").
//
// 1. Transversals. The mirrors of each line are merged into maximal
//    segments; a horizontal segment is cut at every point where a vertical
//    mirror crosses it, so that each state belongs to exactly one
//    transversal (a crossing point's states are on the vertical one: a ray
//    arriving there meets the vertical mirror, whatever else it meets).
// 2. Pieces. Each transversal position is owned by the first mirror of its
//    segment that contains it, and each of that mirror's table pieces,
//    restricted to the orbit's class, becomes a translation of consecutive
//    state numbers (checked at both ends: a piece that is not one would be
//    a bug in the tables, and throws).
// 3. Marks. x (the state after reflection 1) and the at most four states
//    whose segment passes the target become pieces of their own.
// 4. Holes. Pieces that escape or are absorbed have no image, and as many
//    states have no preimage; the former are mapped onto the latter in
//    order, so the exchange is a bijection (the orbit of x never uses those
//    images before its first event).
// 5. Rotation, so that x is 0.
#pragma once

#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "orthoray/exchange.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace orthoray::induction {

using lattice::floor_mod;

class ExchangeLayout {
public:
    // x: the state after reflection 1, a lattice point and its direction.
    // `poll` is called once a mirror, segment and transversal.
    ExchangeLayout(const lattice::LatticeScene& scene, const Integer (&x)[2], unsigned x_negative,
                   const lattice::SetupPoll& poll = {});

    // The transversal and number of state (p, negative), if it is one.
    std::optional<std::pair<std::size_t, Integer>> locate(const Integer (&p)[2],
                                                          unsigned negative) const;
    // Raw coordinate of a located state.
    Integer raw(const std::pair<std::size_t, Integer>& at) const {
        return transversals_[at.first].start + at.second;
    }

    struct Owner {
        std::uint32_t element;
        Integer from, to; // the positions of the transversal it owns
    };
    // Every transversal of a segment shares the segment's owners.
    const std::vector<Owner>& owners(std::size_t transversal) const {
        return owners_[segment_of_[transversal]];
    }

    const Integer& modulus() const { return modulus_; }
    std::vector<Transversal>& transversals() { return transversals_; }
    const std::vector<Transversal>& transversals() const { return transversals_; }
    const Integer& size() const { return size_; }

private:
    struct Segment {
        int axis;
        Integer offset, lo, hi;
    };
    std::vector<Segment> segments_;           // sorted by (axis, offset, lo)
    std::vector<std::vector<Owner>> owners_;  // per segment
    std::vector<std::size_t> transversal_of_; // segment * 4 + direction -> id or npos
    std::vector<std::size_t> segment_of_;     // per transversal
    std::vector<Transversal> transversals_;
    Integer modulus_, w_first_, size_;
};

// Positions of the class in [from, to] on transversal t: the least and the
// greatest, or nothing.
std::optional<std::pair<Integer, Integer>> class_range(const Transversal& t, const Integer& modulus,
                                                       const Integer& from, const Integer& to);
// Number of position u (in the class) on transversal t.
Integer number_of(const Transversal& t, const Integer& modulus, const Integer& u);

// Raw pieces (before marks, holes and rotation) from the tables.
struct RawPiece {
    Integer start, length, image;
    PieceKind kind = PieceKind::reflect;
    bool hit = false;
};

// Steps 3-5 on raw pieces that tile [0, N): split out x and the hit states,
// close the holes, rotate.
// `size` states, classes modulo `modulus`; the transversals go into the
// result as they are. `poll` is called once a piece.
IntervalExchange finish_exchange(const Integer& size, const Integer& modulus,
                                 std::vector<Transversal> transversals,
                                 std::vector<RawPiece> pieces, const Integer& raw_first,
                                 const std::vector<Integer>& raw_hits,
                                 const lattice::SetupPoll& poll = {});

// `poll` is called once a piece (it may throw lattice::SetupStopped).
template <class Int>
IntervalExchange build_exchange(const lattice::LatticeScene& scene,
                                const shoot::UniformGrid<Int, 2>& grid,
                                const shoot::PieceTable<Int>& table, const Integer (&x)[2],
                                unsigned x_negative, const lattice::SetupPoll& poll = {}) {
    using lattice::to_integer;
    ExchangeLayout layout(scene, x, x_negative, poll);
    const Integer& g = layout.modulus();
    std::vector<RawPiece> raw;

    auto image_of = [&](const Transversal& t, const Integer& u,
                        const typename shoot::PieceTable<Int>::Piece& piece) {
        const Integer from = to_integer(piece.from);
        const Integer at = to_integer(piece.t0) + piece.slope() * (u - from);
        Integer q[2];
        q[t.axis] = t.offset;
        q[1 - t.axis] = u;
        for (int j = 0; j < 2; ++j) q[j] += ((t.negative >> j) & 1u) ? Integer(-at) : at;
        auto located = layout.locate(q, t.negative ^ piece.flip);
        if (!located) throw std::logic_error("a piece's image is not a state of any transversal");
        return *located;
    };

    using Kind = typename shoot::PieceTable<Int>::Kind;
    // The states of transversal t at positions first .. last (in the
    // class) all follow `piece`: one raw piece.
    auto add = [&](const Transversal& t, const Integer& first, const Integer& last,
                   const typename shoot::PieceTable<Int>::Piece& table_piece) {
        poll();
        const Integer a = number_of(t, g, first);
        const Integer b = number_of(t, g, last);
        RawPiece piece;
        piece.start = t.start + std::min(a, b);
        piece.length = abs(b - a) + 1;
        switch (table_piece.kind()) {
        case Kind::escape:
            piece.kind = PieceKind::escape;
            break;
        case Kind::absorb:
            piece.kind = PieceKind::absorbed;
            break;
        case Kind::reflect: {
            const auto ia = image_of(t, first, table_piece);
            const auto ib = image_of(t, last, table_piece);
            // A translation: same transversal, numbers in the same order.
            if (ia.first != ib.first || ib.second - ia.second != b - a)
                throw std::logic_error("a piece of the tables is not a translation in w");
            piece.image = layout.raw(ia.second < ib.second ? ia : ib);
            break;
        }
        }
        raw.push_back(std::move(piece));
    };

    for (std::size_t id = 0; id < layout.transversals().size(); ++id) {
        const Transversal& t = layout.transversals()[id];
        for (const auto& owner : layout.owners(id)) {
            const auto pieces = table.pieces(owner.element, t.negative);
            for (std::size_t i = 0; i < pieces.size(); ++i) {
                poll();
                Integer lo = to_integer(pieces[i].from);
                Integer hi = i + 1 < pieces.size() ? Integer(to_integer(pieces[i + 1].from) - 1)
                                                   : Integer(t.hi);
                if (lo < owner.from) lo = owner.from;
                if (hi > owner.to) hi = owner.to;
                if (lo > hi) continue;
                const auto range = class_range(t, g, lo, hi);
                if (!range) continue;
                // A corner negates w, so a run of corners (mirrors crossing
                // a line at consecutive lattice points) is no translation:
                // each of its states, one per crossing, is a piece of its own.
                if (pieces[i].kind() == Kind::reflect && pieces[i].flip == 3u &&
                    range->first != range->second) {
                    for (Integer u = range->first; u <= range->second; u += g)
                        add(t, u, u, pieces[i]);
                } else {
                    add(t, range->first, range->second, pieces[i]);
                }
            }
        }
    }

    // The states whose segment passes the target: shoot back from it. (The
    // states at the target itself never matter, since the ray passes it on
    // arriving there, but the marks are exact.)
    std::vector<Integer> hits;
    if (scene.target_reachable) {
        Int p[2];
        for (int j = 0; j < 2; ++j) p[j] = lattice::from_integer<Int>(scene.target[j]);
        const Integer target[2] = {scene.target[0], scene.target[1]};
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            // A segment also passes its own first point: states on the target.
            if (const auto at = layout.locate(target, d)) hits.push_back(layout.raw(*at));
            const shoot::Shot<Int> back = grid.shoot(p, d ^ 3u);
            if (back.escape || back.flip == 0) continue;
            Integer q[2];
            for (int j = 0; j < 2; ++j)
                q[j] = scene.target[j] +
                       (((d >> j) & 1u) ? to_integer(back.t) : Integer(-to_integer(back.t)));
            if (const auto at = layout.locate(q, d)) hits.push_back(layout.raw(*at));
        }
    }
    const auto first = layout.locate(x, x_negative);
    if (!first) throw std::logic_error("the first reflection state is on no transversal");
    // raw() reads the transversals, so it must run before they are moved
    // into the exchange: argument order is unspecified (clang goes left to
    // right, and the fuzz build read an emptied vector).
    const Integer raw_first = layout.raw(*first);
    IntervalExchange exchange =
        finish_exchange(layout.size(), layout.modulus(), std::move(layout.transversals()),
                        std::move(raw), raw_first, hits, poll);
    exchange.first_transversal = first->first;
    exchange.first_index = first->second;
    for (int j = 0; j < 2; ++j) exchange.scale[j] = scene.scale[j];
    return exchange;
}

// The exchange of the ray from the scene's start, x being the state after
// its first reflection; nothing when the first shot escapes or is absorbed.
template <class Int>
std::optional<IntervalExchange> build_exchange_from_start(const lattice::LatticeScene& scene,
                                                          const shoot::UniformGrid<Int, 2>& grid,
                                                          const shoot::PieceTable<Int>& table,
                                                          const lattice::SetupPoll& poll = {}) {
    Int start[2];
    for (int j = 0; j < 2; ++j) start[j] = lattice::from_integer<Int>(scene.start[j]);
    const shoot::Shot<Int> first = grid.shoot(start, scene.start_direction);
    if (first.escape || first.absorber || first.flip == 0) return std::nullopt;
    Integer x[2];
    for (int j = 0; j < 2; ++j)
        x[j] = scene.start[j] + (((scene.start_direction >> j) & 1u)
                                     ? Integer(-lattice::to_integer(first.t))
                                     : lattice::to_integer(first.t));
    return build_exchange(scene, grid, table, x, scene.start_direction ^ first.flip, poll);
}

} // namespace orthoray::induction
