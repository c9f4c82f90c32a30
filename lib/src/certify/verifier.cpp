// The independent certificate checker (docs/certificates.md). It replays the
// listed path with its own "first element met" scan in plain rationals and
// shares no code with any solver, so trusting an answer only means trusting
// this file, the scene parser and the certificate tokenizer
// (certificate_reader.cpp, pure parsing). The certificate is read as a stream: the
// path may have 10^8 points, so only the current state, state 1 and counters
// are kept, never the points themselves.
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"

#include "certify/certificate_reader.hpp"
#include "certify/induction_verifier.hpp"
#include "certify/path_geometry.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace orthoray {
namespace {

using certify::advance;
using certify::Event;
using certify::first_met;
using certify::on_ray;
using certify::same;
using certify::show;

// Portable std::uint64_t -> mpz (unsigned long may be 32 bits).
Integer to_integer(std::uint64_t n) {
    Integer result = static_cast<unsigned long>(n >> 32);
    result <<= 32;
    result += static_cast<unsigned long>(n & 0xffffffffu);
    return result;
}

// ------------------------------------------------------------------- path --

// Replays the path point by point. After the first failure it only counts
// points, so the rest of the file is still parsed (syntax errors win) but the
// first failing step is the one reported.
class PathCheck {
public:
    explicit PathCheck(const Scene& scene) : scene_(scene), dim_(scene.dim) {}

    void point(const Vector& q) {
        const std::uint64_t k = points_++;
        if (failure_) return;
        if (k == 0) {
            if (!same(q, scene_.ray().start, dim_))
                fail(k, "point 0 is " + show(q, dim_) + ", not the start point " +
                            show(scene_.ray().start, dim_));
            p_ = q;
            v_ = scene_.ray().direction;
            return;
        }
        const std::string from = "point " + std::to_string(k - 1);
        if (stopped_) return fail(k, "the ray is absorbed at " + from + ", yet a point follows");
        const Event e = first_met(scene_, p_, v_);
        if (!e.met)
            return fail(k, "the ray from " + from + " meets no element, yet a point follows");
        const Vector expected = advance(p_, v_, e.t, dim_);
        if (!same(q, expected, dim_))
            return fail(k, "point " + std::to_string(k) + " is " + show(q, dim_) +
                               ", but the ray from " + from + " first meets an element at " +
                               show(expected, dim_));
        // Every listed segment comes before the one a hit claims, so the
        // target must be on none of them whatever the reason.
        if (on_ray(scene_.target(), p_, v_, e, dim_))
            return fail(k, "the target lies on the segment from " + from + " to point " +
                               std::to_string(k));
        p_ = q;
        if (e.absorbed) {
            stopped_ = true;
            return;
        }
        for (int j = 0; j < dim_; ++j)
            if (e.flip[j]) v_[j] = -v_[j];
        // Keep state 1 and the first later state equal to it: the step map
        // is injective, so a periodic path returns to state 1 first.
        if (k == 1) {
            p1_ = p_;
            v1_ = v_;
        } else if (!repeat_ && same(p_, p1_, dim_) && same(v_, v1_, dim_)) {
            repeat_ = k;
        }
    }

    const std::optional<std::string>& failure() const { return failure_; }
    std::uint64_t points() const { return points_; }
    const Vector& p() const { return p_; }
    const Vector& v() const { return v_; }
    const Vector& p1() const { return p1_; }
    const Vector& v1() const { return v1_; }
    bool stopped() const { return stopped_; }
    const std::optional<std::uint64_t>& repeat() const { return repeat_; }

private:
    void fail(std::uint64_t step, const std::string& what) {
        failure_ = "invalid: step " + std::to_string(step) + ": " + what;
    }

