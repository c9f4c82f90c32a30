#include "induction/rho_walk.hpp"

#include "induction/rauzy_induction.hpp"
#include "lattice/lattice_int.hpp"

#include <algorithm>
#include <map>

namespace orthoray::induction {

ExchangeOn<Integer> reroot(const ExchangeOn<Integer>& listed, const Integer& from,
                           const std::vector<Integer>& marks, bool keep_hits) {
    using Piece = RawPieceOn<Integer>;
    const Integer& n = listed.size;
    std::vector<Integer> cuts = marks;
    cuts.push_back(from);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    // Each piece split at c and c + 1 for every cut point c inside it; a
    // part starting at a mark is the mark alone. Every kind's image moves
    // with its domain (dead ends map onto holes in order).
    std::vector<Piece> split;
    split.reserve(listed.pieces.size() + 2 * cuts.size());
    auto c = cuts.begin();
    for (const Piece& whole : listed.pieces) {
        Piece p = whole;
        if (!keep_hits) p.hit = false;
        const Integer end = p.start + p.length;
        while (c != cuts.end() && *c < end) {
            for (const Integer& at : {*c, Integer(*c + 1)}) {
                if (!(p.start < at && at < end)) continue;
                Piece head = p;
                head.length = at - p.start;
                split.push_back(head);
                p.image += head.length;
                p.start = at;
                p.length -= head.length;
            }
            ++c;
        }
        split.push_back(p);
    }
    for (Piece& p : split)
        if (p.length == 1 && std::binary_search(marks.begin(), marks.end(), p.start)) p.hit = true;
    // Rotated so that `from` is 0, in domain order from it; an image that
    // wraps around is cut in two.
    const auto first =
        std::find_if(split.begin(), split.end(), [&](const Piece& p) { return p.start == from; });
    std::rotate(split.begin(), first, split.end());
    ExchangeOn<Integer> out;
    out.size = n;
    out.modulus = listed.modulus;
    out.pieces.reserve(split.size() + 1);
    for (Piece q : split) {
        q.start = lattice::floor_mod(Integer(q.start - from), n);
        q.image = lattice::floor_mod(Integer(q.image - from), n);
        if (q.image + q.length > n) {
            Piece rest = q;
            const Integer head = n - q.image;
            rest.start += head;
            rest.length -= head;
            rest.image = 0;
            q.length = head;
            out.pieces.push_back(q);
            out.pieces.push_back(rest);
        } else {
            out.pieces.push_back(q);
        }
    }
    return out;
}

std::vector<Integer> special_states(const RhoMap& map) {
    std::vector<Integer> s{Integer(0)};
    for (const auto& [state, join] : map.cuts) {
        s.push_back(state);
        s.push_back(join);
    }
    for (const auto& [state, twin] : map.twins) s.push_back(twin);
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
}

ExchangeOn<Integer> search_exchange(const RhoMap& map, const RhoSearch& search) {
    if (search.only) return reroot(map.listed, search.from, {*search.only}, false);
    std::vector<Integer> marks = special_states(map);
    marks.erase(std::remove(marks.begin(), marks.end(), search.from), marks.end());
    return reroot(map.listed, search.from, marks, true);
}

namespace {

class Walk {
public:
    Walk(const RhoMap& map, const std::function<bool(std::uint64_t)>& stop)
        : map_(map), stop_(stop), specials_(special_states(map)) {
        for (const auto& p : map.listed.pieces)
            if (p.hit) targets_.push_back(p.start); // each a piece of its own
    }

