#include "induction/rho_walk.hpp"

#include "induction/rauzy_induction.hpp"

#include <algorithm>
#include <map>

namespace orthoray::induction {
namespace {

class Walk {
public:
    Walk(const RhoMap& map, const std::function<bool(std::uint64_t)>& stop)
        : map_(map), stop_(stop) {
        specials_.push_back(map.first);
        if (map.first_twin) specials_.push_back(*map.first_twin);
        for (const Collision& c : map.collisions) {
            specials_.push_back(c.state);
            specials_.push_back(c.join);
        }
        for (const auto& [state, twin] : map.twins) specials_.push_back(twin);
        std::sort(specials_.begin(), specials_.end());
        specials_.erase(std::unique(specials_.begin(), specials_.end()), specials_.end());
    }

    std::optional<RhoOrbit> run() {
        Integer p = map_.first, t = 0;
        visit(p, t);
        for (;;) {
            for (auto join = join_of(p); join; join = join_of(p)) {
                // The step by hand: p's segment may pass the target first.
                if (std::binary_search(map_.hits.begin(), map_.hits.end(), p))
                    return event(ExchangeEvent::hit, t);
                p = *join;
                t += 1;
                if (visit(p, t)) return out_;
            }
            std::vector<Integer> marks = map_.hits;
            for (const Integer& s : specials_)
                if (s != p) marks.push_back(s);
            const std::optional<InducedOrbit> o = induce_from(p, marks);
            if (!o) return std::nullopt;
            if (o->event == ExchangeEvent::none) { // back at p
                visit(p, Integer(t + o->period));
                return out_;
            }
            if (o->event != ExchangeEvent::hit) return event(o->event, t + o->offset);
            // Which mark: the target's first, so that it wins a tie.
            const std::optional<std::size_t> z = identify(p, marks, o->offset);
            if (!z) return std::nullopt;
            if (*z < map_.hits.size()) return event(ExchangeEvent::hit, t + o->offset);
            p = marks[*z];
            t += o->offset;
            if (visit(p, t)) return out_;
        }
    }

private:
    std::optional<InducedOrbit> induce_from(const Integer& p, const std::vector<Integer>& marks) {
        const ExchangeOn<Integer> e =
            finish_exchange_on(map_.size, map_.modulus, {}, map_.pieces, p, marks);
        const std::optional<InducedOrbit> o = induce(e, stop_);
        if (o) {
            out_.steps += o->steps;
            out_.rounds += o->rounds;
            ++out_.inductions;
        }
        return o;
    }

    // The mark that T^k(p) is, k being the first hit with all of `marks`:
    // halve them, keeping the half whose first hit is still at k.
    std::optional<std::size_t> identify(const Integer& p, const std::vector<Integer>& marks,
                                        const Integer& k) {
        std::size_t lo = 0, hi = marks.size();
        while (hi - lo > 1) {
            const std::size_t mid = lo + (hi - lo) / 2;
            const std::vector<Integer> half(marks.begin() + static_cast<std::ptrdiff_t>(lo),
                                            marks.begin() + static_cast<std::ptrdiff_t>(mid));
            const std::optional<InducedOrbit> o = induce_from(p, half);
            if (!o) return std::nullopt;
            if (o->event == ExchangeEvent::hit && o->offset == k)
                hi = mid;
            else
                lo = mid;
        }
        return lo;
    }

    std::optional<Integer> join_of(const Integer& p) const {
        for (const Collision& c : map_.collisions)
            if (c.state == p) return c.join;
        return std::nullopt;
    }

    // One physical state per pair of lifts.
    Integer physical(const Integer& r) const {
        const auto it = std::lower_bound(
            map_.twins.begin(), map_.twins.end(), r,
            [](const std::pair<Integer, Integer>& e, const Integer& v) { return e.first < v; });
        if (it != map_.twins.end() && it->first == r) return std::min(r, it->second);
        if (r == map_.first && map_.first_twin) return std::min(r, *map_.first_twin);
        if (map_.first_twin && r == *map_.first_twin) return std::min(r, map_.first);
        return r;
    }

    // True when p's physical state was seen before: the cycle is found.
    bool visit(const Integer& p, const Integer& t) {
        const auto [it, fresh] = seen_.emplace(physical(p), t);
        if (fresh) return false;
        out_.event = ExchangeEvent::none;
        out_.tail = it->second;
        out_.period = t - it->second;
        return true;
    }

    std::optional<RhoOrbit> event(ExchangeEvent e, const Integer& offset) {
        out_.event = e;
        out_.offset = offset;
        return out_;
    }

    const RhoMap& map_;
    const std::function<bool(std::uint64_t)>& stop_;
    std::vector<Integer> specials_;
    std::map<Integer, Integer> seen_; // physical state -> time of its first visit
    RhoOrbit out_;
};

} // namespace

std::optional<RhoOrbit> walk_rho(const RhoMap& map,
                                 const std::function<bool(std::uint64_t)>& stop) {
    return Walk(map, stop).run();
}

} // namespace orthoray::induction
