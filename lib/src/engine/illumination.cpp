// Dijkstra over branch states (docs/optics.md, "Illumination").
//
// A label is a pair (reflections, ray) compared lexicographically. The
// label of a branch state is the least label of a branch reaching it; a ray's
// start begins at (0, ray). Expanding a branch state with label (K, R) walks
// its stretch: a target first passed w reflections into it gets the
// candidate (K + w, R), and where the stretch ends at a junction (a point
// where some arrival has several ways out), each (event point, direction)
// leaving it is reached with (K + w + [the direction changed], R). Every
// branch with an event at a junction ends its stretch there, whichever way
// it arrives, so every branch reaching a branch state reaches it by such an
// edge. Edge weights are never negative and keep the ray, so the order is
// preserved and labels settle in increasing order: each branch state with
// the least label over every branch reaching it, and a target's best
// candidate is final once it is <= the least label still waiting, as
// nothing expanded later can offer less.
#include "engine/illumination.hpp"

#include "engine/branch_search_answer.hpp"
#include "engine/branch_state_set.hpp"
#include "engine/branch_witness.hpp"
#include "engine/explored_states.hpp"
#include "engine/lattice_stepper.hpp"
#include "engine/stretch.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <tuple>

namespace orthoray::engine {
namespace {

struct Label {
    std::uint64_t reflections = 0;
    std::uint32_t ray = 0; // from 1
    bool operator<(const Label& other) const {
        return std::tie(reflections, ray) < std::tie(other.reflections, other.ray);
    }
    bool operator==(const Label&) const = default;
};

// What is kept per branch state besides its key: 16 bytes.
struct Record {
    std::uint64_t reflections;
    std::uint32_t ray : 31;
    std::uint32_t settled : 1;
    std::uint32_t parent; // the branch state whose expansion gave the label
};

// A queue entry; one left behind by a better label later is skipped.
struct Waiting {
    Label label;
    std::uint32_t state;
    bool operator>(const Waiting& other) const {
        return std::tie(label, state) > std::tie(other.label, other.state);
    }
};

// A target's least candidate so far: the branch state whose stretch passes
// it, w reflections in.
struct Candidate {
    bool found = false;
    Label label;
    std::uint32_t branch = 0;

    bool beaten_by(const Label& other) const { return !found || other < label; }
};

class IlluminationSearch {
public:
    // With no stepper given, run() builds the fastest that suits the scene.
    IlluminationSearch(const Scene& scene, const SolveOptions& options, const EventStepper* stepper)
        : scene_(scene), options_(options), stepper_(stepper), budget_(options.max_state_bytes),
          states_(scene, budget_), best_(scene.targets.size()) {}

    Answer run() {
        if (!stepper_) {
            // The lattices' shooters take O(n) memory and time each: built
            // here, where running out of memory is a memory limit like any
            // other and a stop request is polled for once an element.
            std::optional<Limit> stopped;
            try {
                owned_ = fastest_stepper(scene_, lattice::SetupPoll(options_.monitor, 0),
                                         options_.max_state_bytes);
            } catch (const std::bad_alloc&) {
                stopped = Limit::memory;
            } catch (const lattice::SetupStopped& stop) {
                stopped = stop.limit;
            }
            if (stopped) return stopped_in_setup(*stopped);
            stepper_ = owned_.get();
        }
        try {
            explored_.emplace(*stepper_, budget_);
            search();
            if (!limit_) count_explored();
        } catch (const std::bad_alloc&) {
            limit_ = Limit::memory;
        }
        Answer answer = conclude();
        if (options_.illumination_observer) report(answer, *options_.illumination_observer);
        return answer;
    }

private:
    using Clock = std::chrono::steady_clock;

    // A limit met while the shooters were built: nothing was stepped, but a
    // target at a ray's start is lit all the same, with 0 reflections, as
    // under `--max-steps 0`. The reference scan needs no setup, so the
    // search with it and no step allowed reports those, and the limit is
    // the one met.
    Answer stopped_in_setup(Limit limit) const {
        const ReferenceStepper scan(scene_);
        SolveOptions no_steps = options_;
        no_steps.max_steps = 0;
        Answer answer = IlluminationSearch(scene_, no_steps, &scan).run();
        answer.limit = limit;
        return answer;
    }

