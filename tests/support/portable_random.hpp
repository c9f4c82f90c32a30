// Random draws for the tests that give the same cases with every standard
// library: all of them go through orthoray::uniform (generate.hpp), whose
// rejection sampling on std::mt19937_64 is fixed by this project, where
// std::uniform_int_distribution, std::bernoulli_distribution and
// std::shuffle are each left to the library to implement.
#pragma once

#include "orthoray/generate.hpp"

#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace orthoray::test {

// A uniform int in [lo, hi].
inline int pick(std::mt19937_64& rng, int lo, int hi) {
    return static_cast<int>(uniform(rng, lo, hi));
}

// A uniform index in [lo, hi].
inline std::size_t pick_index(std::mt19937_64& rng, std::size_t lo, std::size_t hi) {
    return static_cast<std::size_t>(
        uniform(rng, static_cast<std::int64_t>(lo), static_cast<std::int64_t>(hi)));
}

// True with probability percent / 100.
inline bool chance(std::mt19937_64& rng, int percent) {
    return uniform(rng, 1, 100) <= percent;
}

// A uniformly random permutation (Fisher and Yates: position i takes a
// uniform pick among positions 0..i).
template <class T>
void shuffle(std::vector<T>& items, std::mt19937_64& rng) {
    for (std::size_t i = items.size(); i > 1; --i)
        std::swap(items[i - 1], items[pick_index(rng, 0, i - 1)]);
}

} // namespace orthoray::test
