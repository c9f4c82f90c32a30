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
#include <array>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace orthoray::induction {

using lattice::floor_mod;

// Every number the build forms is a lattice coordinate, a w, a state
// number or a sum of a few of them, at most 8 max(B, N) in size (B the
// scene's largest lattice value, N the number of states), and N is at most
// 4 times the number of lattice points on the mirrors (docs/induction.md,
// "Which integers, and why they are enough"). So the build runs on the narrowest of
// int64_t, __int128 and GMP integers whose limit (lattice_int.hpp: 2^59,
// 2^123) exceeds both B and that count.
ArithmeticUsed exchange_arithmetic(const lattice::LatticeScene& scene);
// What the build runs on: that, or the tables' integers Int if wider
// (SolveOptions::arithmetic forces wider ones, and the tests run every path
// so).
template <class Int>
ArithmeticUsed build_arithmetic(const lattice::LatticeScene& scene) {
    return std::max(exchange_arithmetic(scene), lattice::arithmetic_used(Int{}));
}

// A transversal (orthoray/exchange.hpp) on the build's integers.
template <class Num>
struct TransversalOn {
    int axis = 0;
    unsigned negative = 0;
    int w_slope = 1;
    Num offset, lo, hi, first, count, start;
};

template <class Num>
class ExchangeLayout {
public:
    // x: the state after reflection 1, a lattice point and its direction.
    // `poll` is called once a mirror, segment and transversal.
    ExchangeLayout(const lattice::LatticeScene& scene, const Num (&x)[2], unsigned x_negative,
                   const lattice::SetupPoll& poll = {});

    // The transversal and number of state (p, negative), if it is one.
    std::optional<std::pair<std::size_t, Num>> locate(const Num (&p)[2], unsigned negative) const;
    // The same, when p is likely on transversal `near`'s segment (the other
    // end of a piece's image): a point is on one segment at most (the
    // horizontal ones are cut at crossings), so if it is on that one, that
    // is the answer locate() gives, found without its two searches.
    std::optional<std::pair<std::size_t, Num>> locate(const Num (&p)[2], unsigned negative,
                                                      std::size_t near) const;
    // Raw coordinate of a located state.
    Num raw(const std::pair<std::size_t, Num>& at) const {
        return transversals_[at.first].start + at.second;
    }

    struct Owner {
        std::uint32_t element;
        Num from, to; // the positions of the transversal it owns
    };
    // Every transversal of a segment shares the segment's owners.
    const std::vector<Owner>& owners(std::size_t transversal) const {
        return owners_[segment_of_[transversal]];
    }

    const Num& modulus() const { return modulus_; }
    const std::vector<TransversalOn<Num>>& transversals() const { return transversals_; }
    // As orthoray/exchange.hpp gives them.
    std::vector<Transversal> public_transversals() const;
    const Num& size() const { return size_; }

private:
    struct Segment {
        int axis;
        Num offset, lo, hi;
    };
    std::vector<Segment> segments_; // sorted by (axis, offset, lo)
    // Per axis, the offsets of the lines with segments (ascending) and where
    // each line's segments begin in segments_, with one more entry for the
    // end: locate() searches these compact keys, not the segments.
    std::array<std::vector<Num>, 2> line_offsets_;
    std::array<std::vector<std::size_t>, 2> line_begins_;
    std::vector<std::vector<Owner>> owners_;  // per segment
    std::vector<std::size_t> transversal_of_; // segment * 4 + direction -> id or npos
    std::vector<std::size_t> segment_of_;     // per transversal
    std::vector<TransversalOn<Num>> transversals_;
    Num modulus_, w_first_, size_;
};

