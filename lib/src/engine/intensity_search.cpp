// The most intense branch first (docs/intensity.md).
//
// A label is a pair (intensity, ray): one label comes before another when
// its intensity is greater, or equal with a smaller ray. A ray's start
// begins with (its intensity, ray). Expanding a branch state with intensity
// I walks its stretch (stretch.hpp): after every event the intensity becomes
// floor(I * f), f the factor of the direction leaving it
// (event_rule.hpp, outgoing_factor); a target passed on the way gets the
// candidate (intensity there, ray), and where the stretch ends at a junction
// each direction leaving it reaches its branch state with floor(I * f).
// Every factor is at most 1, so intensities never grow along a branch, and
// I -> floor(I * f) is monotone, so the more intense of two labels at a
// state stays at least as intense along every continuation. Hence, as in
// Dijkstra's algorithm (and Isobe et al.'s order over their objects), the
// first time a state is popped its intensity is the greatest over all
// branches reaching it, and a target's best candidate is final once no
// waiting state is more intense. A stretch stops as soon as its intensity
// is <= the threshold: nothing after it can light a target.
#include "engine/intensity_search.hpp"

#include "engine/branch_search_answer.hpp"
#include "engine/branch_state_set.hpp"
#include "engine/branch_witness.hpp"
#include "engine/lattice_stepper.hpp"
#include "engine/stretch.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <new>
#include <stdexcept>

namespace orthoray::engine {
namespace {

// What is kept per branch state besides its key.
struct Record {
    Integer intensity;
    std::uint64_t reflections; // of the branch that gave the intensity
    std::uint32_t ray;         // from 1
    std::uint32_t parent;      // the state whose stretch gave it; no_parent at a ray's start
    bool settled;
};

// A queue entry; one left behind by a more intense label later is skipped.
struct Waiting {
    Integer intensity;
    std::uint32_t ray, state;
};

// Whether `a` is served after `b`: the heap keeps the first served on top.
bool after(const Waiting& a, const Waiting& b) {
    if (a.intensity != b.intensity) return a.intensity < b.intensity;
    if (a.ray != b.ray) return a.ray > b.ray;
    return a.state > b.state;
}

// A target's most intense candidate so far.
struct Candidate {
    bool found = false;
    Integer intensity;
    std::uint32_t ray = 0;
    std::uint64_t reflections = 0;
    std::uint32_t branch = 0; // the state whose stretch passes the target

    // Whether a branch of ray `from` passing the target with intensity `by`
    // replaces this candidate: more intense, or as intense from a smaller ray.
    bool beaten_by(const Integer& by, std::uint32_t from) const {
        return !found || intensity < by || (by == intensity && from < ray);
    }
};

// The heap bytes of a big integer's digits, for the byte budget: an
// intensity of a million digits takes as much room as thousands of states.
// Counted from the value, so a copy frees what the original was charged.
std::size_t digit_bytes(const Integer& n) {
    return mpz_size(n.get_mpz_t()) * sizeof(mp_limb_t);
}

// floor(intensity * factor): the intensity after an event (intensity >= 0).
Integer attenuated(const Integer& intensity, const Rational& factor) {
    if (factor == 1) return intensity;
    Integer product = intensity * factor.get_num();
    mpz_fdiv_q(product.get_mpz_t(), product.get_mpz_t(), factor.get_den().get_mpz_t());
    return product;
}

class IntensitySearch {
public:
    IntensitySearch(const Scene& scene, const SolveOptions& options, const EventStepper& stepper)
        : scene_(scene), options_(options), stepper_(stepper), threshold_(*options.min_intensity),
          budget_(options.max_state_bytes), states_(scene, budget_), best_(scene.targets.size()) {}

    Answer run() {
        try {
            search();
        } catch (const std::bad_alloc&) {
            limit_ = Limit::memory;
        }
        Answer answer = conclude();
        if (options_.intensity_observer) report(answer, *options_.intensity_observer);
        return answer;
    }

private:
    using Clock = std::chrono::steady_clock;

    void search() {
        for (std::size_t r = 0; r < scene_.rays.size(); ++r) {
            const Ray& ray = scene_.rays[r];
            if (*ray.intensity <= threshold_) continue; // it lights nothing
            const auto number = static_cast<std::uint32_t>(r + 1);
            const std::optional<std::uint32_t> state =
                reach(ray.start, ray.direction, *ray.intensity, 0, number, no_parent);
            if (!state) {
                limit_ = Limit::memory;
                return;
            }
            // A target at a ray's start is lit by it with 0 reflections
            // before any event is stepped: even a cap of 0 steps reports it
            // once no waiting ray is more intense (or as intense and lower).
            for (std::size_t t = 0; t < best_.size(); ++t) {
                Candidate& c = best_[t];
                if (scene_.targets[t] == ray.start && c.beaten_by(*ray.intensity, number))
                    c = {true, *ray.intensity, number, 0, *state};
            }
        }
        for (;;) {
            const std::optional<Waiting> next = pop();
            if (!next) return; // every branch state above the threshold is expanded
            if (all_final(next->intensity)) return;
            pending_ = next->intensity;
            if (!poll()) return;
            Record& record = records_[next->state];
            record.settled = true;
            ++expanded_;
            if (!expand(next->state, record.intensity, record.reflections, record.ray)) return;
            pending_.reset();
        }
    }

