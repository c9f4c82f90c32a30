// Scaling a scene's coordinates onto a lattice: x times a fixed scale that
// every denominator divides, so the product is an integer. Both lattices
// (lattice_scene.hpp, octagonal_lattice.hpp) scale every coordinate of the
// scene this way, so on large scenes this is most of their setup, and it is
// inline: a call a coordinate showed in the setup's time.
#pragma once

#include "orthoray/number.hpp"

#include <cstdint>
#include <optional>
#include <utility>

namespace orthoray::lattice {

// a's value when it has at most one limb below 2^62, read inline (GMP's own
// tests are calls): the common case of scene coordinates and scales.
inline std::optional<std::int64_t> small_value(mpz_srcptr a) {
    if (mpz_size(a) > 1) return std::nullopt;
    const mp_limb_t limb = mpz_getlimbn(a, 0); // 0 for a = 0
    if (limb >= (mp_limb_t{1} << 62)) return std::nullopt;
    const auto value = static_cast<std::int64_t>(limb);
    return mpz_sgn(a) < 0 ? -value : value;
}

class Scaling {
public:
    explicit Scaling(Integer scale)
        : scale_(std::move(scale)), small_scale_(small_value(scale_.get_mpz_t())) {}

    // x * scale, for an x whose denominator divides the scale: computed as
    // num * (scale / den), without a gcd; an integer of one limb times a
    // scale of one limb in machine words when the product fits (GMP's
    // product into a fresh integer allocates twice: a third of the scaling's
    // time on large scenes, measured).
    Integer operator()(const Rational& x) const {
        if (!is_integer(x)) return Integer(x.get_num() * (scale_ / x.get_den()));
        const std::optional<std::int64_t> num = small_value(x.get_num_mpz_t());
        long product = 0;
        if (num && small_scale_ && !__builtin_mul_overflow(*num, *small_scale_, &product))
            return Integer(product);
        return Integer(x.get_num() * scale_);
    }

private:
    Integer scale_;
    std::optional<std::int64_t> small_scale_;
};

} // namespace orthoray::lattice
