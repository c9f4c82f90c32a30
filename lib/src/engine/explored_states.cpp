#include "engine/explored_states.hpp"

#include "engine/branch_state_set.hpp"

#include <algorithm>
#include <new>
#include <tuple>
#include <unordered_map>

namespace orthoray::engine {
namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
    // splitmix64's finaliser over the running value
    h ^= x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    return h ^ (h >> 31);
}

std::uint64_t mix(std::uint64_t h, const mpz_class& z) {
    h = mix(h, static_cast<std::uint64_t>(sgn(z) + 1));
    for (std::size_t i = 0; i < mpz_size(z.get_mpz_t()); ++i)
        h = mix(h, static_cast<std::uint64_t>(mpz_getlimbn(z.get_mpz_t(), i)));
    return h;
}

std::uint64_t hash_of(const StretchState& s) {
    std::uint64_t h = 0;
    for (const Vector* x : {&s.p, &s.v})
        for (const Rational& q : *x) h = mix(mix(h, q.get_num()), q.get_den());
    return h;
}

// A stretch, or a cycle's tail, as the grouping sees it: `length` states
// from `branch`'s, the last of them hashed to `end`; `whole` the distinct
// states of the walk it came from (a tail's with its cycle's).
struct Path {
    std::uint32_t branch;
    bool tail; // of a cycle: the last state is the cycle's entry
    std::uint64_t length;
    std::uint64_t end;
    std::uint64_t whole;
};

// A cycle entered by a stretch: the state entering it and its period.
struct Cycle {
    StretchState entry;
    std::uint64_t period;
    std::uint64_t least_hash = 0; // over its states: the same for every entry
};

// The walks again, from branch states.
class Rewalk {
public:
    Rewalk(const EventStepper& stepper, const BranchStateSet& branches,
           const std::function<bool()>& keep_going)
        : stepper_(stepper), branches_(branches), keep_going_(keep_going) {}

    StretchState start(std::uint32_t branch) const {
        StretchState s;
        branches_.state(branch, s.p, s.v);
        return s;
    }

    // One step along a stretch; s is not its last state. False when
    // keep_going said to stop.
    bool step(StretchState& s) {
        s.follow(stepper_.next(s.p, s.v));
        return ++steps_ % 256 != 0 || keep_going_();
    }

    // The tail length mu of the stretch from `branch` that repeats with
    // period `period`, and the state s_mu entering the cycle: the first i
    // with s_i = s_(i + period).
    std::optional<std::pair<std::uint64_t, StretchState>> entry(std::uint32_t branch,
                                                                std::uint64_t period) {
        StretchState behind = start(branch), ahead = behind;
        for (std::uint64_t i = 0; i < period; ++i)
            if (!step(ahead)) return std::nullopt;
        std::uint64_t mu = 0;
        for (; !(behind == ahead); ++mu)
            if (!step(behind) || !step(ahead)) return std::nullopt;
        return std::pair{mu, std::move(behind)};
    }

    // The states of the distinct cycles, each entered by some walk. Only
    // cycles of one period and least hash can be one, so only those are
    // compared, by walking.
    std::optional<std::uint64_t> cycles(std::vector<Cycle>& entered) {
        if (entered.size() > 1)
            for (Cycle& c : entered)
                if (!name(c)) return std::nullopt;
        std::sort(entered.begin(), entered.end(), [](const Cycle& a, const Cycle& b) {
            return std::tie(a.period, a.least_hash) < std::tie(b.period, b.least_hash);
        });
        std::uint64_t total = 0;
        for (auto first = entered.begin(); first != entered.end();) {
            const auto last = std::find_if(first, entered.end(), [&](const Cycle& c) {
                return c.period != first->period || c.least_hash != first->least_hash;
            });
            std::vector<const Cycle*> distinct;
            for (auto c = first; c != last; ++c) {
                bool seen = false;
                for (const Cycle* d : distinct) {
                    const std::optional<bool> one = same(*d, *c);
                    if (!one) return std::nullopt;
                    if ((seen = *one)) break;
                }
                if (!seen) {
                    distinct.push_back(&*c);
                    total += c->period;
                }
            }
            first = last;
        }
        return total;
    }

