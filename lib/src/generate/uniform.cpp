// Integer randomness that is the same on every machine.
#include "orthoray/generate.hpp"

#include <limits>
#include <stdexcept>

namespace orthoray {

std::int64_t uniform(std::mt19937_64& rng, std::int64_t lo, std::int64_t hi) {
    if (hi < lo) throw std::invalid_argument("uniform: empty range");
    const std::uint64_t range = static_cast<std::uint64_t>(hi - lo) + 1; // 0: all 2^64 values
    if (range == 0) return static_cast<std::int64_t>(rng());
    const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    const std::uint64_t limit = max - (max % range + 1) % range; // a multiple of range, minus 1
    std::uint64_t x;
    do x = rng();
    while (x > limit);
    return lo + static_cast<std::int64_t>(x % range);
}

std::int64_t integer_root(std::int64_t n, int dim) {
    std::int64_t r = 1;
    auto power = [&](std::int64_t x) {
        std::int64_t p = 1;
        for (int i = 0; i < dim; ++i) p *= x;
        return p;
    };
    while (power(r + 1) <= n) ++r;
    return r;
}

} // namespace orthoray
