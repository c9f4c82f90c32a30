// The builder's geometry (octagonal_builder.hpp): vertices, lines cut into
// transversals, where a lifted state lies and where it steps.
#include "induction/octagonal_builder.hpp"

#include "induction/octagonal_crossings.hpp"

#include <algorithm>
#include <tuple>

namespace orthoray::induction::octagonal::detail {

template <class Int>
void Builder<Int>::find_vertices() {
    const auto& segs = s_.segments;
    for (const Segment<Int>& seg : segs) {
        poll();
        vertices_.push_back(point_on(seg.orientation, seg.c, seg.lo));
        vertices_.push_back(point_on(seg.orientation, seg.c, seg.hi));
    }
    constexpr Orientation all[] = {Orientation::vertical, Orientation::horizontal,
                                   Orientation::rising, Orientation::falling};
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
            crossings_of(segs, all[i], all[j], vertices_, [this] { poll(); });
    std::sort(vertices_.begin(), vertices_.end());
    vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());
}

template <class Int>
std::optional<std::size_t> Builder<Int>::line_of(Orientation o, const Int& c) const {
    auto it =
        std::lower_bound(lines_.begin(), lines_.end(), std::make_pair(o, c),
                         [](const Line& l, const std::pair<Orientation, Int>& key) {
                             return std::tie(l.orientation, l.c) < std::tie(key.first, key.second);
                         });
    if (it == lines_.end() || it->orientation != o || it->c != c) return std::nullopt;
    return static_cast<std::size_t>(it - lines_.begin());
}

template <class Int>
std::optional<std::size_t> Builder<Int>::vertex_of(const Point<Int>& p) const {
    auto it = std::lower_bound(vertices_.begin(), vertices_.end(), p);
    if (it == vertices_.end() || *it != p) return std::nullopt;
    return static_cast<std::size_t>(it - vertices_.begin());
}

template <class Int>
void Builder<Int>::cut_lines() {
    for (const Segment<Int>& seg : s_.segments)
        lines_.push_back({seg.orientation, seg.c, {}, {}, {}});
    std::sort(lines_.begin(), lines_.end(), [](const Line& l, const Line& m) {
        return std::tie(l.orientation, l.c) < std::tie(m.orientation, m.c);
    });
    lines_.erase(std::unique(lines_.begin(), lines_.end(),
                             [](const Line& l, const Line& m) {
                                 return l.orientation == m.orientation && l.c == m.c;
                             }),
                 lines_.end());
    for (const Point<Int>& v : vertices_)
        for (Orientation o : {Orientation::vertical, Orientation::horizontal, Orientation::rising,
                              Orientation::falling})
            if (auto l = line_of(o, line_constant(o, v))) lines_[*l].cuts.push_back(position(o, v));
    for (Line& l : lines_) {
        std::sort(l.cuts.begin(), l.cuts.end());
        l.cuts.erase(std::unique(l.cuts.begin(), l.cuts.end()), l.cuts.end());
    }
    // Per interval: how many mirrors and absorbers cover it (difference arrays).
    std::vector<std::vector<int>> mirrors(lines_.size()), absorbers(lines_.size());
    for (std::size_t l = 0; l < lines_.size(); ++l) {
        mirrors[l].assign(lines_[l].cuts.size() + 1, 0);
        absorbers[l].assign(lines_[l].cuts.size() + 1, 0);
    }
    for (const Segment<Int>& seg : s_.segments) {
        const std::size_t l = *line_of(seg.orientation, seg.c);
        const auto& cuts = lines_[l].cuts;
        const auto from = std::lower_bound(cuts.begin(), cuts.end(), seg.lo) - cuts.begin();
        const auto to = std::lower_bound(cuts.begin(), cuts.end(), seg.hi) - cuts.begin();
        auto& count = seg.absorber ? absorbers[l] : mirrors[l];
        ++count[static_cast<std::size_t>(from)];
        --count[static_cast<std::size_t>(to)];
    }
    for (std::size_t l = 0; l < lines_.size(); ++l) {
        Line& line = lines_[l];
        const std::size_t intervals = line.cuts.empty() ? 0 : line.cuts.size() - 1;
        line.mirror_only.assign(intervals, 0);
        int m = 0, a = 0;
        for (std::size_t i = 0; i < intervals; ++i) {
            m += mirrors[l][i];
            a += absorbers[l][i];
            line.mirror_only[i] = m > 0 && a == 0;
        }
        line.slot.assign(intervals * 8, npos);
    }
}

