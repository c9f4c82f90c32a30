// What `verify` says about a certificate given as text, for the certificate
// tests: a malformed certificate (InputError) is not valid, and its message
// is kept so that a test can demand the reason it was rejected for.
#pragma once

#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"

#include <sstream>
#include <string>

namespace orthoray::test {

struct Outcome {
    bool valid = false;
    bool input_error = false;
    std::string message;
};

inline Outcome verify(const Scene& scene, const std::string& text) {
    std::istringstream in(text);
    try {
        const Verdict verdict = verify_certificate(scene, in, "<test>");
        return {verdict.valid, false, verdict.message};
    } catch (const InputError& error) {
        return {false, true, error.what()};
    }
}

} // namespace orthoray::test
