// read_number and to_string: the exact number syntax of .scene and
// certificate files.
#include "orthoray/number.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using orthoray::Integer;
using orthoray::NumberToken;
using orthoray::Rational;
using orthoray::read_number;

namespace {

Rational q(long num, long den = 1) {
    Rational r(num, den);
    r.canonicalize();
    return r;
}

// The value of a token that must be well formed.
Rational value_of(const std::string& text) {
    NumberToken t = read_number(text);
    INFO("token '" << text << "'");
    REQUIRE(t.status == NumberToken::Status::ok);
    return t.value;
}

NumberToken::Status status_of(const std::string& text) {
    return read_number(text).status;
}

} // namespace

TEST_CASE("read_number reads integers with an optional sign", "[number]") {
    CHECK(value_of("0") == 0);
    CHECK(value_of("7") == 7);
    CHECK(value_of("-3") == -3);
    CHECK(value_of("+3") == 3);
    CHECK(value_of("-0") == 0);
    CHECK(value_of("007") == 7);
    CHECK(value_of("123456789012345678901234567890") ==
          Rational(Integer("123456789012345678901234567890")));
    CHECK(orthoray::to_string(value_of("-0")) == "0");
    // Up to 18 digits are read in a machine word, more on GMP: both sides of
    // that line, and the largest values near it.
    CHECK(value_of("999999999999999999") == Rational(Integer("999999999999999999")));
    CHECK(value_of("-999999999999999999") == Rational(Integer("-999999999999999999")));
    CHECK(value_of("1000000000000000000") == Rational(Integer("1000000000000000000")));
    CHECK(value_of("-9223372036854775808") == Rational(Integer("-9223372036854775808")));
    CHECK(value_of("18446744073709551617") == Rational(Integer("18446744073709551617")));
    CHECK(value_of("000000000000000000012") == 12);
    CHECK(value_of("-000000000000000012") == -12);
    CHECK(value_of("123456789012345678").get_den() == 1);
}

TEST_CASE("read_number reads fractions in lowest terms", "[number]") {
    CHECK(value_of("7/2") == q(7, 2));
    CHECK(value_of("-7/2") == q(-7, 2));
    CHECK(value_of("+7/2") == q(7, 2));
    CHECK(value_of("6/4") == value_of("3/2"));
    CHECK(orthoray::to_string(value_of("6/4")) == "3/2");
    CHECK(orthoray::to_string(value_of("-10/5")) == "-2");
    CHECK(orthoray::to_string(value_of("0/9")) == "0");
    // The stored value is canonical, so its parts are the reduced ones.
    Rational r = value_of("-12/18");
    CHECK(r.get_num() == -2);
    CHECK(r.get_den() == 3);
}

TEST_CASE("read_number reads exact decimals", "[number]") {
    CHECK(value_of("0.125") == q(1, 8));
    CHECK(value_of("-2.5") == q(-5, 2));
    CHECK(value_of("1.") == 1);
    CHECK(value_of("-2.") == -2);
    CHECK(value_of(".5") == q(1, 2));
    CHECK(value_of("-.5") == q(-1, 2));
    CHECK(value_of("+.25") == q(1, 4));
    CHECK(value_of("0.0") == 0);
    CHECK(value_of("12.375") == q(99, 8));
    CHECK(value_of("0.1") == q(1, 10)); // exact, not the nearest double
    CHECK(orthoray::to_string(value_of("2.50")) == "5/2");
    CHECK(orthoray::to_string(value_of("3.000")) == "3");
    Rational tiny = value_of(std::string("0.").append(99, '0') + "1");
    Integer ten_to_100;
    mpz_ui_pow_ui(ten_to_100.get_mpz_t(), 10, 100);
    CHECK(tiny == Rational(Integer(1), ten_to_100));
}

TEST_CASE("to_string writes canonical text", "[number]") {
    CHECK(orthoray::to_string(q(7)) == "7");
    CHECK(orthoray::to_string(q(-7, 2)) == "-7/2");
    CHECK(orthoray::to_string(q(0)) == "0");
    CHECK(orthoray::to_string(q(1, 8)) == "1/8");
    for (const char* text : {"0", "1", "-1", "7/2", "-7/2", "1/3", "-123/1000"})
        CHECK(orthoray::to_string(value_of(text)) == text);
}