    void search() {
        for (std::size_t r = 0; r < scene_.rays.size(); ++r) {
            const Label start{0, static_cast<std::uint32_t>(r + 1)};
            const std::optional<std::uint32_t> state =
                reach(scene_.rays[r].start, scene_.rays[r].direction, start, no_parent);
            if (!state) {
                limit_ = Limit::memory;
                return;
            }
            ray_starts_.push_back(*state);
            // A target at a ray's start is lit with 0 reflections before
            // any event is stepped, so even a cap of 0 steps reports it (it
            // is final once no ray numbered lower is still waiting).
            for (std::size_t t = 0; t < best_.size(); ++t)
                if (scene_.targets[t] == scene_.rays[r].start) offer(t, start, *state);
        }
        for (;;) {
            const std::optional<Waiting> next = pop();
            if (!next) return; // every reachable branch state is expanded
            // Without a certificate to write, stop once every target is lit
            // with a final count.
            if (!options_.illumination_observer && all_final(next->label)) return;
            pending_ = next->label;
            if (!poll()) return;
            records_[next->state].settled = 1;
            ++expanded_;
            if (!expand(next->state, next->label)) return;
            if (finished_) return;
            pending_.reset();
        }
    }

    // Target t is passed with `label` by the stretch of branch state `branch`:
    // kept when it is the least so far.
    void offer(std::size_t t, Label label, std::uint32_t branch) {
        Candidate& c = best_[t];
        if (!c.beaten_by(label)) return;
        if (!c.found) --unfound_;
        c = {true, label, branch};
        if (unfound_ == 0) {
            worst_ = best_.front().label;
            for (const Candidate& other : best_) worst_ = std::max(worst_, other.label);
        }
    }

    // Every target has a candidate no later stretch can beat, with `open`
    // the least label the stretch being walked can still offer: without a
    // certificate to write the search is done, even in the middle of a
    // stretch that would run for 10^70 events. The heap's top bounds every
    // waiting label from below (an entry left behind only lowers it).
    bool done_within(const Label& open) const {
        if (options_.illumination_observer || unfound_ != 0 || open < worst_) return false;
        return queue_.empty() || !(queue_.front().label < worst_);
    }

    // The least waiting entry whose state is not settled and still carries
    // that label; nullopt when none is left.
    std::optional<Waiting> pop() {
        while (!queue_.empty()) {
            std::pop_heap(queue_.begin(), queue_.end(), std::greater<>{});
            const Waiting w = queue_.back();
            queue_.pop_back();
            const Record& r = records_[w.state];
            if (!r.settled && Label{r.reflections, r.ray} == w.label) return w;
        }
        return std::nullopt;
    }

    bool all_final(const Label& least_waiting) const {
        for (const Candidate& c : best_)
            if (!c.found || least_waiting < c.label) return false;
        return true;
    }

    // Polls the monitor about every 10 ms; false (limit_ set) to stop.
    bool poll() {
        limit_ = ask_monitor();
        return !limit_;
    }

    // The limit the monitor reports, asked about every 10 ms.
    std::optional<Limit> ask_monitor() {
        if (!options_.monitor) return std::nullopt;
        const Clock::time_point now = Clock::now();
        if (now < next_poll_) return std::nullopt;
        next_poll_ = now + std::chrono::milliseconds(10);
        return options_.monitor->poll(expanded_);
    }

    // Reaches (p, v) with `label` from `parent`: its branch state's number,
    // or nullopt when the budget refuses room for it.
    std::optional<std::uint32_t> reach(const Vector& p, const Vector& v, Label label,
                                       std::uint32_t parent) {
        if (!budget_.make_room(records_) || !budget_.make_room(queue_)) return std::nullopt;
        const std::optional<BranchStateSet::Inserted> at = states_.insert(p, v);
        if (!at) return std::nullopt;
        if (at->added) {
            records_.push_back({label.reflections, label.ray, 0, parent});
        } else {
            Record& r = records_[at->index];
            if (r.settled || !(label < Label{r.reflections, r.ray})) return at->index;
            r.reflections = label.reflections;
            r.ray = label.ray;
            r.parent = parent;
        }
        queue_.push_back({label, at->index});
        std::push_heap(queue_.begin(), queue_.end(), std::greater<>{});
        return at->index;
    }

    // Walks the stretch of branch state `b`; false (limit_ set) when a limit
    // cut it short.
    bool expand(std::uint32_t b, Label label) {
        Vector p, v;
        states_.state(b, p, v);
        const StretchEnd end = walk_stretch(
            *stepper_, p, v,
            [&](const Vector& q, const Vector& u, std::uint64_t w, const ReferenceEvent& e) {
                // The segment from q is w reflections into the stretch: it
                // and every later one offer at least `here` (once it is
                // credited, `pending_` says so to a limit).
                const Label here{label.reflections + w, label.ray};
                // --max-steps caps the events stepped in all stretches
                // together, not the branch states: one stretch alone can
                // be 10^70 reflections long before it repeats.
                if (options_.max_steps && events_ == *options_.max_steps) {
                    limit_ = Limit::steps;
                    return false;
                }
                ++events_;
                for (std::size_t t = 0; t < best_.size(); ++t)
                    if (best_[t].beaten_by(here) && stepper_->passes(scene_.targets[t], q, u, e))
                        offer(t, here, b);
                if (done_within(here)) {
                    finished_ = true;
                    return false;
                }
                pending_ = here;
                return poll();
            });
        if (finished_) return true;
        if (end.kind == StretchEnd::Kind::stopped) return false;
        if (!explored_->walked(b, end)) {
            limit_ = Limit::memory;
            return false;
        }
        if (end.kind != StretchEnd::Kind::junction) return true;
        for (const Outgoing& out : end.outgoing) {
            const Label child{label.reflections + end.reflections + (out.reflection ? 1 : 0),
                              label.ray};
            if (!reach(end.point, out.direction, child, b)) {
                limit_ = Limit::memory;
                return false;
            }
        }
        return true;
    }

