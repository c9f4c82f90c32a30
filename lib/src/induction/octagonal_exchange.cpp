#include "induction/octagonal_exchange.hpp"

#include "induction/collisions.hpp"
#include "induction/octagonal_crossings.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>
#include <type_traits>

namespace orthoray::induction::octagonal {
namespace {

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

} // namespace

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

template <class Int>
std::optional<OctagonalLayout> build_layout(const OctagonalScene<Int>& scene,
                                            const Point<Int>& first_point, int first_sheet,
                                            std::size_t max_pieces, BuildFailure& failure,
                                            std::ostream* dump, const std::function<bool()>& stop) {
    Builder<Int> builder(scene, first_point, first_sheet);
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

template std::optional<OctagonalLayout> build_layout(const OctagonalScene<int128_t>&,
                                                     const Point<int128_t>&, int, std::size_t,
                                                     BuildFailure&, std::ostream*,
                                                     const std::function<bool()>&);
template std::optional<OctagonalLayout> build_layout(const OctagonalScene<Integer>&,
                                                     const Point<Integer>&, int, std::size_t,
                                                     BuildFailure&, std::ostream*,
                                                     const std::function<bool()>&);

} // namespace orthoray::induction::octagonal
