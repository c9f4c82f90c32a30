#include "lattice/scaling.hpp"

#include <utility>

namespace orthoray::lattice {

std::optional<std::int64_t> small_value(mpz_srcptr a) {
    if (mpz_size(a) > 1) return std::nullopt;
    const mp_limb_t limb = mpz_getlimbn(a, 0); // 0 for a = 0
    if (limb >= (mp_limb_t{1} << 62)) return std::nullopt;
    const auto value = static_cast<std::int64_t>(limb);
    return mpz_sgn(a) < 0 ? -value : value;
}

Scaling::Scaling(Integer scale)
    : scale_(std::move(scale)), small_scale_(small_value(scale_.get_mpz_t())) {}

Integer Scaling::operator()(const Rational& x) const {
    if (!is_integer(x)) return Integer(x.get_num() * (scale_ / x.get_den()));
    const std::optional<std::int64_t> num = small_value(x.get_num_mpz_t());
    long product = 0;
    if (num && small_scale_ && !__builtin_mul_overflow(*num, *small_scale_, &product))
        return Integer(product);
    return Integer(x.get_num() * scale_);
}

} // namespace orthoray::lattice
