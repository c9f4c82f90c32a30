// The independent certificate checker (docs/certificates.md). It replays the
// listed path with its own first acting event scan (acting_rule.hpp) in
// plain rationals and shares no code with any solver, so trusting an answer
// only means trusting the certify/ checker files, the scene parser and the
// certificate tokenizer (certificate_reader.cpp, pure parsing). The
// certificate is read as a stream: the path may have 10^8 points, so only
// the current state, state 1 and counters are kept, never the points
// themselves. Illumination certificates go to illumination_verifier.cpp,
// induction certificates to induction_verifier.cpp.
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"

#include "certify/certificate_reader.hpp"
#include "certify/illumination_verifier.hpp"
#include "certify/induction_verifier.hpp"
#include "certify/octagonal_induction_verifier.hpp"
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
using certify::to_integer;
using certify::to_uint64;

// ------------------------------------------------------------------- path --

// Replays the path point by point. After the first failure it only counts
// points, so the rest of the file is still parsed (syntax errors win) but the
// first failing step is the one reported.
class PathCheck {
public:
    explicit PathCheck(const Scene& scene) : scene_(scene), dim_(scene.dim) {
        // The points of one path answer only the question of one ray and
        // one target; the rest of the file is still parsed.
        if (!scene.single_trajectory())
            failure_ = "invalid: the scene has several rays or targets, or a splitter: its "
                       "certificate must answer the illumination question ('illumination')";
    }

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
        // No splitter acts on a single trajectory: one way on.
        v_ = certify::outgoing(v_, e, dim_).front();
        // Keep state 1 and the first later state equal to it: for a cycle
        // without a tail that return settles the claim in this one pass.
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
    std::optional<Integer> tail; // cycle: the `tail` line, when given
};

// The cycle claim (docs/certificates.md): with s_i the state after event
// i, s_(T+1) is the stated state, s_(T+1+L) returns to it and no state in
// between does (L least), and if T >= 1 then s_T != s_(T+L): the state
// before the cycle's start is not on the cycle, so T is least (a state on
// the cycle stays on it). The listed points were checked to be these
// events, and the caller checked that they reach p_(T+L+1), so T and L fit
// in 64 bits.
std::optional<std::string> check_cycle(const Scene& scene, const PathCheck& path,
                                       const Claim& claim, std::uint64_t tail,
                                       std::uint64_t period) {
    const int dim = scene.dim;
    auto point = [](std::uint64_t i) { return "point " + std::to_string(i); };
    auto returns = [&](std::uint64_t start, std::uint64_t i) {
        return "period " + std::to_string(period) + ", but the state at " + point(start) +
               " returns at " + point(i) + ": period " + std::to_string(i - start);
    };
    auto no_return = [&](std::uint64_t start) {
        return "period " + std::to_string(period) + ", but the state at " + point(start + period) +
               " is not the state at " + point(start) + ": no cycle of that period starts there";
    };
    auto not_start = [&](std::uint64_t start, const Vector& p, const Vector& v) {
        return "state " + show(claim.extra, dim) + " " + show(claim.extra_v, dim) +
               " is not the state at " + point(start) + " (tail + 1), " + show(p, dim) + " " +
               show(v, dim);
    };
    // Without a tail, state 1 and its first return were kept while the
    // points streamed by: no second walk (two-sided scenes always take
    // this way).
    if (tail == 0) {
        if (!same(path.p1(), claim.extra, dim) || !same(path.v1(), claim.extra_v, dim))
            return not_start(1, path.p1(), path.v1());
        if (path.repeat() && *path.repeat() < 1 + period) return returns(1, *path.repeat());
        if (path.repeat() != 1 + period) return no_return(1);
        return std::nullopt;
    }
    // With a tail, T and L are read only after the points, so the states
    // are walked again from the start: T + L + 1 steps, O(1) memory.
    Vector p = scene.ray().start, v = scene.ray().direction;
    Vector p_tail, v_tail; // s_T
    const std::uint64_t start = tail + 1;
    for (std::uint64_t i = 1; i <= start + period; ++i) {
        const Event e = first_met(scene, p, v);
        p = advance(p, v, e.t, dim); // met, not absorbed: the points were checked
        v = certify::outgoing(v, e, dim).front();
        const bool at_start = same(p, claim.extra, dim) && same(v, claim.extra_v, dim);
        if (i == tail) {
            p_tail = p;
            v_tail = v;
        } else if (i == start && !at_start) {
            return not_start(start, p, v);
        } else if (i > start && i < start + period && at_start) {
            return returns(start, i);
        } else if (i == start + period && !at_start) {
            return no_return(start);
        }
        if (i == tail + period && same(p, p_tail, dim) && same(v, v_tail, dim))
            return "tail " + std::to_string(tail) + ", but the state at " + point(tail) +
                   " returns at " + point(i) + ": it is on the cycle, so the tail is shorter";
    }
    return std::nullopt;
}

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
        const Integer tail = claim.tail.value_or(0);
        // Both can merge two states into one, so a cycle may have a tail.
        if (!claim.tail && (scene.has_one_sided() || scene.has_diagonal()))
            return bad("a cycle in a scene with one-sided elements or diagonals needs its "
                       "'tail' line");
        if (claim.period == 0) return bad("period 0: a cycle's period is at least 1");
        // The listed points must reach p_(T+L+1), the first return to the
        // cycle's start; a detector that notices the cycle late (Brent's)
        // streams a few more, checked as steps like any other.
        const Integer needed = tail + claim.period + 1;
        if (to_integer(last) < needed)
            return bad("tail " + tail.get_str() + " and period " + claim.period.get_str() +
                       " need the points up to point " + needed.get_str() + ", but the last is " +
                       at_last);
        if (auto failure =
                check_cycle(scene, path, claim, to_uint64(tail), to_uint64(claim.period)))
            return bad(*failure);
        expected = tail + claim.period;
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
    certify::CertificateReader in(certificate, certificate_name);
    PathCheck path(scene);
    Claim claim;
    const int dim = scene.dim;
    try {
        in.read_header(dim);
        // The illumination question has its own form and checker.
        if (in.keyword() == "illumination") return certify::verify_illumination(scene, in);
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
            // Induction needs a bijective step map: two-sided elements
            // only; diagonals only in the octagonal form, which reads the
            // lattice for itself.
            const bool octagonal = in.size() > 1 && in.token(1) == "octagonal-induction";
            if (!prefix.failure && scene.has_one_sided())
                prefix.failure = "invalid: induction certificates are for scenes without "
                                 "one-sided elements";
            if (!prefix.failure && scene.has_diagonal() && !octagonal)
                prefix.failure = "invalid: a scene with diagonals needs `method "
                                 "octagonal-induction`";
            prefix.points = path.points();
            prefix.absorbed = path.stopped();
            prefix.p1 = path.p1();
            prefix.v1 = path.v1();
            if (octagonal) return certify::verify_octagonal_induction(scene, in, prefix);
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
        // A cycle's tail (docs/certificates.md) may be left out when it is 0.
        if (claim.reason == Reason::cycle && in.keyword() == "tail") {
            in.expect("tail", 1, "a non-negative integer");
            claim.tail = in.count(1);
            in.advance();
        }
        in.expect("end", 0, in.end_of_statement());
        if (in.next()) in.fail(0, "end of file (nothing may follow 'end')");
    } catch (const certify::IncompleteCertificate&) {
        return {false, "invalid: incomplete certificate (no 'end' line)"};
    }
    return judge(scene, path, claim);
}

} // namespace orthoray