TEST_CASE("is_integer is true exactly when the denominator is 1", "[number]") {
    using orthoray::is_integer;
    for (const char* text : {"0", "1", "-1", "7", "-7", "1000000000000000000000000"})
        CHECK(is_integer(value_of(text)));
    for (const char* text : {"1/2", "-1/2", "7/3", "1/1000000000000000000000000",
                             "1000000000000000000000001/1000000000000000000000000"})
        CHECK_FALSE(is_integer(value_of(text)));
    // Read as it is stored: 4/2 before canonicalize has denominator 2.
    CHECK_FALSE(is_integer(Rational(4, 2)));
    // A denominator of more than one limb whose lowest limb is 1 (2^64 + 1).
    Rational wide(Integer(1), Integer("18446744073709551617"));
    CHECK_FALSE(is_integer(wide));
}

TEST_CASE("200-digit numbers round-trip through to_string", "[number]") {
    // 10^199 + 1 and 10^199 + 3: both have 200 digits, both are odd, and
    // they differ by 2, so they are coprime and num/den is already canonical.
    const std::string num = std::string("1").append(198, '0') + "1";
    const std::string den = std::string("1").append(198, '0') + "3";
    REQUIRE(num.size() == 200);
    REQUIRE(den.size() == 200);
    const Integer n(num), d(den);

    Rational v = value_of(num + "/" + den);
    CHECK(v.get_num() == n);
    CHECK(v.get_den() == d);
    CHECK(orthoray::to_string(v) == num + "/" + den);
    CHECK(value_of(orthoray::to_string(v)) == v);

    Rational neg = value_of("-" + num + "/" + den);
    CHECK(orthoray::to_string(neg) == "-" + num + "/" + den);
    CHECK(value_of(orthoray::to_string(neg)) == neg);

    // The same value with a common factor of 6 is reduced to the same text.
    const Integer n6 = n * 6, d6 = d * 6;
    CHECK(orthoray::to_string(value_of(n6.get_str() + "/" + d6.get_str())) == num + "/" + den);

    // A 200-digit integer, and a decimal with 100 digits on each side of the point.
    CHECK(orthoray::to_string(value_of(num)) == num);
    // Appended, not `+ "5"`: GCC 12 at -O3 warns falsely on that (-Warray-bounds).
    const std::string whole = std::string("1").append(99, '2'),
                      frac = std::string(99, '4').append("5");
    Rational dec = value_of(whole + "." + frac);
    Integer scale;
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, 100);
    Rational dec_expected(Integer(whole + frac), scale);
    dec_expected.canonicalize();
    CHECK(dec == dec_expected);
    CHECK(value_of(orthoray::to_string(dec)) == dec);
}

TEST_CASE("read_number rejects malformed tokens", "[number]") {
    const std::vector<std::string> bad = {
        "",     ".",    "-",    "+",    "-.",    "+.", "1e3", "1E3",   "1/2/3", "--1",
        "+-1",  "-+1",  "1/-2", "1/+2", "-1/-2", "/2", "1/",  "/",     "1.2.3", "1..2",
        "1./2", "1/2.", ".5/2", "0x10", "a",     "1a", "1 2", " 1",    "1 ",    "1,5",
        "inf",  "nan",  "1-",   "1+1",  "½",     "١",  "\t1", "1_000", "2-3",   "3/4/",
    };
    for (const std::string& text : bad) {
        INFO("token '" << text << "'");
        CHECK(status_of(text) == NumberToken::Status::malformed);
    }
}

TEST_CASE("read_number reports a zero denominator separately", "[number]") {
    for (const char* text : {"1/0", "-1/0", "0/0", "+5/000", "7/00000000000000000000000000"}) {
        INFO("token '" << text << "'");
        CHECK(status_of(text) == NumberToken::Status::zero_denominator);
    }
    // A zero denominator only counts when the rest of the fraction is well formed.
    CHECK(status_of("a/0") == NumberToken::Status::malformed);
    CHECK(status_of("1.5/0") == NumberToken::Status::malformed);
}