    // The first entry to serve whose state is unsettled and still carries
    // that label; nullopt when none is left.
    std::optional<Waiting> pop() {
        while (!queue_.empty()) {
            std::pop_heap(queue_.begin(), queue_.end(), after);
            Waiting w = std::move(queue_.back());
            queue_.pop_back();
            budget_.freed(digit_bytes(w.intensity));
            const Record& r = records_[w.state];
            if (!r.settled && r.intensity == w.intensity && r.ray == w.ray) return w;
        }
        return std::nullopt;
    }

    // Every target has a candidate no waiting state can beat: a state with
    // intensity I gives nothing more intense than I.
    bool all_final(const Integer& most_waiting) const {
        for (const Candidate& c : best_)
            if (!c.found || c.intensity < most_waiting) return false;
        return true;
    }

    // Polls the monitor about every 10 ms; false (limit_ set) to stop.
    bool poll() {
        if (!options_.monitor) return true;
        const Clock::time_point now = Clock::now();
        if (now < next_poll_) return true;
        next_poll_ = now + std::chrono::milliseconds(10);
        limit_ = options_.monitor->poll(expanded_);
        return !limit_;
    }

    // Reaches (p, v) with this label from the stretch of `parent`: its
    // branch state's number, or nullopt when the budget refuses room (the
    // intensity's digits are counted twice: the record's copy and the
    // queue's).
    std::optional<std::uint32_t> reach(const Vector& p, const Vector& v, const Integer& intensity,
                                       std::uint64_t reflections, std::uint32_t ray,
                                       std::uint32_t parent) {
        const std::size_t digits = digit_bytes(intensity);
        if (!budget_.make_room(records_) || !budget_.make_room(queue_) || !budget_.fits(2 * digits))
            return std::nullopt;
        const std::optional<BranchStateSet::Inserted> at = states_.insert(p, v);
        if (!at) return std::nullopt;
        const Waiting entry{intensity, ray, at->index};
        if (at->added) {
            records_.push_back({intensity, reflections, ray, parent, false});
        } else {
            Record& r = records_[at->index];
            if (r.settled || !after(Waiting{r.intensity, r.ray, at->index}, entry))
                return at->index;
            budget_.freed(digit_bytes(r.intensity));
            r.intensity = intensity;
            r.reflections = reflections;
            r.ray = ray;
            r.parent = parent;
        }
        budget_.allocated(2 * digits);
        queue_.push_back(entry);
        std::push_heap(queue_.begin(), queue_.end(), after);
        return at->index;
    }

    // Walks the stretch of branch state `b`; false (limit_ set) when a limit
    // cut it short.
    bool expand(std::uint32_t b, Integer intensity, std::uint64_t reflections, std::uint32_t ray) {
        Vector p, v;
        states_.state(b, p, v);
        bool faded = false;
        std::vector<const Element*> junction_acting; // the elements at the junction ending it
        const StretchEnd end = walk_stretch(
            stepper_, p, v,
            [&](const Vector& q, const Vector& u, std::uint64_t w, const ReferenceEvent& e) {
                if (intensity <= threshold_) {
                    faded = true;
                    return false;
                }
                if (options_.max_steps && events_ == *options_.max_steps) {
                    // What the stretch can still offer is no more intense
                    // than this segment, which it has not yet credited.
                    limit_ = Limit::steps;
                    pending_ = intensity;
                    return false;
                }
                ++events_;
                for (std::size_t t = 0; t < best_.size(); ++t) {
                    Candidate& c = best_[t];
                    if (c.beaten_by(intensity, ray) && stepper_.passes(scene_.targets[t], q, u, e))
                        c = {true, intensity, ray, reflections + w, b};
                }
                pending_ = intensity; // the rest of the stretch offers no more
                if (!e.escape && !e.absorbed) {
                    if (e.junction) // the stretch ends here: the factors come below
                        junction_acting = e.acting;
                    else
                        intensity = attenuated(
                            intensity, outgoing_factor(e.acting, u, e.outgoing.front().direction));
                }
                return poll();
            });
        if (end.kind == StretchEnd::Kind::stopped) return faded;
        if (end.kind != StretchEnd::Kind::junction) return true;
        for (const Outgoing& out : end.outgoing) {
            const Integer child =
                attenuated(intensity, outgoing_factor(junction_acting, end.last.v, out.direction));
            if (child <= threshold_) continue;
            if (!reach(end.point, out.direction, child,
                       reflections + end.reflections + (out.reflection ? 1 : 0), ray, b)) {
                limit_ = Limit::memory;
                return false;
            }
        }
        return true;
    }

