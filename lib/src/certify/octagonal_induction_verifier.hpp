// The checker for induction certificates of octagonal scenes
// (docs/induction-certificates.md, "Octagonal scenes"): the exchange on
// the eight-sheeted cover with its states written out as lattice points,
// the induction steps, and on a double cover the twin search. Checker code
// only: it shares nothing with the induction engine but the statement
// syntax.
#pragma once

#include "orthoray/certificate.hpp"
#include "orthoray/scene.hpp"

#include "certify/certificate_reader.hpp"
#include "certify/induction_verifier.hpp"

namespace orthoray::certify {

// Reads the rest of the certificate from `method octagonal-induction` to
// `end` and checks it; as verify_induction does for axis-parallel scenes.
Verdict verify_octagonal_induction(const Scene& scene, CertificateReader& in,
                                   const PathPrefix& prefix);

} // namespace orthoray::certify
