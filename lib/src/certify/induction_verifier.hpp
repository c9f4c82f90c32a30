// The checker for induction certificates (docs/induction-certificates.md):
// the interval exchange built from a 2D scene and the induction steps taken
// on it. Checker code only: it shares nothing with the induction engine but
// the statement syntax, and uses plain integer and rational arithmetic.
#pragma once

#include "orthoray/certificate.hpp"
#include "orthoray/scene.hpp"

#include "certify/certificate_reader.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace orthoray::certify {

// The path prefix p0 .. pr before `method`, as the path checker found it.
struct PathPrefix {
    std::optional<std::string> failure; // the path checker's first failing step
    std::uint64_t points = 0;           // r + 1
    bool absorbed = false;              // an absorber is met at pr
    Vector p1, v1;                      // state 1, when points >= 2
};

// Reads the rest of an induction certificate, from its `method` statement
// (the header and the path prefix have been read) to `end`, then checks it
// against the scene. Malformed syntax throws InputError; a file that ends
// before `end` throws IncompleteCertificate, as in the path checker.
Verdict verify_induction(const Scene& scene, CertificateReader& in, const PathPrefix& prefix);

} // namespace orthoray::certify