template <class Int>
void Builder<Int>::make_slots() {
    // Every translation is w(q, g') - w(q, g) at a point q of a line (a
    // vertex of it will do) or at a vertex: their gcd is the modulus.
    modulus_ = 0;
    for (const Point<Int>& v : vertices_) {
        const Integer w0 = to_integer(s_.w(v, 0));
        for (int g = 1; g < 8; ++g) modulus_ = gcd(modulus_, Integer(to_integer(s_.w(v, g)) - w0));
    }
    size_ = 0;
    auto add = [&](Slot slot, const Integer& lo, const Integer& hi) -> std::size_t {
        // The class in the open range (lo, hi) (for a vertex, lo = w - 1, hi = w + 1).
        if (modulus_ == 0) {
            if (!(lo < w_x_ && w_x_ < hi)) return npos;
            slot.first = w_x_;
            slot.count = 1;
        } else {
            slot.first = lo + 1 + floor_mod(w_x_ - lo - 1, modulus_);
            if (!(slot.first < hi)) return npos;
            slot.count = (hi - 1 - slot.first) / modulus_ + 1;
        }
        slot.start = size_;
        size_ += slot.count;
        slots_.push_back(std::move(slot));
        return slots_.size() - 1;
    };
    for (std::size_t l = 0; l < lines_.size(); ++l) {
        Line& line = lines_[l];
        for (std::size_t i = 0; i < line.mirror_only.size(); ++i) {
            if (!line.mirror_only[i]) continue;
            const Point<Int> p = point_on(line.orientation, line.c, line.cuts[i]);
            const Point<Int> q = point_on(line.orientation, line.c, line.cuts[i + 1]);
            for (int g = 0; g < 8; ++g) {
                const Integer wp = to_integer(s_.w(p, g)), wq = to_integer(s_.w(q, g));
                if (wp == wq) continue; // the sheet runs along the line
                Slot slot;
                slot.line = l;
                slot.interval = i;
                slot.sheet = g;
                slot.w_at_cut = wp;
                slot.kappa = (wq - wp) / to_integer(Int(line.cuts[i + 1] - line.cuts[i]));
                line.slot[i * 8 + static_cast<std::size_t>(g)] =
                    add(std::move(slot), std::min(wp, wq), std::max(wp, wq));
            }
        }
    }
    // A vertex has a state on sheet R g whenever a ray arriving on sheet g
    // leaves it (the sheets the rule of the event sends rays to).
    vertex_slot_.assign(vertices_.size() * 8, npos);
    for (std::size_t v = 0; v < vertices_.size(); ++v)
        for (int g = 0; g < 8; ++g) {
            const auto acting = s_.acting_at(vertices_[v], g);
            if (acting.empty()) continue;
            const Outcome<Int> out = outcome_at(s_, acting, g);
            if (out.absorbed) continue;
            std::size_t& at = vertex_slot_[v * 8 + static_cast<std::size_t>(out.sheet)];
            if (at != npos) continue;
            Slot slot;
            slot.vertex = true;
            slot.line = v;
            slot.sheet = out.sheet;
            const Integer w = to_integer(s_.w(vertices_[v], out.sheet));
            at = add(std::move(slot), Integer(w - 1), Integer(w + 1));
        }
}

template <class Int>
Point<Int> Builder<Int>::point_of(const Slot& t, const Integer& w) const {
    if (t.vertex) return vertices_[t.line];
    const Line& line = lines_[t.line];
    const Integer offset = w - t.w_at_cut;
    if (offset % t.kappa != 0) throw std::logic_error("a state off the lattice");
    const Int pos = Int(line.cuts[t.interval] + lattice::from_integer<Int>(offset / t.kappa));
    return point_on(line.orientation, line.c, pos);
}

