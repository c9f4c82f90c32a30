// The checker's replay of induction steps (certify/replayed_exchange.cpp)
// against the real induction (induction/rauzy_induction.cpp): on thousands
// of seeded random exchanges, every step the engine takes is accepted by the
// replay, the replay's positions stay two tilings of [0, L), and x's final
// piece gives the engine's answer (which test_rauzy_induction.cpp holds to
// the orbit iterated point by point). Naming any other piece in a step is
// rejected. The two sides share no code: the test is where they meet.
#include "certify/induction_check_failure.hpp"
#include "certify/replayed_exchange.hpp"
#include "induction/rauzy_induction.hpp"

#include "orthoray/generate.hpp"

#include "support/case_count.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

using namespace orthoray;
namespace check = orthoray::certify::induction_check;

namespace {

// A random exchange: piece 0 is x = [0, 1), the others have lengths in
// [1, max_length], images in a random order, and an event one time in ten
// each (hit, escape or absorbed).
IntervalExchange random_exchange(std::mt19937_64& rng, std::int64_t max_length) {
    const auto k = static_cast<std::size_t>(uniform(rng, 1, 9));
    IntervalExchange e;
    Integer at = 0;
    for (std::size_t i = 0; i < k; ++i) {
        ExchangePiece p;
        p.start = at;
        p.length = i == 0 ? 1 : uniform(rng, 1, max_length);
        at += p.length;
        const std::int64_t roll = uniform(rng, 0, 9);
        p.hit = roll == 0;
        p.kind = roll == 1   ? PieceKind::escape
                 : roll == 2 ? PieceKind::absorbed
                             : PieceKind::reflect;
        e.pieces.push_back(p);
    }
    e.size = at;
    std::vector<std::size_t> order(k);
    for (std::size_t i = 0; i < k; ++i) order[i] = i;
    for (std::size_t i = k; i > 1; --i) // Fisher-Yates on uniform()
        std::swap(
            order[i - 1],
            order[static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(i) - 1))]);
    Integer image = 0;
    for (std::size_t i : order) {
        e.pieces[i].image = image;
        image += e.pieces[i].length;
    }
    return e;
}

std::vector<check::PieceSpec> specs_of(const IntervalExchange& e) {
    std::vector<check::PieceSpec> specs;
    for (const ExchangePiece& p : e.pieces) {
        check::PieceSpec s;
        s.start = p.start;
        s.length = p.length;
        s.image = p.image;
        s.hit = p.hit;
        s.kind = p.kind == PieceKind::escape     ? check::Kind::escape
                 : p.kind == PieceKind::absorbed ? check::Kind::absorbed
                                                            : check::Kind::reflect;
        specs.push_back(s);
    }
    return specs;
}

// The engine's steps, in the certificate's words.
class RecordedSteps : public InductionObserver {
public:
    std::vector<check::StepSpec> steps;
    void top(std::size_t d, std::size_t r) override { add(check::StepKind::top, d, r); }
    void bottom(std::size_t r, std::size_t d) override { add(check::StepKind::bottom, r, d); }
    void equal(std::size_t r, std::size_t d) override { add(check::StepKind::equal, r, d); }
    void invariant(std::size_t d) override { add(check::StepKind::invariant, d, 0); }
    void top_cycle(std::size_t d, const Integer& rounds) override {
        add(check::StepKind::top_cycle, d, rounds);
    }
    void bottom_cycle(std::size_t r, const Integer& rounds) override {
        add(check::StepKind::bottom_cycle, r, rounds);
    }

private:
    void add(check::StepKind kind, std::size_t first, const Integer& second) {
        steps.push_back({kind, Integer(static_cast<unsigned long>(first)), second});
    }
};

// The live pieces' domains and images each tile [0, L).
bool tiles(const check::ReplayedExchange& replay) {
    std::vector<std::pair<Integer, Integer>> domains, images;
    for (const check::ReplayedPiece& p : replay.pieces()) {
        if (p.removed) continue;
        if (sgn(p.length) <= 0) return false;
        domains.emplace_back(p.domain_start, p.length);
        images.emplace_back(p.image_start, p.length);
    }
    for (auto* intervals : {&domains, &images}) {
        std::sort(intervals->begin(), intervals->end());
        Integer end = 0;
        for (const auto& [start, length] : *intervals) {
            if (start != end) return false;
            end += length;
        }
        if (end != replay.induced_length()) return false;
    }
    return true;
}

