// Exact rational numbers from and to text.
#include "orthoray/number.hpp"

#include <cctype>

namespace orthoray {
namespace {

bool all_digits(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

Integer integer_of(std::string_view digits) {
    return Integer(std::string(digits), 10);
}

} // namespace

NumberToken::Status read_number(std::string_view text, Rational& value) {
    bool negative = false;
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
        negative = text.front() == '-';
        text.remove_prefix(1);
    }
    // An integer of up to 18 digits (below 10^18) fits a machine word: read
    // there, without GMP's string conversion and the temporaries below. A
    // scene's coordinates are nearly all such, and reading them was most of
    // the time to read a large scene.
    if (text.size() <= 18 && all_digits(text)) {
        long digits = 0;
        for (char c : text) digits = 10 * digits + (c - '0');
        mpq_set_si(value.get_mpq_t(), negative ? -digits : digits, 1);
        return NumberToken::Status::ok;
    }
    if (auto slash = text.find('/'); slash != std::string_view::npos) {
        std::string_view num = text.substr(0, slash), den = text.substr(slash + 1);
        if (!all_digits(num) || !all_digits(den)) return NumberToken::Status::malformed;
        Integer d = integer_of(den);
        if (d == 0) return NumberToken::Status::zero_denominator;
        value = Rational(integer_of(num), d);
    } else if (auto dot = text.find('.'); dot != std::string_view::npos) {
        // An exact decimal: 12.375 = 12375 / 10^3. At least one digit overall.
        std::string_view whole = text.substr(0, dot), frac = text.substr(dot + 1);
        if ((!whole.empty() && !all_digits(whole)) || (!frac.empty() && !all_digits(frac)) ||
            (whole.empty() && frac.empty()))
            return NumberToken::Status::malformed;
        Integer scale;
        mpz_ui_pow_ui(scale.get_mpz_t(), 10, frac.size());
        Integer digits = integer_of(std::string(whole.empty() ? "0" : whole) + std::string(frac));
        value = Rational(digits, scale);
    } else {
        if (!all_digits(text)) return NumberToken::Status::malformed;
        value = Rational(integer_of(text));
    }
    value.canonicalize();
    if (negative) mpq_neg(value.get_mpq_t(), value.get_mpq_t());
    return NumberToken::Status::ok;
}

NumberToken read_number(std::string_view text) {
    NumberToken result;
    result.status = read_number(text, result.value);
    return result;
}

std::string to_string(const Rational& value) {
    return value.get_str(10);
}

} // namespace orthoray
