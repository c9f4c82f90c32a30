#include "induction/exchange_builder.hpp"

#include <numeric>

namespace orthoray::induction {

ArithmeticUsed exchange_arithmetic(const lattice::LatticeScene& scene) {
    // Lattice points on the mirrors: N is at most four times as many (four
    // directions; a segment's points are some of its mirrors' points).
    Integer points = 0;
    for (const lattice::LatticeElement& e : scene.elements)
        if (!e.absorber) points += e.hi[1 - e.axis] - e.lo[1 - e.axis] + 1;
    const Integer bound = std::max(scene.magnitude, Integer(4 * points));
    if (bound < lattice::int64_limit()) return ArithmeticUsed::int64;
    if (bound < lattice::int128_limit()) return ArithmeticUsed::int128;
    return ArithmeticUsed::gmp;
}

namespace {

using lattice::convert;
using lattice::gcd_of;

constexpr std::size_t npos = ~std::size_t{0};

int sign_of(unsigned negative, int axis) {
    return ((negative >> axis) & 1u) ? -1 : 1;
}

// w = slope * u + intercept on the line {axis = offset}, direction `negative`.
int w_slope(int axis, unsigned negative) {
    return axis == 0 ? sign_of(negative, 1) : -sign_of(negative, 0);
}
template <class Num>
Num w_intercept(int axis, const Num& offset, unsigned negative) {
    return axis == 0 ? Num(-sign_of(negative, 0) * offset) : Num(sign_of(negative, 1) * offset);
}

} // namespace

template <class Num>
ExchangeLayout<Num>::ExchangeLayout(const lattice::LatticeScene& scene, const Num (&x)[2],
                                    unsigned x_negative, const lattice::SetupPoll& poll) {
    struct Mirror {
        int axis;
        Num offset, lo, hi;
        std::uint32_t element;
    };
    std::vector<Mirror> mirrors;
    modulus_ = 0;
    for (std::uint32_t e = 0; e < scene.elements.size(); ++e) {
        poll();
        const auto& element = scene.elements[e];
        if (element.absorber) continue;
        const int axis = element.axis;
        mirrors.push_back({axis, convert<Num>(element.lo[axis]), convert<Num>(element.lo[1 - axis]),
                           convert<Num>(element.hi[1 - axis]), e});
        // A reflection on {axis = c} moves w by +-2c, so w mod gcd(2c) is invariant.
        modulus_ = gcd_of(modulus_, Num(2 * mirrors.back().offset));
    }
    w_first_ = sign_of(x_negative, 1) * x[1] - sign_of(x_negative, 0) * x[0];
    std::sort(mirrors.begin(), mirrors.end(), [](const Mirror& a, const Mirror& b) {
        return std::tie(a.axis, a.offset, a.lo) < std::tie(b.axis, b.offset, b.lo);
    });
    const std::size_t verticals = static_cast<std::size_t>(
        std::find_if(mirrors.begin(), mirrors.end(), [](const Mirror& m) { return m.axis == 1; }) -
        mirrors.begin());

    // Segments: the merged mirrors of each line, horizontal ones cut at crossings.
    std::vector<std::pair<std::size_t, std::size_t>> group_of_segment; // mirrors of its line
    for (std::size_t begin = 0; begin < mirrors.size();) {
        std::size_t end = begin;
        while (end < mirrors.size() && mirrors[end].axis == mirrors[begin].axis &&
               mirrors[end].offset == mirrors[begin].offset)
            ++end;
        const int axis = mirrors[begin].axis;
        const Num& offset = mirrors[begin].offset;
        auto add = [&](const Num& lo, const Num& hi) {
            segments_.push_back({axis, offset, lo, hi});
            group_of_segment.emplace_back(begin, end);
        };
        for (std::size_t i = begin; i < end;) {
            poll();
            Num lo = mirrors[i].lo, hi = mirrors[i].hi;
            std::size_t j = i + 1;
            for (; j < end && mirrors[j].lo <= hi; ++j)
                if (mirrors[j].hi > hi) hi = mirrors[j].hi;
            if (axis == 0) {
                add(lo, hi);
            } else {
                // Vertical mirrors crossing [lo, hi] on the line Y = offset.
                auto v = std::lower_bound(
                    mirrors.begin(), mirrors.begin() + static_cast<std::ptrdiff_t>(verticals), lo,
                    [](const Mirror& m, const Num& value) { return m.offset < value; });
                Num from = lo;
                for (; v != mirrors.begin() + static_cast<std::ptrdiff_t>(verticals) &&
                       v->offset <= hi;
                     ++v) {
                    if (v->lo > offset || offset > v->hi || v->offset < from) continue;
                    if (from <= v->offset - 1) add(from, Num(v->offset - 1));
                    from = v->offset + 1;
                }
                if (from <= hi) add(from, hi);
            }
            i = j;
        }
        begin = end;
    }

    for (std::size_t s = 0; s < segments_.size(); ++s) {
        const Segment& segment = segments_[s];
        auto& offsets = line_offsets_[static_cast<std::size_t>(segment.axis)];
        if (offsets.empty() || offsets.back() != segment.offset) {
            offsets.push_back(segment.offset);
            line_begins_[static_cast<std::size_t>(segment.axis)].push_back(s);
        }
    }
    line_begins_[0].push_back(line_begins_[1].empty() ? segments_.size() : line_begins_[1][0]);
    line_begins_[1].push_back(segments_.size());

    // Owners: each position goes to the first mirror (by lo) containing it.
    owners_.resize(segments_.size());
    for (std::size_t s = 0; s < segments_.size(); ++s) {
        poll();
        const Segment& segment = segments_[s];
        Num covered = segment.lo - 1;
        for (std::size_t i = group_of_segment[s].first; i < group_of_segment[s].second; ++i) {
            const Mirror& m = mirrors[i];
            if (m.lo > segment.hi) break;
            Num from = std::max(m.lo, Num(covered + 1));
            Num to = std::min(m.hi, segment.hi);
            if (from > to) continue;
            covered = to;
            owners_[s].push_back({m.element, std::move(from), std::move(to)});
        }
    }

    // Transversals: every segment in every direction, if its class is not empty.
    transversal_of_.assign(segments_.size() * 4, npos);
    // At most four a segment; reserving them does not touch the memory.
    transversals_.reserve(segments_.size() * 4);
    segment_of_.reserve(segments_.size() * 4);
    size_ = 0;
    for (std::size_t s = 0; s < segments_.size(); ++s) {
        const Segment& segment = segments_[s];
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            TransversalOn<Num> t;
            t.axis = segment.axis;
            t.offset = segment.offset;
            t.lo = segment.lo;
            t.hi = segment.hi;
            t.negative = d;
            t.w_slope = w_slope(segment.axis, d);
            // w(u) = slope u + intercept = w(x) (mod G) <=> u = slope (w(x) - intercept).
            const Num u = t.w_slope * (w_first_ - w_intercept(segment.axis, segment.offset, d));
            if (modulus_ == 0) {
                if (u < segment.lo || u > segment.hi) continue;
                t.first = u;
                t.count = 1;
            } else {
                t.first = segment.lo + floor_mod(Num(u - segment.lo), modulus_);
                if (t.first > segment.hi) continue;
                t.count = (segment.hi - t.first) / modulus_ + 1;
            }
            t.start = size_;
            size_ += t.count;
            transversal_of_[s * 4 + d] = transversals_.size();
            segment_of_.push_back(s);
            transversals_.push_back(std::move(t));
        }
    }
}

