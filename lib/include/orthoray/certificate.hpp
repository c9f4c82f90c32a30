// Certificates: the evidence behind an answer, and their independent check.
// The file format is in docs/certificates.md.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace orthoray {

enum class CertificateFormat {
    text,  // one statement a line
    jsonl, // JSON Lines: one JSON object a line, for other tools
};

// Streams a certificate while a solver runs: attach() it to the options,
// then call finish() with the answer. Memory stays O(1) in the path length.
class CertificateWriter : public PathSink {
public:
    CertificateWriter(std::ostream& out, const Scene& scene,
                      CertificateFormat format = CertificateFormat::text);
    ~CertificateWriter() override;
    // Sets options.path to this writer and options.induction_observer to its
    // induction section, which records the exchange and steps when the
    // induction engine decides (docs/induction-certificates.md); the points
    // so far are their prefix. For the illumination question (several rays
    // or targets, or a splitter) it sets options.illumination_observer to
    // its illumination section instead (docs/certificates.md), and for the
    // intensity question (options.min_intensity set, docs/intensity.md)
    // options.intensity_observer to the same section in its intensity form.
    void attach(SolveOptions& options);
    void visit(const Vector& point, const Vector& direction) override;
    // The start of a cycle entered after a tail: the verdict's `state`.
    void cycle_start(const Vector& point, const Vector& direction) override;
    void finish(const Answer& answer);

private:
    class InductionSection;
    class IlluminationSection;
    void write_vector(const Vector& x);
    void write_number(const Rational& x);

    std::ostream& out_;
    const Scene& scene_;
    CertificateFormat format_;
    std::uint64_t visits_ = 0;
    Vector first_reflection_point_, first_reflection_direction_;
    // s_(T+1), when the engine reported it (one-sided elements); else the
    // cycle starts at the first reflection.
    std::optional<std::pair<Vector, Vector>> cycle_start_;
    Vector last_direction_;
    std::vector<char> digits_; // write_number's buffer
    std::unique_ptr<InductionSection> induction_;
    std::unique_ptr<IlluminationSection> illumination_;
    bool induced_ = false; // the induction engine has begun recording
};

struct Verdict {
    bool valid = false;
    std::string message; // "valid: ..." or the first failing step
};

// Checks a certificate (either format, recognised from its first line)
// against the scene with plain rational geometry that
// shares no code with the solvers. A malformed certificate throws InputError.
Verdict verify_certificate(const Scene& scene, std::istream& certificate,
                           const std::string& certificate_name = "<certificate>");

// What a certificate claims, read without being checked (verify checks it).
struct CertificateClaim {
    bool complete = false; // the verdict and the final 'end' are there
    std::string answer;    // yes, no or unknown
    Reason reason = Reason::limit;
    Integer reflections;
    Vector direction; // escape: the final ray's direction
    // False for an induction certificate, whose points stop at the first
    // reflection (docs/induction-certificates.md): the rest of the path is
    // the induction's to prove, not listed.
    bool lists_path = true;
};

// Streams a certificate's points (either format) to `sink`, with a zero
// direction since the file lists points only, and returns its verdict. For
// drawing paths; a malformed certificate throws InputError.
CertificateClaim read_certificate_path(const Scene& scene, std::istream& certificate,
                                       const std::string& certificate_name, PathSink& sink);

} // namespace orthoray
