// Reads the path a certificate claims, for pictures: the points, and the
// verdict lines that say how the path ends. Nothing is checked beyond the
// syntax; a truncated file simply yields the points it has. An induction
// certificate's statements between its points and its verdict are skipped.
#include "orthoray/certificate.hpp"

#include "certify/certificate_reader.hpp"

namespace orthoray {
namespace {

bool reason_named(std::string_view word, Reason& reason) {
    for (Reason r : {Reason::hit, Reason::escape, Reason::absorbed, Reason::cycle, Reason::limit})
        if (word == to_string(r)) {
            reason = r;
            return true;
        }
    return false;
}

} // namespace

CertificateClaim read_certificate_path(const Scene& scene, std::istream& certificate,
                                       const std::string& certificate_name, PathSink& sink) {
    certify::CertificateReader in(certificate, certificate_name);
    CertificateClaim claim;
    const int dim = scene.dim;
    const Vector none;
    try {
        in.read_header(dim);
        while (in.keyword() == "point") {
            in.expect("point", dim, "a number");
            sink.visit(in.vector(1, dim), none);
            in.advance();
        }
        // An induction certificate lists the path up to the first reflection
        // only; its proof is the induction, which only `verify` replays.
        if (in.keyword() == "method") {
            claim.lists_path = false;
            while (in.keyword() != "answer") in.advance();
        }
        in.expect("answer", 1, "yes, no or unknown");
        claim.answer = std::string(in.token(1));
        in.advance();
        in.expect("reason", 1, "hit, escape, absorbed, cycle or limit");
        if (!reason_named(in.token(1), claim.reason))
            in.fail(1, "hit, escape, absorbed, cycle or limit");
        in.advance();
        in.expect("reflections", 1, "a non-negative integer");
        claim.reflections = in.count(1);
        // The reason's own statements; only the escape direction is drawn.
        while (in.next()) {
            if (in.keyword() == "direction") {
                in.expect("direction", dim, "a number");
                claim.direction = in.vector(1, dim);
            }
            if (in.keyword() == "end") {
                claim.complete = true;
                break;
            }
        }
    } catch (const certify::IncompleteCertificate&) {
        claim.complete = false;
    }
    return claim;
}

} // namespace orthoray
