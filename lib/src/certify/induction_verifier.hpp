// The checker for induction certificates (docs/induction-certificates.md):
// the interval exchange built from a 2D scene and the induction steps taken
// on it. Checker code only: it shares nothing with the induction engine but
// the statement syntax, and uses plain integer and rational arithmetic.
#pragma once

#include "orthoray/certificate.hpp"
#include "orthoray/scene.hpp"

#include "certify/certificate_reader.hpp"

namespace orthoray::certify {

// Reads the rest of an induction certificate, from its `method` statement
// (the header has been read) to `end`, then checks it against the scene.
// Malformed syntax throws InputError; a file that ends before `end` throws
// IncompleteCertificate, as in the path checker.
Verdict verify_induction(const Scene& scene, CertificateReader& in);

} // namespace orthoray::certify