template <class Int>
std::optional<std::pair<std::size_t, Integer>> Builder<Int>::locate(const Point<Int>& q,
                                                                    int g) const {
    const Integer w = to_integer(s_.w(q, g));
    if (!in_class(w)) return std::nullopt;
    if (auto v = vertex_of(q)) {
        const std::size_t slot = vertex_slot_[*v * 8 + static_cast<std::size_t>(g)];
        if (slot == npos) return std::nullopt;
        return std::make_pair(slot, w);
    }
    for (Orientation o : {Orientation::vertical, Orientation::horizontal, Orientation::rising,
                          Orientation::falling}) {
        const auto l = line_of(o, line_constant(o, q));
        if (!l) continue;
        const Line& line = lines_[*l];
        const Int& pos = position(o, q);
        const auto after = std::upper_bound(line.cuts.begin(), line.cuts.end(), pos);
        if (after == line.cuts.begin() || after == line.cuts.end()) continue;
        const std::size_t i = static_cast<std::size_t>(after - line.cuts.begin()) - 1;
        const std::size_t slot = line.slot[i * 8 + static_cast<std::size_t>(g)];
        if (slot != npos) return std::make_pair(slot, w);
    }
    return std::nullopt;
}

template <class Int>
std::optional<std::pair<std::size_t, Integer>> Builder<Int>::twin_at(const Point<Int>& q,
                                                                     int g) const {
    const auto& d = s_.direction;
    for (int h = 0; h < 8; ++h)
        if (h != g && d[static_cast<std::size_t>(h)] == d[static_cast<std::size_t>(g)])
            return locate(q, h);
    return std::nullopt;
}

template <class Int>
std::optional<Integer> Builder<Int>::twin_of(const Integer& raw_state) const {
    const auto after =
        std::upper_bound(slots_.begin(), slots_.end(), raw_state,
                         [](const Integer& r, const Slot& t) { return r < t.start; });
    const Slot& t = *(after - 1);
    const Integer w = modulus_ == 0 ? t.first : Integer(t.first + (raw_state - t.start) * modulus_);
    const auto twin = twin_at(point_of(t, w), t.sheet);
    if (!twin) return std::nullopt;
    return raw(twin->first, twin->second);
}

template <class Int>
typename Builder<Int>::Step Builder<Int>::step(std::size_t slot, const Integer& w) const {
    const Slot& t = slots_[slot];
    const Point<Int> q = point_of(t, w);
    const Shot<Int> shot = s_.shoot(q, t.sheet);
    Step out;
    if (!shot.found) {
        out.kind = PieceKind::escape;
        return out;
    }
    const Point<Int> hit = s_.advance(q, t.sheet, shot, false);
    const Outcome<Int> event = outcome_at(s_, s_.acting_at(hit, t.sheet), t.sheet);
    if (event.absorbed) {
        out.kind = PieceKind::absorbed;
        return out;
    }
    const auto located = locate(hit, event.sheet);
    if (!located) throw std::logic_error("a state steps to no transversal");
    out.slot = located->first;
    out.w = located->second;
    return out;
}

template <class Int>
void Builder<Int>::add_run(std::size_t slot, const Integer& first, const Integer& last) {
    const Step a = step(slot, first);
    RawPiece piece;
    piece.start = raw(slot, first);
    piece.length = modulus_ == 0 ? Integer(1) : Integer((last - first) / modulus_ + 1);
    piece.kind = a.kind;
    if (a.kind == PieceKind::reflect) {
        piece.image = raw(a.slot, a.w);
        if (last != first) {
            const Step b = step(slot, last);
            if (b.kind != a.kind || b.slot != a.slot || b.w - a.w != last - first)
                throw std::logic_error("an octagonal piece is not a translation in w");
        }
    }
    pieces_.push_back(std::move(piece));
}

// This instantiates the members defined above; build, build_all and dump
// (octagonal_layout.cpp) are instantiated where build_layout uses them.
template class Builder<int128_t>;
template class Builder<Integer>;

} // namespace orthoray::induction::octagonal::detail
