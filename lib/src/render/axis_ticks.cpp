// Exact tick values: the step is m * 10^e with m in {1, 2, 5}, the ticks are
// the multiples of the step in [lo, hi], and a label is the decimal text of
// k * m with the decimal point moved by e, so nothing is rounded.
#include "render/axis_ticks.hpp"

#include <cmath>

namespace orthoray::render {
namespace {

Integer power_of_ten(long exponent) {
    Integer result;
    mpz_ui_pow_ui(result.get_mpz_t(), 10, static_cast<unsigned long>(exponent));
    return result;
}

// The decimal text of digits * 10^exponent.
std::string decimal(const Integer& digits, long exponent) {
    std::string text = Integer(abs(digits)).get_str();
    if (exponent >= 0) {
        if (digits != 0) text.append(static_cast<std::size_t>(exponent), '0');
    } else {
        const auto places = static_cast<std::size_t>(-exponent);
        // At least one digit before the point: 5 * 10^-2 is 0.05.
        std::string padded(text.size() <= places ? places + 1 - text.size() : 0, '0');
        padded += text;
        text =
            padded.substr(0, padded.size() - places) + "." + padded.substr(padded.size() - places);
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    return (digits < 0 ? "-" : "") + text;
}

// digits * 10^exponent as d.ddddde+N with at most `significant` digits
// (cut, not rounded), taken from the exact digits: the value may be far
// beyond what a double holds.
std::string scientific(const Integer& digits, long exponent, std::size_t significant = 6) {
    const std::string text = Integer(abs(digits)).get_str();
    std::string mantissa = text.substr(0, 1);
    std::string rest = text.substr(1, significant - 1);
    while (!rest.empty() && rest.back() == '0') rest.pop_back();
    if (!rest.empty()) mantissa += "." + rest;
    const long power = static_cast<long>(text.size()) - 1 + exponent;
    return (digits < 0 ? "-" : "") + mantissa + "e" + std::to_string(power);
}

// Labels longer than this are shown with 6 significant digits: a tick that
// names a 40-digit coordinate in full would cover its neighbours.
constexpr std::size_t max_label = 10;

// The label of digits * 10^exponent: its decimal text, or 6 significant
// digits when that is too long.
std::string label_of(const Integer& digits, long exponent) {
    std::string label = decimal(digits, exponent);
    return label.size() > max_label ? scientific(digits, exponent) : label;
}

// digits * 10^exponent in full: decimal when short, else every significant
// digit before the exponent (an offset is named once, so length is no harm,
// and it must be exact).
std::string exact_text(const Integer& digits, long exponent) {
    std::string label = decimal(digits, exponent);
    return label.size() <= 2 * max_label ? label : scientific(digits, exponent, std::string::npos);
}

} // namespace

AxisTicks axis_ticks(const Rational& lo, const Rational& hi, int count) {
    const Rational span = hi - lo;
    if (sgn(span) <= 0 || count < 1) return {};
    // log10 of the step we would like, span / count; from the digit counts
    // when the span is beyond a double.
    double log_span = std::log10(span.get_d());
    if (!std::isfinite(log_span))
        log_span = static_cast<double>(mpz_sizeinbase(span.get_num_mpz_t(), 10)) -
                   static_cast<double>(mpz_sizeinbase(span.get_den_mpz_t(), 10));
    const double log_raw = log_span - std::log10(static_cast<double>(count));
    long exponent = std::lround(std::floor(log_raw));
    const double base = std::pow(10.0, log_raw - static_cast<double>(exponent));
    long m = base <= 1 ? 1 : base <= 2 ? 2 : base <= 5 ? 5 : 10;
    if (m == 10) {
        m = 1;
        ++exponent;
    }
    const Rational step = exponent >= 0 ? Rational(m * power_of_ten(exponent))
                                        : Rational(Integer(m), power_of_ten(-exponent));
    // k from ceil(lo / step) to floor(hi / step).
    const Rational first = lo / step, last = hi / step;
    Integer k, k_last;
    mpz_cdiv_q(k.get_mpz_t(), first.get_num_mpz_t(), first.get_den_mpz_t());
    mpz_fdiv_q(k_last.get_mpz_t(), last.get_num_mpz_t(), last.get_den_mpz_t());
    AxisTicks axis;
    std::vector<Integer> digits; // tick i is digits[i] * 10^exponent
    for (; k <= k_last && axis.ticks.size() < 4 * static_cast<std::size_t>(count); ++k) {
        const Rational value = Rational(k) * step;
        digits.push_back(Integer(k * m));
        axis.ticks.push_back(
            {Rational((value - lo) / span).get_d(), label_of(digits.back(), exponent)});
    }
    bool distinct = true;
    for (std::size_t i = 1; i < axis.ticks.size(); ++i)
        distinct = distinct && axis.ticks[i].label != axis.ticks[i - 1].label;
    if (distinct) return axis;
    // Far from the origin: count from a round offset, the first tick's
    // digits with the last four places (of 10^exponent) cleared, so that
    // each label keeps at most about five significant digits.
    const Integer unit = power_of_ten(4);
    Integer offset;
    mpz_fdiv_q(offset.get_mpz_t(), digits.front().get_mpz_t(), unit.get_mpz_t());
    offset *= unit;
    axis.offset_negative = offset < 0;
    axis.offset = exact_text(Integer(abs(offset)), exponent);
    for (std::size_t i = 0; i < axis.ticks.size(); ++i)
        axis.ticks[i].label = label_of(Integer(digits[i] - offset), exponent);
    return axis;
}

} // namespace orthoray::render