    // The distinct states explored (explored_states.hpp). The search has
    // answered by now, so a limit met while counting (time, a signal,
    // memory) leaves the answer as it is and `states` at the branch states
    // stored, a lower bound, as after a limit in the search.
    void count_explored() {
        try {
            explored_count_ =
                explored_->count(states_, ray_starts_, [&] { return !ask_monitor(); });
        } catch (const std::bad_alloc&) {
            explored_count_.reset();
        }
    }

    Answer conclude() {
        Answer answer;
        answer.engine = EngineUsed::branches;
        answer.arithmetic = ArithmeticUsed::rational;
        if (stepper_) stepper_->describe(answer);
        // At a limit a candidate is final only when no waiting branch state
        // (nor the stretch cut short) has a smaller label; a target with a
        // candidate is lit either way (optics.md: a limit reports the
        // targets lit so far).
        std::optional<Label> least = pending_;
        if (limit_)
            for (const Waiting& w : queue_) {
                const Record& r = records_[w.state];
                if (!r.settled && Label{r.reflections, r.ray} == w.label &&
                    (!least || w.label < *least))
                    least = w.label;
            }
        conclude_targets(answer, best_.size(), limit_, [&](std::size_t t, TargetAnswer& target) {
            const Candidate& c = best_[t];
            if (!c.found) return false;
            target.reflections = Integer(static_cast<unsigned long>(c.label.reflections));
            target.ray = c.label.ray;
            target.best_proven = !(limit_ && least && *least < c.label);
            return true;
        });
        answer.states = Integer(
            static_cast<unsigned long>(explored_count_ ? *explored_count_ : states_.size()));
        answer.states_lower_bound = !explored_count_;
        answer.stats.illumination = {expanded_, events_, budget_.used()};
        return answer;
    }

    // The evidence, for a certificate: every branch state with its label,
    // then each target's verdict, with a witness when it is lit.
    void report(const Answer& answer, IlluminationObserver& observer) const {
        Vector p, v;
        for (std::uint32_t s = 0; s < states_.size(); ++s) {
            states_.state(s, p, v);
            observer.branch(p, v, records_[s].ray, records_[s].reflections);
        }
        report_targets(answer, observer, [&](std::size_t t) {
            observer.lit(t + 1, best_[t].label.reflections, best_[t].label.ray);
            witness(t, observer);
        });
    }

    void witness(std::size_t t, IlluminationObserver& observer) const {
        replay_witness(
            states_, *stepper_, [&](std::uint32_t s) { return records_[s].parent; },
            best_[t].branch, scene_.targets[t], observer);
    }

    const Scene& scene_;
    const SolveOptions& options_;
    const EventStepper* stepper_;
    std::unique_ptr<EventStepper> owned_; // the stepper run() built, if any
    ByteBudget budget_;
    BranchStateSet states_;
    std::vector<Record> records_;
    std::vector<Waiting> queue_; // a binary heap, least label on top
    std::vector<Candidate> best_;
    std::vector<std::uint32_t> ray_starts_; // each ray's branch state
    std::optional<ExploredStates> explored_;
    std::optional<std::uint64_t> explored_count_;
    std::optional<Limit> limit_;
    // The least label the stretch being walked can still offer (its branch
    // state's, raised by the reflections walked): the least still open.
    std::optional<Label> pending_;
    std::size_t unfound_ = best_.size(); // targets without a candidate
    Label worst_;                        // the largest candidate once every target has one
    bool finished_ = false;              // every target got a final candidate in mid-stretch
    std::uint64_t expanded_ = 0, events_ = 0;
    Clock::time_point next_poll_ = Clock::now();
};

} // namespace

Answer solve_illumination(const Scene& scene, const SolveOptions& options,
                          const EventStepper& stepper) {
    return IlluminationSearch(scene, options, &stepper).run();
}

Answer solve_illumination(const Scene& scene, const SolveOptions& options) {
    return IlluminationSearch(scene, options, nullptr).run();
}

} // namespace orthoray::engine
