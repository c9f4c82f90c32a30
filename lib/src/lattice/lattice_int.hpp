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
#include <type_traits>

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
    // |x| < 2^123: the two low limbs of the magnitude, then the sign (read in
    // place: building the exchange converts every piece once).
    static_assert(GMP_NUMB_BITS == 64, "64-bit GMP limbs");
    const mpz_srcptr z = x.get_mpz_t();
    const uint128_t m = (static_cast<uint128_t>(mpz_getlimbn(z, 1)) << 64) | mpz_getlimbn(z, 0);
    return mpz_sgn(z) < 0 ? -static_cast<int128_t>(m) : static_cast<int128_t>(m);
}
template <>
inline Integer from_integer<Integer>(const Integer& x) {
    return x;
}

// r = x, reusing r's limbs (no allocation once r has two).
inline void set_integer(Integer& r, std::int64_t x) {
    r = static_cast<long>(x);
}
inline void set_integer(Integer& r, int128_t x) {
    const bool negative = x < 0;
    const uint128_t m = negative ? -static_cast<uint128_t>(x) : static_cast<uint128_t>(x);
    mp_limb_t* limbs = mpz_limbs_write(r.get_mpz_t(), 2);
    limbs[0] = static_cast<mp_limb_t>(m);
    limbs[1] = static_cast<mp_limb_t>(m >> 64);
    mpz_limbs_finish(r.get_mpz_t(), negative ? -2 : 2); // normalizes the size
}
inline void set_integer(Integer& r, const Integer& x) {
    r = x;
}
inline Integer to_integer(std::int64_t x) {
    return Integer(static_cast<long>(x));
}
inline Integer to_integer(int128_t x) {
    Integer r;
    set_integer(r, x);
    return r;
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

// a - b * floor(a / b), in [0, b) for b > 0, on machine integers.
template <class Int>
Int floor_mod(Int a, Int b) {
    const Int r = a % b;
    return r < 0 ? Int(r + b) : r;
}

// gcd(a, b) >= 0 (gcd(0, 0) = 0), on machine integers: Euclid.
template <class Int>
Int gcd_of(Int a, Int b) {
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    while (b != 0) {
        const Int r = a % b;
        a = b;
        b = r;
    }
    return a;
}
inline Integer gcd_of(const Integer& a, const Integer& b) {
    return gcd(a, b);
}

// A value of one lattice integer type as another that holds it (the
// caller's bound says it does).
template <class To, class From>
To convert(const From& x) {
    if constexpr (std::is_same_v<To, From>)
        return x;
    else if constexpr (std::is_same_v<From, Integer>)
        return from_integer<To>(x);
    else if constexpr (std::is_same_v<To, Integer>)
        return to_integer(x);
    else
        return static_cast<To>(x);
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