    const Scene& scene_;
    const int dim_;
    std::uint64_t points_ = 0;
    Vector p_, v_;         // the last point and the direction the ray leaves it in
    Vector p1_, v1_;       // state 1
    bool stopped_ = false; // an absorber is met at the last point
    std::optional<std::uint64_t> repeat_;
    std::optional<std::string> failure_;
};

// ---------------------------------------------------------------- verdict --

// The verdict lines after the points; `extra` holds the reason's own vector
// (target, direction, or the point of `state`) and `extra_v` the state's
// direction.
struct Claim {
    std::string answer;
    Reason reason = Reason::limit;
    Integer reflections;
    Vector extra, extra_v;
    Integer period;
};

Verdict bad(const std::string& what) {
    return {false, "invalid: verdict: " + what};
}

Verdict judge(const Scene& scene, const PathCheck& path, const Claim& claim) {
    if (path.failure()) return {false, *path.failure()};
    const int dim = scene.dim;
    const char* reason = to_string(claim.reason);
    const char* word = claim.reason == Reason::hit     ? "yes"
                       : claim.reason == Reason::limit ? "unknown"
                                                       : "no";
    if (claim.answer != word)
        return bad("answer " + claim.answer + " does not go with reason " + reason);

    const std::uint64_t last = path.points() - 1; // index of the last point
    const std::string at_last = "point " + std::to_string(last);
    if (path.stopped() && claim.reason != Reason::absorbed)
        return bad("the ray is absorbed at " + at_last + ", yet the reason is " + reason);

    // Reflections implied by the point count (see the table in the docs).
    Integer expected = to_integer(last);
    switch (claim.reason) {
    case Reason::hit:
        if (!same(claim.extra, scene.target(), dim))
            return bad("target " + show(claim.extra, dim) + " is not the scene's target " +
                       show(scene.target(), dim));
        if (!on_ray(scene.target(), path.p(), path.v(), first_met(scene, path.p(), path.v()), dim))
            return bad("the target does not lie on the ray from " + at_last +
                       " up to the next element met");
        break;
    case Reason::escape: {
        const Event e = first_met(scene, path.p(), path.v());
        if (e.met)
            return bad("the ray from " + at_last + " meets an element at " +
                       show(advance(path.p(), path.v(), e.t, dim), dim));
        if (!same(claim.extra, path.v(), dim))
            return bad("direction " + show(claim.extra, dim) + " is not the ray's direction " +
                       show(path.v(), dim));
        if (on_ray(scene.target(), path.p(), path.v(), e, dim))
            return bad("the target lies on the final ray from " + at_last);
        break;
    }
    case Reason::absorbed:
        if (!path.stopped()) return bad("no absorber is met at " + at_last);
        expected -= 1;
        break;
    case Reason::cycle: {
        // The points run at least to the first return to state 1 (a detector
        // that notices the cycle late, like Brent's, streams a few more; they
        // were checked as steps like any other). That first return fixes L.
        if (path.points() < 3) return bad("a cycle needs at least two points after point 0");
        if (!same(claim.extra, path.p1(), dim) || !same(claim.extra_v, path.v1(), dim))
            return bad("state " + show(claim.extra, dim) + " " + show(claim.extra_v, dim) +
                       " is not state 1 " + show(path.p1(), dim) + " " + show(path.v1(), dim));
        if (!path.repeat()) return bad("the path never returns to state 1 by " + at_last);
        expected = to_integer(*path.repeat() - 1);
        if (claim.period != expected)
            return bad("period " + claim.period.get_str() + ", but the path first returns to " +
                       "state 1 at point " + std::to_string(*path.repeat()) + ": period " +
                       expected.get_str());
        break;
    }
    case Reason::limit:
        break;
    case Reason::lit:   // read_reason never yields these: no certificate
    case Reason::unlit: // format covers the illumination question yet
        return bad(std::string("reason ") + reason + " has no certificate format");
    }
    if (claim.reflections != expected)
        return bad("reflections " + claim.reflections.get_str() + ", but " +
                   std::to_string(last + 1) + " points give " + expected.get_str() +
                   " for reason " + reason);
    if (claim.reason == Reason::limit)
        return {false, "partial certificate: " + expected.get_str() +
                           " reflections checked, no answer proven"};
    return {true, "valid: " + std::string(reason) + ", " + expected.get_str() + " reflections"};
}

Reason read_reason(const certify::CertificateReader& in) {
    static constexpr Reason all[] = {Reason::hit, Reason::escape, Reason::absorbed, Reason::cycle,
                                     Reason::limit};
    in.expect("reason", 1, "hit, escape, absorbed, cycle or limit");
    for (Reason r : all)
        if (in.token(1) == to_string(r)) return r;
    in.fail(1, "hit, escape, absorbed, cycle or limit");
}

} // namespace