template <class Num>
std::optional<std::pair<std::size_t, Num>> ExchangeLayout<Num>::locate(const Num (&p)[2],
                                                                       unsigned negative) const {
    for (int axis = 0; axis < 2; ++axis) {
        const Num& offset = p[axis];
        const Num& u = p[1 - axis];
        // The line first, then the last of its segments starting at or before u.
        const auto& offsets = line_offsets_[static_cast<std::size_t>(axis)];
        const auto line = std::lower_bound(offsets.begin(), offsets.end(), offset);
        if (line == offsets.end() || *line != offset) continue;
        const auto& begins = line_begins_[static_cast<std::size_t>(axis)];
        const std::size_t i = static_cast<std::size_t>(line - offsets.begin());
        const auto first = segments_.begin() + static_cast<std::ptrdiff_t>(begins[i]);
        const auto after =
            std::upper_bound(first, segments_.begin() + static_cast<std::ptrdiff_t>(begins[i + 1]),
                             u, [](const Num& v, const Segment& s) { return v < s.lo; });
        if (after == first) continue;
        const Segment& s = *(after - 1);
        if (u > s.hi) continue;
        // On a vertical segment the state is that one's, in class or not.
        const std::size_t id =
            transversal_of_[static_cast<std::size_t>(after - 1 - segments_.begin()) * 4 + negative];
        if (id == npos) return std::nullopt;
        const TransversalOn<Num>& t = transversals_[id];
        if (modulus_ == 0 ? u != t.first : floor_mod(Num(u - t.first), modulus_) != 0)
            return std::nullopt;
        return std::make_pair(id, number_of(t, modulus_, u));
    }
    return std::nullopt;
}