    // The distinct states of the paths, grouped by end; a tail's last
    // state, its cycle's entry, is the cycle's and counted there.
    std::optional<std::uint64_t> paths(std::vector<Path>& sorted) {
        std::sort(sorted.begin(), sorted.end(), [](const Path& a, const Path& b) {
            return std::tie(a.tail, a.end) < std::tie(b.tail, b.end);
        });
        std::uint64_t total = 0;
        for (auto first = sorted.begin(); first != sorted.end();) {
            auto last = std::find_if(first, sorted.end(), [&](const Path& p) {
                return p.tail != first->tail || p.end != first->end;
            });
            if (last - first == 1) {
                total += first->length - (first->tail ? 1 : 0);
            } else {
                const std::optional<Union> u = union_of(first, last);
                if (!u) return std::nullopt;
                total += u->states - (first->tail ? u->ends : 0);
            }
            first = last;
        }
        return total;
    }

    // How many of `loose` lie on the walks the paths came from, looked up
    // by hash.
    std::optional<std::uint64_t> inside(const std::vector<Path>& paths,
                                        const std::vector<StretchState>& loose) {
        if (loose.empty()) return 0;
        std::unordered_multimap<std::uint64_t, std::size_t> by_hash;
        for (std::size_t j = 0; j < loose.size(); ++j) by_hash.emplace(hash_of(loose[j]), j);
        std::vector<bool> found(loose.size());
        std::uint64_t inside = 0;
        for (std::size_t i = 0; i < paths.size() && inside < loose.size(); ++i) {
            StretchState s = start(paths[i].branch);
            for (std::uint64_t k = 0; k < paths[i].whole; ++k) {
                const auto [first, last] = by_hash.equal_range(hash_of(s));
                for (auto it = first; it != last; ++it)
                    if (!found[it->second] && loose[it->second] == s) {
                        found[it->second] = true;
                        ++inside;
                    }
                if (k + 1 < paths[i].whole && !step(s)) return std::nullopt;
            }
        }
        return inside;
    }

private:
    // The least hash over c's states, the same from every entry.
    bool name(Cycle& c) {
        StretchState s = c.entry;
        c.least_hash = hash_of(s);
        for (std::uint64_t i = 1; i < c.period; ++i) {
            if (!step(s)) return false;
            c.least_hash = std::min(c.least_hash, hash_of(s));
        }
        return true;
    }

    // Whether b's entry lies on a's cycle (then the cycles are one).
    std::optional<bool> same(const Cycle& a, const Cycle& b) {
        if (a.period != b.period || a.least_hash != b.least_hash) return false;
        StretchState s = a.entry;
        for (std::uint64_t i = 0; i < a.period; ++i) {
            if (s == b.entry) return true;
            if (i + 1 < a.period && !step(s)) return std::nullopt;
        }
        return false;
    }

    // The distinct states of paths sharing an end hash, and how many
    // distinct last states they have: the lockstep walk of the file's
    // comment, aligned at the paths' ends.
    struct Union {
        std::uint64_t states = 0, ends = 0;
    };
    std::optional<Union> union_of(std::vector<Path>::const_iterator first,
                                  std::vector<Path>::const_iterator last) {
        std::vector<const Path*> group;
        for (auto it = first; it != last; ++it) group.push_back(&*it);
        std::sort(group.begin(), group.end(),
                  [](const Path* a, const Path* b) { return a->length > b->length; });
        std::vector<StretchState> apart; // one walk for each set of walks agreeing so far
        std::size_t joined = 0;
        Union u;
        for (std::uint64_t d = group.front()->length; d-- > 0;) {
            // Paths whose first state lies d steps before the end join here.
            for (; joined < group.size() && group[joined]->length - 1 == d; ++joined)
                apart.push_back(start(group[joined]->branch));
            if (apart.size() > 1) drop_agreeing(apart);
            u.states += apart.size();
            if (d == 0) {
                u.ends = apart.size();
                break;
            }
            for (StretchState& s : apart)
                if (!step(s)) return std::nullopt;
        }
        return u;
    }

