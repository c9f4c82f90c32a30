// The integer types lattice code runs on, and the few operations it needs
// that the built-in operators do not give the same way for all of them.
//
// make_lattice reports the largest |value| B in the scaled scene. Every value
// the grid and the stepper compute is a sum or difference of at most a few
// such values plus one cell size (<= 2B + 1), so |intermediate| <= 8B. Hence
// int64_t is provably safe for B < 2^59, __int128 for B < 2^123, and GMP
// integers take everything else.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/number.hpp"

#include <cstdint>

namespace orthoray::lattice {

__extension__ typedef __int128 int128_t; // GCC/Clang extension, silenced for -Wpedantic
__extension__ typedef unsigned __int128 uint128_t;

inline const Integer& int64_limit() {
    static const Integer limit = Integer(1) << 59;
    return limit;
}
inline const Integer& int128_limit() {
    static const Integer limit = Integer(1) << 123;
    return limit;
}

template <class Int>
Int from_integer(const Integer& x);
template <>
inline std::int64_t from_integer<std::int64_t>(const Integer& x) {
    return x.get_si();
}
template <>
inline int128_t from_integer<int128_t>(const Integer& x) {
    // |x| < 2^123: two 64-bit limbs of the magnitude, then the sign.
    Integer magnitude = abs(x);
    Integer high = magnitude >> 64;
    Integer low = magnitude - (high << 64);
    int128_t r = (static_cast<int128_t>(high.get_ui()) << 64) | low.get_ui();
    return x < 0 ? -r : r;
}
template <>
inline Integer from_integer<Integer>(const Integer& x) {
    return x;
}

inline Integer to_integer(std::int64_t x) {
    return Integer(static_cast<long>(x));
}
inline Integer to_integer(int128_t x) {
    const bool negative = x < 0;
    const uint128_t m = negative ? -static_cast<uint128_t>(x) : static_cast<uint128_t>(x);
    Integer r = Integer(static_cast<unsigned long>(m >> 64));
    r <<= 64;
    r += Integer(static_cast<unsigned long>(m & ~std::uint64_t{0}));
    return negative ? Integer(-r) : r;
}
inline const Integer& to_integer(const Integer& x) {
    return x;
}

// floor(a / b) for b > 0.
template <class Int>
Int floor_div(Int a, Int b) {
    Int q = a / b;
    return (a % b != 0 && a < 0) ? Int(q - 1) : q;
}
inline Integer floor_div(const Integer& a, const Integer& b) {
    Integer q;
    mpz_fdiv_q(q.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return q;
}
// a - b * floor(a / b), in [0, b) for b > 0.
inline Integer floor_mod(const Integer& a, const Integer& b) {
    Integer r;
    mpz_fdiv_r(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return r;
}

// Cell indices are small (the grid has O(n) cells), whatever Int is.
template <class Int>
std::int64_t to_index(Int x) {
    return static_cast<std::int64_t>(x);
}
inline std::int64_t to_index(const Integer& x) {
    return x.get_si();
}

// The number of bits of x > 0: floor(log2 x) + 1.
template <class Int>
unsigned bit_length(Int x) {
    unsigned bits = 0;
    for (; x > 0; x >>= 1) ++bits; // at most 127 rounds on machine integers
    return bits;
}
inline unsigned bit_length(const Integer& x) {
    return static_cast<unsigned>(mpz_sizeinbase(x.get_mpz_t(), 2));
}

inline ArithmeticUsed arithmetic_used(std::int64_t) {
    return ArithmeticUsed::int64;
}
inline ArithmeticUsed arithmetic_used(int128_t) {
    return ArithmeticUsed::int128;
}
inline ArithmeticUsed arithmetic_used(const Integer&) {
    return ArithmeticUsed::gmp;
}

} // namespace orthoray::lattice
