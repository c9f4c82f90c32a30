// The checker for illumination certificates (docs/certificates.md): scenes
// with several rays or targets, or a splitter. Checker code only: its own
// acting rule (acting_rule.hpp), its own stretch walk (stretch_walk.hpp),
// exact rationals; nothing from the engines.
#pragma once

#include "orthoray/certificate.hpp"
#include "orthoray/scene.hpp"

#include "certify/certificate_reader.hpp"

namespace orthoray::certify {

// Reads the rest of the certificate from its `illumination` statement (the
// header has been read) to `end`, then checks it against the scene.
// Malformed syntax throws InputError; a file that ends before `end` throws
// IncompleteCertificate, as in the path checker.
Verdict verify_illumination(const Scene& scene, CertificateReader& in);

} // namespace orthoray::certify