// Positions of the class in [from, to] on transversal t: the least and the
// greatest, or nothing.
template <class Num>
std::optional<std::pair<Num, Num>> class_range(const TransversalOn<Num>& t, const Num& modulus,
                                               const Num& from, const Num& to) {
    if (modulus == 0) {
        if (t.first < from || t.first > to) return std::nullopt;
        return std::make_pair(t.first, t.first);
    }
    Num lo = from + floor_mod(Num(t.first - from), modulus);
    if (lo > to) return std::nullopt;
    Num hi = lo + (to - lo) / modulus * modulus;
    return std::make_pair(std::move(lo), std::move(hi));
}
// Number of position u (in the class) on transversal t.
template <class Num>
Num number_of(const TransversalOn<Num>& t, const Num& modulus, const Num& u) {
    if (modulus == 0) return 0;
    Num j = (u - t.first) / modulus;
    return t.w_slope > 0 ? j : Num(t.count - 1 - j);
}

// Raw pieces (before marks, holes and rotation) from the tables.
template <class Num>
struct RawPieceOn {
    Num start, length, image;
    PieceKind kind = PieceKind::reflect;
    bool hit = false;
};
using RawPiece = RawPieceOn<Integer>;

// Splits piece i of `pieces` (sorted by start) at `offset` into
// [start, start + offset) and the rest.
template <class Num>
void split_piece(std::vector<RawPieceOn<Num>>& pieces, std::size_t i, const Num& offset) {
    RawPieceOn<Num> rest = pieces[i];
    rest.start += offset;
    rest.length -= offset;
    if (rest.kind == PieceKind::reflect) rest.image += offset;
    pieces[i].length = offset;
    pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(i) + 1, std::move(rest));
}

// Makes the state at raw coordinate c a piece of its own; returns its index.
template <class Num>
std::size_t isolate_state(std::vector<RawPieceOn<Num>>& pieces, const Num& c) {
    auto after =
        std::upper_bound(pieces.begin(), pieces.end(), c,
                         [](const Num& v, const RawPieceOn<Num>& p) { return v < p.start; });
    std::size_t i = static_cast<std::size_t>(after - pieces.begin()) - 1;
    if (pieces[i].start < c) {
        split_piece(pieces, i, Num(c - pieces[i].start));
        ++i;
    }
    if (pieces[i].length > 1) split_piece(pieces, i, Num(1));
    return i;
}

// An exchange on the build's integers: IntervalExchange's data with the
// pieces as the build made them (RawPieceOn, rotated so that x is 0 and
// sorted by start), for the induction to read without converting each
// number to GMP and back.
template <class Num>
struct ExchangeOn {
    Num size, modulus;
    std::vector<RawPieceOn<Num>> pieces;
    std::vector<Transversal> transversals;
    std::size_t first_transversal = 0;
    Num first_index = 0;
    Integer scale[2];
};
// The public exchange: every number converted once to GMP.
template <class Num>
IntervalExchange to_public(const ExchangeOn<Num>& exchange);

// Steps 3-5 on raw pieces that tile [0, N): split out x and the hit states,
// close the holes, rotate.
// `size` states, classes modulo `modulus`; the transversals go into the
// result as they are. `poll` is called once a piece.
template <class Num>
ExchangeOn<Num>
finish_exchange_on(const Num& size, const Num& modulus, std::vector<Transversal> transversals,
                   std::vector<RawPieceOn<Num>> pieces, const Num& raw_first,
                   const std::vector<Num>& raw_hits, const lattice::SetupPoll& poll = {});
template <class Num>
IntervalExchange
finish_exchange(const Num& size, const Num& modulus, std::vector<Transversal> transversals,
                std::vector<RawPieceOn<Num>> pieces, const Num& raw_first,
                const std::vector<Num>& raw_hits, const lattice::SetupPoll& poll = {}) {
    return to_public(finish_exchange_on(size, modulus, std::move(transversals), std::move(pieces),
                                        raw_first, raw_hits, poll));
}

