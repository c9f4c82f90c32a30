// An InductionObserver that counts what it is shown: the steps (an
// accelerated one counting once, as InducedOrbit::steps does), the
// accelerated ones, and the exchange it began with.
#pragma once

#include "orthoray/exchange.hpp"

#include <cstddef>
#include <cstdint>

namespace orthoray::test {

class CountingObserver : public InductionObserver {
public:
    int begun = 0;
    std::size_t pieces = 0;
    Integer states;
    std::uint64_t steps = 0, rounds = 0;
    bool begin(const IntervalExchange& exchange, const std::function<bool()>&) override {
        ++begun;
        pieces = exchange.pieces.size();
        states = exchange.size;
        return true;
    }
    void top(std::size_t, std::size_t) override { ++steps; }
    void bottom(std::size_t, std::size_t) override { ++steps; }
    void equal(std::size_t, std::size_t) override { ++steps; }
    void invariant(std::size_t) override { ++steps; }
    void top_cycle(std::size_t, const Integer&) override { ++steps, ++rounds; }
    void bottom_cycle(std::size_t, const Integer&) override { ++steps, ++rounds; }
};

} // namespace orthoray::test
