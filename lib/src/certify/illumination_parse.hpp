// Reads an illumination certificate (docs/certificates.md) from its
// `illumination` statement to `end`. Pure syntax, plus feeding each lit
// witness's steps to a WitnessCheck as they are read; every other check is
// in illumination_verifier.cpp, after the whole file has been read (syntax
// errors win over every verdict).
#pragma once

#include "certify/certificate_reader.hpp"
#include "certify/illumination_claims.hpp"
#include "certify/witness_check.hpp"

namespace orthoray::certify {

// `in` is on the `illumination` statement. Malformed statements throw
// InputError; a file that ends before `end` throws IncompleteCertificate.
IlluminationClaims parse_illumination(CertificateReader& in, int dim, WitnessCheck& witnesses);

} // namespace orthoray::certify
