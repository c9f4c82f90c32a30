// Rauzy-Zorich induction on bare interval exchanges: against iterating the
// map point by point on thousands of random small exchanges, and against
// the closed form of a rotation far too long to iterate.
#include "induction/rauzy_induction.hpp"
#include "support/portable_random.hpp"

#include "support/counting_observer.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

using namespace orthoray;
using namespace orthoray::induction;

namespace {

// Pieces with these lengths (piece 0 has length 1: x), images in the order
// `image_order`, and the given events.
IntervalExchange make_exchange(const std::vector<long>& lengths,
                               const std::vector<std::size_t>& image_order,
                               const std::vector<ExchangeEvent>& events) {
    IntervalExchange e;
    Integer at = 0;
    for (std::size_t i = 0; i < lengths.size(); ++i) {
        ExchangePiece p;
        p.start = at;
        p.length = lengths[i];
        at += lengths[i];
        p.hit = events[i] == ExchangeEvent::hit;
        p.kind = events[i] == ExchangeEvent::escape     ? PieceKind::escape
                 : events[i] == ExchangeEvent::absorbed ? PieceKind::absorbed
                                                        : PieceKind::reflect;
        e.pieces.push_back(p);
    }
    e.size = at;
    Integer image = 0;
    for (std::size_t i : image_order) {
        e.pieces[i].image = image;
        image += lengths[i];
    }
    return e;
}

// The orbit of 0, one point at a time.
InducedOrbit iterate(const IntervalExchange& e) {
    InducedOrbit orbit;
    Integer p = 0;
    for (long t = 0;; ++t) {
        std::size_t i = 0;
        while (!(e.pieces[i].start <= p && p < e.pieces[i].start + e.pieces[i].length)) ++i;
        const ExchangePiece& piece = e.pieces[i];
        const ExchangeEvent event = piece.hit                           ? ExchangeEvent::hit
                                    : piece.kind == PieceKind::escape   ? ExchangeEvent::escape
                                    : piece.kind == PieceKind::absorbed ? ExchangeEvent::absorbed
                                                                        : ExchangeEvent::none;
        if (event != ExchangeEvent::none) {
            orbit.event = event;
            orbit.offset = t;
            return orbit;
        }
        p += piece.image - piece.start;
        if (p == 0) {
            orbit.period = t + 1;
            return orbit;
        }
    }
}

} // namespace

TEST_CASE("induction finds the orbit of x on random small exchanges", "[rauzy]") {
    std::mt19937_64 rng(11);
    int with_event = 0, cycles = 0, accelerated = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const std::size_t k = test::pick_index(rng, 1, 9);
        std::vector<long> lengths(k, 1);
        for (std::size_t i = 1; i < k; ++i) lengths[i] = test::pick(rng, 1, trial % 2 ? 40 : 4);
        std::vector<std::size_t> order(k);
        std::iota(order.begin(), order.end(), std::size_t{0});
        test::shuffle(order, rng);
        std::vector<ExchangeEvent> events(k, ExchangeEvent::none);
        for (auto& ev : events) {
            const int roll = test::pick(rng, 0, 9);
            ev = roll == 0   ? ExchangeEvent::hit
                 : roll == 1 ? ExchangeEvent::escape
                 : roll == 2 ? ExchangeEvent::absorbed
                             : ExchangeEvent::none;
        }
        const IntervalExchange e = make_exchange(lengths, order, events);
        // The steps an observer receives, to hold the engine's own count to it.
        test::CountingObserver sink;
        const auto induced = induce(e, &sink, {});
        REQUIRE(induced);
        const InducedOrbit expected = iterate(e);
        INFO("trial " << trial);
        REQUIRE(induced->event == expected.event);
        if (expected.event == ExchangeEvent::none) {
            REQUIRE(induced->period == expected.period);
            ++cycles;
        } else {
            REQUIRE(induced->offset == expected.offset);
            ++with_event;
        }
        REQUIRE(sink.steps == induced->steps);
        REQUIRE(sink.rounds == induced->rounds);
        accelerated += induced->rounds > 0;
    }
    CHECK(with_event > 1000);
    CHECK(cycles > 1000);
    CHECK(accelerated > 500);
}

TEST_CASE("induction gives a rotation's period in few steps", "[rauzy]") {
    // Rotation by a on [0, N): 0 -> a, with x = [0, 1) cut off the first
    // piece. The orbit of 0 has period N / gcd(N, a).
    const Integer n = Integer("1000000000000000000000000000057"); // 10^30 + 57
    for (const Integer& a : {Integer(1), Integer("618033988749894848204586834365"),
                             Integer("333333333333333333333333333352"), Integer(2)}) {
        IntervalExchange e;
        e.size = n;
        auto piece = [](const Integer& start, const Integer& length, const Integer& image) {
            ExchangePiece p;
            p.start = start;
            p.length = length;
            p.image = image;
            return p;
        };
        e.pieces = {piece(0, 1, a), piece(1, n - a - 1, a + 1), piece(n - a, a, 0)};
        const auto orbit = induce(e, nullptr, {});
        REQUIRE(orbit);
        Integer g;
        mpz_gcd(g.get_mpz_t(), n.get_mpz_t(), a.get_mpz_t());
        REQUIRE(orbit->event == ExchangeEvent::none);
        REQUIRE(orbit->period == n / g);
        // Acceleration makes it Euclid's algorithm: O(log N) steps.
        CHECK(orbit->steps < 400);
    }
}

TEST_CASE("induction takes about k log N steps, and stops when asked", "[rauzy]") {
    // 2,000 pieces of up to 2^60 states, images in random order.
    std::mt19937_64 rng(5);
    const std::size_t k = 2000;
    std::vector<long> lengths(k, 1);
    for (std::size_t i = 1; i < k; ++i) lengths[i] = uniform(rng, 1, std::int64_t{1} << 60);
    std::vector<std::size_t> order(k);
    std::iota(order.begin(), order.end(), std::size_t{0});
    test::shuffle(order, rng);
    const IntervalExchange e = make_exchange(lengths, order, std::vector<ExchangeEvent>(k));
    int polls = 0;
    CHECK_FALSE(induce(e, nullptr, [&](std::uint64_t) { return ++polls > 0; }));
    CHECK(polls == 1);
    const auto orbit = induce(e, nullptr, {});
    REQUIRE(orbit);
    const double log_n = static_cast<double>(mpz_sizeinbase(e.size.get_mpz_t(), 2));
    WARN(orbit->steps << " steps, " << orbit->rounds
                      << " accelerated, k log2 N = " << static_cast<double>(k) * log_n);
    // Without acceleration a step can cost as little as one state.
    CHECK(static_cast<double>(orbit->steps) < 2.0 * static_cast<double>(k) * log_n);
}