    Answer conclude() const {
        Answer answer;
        answer.engine = EngineUsed::branches;
        answer.arithmetic = ArithmeticUsed::rational;
        stepper_.describe(answer);
        // At a limit a candidate is final only when no waiting state (nor
        // the one cut short) is more intense.
        std::optional<Integer> most = pending_;
        if (limit_)
            for (const Waiting& w : queue_) {
                const Record& r = records_[w.state];
                if (!r.settled && r.intensity == w.intensity && r.ray == w.ray &&
                    (!most || *most < w.intensity))
                    most = w.intensity;
            }
        conclude_targets(answer, best_.size(), limit_, [&](std::size_t t, TargetAnswer& target) {
            const Candidate& c = best_[t];
            if (!c.found) return false;
            target.best_proven = !(limit_ && most && c.intensity < *most);
            target.intensity = c.intensity;
            target.reflections = Integer(static_cast<unsigned long>(c.reflections));
            target.ray = c.ray;
            return true;
        });
        answer.states = Integer(static_cast<unsigned long>(states_.size()));
        answer.stats.illumination = {expanded_, events_, budget_.used()};
        return answer;
    }

    // The evidence, for a certificate (docs/certificates.md, "The intensity
    // question"): every expanded branch state with its intensity, final
    // when it was expanded, then each target's verdict, with a witness when
    // it is lit. States left waiting when every target's best was final are
    // not listed: no branch through them can pass a target more intensely
    // than the target's best, which is what the checker asks of them.
    void report(const Answer& answer, IntensityObserver& observer) const {
        Vector p, v;
        for (std::uint32_t s = 0; s < states_.size(); ++s) {
            if (!records_[s].settled) continue;
            states_.state(s, p, v);
            observer.branch(p, v, records_[s].intensity);
        }
        report_targets(answer, observer, [&](std::size_t t) {
            observer.lit(t + 1, best_[t].reflections, best_[t].ray, best_[t].intensity);
            witness(t, observer);
        });
    }

    void witness(std::size_t t, IntensityObserver& observer) const {
        replay_witness(
            states_, stepper_, [&](std::uint32_t s) { return records_[s].parent; }, best_[t].branch,
            scene_.targets[t], observer);
    }

    const Scene& scene_;
    const SolveOptions& options_;
    const EventStepper& stepper_;
    const Integer threshold_;
    ByteBudget budget_;
    BranchStateSet states_;
    std::vector<Record> records_;
    std::vector<Waiting> queue_; // a binary heap, the most intense on top
    std::vector<Candidate> best_;
    std::optional<Limit> limit_;
    // The intensity of the branch state being expanded.
    std::optional<Integer> pending_;
    std::uint64_t expanded_ = 0, events_ = 0;
    Clock::time_point next_poll_ = Clock::now();
};

void check(const Scene& scene, const SolveOptions& options) {
    if (!options.min_intensity || *options.min_intensity < 0)
        throw std::invalid_argument("solve_intensity: min_intensity must be a natural number");
    if (options.illumination_observer || options.induction_observer || options.path)
        throw std::invalid_argument("the intensity search reports to an IntensityObserver only");
    for (const Ray& ray : scene.rays)
        if (!ray.intensity)
            throw UnsupportedScene("the intensity question needs an intensity on every ray (the "
                                   "ray on line " +
                                   std::to_string(ray.line) + " has none)");
}

} // namespace

Answer solve_intensity(const Scene& scene, const SolveOptions& options,
                       const EventStepper& stepper) {
    check(scene, options);
    return IntensitySearch(scene, options, stepper).run();
}

Answer solve_intensity(const Scene& scene, const SolveOptions& options) {
    check(scene, options);
    // The lattices' shooters take O(n) memory and time each: running out of
    // memory while building them is a memory limit like any other, and a
    // stop request is polled for once an element. Stopped there, nothing
    // was stepped, but a target at a ray's start is lit all the same, as
    // under --max-steps 0: the reference scan, which needs no setup, with
    // no step allowed reports it.
    std::unique_ptr<EventStepper> stepper;
    auto stopped = [&](Limit limit) {
        const ReferenceStepper scan(scene);
        SolveOptions no_steps = options;
        no_steps.max_steps = 0;
        Answer answer = IntensitySearch(scene, no_steps, scan).run();
        answer.limit = limit;
        return answer;
    };
    try {
        stepper = options.engine == Engine::reference
                      ? std::make_unique<ReferenceStepper>(scene)
                      : fastest_stepper(scene, lattice::SetupPoll(options.monitor, 0),
                                        options.max_state_bytes);
    } catch (const std::bad_alloc&) {
        return stopped(Limit::memory);
    } catch (const lattice::SetupStopped& stop) {
        return stopped(stop.limit);
    }
    return IntensitySearch(scene, options, *stepper).run();
}

} // namespace orthoray::engine