    static void drop_agreeing(std::vector<StretchState>& walks) {
        std::vector<std::pair<std::uint64_t, std::size_t>> order;
        for (std::size_t i = 0; i < walks.size(); ++i) order.emplace_back(hash_of(walks[i]), i);
        std::sort(order.begin(), order.end());
        std::vector<bool> dropped(walks.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            for (std::size_t j = i + 1; j < order.size() && order[j].first == order[i].first; ++j)
                if (!dropped[order[j].second] && walks[order[i].second] == walks[order[j].second])
                    dropped[order[j].second] = true;
        std::size_t kept = 0;
        for (std::size_t i = 0; i < walks.size(); ++i)
            if (!dropped[i]) walks[kept++] = std::move(walks[i]);
        walks.resize(kept);
    }

    const EventStepper& stepper_;
    const BranchStateSet& branches_;
    const std::function<bool()>& keep_going_;
    std::uint64_t steps_ = 0;
};

} // namespace

bool ExploredStates::walked(std::uint32_t branch, const StretchEnd& end) {
    if (!budget_.make_room(walked_)) return false;
    const bool cycle = end.kind == StretchEnd::Kind::cycle;
    walked_.push_back({branch, cycle, end.visited, cycle ? end.period : hash_of(end.last)});
    return true;
}

std::optional<std::uint64_t> ExploredStates::count(const BranchStateSet& branches,
                                                   const std::vector<std::uint32_t>& ray_starts,
                                                   const std::function<bool()>& keep_going) const {
    // The count's own arrays are held to the search's budget too.
    const std::size_t cycle_walks = static_cast<std::size_t>(
        std::count_if(walked_.begin(), walked_.end(), [](const Walked& w) { return w.cycle; }));
    if (!budget_.fits(walked_.size() * sizeof(Path) + cycle_walks * sizeof(Cycle) +
                      branches.size() / 8))
        throw std::bad_alloc();
    Rewalk rewalk(stepper_, branches, keep_going);
    // Each walk as a path, a cycle's cut at its entry, and the cycles apart.
    std::vector<Path> paths;
    std::vector<Cycle> cycles;
    paths.reserve(walked_.size());
    cycles.reserve(cycle_walks);
    for (const Walked& w : walked_) {
        if (!w.cycle) {
            paths.push_back({w.branch, false, w.visited, w.last_or_period, w.visited});
            continue;
        }
        auto found = rewalk.entry(w.branch, w.last_or_period);
        if (!found) return std::nullopt;
        auto& [mu, entry] = *found;
        paths.push_back({w.branch, true, mu + 1, hash_of(entry), mu + w.last_or_period});
        cycles.push_back({std::move(entry), w.last_or_period});
    }
    const std::optional<std::uint64_t> on_cycles = rewalk.cycles(cycles);
    const std::optional<std::uint64_t> on_paths = on_cycles ? rewalk.paths(paths) : std::nullopt;
    if (!on_paths) return std::nullopt;

    // The branch states not walked to an end count once each, unless a
    // ray's start among them lies inside a stretch walked.
    std::vector<bool> walked(branches.size());
    for (const Walked& w : walked_) walked[w.branch] = true;
    std::vector<StretchState> loose;
    for (std::uint32_t r : ray_starts)
        if (!walked[r]) {
            walked[r] = true; // two rays from one state: one branch state
            loose.push_back(rewalk.start(r));
        }
    const std::optional<std::uint64_t> inside = rewalk.inside(paths, loose);
    if (!inside) return std::nullopt;
    return *on_cycles + *on_paths + (branches.size() - walked_.size()) - *inside;
}

} // namespace orthoray::engine
