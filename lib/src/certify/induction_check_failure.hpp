// How the induction checker's parts report the first failure they find, and
// the few integer helpers they share. Checker code only.
#pragma once

#include "orthoray/number.hpp"

#include <optional>
#include <string>

namespace orthoray::certify::induction_check {

// The first failure ends the check; thrown and caught inside the checker
// only (induction_verifier.cpp turns it into the verdict "invalid: ...").
struct CheckFailure {
    std::string message;
};

// `where` names the statement at fault ("piece 3", "step 12 (...)").
[[noreturn]] inline void fail(const std::string& where, const std::string& what) {
    throw CheckFailure{"invalid: " + where + ": " + what};
}

// Runs the checks of a certificate as its statements arrive, until one
// fails, and keeps that first failure (both induction verifiers' drivers).
class FirstFailure {
public:
    // Runs `check` unless a check failed before.
    template <class Check>
    void guard(Check check) {
        if (failure_) return;
        try {
            check();
        } catch (const CheckFailure& failure) {
            failure_ = failure.message;
        }
    }
    const std::optional<std::string>& failure() const { return failure_; }

private:
    std::optional<std::string> failure_;
};

// a mod m in [0, m), m > 0.
inline Integer floor_mod(const Integer& a, const Integer& m) {
    Integer r;
    mpz_fdiv_r(r.get_mpz_t(), a.get_mpz_t(), m.get_mpz_t());
    return r;
}

inline std::string str(const Integer& n) {
    return n.get_str();
}

// "(x, y)".
inline std::string pair_text(const Integer& x, const Integer& y) {
    // Appended piece by piece: GCC 12 misreads "(" + std::string as an
    // overlapping copy (-Wrestrict).
    std::string text = "(";
    text += x.get_str();
    text += ", ";
    text += y.get_str();
    text += ')';
    return text;
}

} // namespace orthoray::certify::induction_check
