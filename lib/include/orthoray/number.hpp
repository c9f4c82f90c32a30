// Exact numbers. Every coordinate orthoray reads or writes is a GMP rational;
// nothing in a decision, certificate or verifier is ever a float.
#pragma once

#include <gmpxx.h>
#include <string>
#include <string_view>

namespace orthoray {

using Integer = mpz_class;
using Rational = mpq_class;

// The outcome of reading one number token.
struct NumberToken {
    enum class Status { ok, malformed, zero_denominator };
    Status status = Status::malformed;
    Rational value;
};

// Whether q is an integer (its denominator is 1), read inline: GMP's compare
// is a call, and the setup asks this of every coordinate of a scene.
inline bool is_integer(const Rational& q) {
    const mpz_srcptr den = q.get_den_mpz_t();
    return mpz_size(den) == 1 && mpz_sgn(den) > 0 && mpz_getlimbn(den, 0) == 1;
}

// Reads an integer (`-3`), a fraction (`7/2`) or an exact decimal (`0.125`,
// `-2.`, `.5`), with an optional sign in front. Any size is fine.
NumberToken read_number(std::string_view text);
// The same into `value`, which is set (in lowest terms) only when the status
// is ok: a reader that fills a scene's numbers in place allocates nothing
// for a short integer.
NumberToken::Status read_number(std::string_view text, Rational& value);

// Canonical text of a rational: `7`, `-7/2`. Inverse of read_number.
std::string to_string(const Rational& value);

} // namespace orthoray
