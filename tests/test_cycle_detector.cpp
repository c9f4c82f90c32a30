// Both detectors report the least period, and Brent also handles a tail.
#include "engine/cycle_detector.hpp"

#include <catch2/catch.hpp>

#include <map>

using namespace orthoray::engine;

namespace {

// The least period of x -> f(x) from x1, by remembering every state.
template <class F>
std::uint64_t brute_period(std::uint64_t x1, F f) {
    std::map<std::uint64_t, std::uint64_t> seen;
    std::uint64_t x = x1;
    for (std::uint64_t i = 1;; ++i, x = f(x)) {
        auto [it, fresh] = seen.emplace(x, i);
        if (!fresh) return i - it->second;
    }
}

template <class Detector, class F>
std::uint64_t detect(std::uint64_t x1, F f) {
    Detector d;
    std::uint64_t x = x1;
    for (std::uint64_t i = 1;; ++i, x = f(x))
        if (auto p = d.observe(x, i)) return *p;
}

} // namespace

TEST_CASE("both detectors find the period of a permutation's cycle", "[cycle]") {
    for (std::uint64_t n : {1u, 2u, 3u, 10u, 97u, 1000u, 4097u})
        for (std::uint64_t a : {1u, 3u, 7u}) {
            auto f = [=](std::uint64_t x) { return (x + a) % n; }; // injective
            const std::uint64_t expected = brute_period(0, f);
            CHECK(detect<FirstStateDetector<std::uint64_t>>(0, f) == expected);
            CHECK(detect<BrentDetector<std::uint64_t>>(0, f) == expected);
        }
}

TEST_CASE("Brent finds the period after a tail", "[cycle]") {
    for (std::uint64_t m : {101u, 1009u, 65537u})
        for (std::uint64_t x1 : {2u, 5u, 17u}) {
            auto f = [=](std::uint64_t x) { return (x * x + 1) % m; }; // not injective
            CHECK(detect<BrentDetector<std::uint64_t>>(x1, f) == brute_period(x1, f));
        }
}

TEST_CASE("brent_detection says at which reflection Brent's detector stops", "[cycle]") {
    // States 1, 2, ..., mu - 1 on the tail, then mu .. mu + lambda - 1 round
    // the cycle: s_i = i for i < mu + lambda, then back to mu.
    for (std::uint64_t mu = 1; mu <= 40; ++mu)
        for (std::uint64_t lambda = 1; lambda <= 40; ++lambda) {
            BrentDetector<std::uint64_t> d;
            std::uint64_t reflection = 1, s = 1;
            while (!d.observe(s, reflection)) {
                ++reflection;
                s = s + 1 < mu + lambda ? s + 1 : mu;
            }
            INFO("mu " << mu << ", lambda " << lambda);
            CHECK(brent_detection(mu, lambda) == reflection);
        }
}
