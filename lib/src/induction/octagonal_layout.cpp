// Assembling the octagonal exchange: breakpoints from shots back from every
// vertex, pieces between them, collisions, and the layout the induction and
// the certificates read (octagonal_exchange.hpp).
#include "induction/octagonal_builder.hpp"

#include "induction/collisions.hpp"

#include <algorithm>
#include <stdexcept>

namespace orthoray::induction::octagonal {
namespace detail {

template <class Int>
std::optional<OctagonalLayout> Builder<Int>::build(const Point<Int>& x, int x_sheet,
                                                   std::size_t max_pieces, BuildFailure& failure) {
    try {
        return build_all(x, x_sheet, max_pieces, failure);
    } catch (const Stopped&) {
        failure = BuildFailure::stopped;
        return std::nullopt;
    }
}

template <class Int>
std::optional<OctagonalLayout> Builder<Int>::build_all(const Point<Int>& x, int x_sheet,
                                                       std::size_t max_pieces,
                                                       BuildFailure& failure) {
    failure = BuildFailure::none;
    find_vertices();
    cut_lines();
    make_slots();

    // Breakpoints: shooting back from every vertex along every sheet finds
    // the edge whose rays along that sheet pass the vertex, at w(vertex).
    std::vector<std::pair<std::size_t, Integer>> breaks;
    for (const Point<Int>& v : vertices_)
        for (int g = 0; g < 8; ++g) {
            poll();
            const Shot<Int> back = s_.shoot(v, g, true);
            if (!back.found) continue;
            const Segment<Int>& seg = s_.segments[back.segment];
            const Line& line = lines_[*line_of(seg.orientation, seg.c)];
            const Point<Int>& d = s_.direction[static_cast<std::size_t>(g)];
            const Int along = seg.orientation == Orientation::vertical ? d[1] : d[0];
            // The position hit, times back.den.
            const Int scaled = Int(position(seg.orientation, v) * back.den - back.num * along);
            const auto after = std::upper_bound(
                line.cuts.begin(), line.cuts.end(), scaled,
                [&](const Int& value, const Int& cut) { return value < Int(cut * back.den); });
            if (after == line.cuts.begin() || after == line.cuts.end()) continue;
            const std::size_t i = static_cast<std::size_t>(after - line.cuts.begin()) - 1;
            if (Int(line.cuts[i] * back.den) == scaled) continue; // a vertex: a slot of its own
            const std::size_t slot = line.slot[i * 8 + static_cast<std::size_t>(g)];
            if (slot != npos) breaks.emplace_back(slot, to_integer(s_.w(v, g)));
        }
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

    std::size_t next_break = 0;
    for (std::size_t id = 0; id < slots_.size(); ++id) {
        poll();
        const Slot& t = slots_[id];
        const Integer last_state =
            modulus_ == 0 ? t.first : Integer(t.first + (t.count - 1) * modulus_);
        Integer from = t.first; // first state not yet in a piece
        for (; next_break < breaks.size() && breaks[next_break].first == id; ++next_break) {
            const Integer& b = breaks[next_break].second;
            if (b < from || b > last_state) continue;
            // The states before b, then b itself if it is one.
            const Integer before =
                modulus_ == 0 ? Integer(b - 1) : Integer(b - 1 - floor_mod(b - 1 - w_x_, modulus_));
            if (from <= before) add_run(id, from, before);
            if (in_class(b)) {
                add_run(id, b, b);
                from = modulus_ == 0 ? Integer(b + 1) : Integer(b + modulus_);
            } else {
                from = modulus_ == 0 ? Integer(b + 1) : Integer(before + modulus_);
            }
        }
        if (from <= last_state) add_run(id, from, last_state);
        if (pieces_.size() > max_pieces) {
            failure = BuildFailure::too_large;
            return std::nullopt;
        }
    }

    // Where two images overlap, two states step to one (collisions.hpp).
    std::optional<std::vector<Collision>> collisions = find_collisions(pieces_);
    if (!collisions) {
        failure = BuildFailure::not_injective;
        return std::nullopt;
    }

    OctagonalLayout layout;
    for (const Collision& c : *collisions)
        for (const Integer& r : {c.state, c.join})
            if (auto twin = twin_of(r)) layout.twins.emplace_back(r, *twin);
    std::sort(layout.twins.begin(), layout.twins.end());
    layout.twins.erase(std::unique(layout.twins.begin(), layout.twins.end()), layout.twins.end());
    layout.collisions = std::move(*collisions);
    layout.size = size_;
    layout.modulus = modulus_;
    const auto first = locate(x, x_sheet);
    if (!first) throw std::logic_error("the first reflection state is on no transversal");
    layout.first = raw(first->first, first->second);
    layout.first_slot = first->first;
    layout.first_index = raw(first->first, first->second) - slots_[first->first].start;
    // The twin: x's other lift, when two sheets share its direction.
    if (const auto twin = twin_at(x, x_sheet)) {
        layout.twin = raw(twin->first, twin->second);
        layout.twin_slot = twin->first;
        layout.twin_index = *layout.twin - slots_[twin->first].start;
    }
    // Each slot's states as lattice points: point_of is affine in w, and
    // the states of a slot are w = first + i * G.
    layout.transversals.reserve(slots_.size());
    for (const Slot& t : slots_) {
        const Point<Int> q0 = point_of(t, t.first);
        const Point<Int>& d = s_.direction[static_cast<std::size_t>(t.sheet)];
        LiftedTransversal lifted{to_integer(q0[0]), to_integer(q0[1]), 0, 0, t.count,
                                 to_integer(d[0]),  to_integer(d[1])};
        if (t.count > 1) {
            const Point<Int> q1 = point_of(t, t.first + modulus_);
            lifted.step_x = to_integer(q1[0]) - lifted.x0;
            lifted.step_y = to_integer(q1[1]) - lifted.y0;
        }
        layout.transversals.push_back(std::move(lifted));
    }
    // The states whose segment passes the target: those at it, and for each
    // sheet the one a shot back from the target finds.
    for (int g = 0; g < 8; ++g) {
        if (!in_class(to_integer(s_.w(s_.target, g)))) continue;
        if (const auto at = locate(s_.target, g)) layout.hits.push_back(raw(at->first, at->second));
        const Shot<Int> back = s_.shoot(s_.target, g, true);
        if (!back.found) continue;
        if (const auto at = locate(s_.advance(s_.target, g, back, true), g))
            layout.hits.push_back(raw(at->first, at->second));
    }
    std::sort(layout.hits.begin(), layout.hits.end());
    layout.hits.erase(std::unique(layout.hits.begin(), layout.hits.end()), layout.hits.end());
    layout.pieces = std::move(pieces_);
    return layout;
}

template <class Int>
void Builder<Int>::dump(std::ostream& out) const {
    static const char* const line_name[] = {"x =", "y =", "y - x =", "y + x ="};
    out << "# octagonal first-return map on the cover: " << pieces_.size() << " pieces on "
        << slots_.size() << " transversals, " << size_ << " states\n"
        << "# coordinates are scene ones times " << s_.scale << "; v = (" << to_integer(s_.a)
        << ", " << to_integer(s_.b) << "); a state's w = cross(v, g^-1 q) is "
        << (modulus_ == 0 ? w_x_ : floor_mod(w_x_, modulus_)) << " modulo " << modulus_ << "\n"
        << "# transversal T: its states in order of increasing w, raw numbers START on\n";
    for (std::size_t id = 0; id < slots_.size(); ++id) {
        const Slot& t = slots_[id];
        const Point<Int>& d = s_.direction[static_cast<std::size_t>(t.sheet)];
        out << "transversal " << id << ": ";
        if (t.vertex) {
            const Point<Int>& v = vertices_[t.line];
            out << "vertex (" << to_integer(v[0]) << ", " << to_integer(v[1]) << ")";
        } else {
            const Line& line = lines_[t.line];
            out << "edge " << line_name[static_cast<int>(line.orientation)] << ' '
                << to_integer(line.c) << ", "
                << (line.orientation == Orientation::vertical ? "y" : "x") << " in ("
                << to_integer(line.cuts[t.interval]) << ", "
                << to_integer(line.cuts[t.interval + 1]) << ")";
        }
        out << ", sheet " << t.sheet << " leaving along (" << to_integer(d[0]) << ", "
            << to_integer(d[1]) << "), w from " << t.first << ", " << t.count << " states, raw "
            << t.start << "\n";
    }
    for (const RawPiece& p : pieces_) {
        out << "piece " << p.start << " +" << p.length << ": ";
        if (p.kind == PieceKind::escape)
            out << "escape\n";
        else if (p.kind == PieceKind::absorbed)
            out << "absorbed\n";
        else
            out << "-> " << p.image << "\n";
    }
}

} // namespace detail

template <class Int>
std::optional<OctagonalLayout> build_layout(const OctagonalScene<Int>& scene,
                                            const Point<Int>& first_point, int first_sheet,
                                            std::size_t max_pieces, BuildFailure& failure,
                                            std::ostream* dump, const std::function<bool()>& stop) {
    detail::Builder<Int> builder(scene, first_point, first_sheet);
    builder.set_stop(stop);
    if (!dump) return builder.build(first_point, first_sheet, max_pieces, failure);
    auto layout = builder.build(first_point, first_sheet, max_pieces, failure);
    if (layout) {
        std::swap(builder.pieces(), layout->pieces);
        builder.dump(*dump);
        std::swap(builder.pieces(), layout->pieces);
        for (const Collision& c : layout->collisions)
            *dump << "collision " << c.state << " -> " << c.join << ": another piece steps to "
                  << c.join << " too\n";
    }
    return layout;
}

template std::optional<OctagonalLayout> build_layout(const OctagonalScene<lattice::int128_t>&,
                                                     const Point<lattice::int128_t>&, int,
                                                     std::size_t, BuildFailure&, std::ostream*,
                                                     const std::function<bool()>&);
template std::optional<OctagonalLayout> build_layout(const OctagonalScene<Integer>&,
                                                     const Point<Integer>&, int, std::size_t,
                                                     BuildFailure&, std::ostream*,
                                                     const std::function<bool()>&);

} // namespace orthoray::induction::octagonal