template <class Num>
std::optional<std::pair<std::size_t, Num>>
ExchangeLayout<Num>::locate(const Num (&p)[2], unsigned negative, std::size_t near) const {
    const TransversalOn<Num>& t = transversals_[near];
    const Num& u = p[1 - t.axis];
    if (t.negative != negative || p[t.axis] != t.offset || u < t.lo || u > t.hi)
        return locate(p, negative);
    if (modulus_ == 0 ? u != t.first : floor_mod(Num(u - t.first), modulus_) != 0)
        return std::nullopt;
    return std::make_pair(near, number_of(t, modulus_, u));
}

template <class Num>
std::vector<Transversal> ExchangeLayout<Num>::public_transversals() const {
    std::vector<Transversal> out;
    out.reserve(transversals_.size());
    for (const TransversalOn<Num>& t : transversals_) {
        Transversal p;
        p.axis = t.axis;
        p.negative = t.negative;
        p.w_slope = t.w_slope;
        p.offset = lattice::to_integer(t.offset);
        p.lo = lattice::to_integer(t.lo);
        p.hi = lattice::to_integer(t.hi);
        p.first = lattice::to_integer(t.first);
        p.count = lattice::to_integer(t.count);
        p.start = lattice::to_integer(t.start);
        out.push_back(std::move(p));
    }
    return out;
}

template <class Num>
ExchangeOn<Num>
finish_exchange_on(const Num& size, const Num& modulus, std::vector<Transversal> transversals,
                   std::vector<RawPieceOn<Num>> pieces, const Num& raw_first,
                   const std::vector<Num>& raw_hits, const lattice::SetupPoll& poll) {
    using Piece = RawPieceOn<Num>;
    const Num& n = size;
    std::sort(pieces.begin(), pieces.end(),
              [](const Piece& a, const Piece& b) { return a.start < b.start; });
    Num at = 0;
    for (const Piece& p : pieces) {
        poll();
        if (p.start != at) throw std::logic_error("the tables' pieces do not tile the states");
        at += p.length;
    }
    if (at != n) throw std::logic_error("the tables' pieces do not tile the states");

    isolate_state(pieces, raw_first);
    for (const Num& h : raw_hits) pieces[isolate_state(pieces, h)].hit = true;

    // Close the holes: escaping and absorbed pieces, in domain order, onto
    // the states no piece maps to, in order.
    std::vector<std::pair<Num, Num>> images; // (start, length) of the reflecting ones
    images.reserve(pieces.size());           // reserving does not touch the memory
    for (const Piece& p : pieces) {
        poll(); // copies: on 10^5-digit numbers, much fresh memory
        if (p.kind == PieceKind::reflect) images.emplace_back(p.image, p.length);
    }
    std::sort(images.begin(), images.end());
    std::vector<std::pair<Num, Num>> holes;
    holes.reserve(images.size() + 1);
    at = 0;
    for (const auto& [start, length] : images) {
        poll();
        if (start < at) throw std::logic_error("two states of the tables have one image");
        if (start > at) holes.emplace_back(at, Num(start - at));
        at = start + length;
    }
    if (at < n) holes.emplace_back(at, Num(n - at));
    images = {};
    // The dead pieces' parts, one a hole they meet, in order.
    std::vector<Piece> parts;
    std::size_t dead = 0;
    std::size_t hole = 0;
    Num used = 0; // of the current hole
    for (const Piece& p : pieces) {
        poll();
        if (p.kind == PieceKind::reflect) continue;
        ++dead;
        Num start = p.start, left = p.length;
        while (left > 0) {
            if (hole == holes.size()) throw std::logic_error("more dead states than holes");
            const Num room = holes[hole].second - used;
            Piece part = p;
            part.start = start;
            part.length = std::min(left, room);
            part.image = holes[hole].first + used;
            start += part.length;
            left -= part.length;
            used += part.length;
            if (used == holes[hole].second) {
                ++hole;
                used = 0;
            }
            parts.push_back(std::move(part));
        }
    }
    // Each dead piece replaced by its parts, in place: the pieces move up
    // from the end, so none is overwritten before it is moved, and no
    // second array of pieces is touched. (One more slot for the piece whose
    // image wraps around, below.)
    std::vector<Piece> closed = std::move(pieces);
    const std::size_t before = closed.size();
    closed.reserve(before + parts.size() - dead + 1);
    closed.resize(before + parts.size() - dead);
    std::size_t to = closed.size();
    for (std::size_t from = before; from-- > 0;) {
        if (closed[from].kind == PieceKind::reflect) {
            if (--to != from) closed[to] = std::move(closed[from]);
            continue;
        }
        const Num start = closed[from].start;
        while (!parts.empty() && parts.back().start >= start) {
            closed[--to] = std::move(parts.back());
            parts.pop_back();
        }
    }

    // Rotate so that x is 0: the pieces in domain order from x's on, then
    // those before it (no sort needed), renumbered in place. The images tile
    // the states once, so at most one of them wraps around: it is cut in
    // two, its second part inserted after it.
    const auto first = std::find_if(closed.begin(), closed.end(),
                                    [&](const Piece& p) { return p.start == raw_first; });
    std::rotate(closed.begin(), first, closed.end());
    std::optional<std::pair<std::size_t, Piece>> wrapped;
    for (std::size_t i = 0; i < closed.size(); ++i) {
        poll();
        Piece& q = closed[i];
        q.start = floor_mod(Num(q.start - raw_first), n);
        q.image = floor_mod(Num(q.image - raw_first), n);
        if (q.image + q.length > n) {
            if (wrapped) throw std::logic_error("two images wrap around");
            Piece rest = q;
            const Num head = n - q.image;
            rest.start += head;
            rest.length -= head;
            rest.image = 0;
            q.length = head;
            wrapped.emplace(i + 1, std::move(rest));
        }
    }
    if (wrapped)
        closed.insert(closed.begin() + static_cast<std::ptrdiff_t>(wrapped->first),
                      std::move(wrapped->second));
    ExchangeOn<Num> exchange;
    exchange.pieces = std::move(closed);
    if (exchange.pieces.front().start != 0 || exchange.pieces.front().length != 1)
        throw std::logic_error("x is not a piece of its own");
    exchange.modulus = modulus;
    exchange.size = n;
    exchange.transversals = std::move(transversals);
    return exchange;
}

