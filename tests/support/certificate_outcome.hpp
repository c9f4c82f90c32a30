// What `verify` says about a certificate given as text, for the certificate
// tests: a malformed certificate (InputError) is not valid, and its message
// is kept so that a test can demand the reason it was rejected for; and the
// checks the tests make of it.
#pragma once

#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

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

// Verified, with exactly `message`.
inline void expect_valid(const Scene& scene, const std::string& text, const std::string& message) {
    const Outcome outcome = verify(scene, text);
    INFO("certificate:\n" << text << "verify said: " << outcome.message);
    CHECK(outcome.valid);
    CHECK(outcome.message == message);
}

// Rejected, not as malformed input, with `reason` in the message: the
// tampering is caught for the reason the test intends.
inline void expect_invalid(const Scene& scene, const std::string& text, const std::string& reason) {
    const Outcome outcome = verify(scene, text);
    INFO("certificate:\n" << text << "verify said: " << outcome.message);
    CHECK_FALSE(outcome.valid);
    CHECK_FALSE(outcome.input_error);
    CHECK(outcome.message.rfind("invalid: ", 0) == 0);
    CHECK(outcome.message.find(reason) != std::string::npos);
}

// A certificate and the answer it was written for.
struct Certified {
    Answer answer;
    std::string text;
};

// Solves with a CertificateWriter attached and returns the whole text.
inline Certified certify(const Scene& scene, SolveOptions options,
                         CertificateFormat format = CertificateFormat::text) {
    std::stringstream out;
    CertificateWriter writer(out, scene, format);
    writer.attach(options);
    Certified result;
    result.answer = solve(scene, options);
    writer.finish(result.answer);
    result.text = out.str();
    return result;
}

inline Certified certify(const Scene& scene, Engine engine,
                         CertificateFormat format = CertificateFormat::text) {
    SolveOptions options;
    options.engine = engine;
    return certify(scene, options, format);
}

// Asserts that a tampered certificate does not verify: either the verdict
// is "invalid: ..." or the text is rejected as malformed.
inline void expect_rejected(const Scene& scene, const std::string& text, const std::string& what) {
    const Outcome outcome = verify(scene, text);
    INFO("tampering: " << what << "\ncertificate:\n" << text << "verify said: " << outcome.message);
    CHECK_FALSE(outcome.valid);
    CHECK_FALSE(outcome.message.starts_with("valid"));
    if (!outcome.input_error) CHECK(outcome.message.starts_with("invalid"));
}

} // namespace orthoray::test