    std::optional<RhoOrbit> run() {
        Integer p = 0, t = 0;
        visit(p, t);
        for (;;) {
            for (const Integer* join = join_of(p); join; join = join_of(p)) {
                // The step by hand: p's segment may pass the target first.
                if (std::binary_search(targets_.begin(), targets_.end(), p))
                    return event(ExchangeEvent::hit, t);
                p = *join;
                t += 1;
                if (visit(p, t)) return out_;
            }
            const RhoSearch all{p, std::nullopt};
            out_.proof.push_back(all);
            const std::optional<InducedOrbit> o = induce_on(search_exchange(map_, all));
            if (!o) return std::nullopt;
            if (o->event == ExchangeEvent::none) { // back at p
                visit(p, Integer(t + o->period));
                return out_;
            }
            if (o->event != ExchangeEvent::hit) return event(o->event, t + o->offset);
            const std::optional<Integer> z = identify(p, o->offset);
            if (!z) return std::nullopt;
            out_.proof.push_back({p, *z});
            // The target's mark wins a tie with a special state.
            if (std::binary_search(targets_.begin(), targets_.end(), *z))
                return event(ExchangeEvent::hit, t + o->offset);
            p = *z;
            t += o->offset;
            if (visit(p, t)) return out_;
        }
    }

private:
    std::optional<InducedOrbit> induce_on(const ExchangeOn<Integer>& e) {
        const std::optional<InducedOrbit> o = induce(e, stop_);
        if (o) {
            out_.steps += o->steps;
            out_.rounds += o->rounds;
        }
        return o;
    }

    // The mark T^k(p) is, k being the first hit of the `all` search from p:
    // halve the marks (the target's first), keeping the half whose first hit
    // is still at k.
    std::optional<Integer> identify(const Integer& p, const Integer& k) {
        std::vector<Integer> marks = targets_;
        for (const Integer& s : specials_)
            if (s != p) marks.push_back(s);
        std::size_t lo = 0, hi = marks.size();
        while (hi - lo > 1) {
            const std::size_t mid = lo + (hi - lo) / 2;
            std::vector<Integer> half(marks.begin() + static_cast<std::ptrdiff_t>(lo),
                                      marks.begin() + static_cast<std::ptrdiff_t>(mid));
            std::sort(half.begin(), half.end());
            const std::optional<InducedOrbit> o = induce_on(reroot(map_.listed, p, half, false));
            if (!o) return std::nullopt;
            if (o->event == ExchangeEvent::hit && o->offset == k)
                hi = mid;
            else
                lo = mid;
        }
        return marks[lo];
    }

    const Integer* join_of(const Integer& p) const {
        const auto it = std::lower_bound(
            map_.cuts.begin(), map_.cuts.end(), p,
            [](const std::pair<Integer, Integer>& c, const Integer& v) { return c.first < v; });
        return it != map_.cuts.end() && it->first == p ? &it->second : nullptr;
    }

    const Integer* twin_of(const Integer& p) const {
        const auto it = std::lower_bound(
            map_.twins.begin(), map_.twins.end(), p,
            [](const std::pair<Integer, Integer>& c, const Integer& v) { return c.first < v; });
        return it != map_.twins.end() && it->first == p ? &it->second : nullptr;
    }

    // True when p was seen before: the lifted cycle is found, and the
    // physical period is half of it when p's twin came half-way.
    bool visit(const Integer& p, const Integer& t) {
        const auto [it, fresh] = seen_.emplace(p, t);
        if (fresh) return false;
        out_.event = ExchangeEvent::none;
        out_.tail = it->second;
        out_.period = t - it->second;
        if (const Integer* twin = twin_of(p)) {
            const auto met = seen_.find(*twin);
            if (met != seen_.end() && 2 * (met->second - out_.tail) == out_.period)
                out_.period /= 2;
        }
        return true;
    }

    std::optional<RhoOrbit> event(ExchangeEvent e, const Integer& offset) {
        out_.event = e;
        out_.offset = offset;
        return out_;
    }

    const RhoMap& map_;
    const std::function<bool(std::uint64_t)>& stop_;
    std::vector<Integer> specials_, targets_;
    std::map<Integer, Integer> seen_; // state -> time of its first visit
    RhoOrbit out_;
};

} // namespace

std::optional<RhoOrbit> walk_rho(const RhoMap& map,
                                 const std::function<bool(std::uint64_t)>& stop) {
    return Walk(map, stop).run();
}

} // namespace orthoray::induction