template <class Num>
IntervalExchange to_public(const ExchangeOn<Num>& exchange) {
    using lattice::to_integer;
    IntervalExchange out;
    for (int j = 0; j < 2; ++j) out.scale[j] = exchange.scale[j];
    out.modulus = to_integer(exchange.modulus);
    out.transversals = exchange.transversals;
    out.first_transversal = exchange.first_transversal;
    out.first_index = to_integer(exchange.first_index);
    out.size = to_integer(exchange.size);
    out.pieces.reserve(exchange.pieces.size());
    for (const RawPieceOn<Num>& p : exchange.pieces) {
        ExchangePiece q;
        q.start = to_integer(p.start);
        q.length = to_integer(p.length);
        q.image = to_integer(p.image);
        q.kind = p.kind;
        q.hit = p.hit;
        out.pieces.push_back(std::move(q));
    }
    return out;
}

template class ExchangeLayout<std::int64_t>;
template class ExchangeLayout<lattice::int128_t>;
template class ExchangeLayout<Integer>;
template ExchangeOn<std::int64_t>
finish_exchange_on(const std::int64_t&, const std::int64_t&, std::vector<Transversal>,
                   std::vector<RawPieceOn<std::int64_t>>, const std::int64_t&,
                   const std::vector<std::int64_t>&, const lattice::SetupPoll&);
template IntervalExchange to_public(const ExchangeOn<std::int64_t>&);
template ExchangeOn<lattice::int128_t>
finish_exchange_on(const lattice::int128_t&, const lattice::int128_t&, std::vector<Transversal>,
                   std::vector<RawPieceOn<lattice::int128_t>>, const lattice::int128_t&,
                   const std::vector<lattice::int128_t>&, const lattice::SetupPoll&);
template IntervalExchange to_public(const ExchangeOn<lattice::int128_t>&);
template ExchangeOn<Integer> finish_exchange_on(const Integer&, const Integer&,
                                                std::vector<Transversal>,
                                                std::vector<RawPieceOn<Integer>>, const Integer&,
                                                const std::vector<Integer>&,
                                                const lattice::SetupPoll&);
template IntervalExchange to_public(const ExchangeOn<Integer>&);

} // namespace orthoray::induction
