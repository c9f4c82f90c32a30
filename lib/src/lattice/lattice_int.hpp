// The integer types lattice code runs on, and the few operations it needs
// that the built-in operators do not give the same way for all of them.
//
// make_lattice reports the largest |value| B in the scaled scene. Every value
// the grid and the stepper compute is a sum or difference of at most a few
// such values plus one cell size (<= 2B + 1), so |intermediate| <= 8B. With
// B < 2^59 that stays below 2^62 and int64_t is provably safe; otherwise GMP.
#pragma once

#include "orthoray/number.hpp"

#include <cstdint>

namespace orthoray::lattice {

inline const Integer& machine_limit() {
    static const Integer limit = Integer(1) << 59;
    return limit;
}

template <class Int>
Int from_integer(const Integer& x);
template <>
inline std::int64_t from_integer<std::int64_t>(const Integer& x) {
    return x.get_si();
}
template <>
inline Integer from_integer<Integer>(const Integer& x) {
    return x;
}

inline Integer to_integer(std::int64_t x) {
    return Integer(static_cast<long>(x));
}
inline const Integer& to_integer(const Integer& x) {
    return x;
}

// floor(a / b) for b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
inline Integer floor_div(const Integer& a, const Integer& b) {
    Integer q;
    mpz_fdiv_q(q.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return q;
}

inline std::int64_t to_index(std::int64_t x) {
    return x;
}
inline std::int64_t to_index(const Integer& x) {
    return x.get_si();
}

inline const char* arithmetic_name(std::int64_t) {
    return "int64";
}
inline const char* arithmetic_name(const Integer&) {
    return "gmp";
}

} // namespace orthoray::lattice
