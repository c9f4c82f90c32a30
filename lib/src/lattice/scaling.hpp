// Scaling a scene's coordinates onto a lattice: x times a fixed scale that
// every denominator divides, so the product is an integer. Both lattices
// (lattice_scene.hpp, octagonal_lattice.hpp) scale every coordinate of the
// scene this way, so on large scenes this is most of their setup.
#pragma once

#include "orthoray/number.hpp"

#include <cstdint>
#include <optional>

namespace orthoray::lattice {

// a's value when it has at most one limb below 2^62, read inline (GMP's own
// tests are calls): the common case of scene coordinates and scales.
std::optional<std::int64_t> small_value(mpz_srcptr a);

class Scaling {
public:
    explicit Scaling(Integer scale);

    // x * scale, for an x whose denominator divides the scale: computed as
    // num * (scale / den), without a gcd; an integer of one limb times a
    // scale of one limb in machine words when the product fits (GMP's
    // product into a fresh integer allocates twice: a third of the scaling's
    // time on large scenes, measured).
    Integer operator()(const Rational& x) const;

    const Integer& scale() const { return scale_; }

private:
    Integer scale_;
    std::optional<std::int64_t> small_scale_;
};

} // namespace orthoray::lattice