// The exchange on integers Num (any of the three, whatever the tables' Int).
// The transversals, in GMP integers (six a transversal), only `with_transversals`:
// the induction does not read them, only the public exchange does.
template <class Num, class Int>
ExchangeOn<Num> build_exchange_on(const lattice::LatticeScene& scene,
                                  const shoot::UniformGrid<Int, 2>& grid,
                                  const shoot::PieceTable<Int>& table, const Integer (&x_in)[2],
                                  unsigned x_negative, const lattice::SetupPoll& poll,
                                  bool with_transversals = true) {
    using lattice::convert;
    Num x[2];
    for (int j = 0; j < 2; ++j) x[j] = convert<Num>(x_in[j]);
    ExchangeLayout<Num> layout(scene, x, x_negative, poll);
    const Num& g = layout.modulus();
    std::vector<RawPieceOn<Num>> raw;
    using TablePiece = typename shoot::PieceTable<Int>::Piece;

    // q: where the state at position u of transversal t arrives, following `piece`.
    auto image_point = [&](const TransversalOn<Num>& t, const Num& u, const TablePiece& piece,
                           Num(&q)[2]) {
        const Num from = convert<Num>(piece.from);
        const Num at = convert<Num>(piece.t0) + Num(piece.slope()) * (u - from);
        q[t.axis] = t.offset;
        q[1 - t.axis] = u;
        for (int j = 0; j < 2; ++j) {
            if ((t.negative >> j) & 1u)
                q[j] -= at;
            else
                q[j] += at;
        }
    };
    // Its transversal and number; the other end of the same piece is
    // likely on the first end's transversal, `near`.
    auto image_of = [&](const TransversalOn<Num>& t, const Num& u, const TablePiece& piece,
                        std::optional<std::size_t> near) {
        Num q[2];
        image_point(t, u, piece, q);
        const unsigned negative = t.negative ^ piece.flip;
        auto located = near ? layout.locate(q, negative, *near) : layout.locate(q, negative);
        if (!located) throw std::logic_error("a piece's image is not a state of any transversal");
        return *located;
    };

    using Kind = typename shoot::PieceTable<Int>::Kind;
    // The states of transversal t at positions first .. last (in the
    // class) all follow `piece`: one raw piece.
    auto add = [&](const TransversalOn<Num>& t, const Num& first, const Num& last,
                   const TablePiece& table_piece) {
        poll();
        const Num a = number_of(t, g, first);
        const Num b = number_of(t, g, last);
        RawPieceOn<Num> piece;
        piece.start = t.start + (a < b ? a : b);
        piece.length = (a < b ? Num(b - a) : Num(a - b)) + 1;
        switch (table_piece.kind()) {
        case Kind::escape:
            piece.kind = PieceKind::escape;
            break;
        case Kind::absorb:
            piece.kind = PieceKind::absorbed;
            break;
        case Kind::reflect: {
            const auto ia = image_of(t, first, table_piece, std::nullopt);
            const auto ib = a == b ? ia : image_of(t, last, table_piece, ia.first);
            // A translation: same transversal, numbers in the same order.
            if (ia.first != ib.first || ib.second - ia.second != b - a)
                throw std::logic_error("a piece of the tables is not a translation in w");
            piece.image = layout.raw(ia.second < ib.second ? ia : ib);
            break;
        }
        }
        raw.push_back(std::move(piece));
    };

    // One raw piece a table piece, mostly (a run of corners gives more):
    // reserved once, the vector is not copied as it grows, nor its fresh
    // pages touched twice.
    std::size_t table_pieces = 0;
    for (std::size_t id = 0; id < layout.transversals().size(); ++id)
        for (const auto& owner : layout.owners(id))
            table_pieces += table.pieces(owner.element, layout.transversals()[id].negative).size();
    raw.reserve(table_pieces);
    for (std::size_t id = 0; id < layout.transversals().size(); ++id) {
        const TransversalOn<Num>& t = layout.transversals()[id];
        for (const auto& owner : layout.owners(id)) {
            const auto pieces = table.pieces(owner.element, t.negative);
            for (std::size_t i = 0; i < pieces.size(); ++i) {
                poll();
                Num lo = convert<Num>(pieces[i].from);
                Num hi = i + 1 < pieces.size() ? Num(convert<Num>(pieces[i + 1].from) - 1) : t.hi;
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
                    for (Num u = range->first; u <= range->second; u += g) add(t, u, u, pieces[i]);
                } else {
                    add(t, range->first, range->second, pieces[i]);
                }
            }
        }
    }

    // The states whose segment passes the target: shoot back from it. (The
    // states at the target itself never matter, since the ray passes it on
    // arriving there, but the marks are exact.)
    std::vector<Num> hits;
    if (scene.target_reachable) {
        Int p[2];
        for (int j = 0; j < 2; ++j) p[j] = lattice::from_integer<Int>(scene.target[j]);
        Num target[2];
        for (int j = 0; j < 2; ++j) target[j] = convert<Num>(scene.target[j]);
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            // A segment also passes its own first point: states on the target.
            if (const auto at = layout.locate(target, d)) hits.push_back(layout.raw(*at));
            const shoot::Shot<Int> back = grid.shoot(p, d ^ 3u);
            if (back.escape || back.flip == 0) continue;
            const Num t = convert<Num>(back.t);
            Num q[2];
            for (int j = 0; j < 2; ++j)
                q[j] = ((d >> j) & 1u) ? Num(target[j] + t) : Num(target[j] - t);
            if (const auto at = layout.locate(q, d)) hits.push_back(layout.raw(*at));
        }
    }
    const auto first = layout.locate(x, x_negative);
    if (!first) throw std::logic_error("the first reflection state is on no transversal");
    ExchangeOn<Num> exchange = finish_exchange_on(layout.size(), layout.modulus(),
                                                  with_transversals ? layout.public_transversals()
                                                                    : std::vector<Transversal>{},
                                                  std::move(raw), layout.raw(*first), hits, poll);
    exchange.first_transversal = first->first;
    exchange.first_index = first->second;
    for (int j = 0; j < 2; ++j) exchange.scale[j] = scene.scale[j];
    return exchange;
}

