#include "orthoray/realistic.hpp"

#include <algorithm>

namespace orthoray {

Integer Transfer::operator()(const Integer& i) const {
    if (kind == Kind::scale) {
        Integer out;
        mpz_fdiv_q(out.get_mpz_t(), Integer(i * p).get_mpz_t(), q.get_mpz_t());
        return out;
    }
    // The last threshold at most i; below the first, nothing passes.
    const auto after = std::upper_bound(thresholds.begin(), thresholds.end(), i);
    return after == thresholds.begin() ? Integer(0) : values[after - thresholds.begin() - 1];
}

} // namespace orthoray
