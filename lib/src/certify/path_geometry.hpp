// The checkers' own geometry (docs/certificates.md): the first acting event
// (acting_rule.hpp) and plain rational helpers around it, shared by the path
// checker (verifier.cpp), the illumination checker (illumination_verifier.cpp)
// and the induction checker (induction_verifier.cpp). Checker code only:
// nothing here comes from, or is used by, a solver.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include "certify/acting_rule.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace orthoray::certify {

// --------------------------------------------------------------- geometry --

inline Vector advance(const Vector& p, const Vector& v, const Rational& t, int dim) {
    Vector q;
    for (int j = 0; j < dim; ++j) q[j] = p[j] + t * v[j];
    return q;
}

inline bool same(const Vector& a, const Vector& b, int dim) {
    for (int j = 0; j < dim; ++j)
        if (a[j] != b[j]) return false;
    return true;
}

// Does `target` = p + tau v hold for some 0 <= tau <= stop.t (any tau >= 0
// when nothing is met)? Axes where v is zero must match exactly.
inline bool on_ray(const Vector& target, const Vector& p, const Vector& v, const Event& stop,
                   int dim) {
    std::optional<Rational> tau;
    for (int j = 0; j < dim; ++j) {
        if (sgn(v[j]) == 0) {
            if (target[j] != p[j]) return false;
            continue;
        }
        Rational s = (target[j] - p[j]) / v[j];
        if (tau && *tau != s) return false;
        tau = std::move(s);
    }
    if (!tau) return true; // v == 0 cannot come from a valid scene; then only p itself
    return sgn(*tau) >= 0 && (!stop.met || *tau <= stop.t);
}

// Portable std::uint64_t -> mpz (unsigned long may be 32 bits).
inline Integer to_integer(std::uint64_t n) {
    Integer result = static_cast<unsigned long>(n >> 32);
    result <<= 32;
    result += static_cast<unsigned long>(n & 0xffffffffu);
    return result;
}

// Its inverse, for 0 <= n < 2^64.
inline std::uint64_t to_uint64(const Integer& n) {
    const Integer high = n >> 32;
    const Integer low = n - (high << 32);
    return (static_cast<std::uint64_t>(high.get_ui()) << 32) | low.get_ui();
}

inline std::string show(const Vector& a, int dim) {
    std::string text = "(";
    for (int j = 0; j < dim; ++j) text += (j ? ", " : "") + to_string(a[j]);
    return text + ")";
}

} // namespace orthoray::certify
