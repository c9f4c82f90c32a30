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

// Reads an integer (`-3`), a fraction (`7/2`) or an exact decimal (`0.125`,
// `-2.`, `.5`), with an optional sign in front. Any size is fine.
NumberToken read_number(std::string_view text);

// Canonical text of a rational: `7`, `-7/2`. Inverse of read_number.
std::string to_string(const Rational& value);

} // namespace orthoray