check::FirstEvent::Kind kind_of(ExchangeEvent event) {
    switch (event) {
    case ExchangeEvent::hit:
        return check::FirstEvent::hit;
    case ExchangeEvent::escape:
        return check::FirstEvent::escape;
    case ExchangeEvent::absorbed:
        return check::FirstEvent::absorbed;
    case ExchangeEvent::none:
        break;
    }
    return check::FirstEvent::none;
}

} // namespace

TEST_CASE("the replayed exchange follows the induction on random exchanges", "[replay]") {
    std::mt19937_64 rng(19);
    int events = 0, cycles = 0, accelerated = 0;
    const int trials = test::case_count(4000);
    for (int trial = 0; trial < trials; ++trial) {
        // Small lengths, then lengths up to 2^40, where the accelerated
        // (cycle) steps take over.
        const std::int64_t max_length = trial % 2 ? std::int64_t{1} << 40 : (trial % 4 ? 40 : 4);
        const IntervalExchange e = random_exchange(rng, max_length);
        RecordedSteps recorded;
        const auto orbit = induction::induce(e, &recorded, {});
        REQUIRE(orbit);
        INFO("trial " << trial);

        check::ReplayedExchange replay(specs_of(e), e.size);
        for (const check::StepSpec& step : recorded.steps) {
            INFO(check::step_text(step));
            try {
                replay.apply(step);
            } catch (const check::CheckFailure& failure) {
                FAIL(failure.message);
            }
            REQUIRE(tiles(replay));
        }
        REQUIRE(replay.steps_applied() == orbit->steps);
        const check::ReplayedPiece& x = replay.first_alone();
        REQUIRE(x.event.kind == kind_of(orbit->event));
        if (orbit->event == ExchangeEvent::none) {
            REQUIRE(x.return_time == orbit->period);
            ++cycles;
        } else {
            REQUIRE(x.event.offset == orbit->offset);
            ++events;
        }
        accelerated += orbit->rounds > 0;
    }
    CHECK(events > trials / 4);
    CHECK(cycles > trials / 8);
    CHECK(accelerated > trials / 8);
}

TEST_CASE("the replayed exchange rejects a step naming another piece", "[replay]") {
    // Only one live piece's domain, and one's image, ends at L: a step that
    // names any other piece in either place must fail its condition.
    std::mt19937_64 rng(23);
    int tampered = 0;
    const int trials = test::case_count(1000);
    for (int trial = 0; trial < trials; ++trial) {
        const IntervalExchange e = random_exchange(rng, 40);
        RecordedSteps recorded;
        REQUIRE(induction::induce(e, &recorded, {}));
        if (recorded.steps.empty()) continue;
        const auto at = static_cast<std::size_t>(uniform(rng, 0, std::ssize(recorded.steps) - 1));
        check::StepSpec wrong = recorded.steps[at];
        const bool names_two = wrong.kind == check::StepKind::top ||
                               wrong.kind == check::StepKind::bottom ||
                               wrong.kind == check::StepKind::equal;
        Integer& named = names_two && uniform(rng, 0, 1) ? wrong.second : wrong.first;
        const auto pieces = static_cast<std::int64_t>(e.pieces.size());
        const Integer other = (named + uniform(rng, 1, pieces)) % (pieces + 1);
        if (other == named) continue;
        named = other;
        INFO("trial " << trial << ", " << check::step_text(wrong));
        check::ReplayedExchange replay(specs_of(e), e.size);
        for (std::size_t s = 0; s < at; ++s) replay.apply(recorded.steps[s]);
        REQUIRE_THROWS_AS(replay.apply(wrong), check::CheckFailure);
        ++tampered;
    }
    CHECK(tampered > trials / 2);
}