Verdict verify_certificate(const Scene& scene, std::istream& certificate,
                           const std::string& certificate_name) {
    // This checker reads the rules of semantics.md only: it would accept
    // paths that ignore a one-sided element's back or a splitter's second
    // branch, so it accepts nothing for such scenes (docs/optics.md).
    if (!scene.single_trajectory() || scene.has_one_sided())
        return {false, "invalid: certificates for scenes with splitters, one-sided elements or "
                       "several rays or targets are not supported yet"};
    certify::CertificateReader in(certificate, certificate_name);
    PathCheck path(scene);
    Claim claim;
    const int dim = scene.dim;
    try {
        in.read_header(dim);
        while (in.keyword() == "point") {
            in.expect("point", dim, "a number");
            path.point(in.vector(1, dim));
            in.advance();
        }
        if (path.points() == 0) in.fail(0, "'point'");
        // `method induction` after a path prefix: the interval exchange and
        // its induction (docs/induction-certificates.md), checked by its own
        // code once the prefix has been checked here like any path.
        if (in.keyword() == "method") {
            certify::PathPrefix prefix;
            prefix.failure = path.failure();
            prefix.points = path.points();
            prefix.absorbed = path.stopped();
            prefix.p1 = path.p1();
            prefix.v1 = path.v1();
            return certify::verify_induction(scene, in, prefix);
        }
        if (in.keyword() != "answer") in.fail(0, "'point', 'method' or 'answer'");
        in.expect("answer", 1, "yes, no or unknown");
        claim.answer = std::string(in.token(1));
        if (claim.answer != "yes" && claim.answer != "no" && claim.answer != "unknown")
            in.fail(1, "yes, no or unknown");
        in.advance();
        claim.reason = read_reason(in);
        in.advance();
        in.expect("reflections", 1, "a non-negative integer");
        claim.reflections = in.count(1);

        // The reason's own statements, in the order of the docs' table.
        switch (claim.reason) {
        case Reason::hit:
            in.advance();
            in.expect("target", dim, "a number");
            claim.extra = in.vector(1, dim);
            break;
        case Reason::escape:
            in.advance();
            in.expect("direction", dim, "a number");
            claim.extra = in.vector(1, dim);
            break;
        case Reason::absorbed:
            break;
        case Reason::cycle:
            in.advance();
            in.expect("state", 2 * dim, "a number");
            claim.extra = in.vector(1, dim);
            claim.extra_v = in.vector(1 + dim, dim);
            in.advance();
            in.expect("period", 1, "a non-negative integer");
            claim.period = in.count(1);
            break;
        case Reason::limit:
            in.advance();
            in.expect("partial", 0, in.end_of_statement());
            break;
        case Reason::lit: // read_reason never yields these
        case Reason::unlit:
            break;
        }
        in.advance();
        in.expect("end", 0, in.end_of_statement());
        if (in.next()) in.fail(0, "end of file (nothing may follow 'end')");
    } catch (const certify::IncompleteCertificate&) {
        return {false, "invalid: incomplete certificate (no 'end' line)"};
    }
    return judge(scene, path, claim);
}

} // namespace orthoray
