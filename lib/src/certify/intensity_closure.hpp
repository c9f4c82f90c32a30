// Checks 3 to 5 of an intensity certificate (docs/certificates.md, "The
// intensity question"), the counterpart for intensities of the label
// closure in illumination_verifier.cpp: every branch line's intensity is an
// upper bound on the intensity of any branch reaching its state (or that
// branch is already too faint to matter), no stretch passes an unlit target
// above the threshold, and none passes a lit one more intensely than
// claimed.
#pragma once

#include "certify/illumination_check_support.hpp"
#include "certify/illumination_claims.hpp"

#include <optional>
#include <vector>

namespace orthoray::certify {

// `claim_of` maps each target to its line in claims.targets, `index` each
// branch line's state to the line (both checked by the shape check before).
// Throws Invalid at the first failure.
void check_intensity_closure(const Scene& scene, const IlluminationClaims& claims,
                             const std::vector<std::optional<std::size_t>>& claim_of,
                             const StateIndex& index);

} // namespace orthoray::certify
