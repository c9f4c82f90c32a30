// Checks 4 (its end) and 5 of docs/induction-certificates.md: the verdict the
// replayed induction gives for x, against the one the certificate states,
// and for short answers a re-simulation with the path checker's own rule.
// Checker code only.
#pragma once

#include "orthoray/scene.hpp"

#include "certify/induction_certificate_parse.hpp"
#include "certify/replayed_exchange.hpp"

#include <string>

namespace orthoray::certify::induction_check {

// The stated answer, reason, reflections and period against x's piece at
// L = 1; returns the "valid: ..." message, throws CheckFailure otherwise.
std::string check_verdict(const Parsed& stated, const ReplayedPiece& first);

// When the path is short (reflections x (elements + 1) up to 10^7), walks
// it with the path checker's own scan and compares: a second, independent
// check of the same verdict.
void resimulate(const Scene& scene, const Parsed& stated);

} // namespace orthoray::certify::induction_check