// On build_arithmetic's integers. `poll` is called once a piece (it may
// throw lattice::SetupStopped).
template <class Int>
IntervalExchange build_exchange(const lattice::LatticeScene& scene,
                                const shoot::UniformGrid<Int, 2>& grid,
                                const shoot::PieceTable<Int>& table, const Integer (&x)[2],
                                unsigned x_negative, const lattice::SetupPoll& poll = {}) {
    switch (build_arithmetic<Int>(scene)) {
    case ArithmeticUsed::int64:
        return to_public(build_exchange_on<std::int64_t>(scene, grid, table, x, x_negative, poll));
    case ArithmeticUsed::int128:
        return to_public(
            build_exchange_on<lattice::int128_t>(scene, grid, table, x, x_negative, poll));
    default:
        return to_public(build_exchange_on<Integer>(scene, grid, table, x, x_negative, poll));
    }
}

// The state after the ray's first reflection; nothing when the first shot
// escapes or is absorbed.
struct FirstState {
    Integer x[2];
    unsigned negative = 0;
};
template <class Int>
std::optional<FirstState> first_state(const lattice::LatticeScene& scene,
                                      const shoot::UniformGrid<Int, 2>& grid) {
    Int start[2];
    for (int j = 0; j < 2; ++j) start[j] = lattice::from_integer<Int>(scene.start[j]);
    const shoot::Shot<Int> first = grid.shoot(start, scene.start_direction);
    if (first.escape || first.absorber || first.flip == 0) return std::nullopt;
    FirstState state;
    for (int j = 0; j < 2; ++j)
        state.x[j] = scene.start[j] + (((scene.start_direction >> j) & 1u)
                                           ? Integer(-lattice::to_integer(first.t))
                                           : lattice::to_integer(first.t));
    state.negative = scene.start_direction ^ first.flip;
    return state;
}

// The exchange of the ray from the scene's start, x being the state after
// its first reflection; nothing when the first shot escapes or is absorbed.
template <class Int>
std::optional<IntervalExchange> build_exchange_from_start(const lattice::LatticeScene& scene,
                                                          const shoot::UniformGrid<Int, 2>& grid,
                                                          const shoot::PieceTable<Int>& table,
                                                          const lattice::SetupPoll& poll = {}) {
    const std::optional<FirstState> first = first_state(scene, grid);
    if (!first) return std::nullopt;
    return build_exchange(scene, grid, table, first->x, first->negative, poll);
}

} // namespace orthoray::induction
