// Cycle detectors: both see the states after reflections 1, 2, 3, ... and
// say when the trajectory has shown itself periodic, with the least period.
// Both keep O(1) states, so memory never grows with the number of reflections.
#pragma once

#include "orthoray/solve.hpp" // CycleDetector

#include <cstdint>
#include <optional>

namespace orthoray::engine {

// Whether two different states may step to the same state, so that a
// trajectory can enter its cycle after a tail. One-sided elements do it
// (docs/optics.md), and so do diagonals (docs/octagonal.md): where a
// diagonal and an x-mirror meet, a ray along x goes back along -x, but a
// ray sliding along the x-mirror (parallel to it) is turned by the diagonal
// alone, onto the same -x.
inline bool may_have_tail(const Scene& scene) {
    return scene.has_one_sided() || scene.has_diagonal();
}

// The detector an engine runs: the one asked for when the step map is
// injective (every element two-sided), else Brent's. Comparing with the
// first state is only sound for an injective map: after a tail the
// trajectory never sees its first state again and would run forever. Every
// engine picks its detector through this function, so no path leads to the
// first-state detector on a scene with one-sided elements.
constexpr CycleDetector detector_for(bool one_sided, CycleDetector asked) {
    return one_sided ? CycleDetector::brent : asked;
}

// The step map on states is injective (reflection is reversible), so a
// periodic trajectory is purely periodic from reflection 1 on: it returns to
// state 1 first, and the first return time is the period.
template <class State>
class FirstStateDetector {
public:
    std::optional<std::uint64_t> observe(const State& s, std::uint64_t reflection) {
        if (reflection == 1) {
            first_ = s;
            return std::nullopt;
        }
        if (s == first_) return reflection - 1;
        return std::nullopt;
    }

private:
    State first_{};
};

// Brent's algorithm: a saved state moves to the current one whenever the
// distance reaches a power of two; the first time the current state equals
// the saved one, the distance is the least period. It needs no injectivity
// (it also finds cycles entered after a tail), at the price of noticing the
// cycle up to about twice as late.
template <class State>
class BrentDetector {
public:
    std::optional<std::uint64_t> observe(const State& s, std::uint64_t reflection) {
        if (reflection == 1) {
            saved_ = s;
            power_ = 1;
            distance_ = 0;
            return std::nullopt;
        }
        ++distance_;
        if (s == saved_) return distance_;
        if (distance_ == power_) {
            saved_ = s;
            power_ *= 2;
            distance_ = 0;
        }
        return std::nullopt;
    }

private:
    State saved_{};
    std::uint64_t power_ = 1, distance_ = 0;
};

// The reflection at which BrentDetector reports the period of a trajectory
// whose cycle starts at state mu >= 1 with period lambda >= 1. The saved
// state sits at reflections 1, 2, 4, 8, ...; from 2^k it is compared with
// the next 2^k states, so the first saved state on the cycle (2^k >= mu)
// whose window covers a period (2^k >= lambda) meets itself again lambda
// reflections later. Lets an engine that knows mu and lambda without
// stepping (the state graph) stop where the simulations stop.
constexpr std::uint64_t brent_detection(std::uint64_t mu, std::uint64_t lambda) {
    std::uint64_t saved = 1;
    while (saved < mu || saved < lambda) saved *= 2;
    return saved + lambda;
}

} // namespace orthoray::engine
