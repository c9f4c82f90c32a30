// The illumination checks, in the order of docs/certificates.md: the
// claims' shape (each target once, numbers in range, no state twice), the
// lit witnesses, then for a complete certificate the closure of the branch
// lines with lower-bound labels, the unlit targets and the least K of the
// lit ones (one walk of every stretch serves all three), and last the
// verdict's counts.
//
// An intensity certificate (a `min-intensity` line) has its own closure
// check, with intensities as upper bounds: intensity_closure.cpp.
//
// Why closure with lower bounds proves minimality: every branch of ray r
// starts at r's start state, whose line has a label <= (0, r), and a branch
// that reaches a branch state after k reflections enters it from the
// stretch of a listed state whose label is <= its own label there; adding
// the stretch's reflections keeps the order, so by induction every branch
// state reached at (k, r) has a line with label <= (k, r). A target first
// met w reflections into a stretch is therefore reached by no branch
// before (label + w), and checking that this is >= the claim for every
// line bounds every branch. Memory: the map from state to line, which
// grows with the number of branch lines, never with the reflections.
#include "certify/illumination_verifier.hpp"

#include "certify/illumination_check_support.hpp"
#include "certify/illumination_parse.hpp"
#include "certify/intensity_closure.hpp"
#include "certify/path_geometry.hpp"
#include "certify/stretch_walk.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace orthoray::certify {
namespace {

class IlluminationCheck {
public:
    IlluminationCheck(const Scene& scene, const IlluminationClaims& claims)
        : scene_(scene), dim_(scene.dim), claims_(claims), claim_of_(scene.targets.size()) {}

    // Each target in exactly one line, in range; the rays of branch and lit
    // lines in range; no state listed twice.
    void shape() {
        const std::size_t n = scene_.targets.size();
        for (const TargetLine& t : claims_.targets) {
            if (!numbers_one_of(t.target, n))
                invalid(at_line(t.line) + ": target " + t.target.get_str() +
                        ", but the scene has " + std::to_string(n) + " targets");
            const std::size_t i = t.target.get_ui() - 1;
            if (claim_of_[i])
                invalid(at_line(t.line) + ": target " + t.target.get_str() +
                        " is already claimed on " + at_line(claims_.targets[*claim_of_[i]].line));
            claim_of_[i] = static_cast<std::size_t>(&t - claims_.targets.data());
            if (t.claim == TargetLine::Claim::lit &&
                !numbers_one_of(t.label.ray, scene_.rays.size()))
                invalid(at_line(t.line) + ": ray " + t.label.ray.get_str() +
                        ", but the scene has " + std::to_string(scene_.rays.size()) + " rays");
            if (t.claim == TargetLine::Claim::unknown && !claims_.partial)
                invalid(at_line(t.line) + ": target " + t.target.get_str() +
                        " is unknown, but only a partial certificate may leave a target unknown");
            if (t.claim == TargetLine::Claim::unlit && claims_.partial)
                invalid(at_line(t.line) + ": target " + t.target.get_str() +
                        " is claimed unlit, which a partial certificate cannot prove");
        }
        for (std::size_t i = 0; i < n; ++i)
            if (!claim_of_[i])
                invalid("target " + std::to_string(i + 1) + " has no lit, unlit or unknown line");
        for (std::size_t b = 0; b < claims_.branches.size(); ++b) {
            const BranchLine& line = claims_.branches[b];
            if (!claims_.min_intensity && !numbers_one_of(line.label.ray, scene_.rays.size()))
                invalid("branch on " + at_line(line.line) + ": ray " + line.label.ray.get_str() +
                        ", but the scene has " + std::to_string(scene_.rays.size()) + " rays");
            const auto [it, fresh] = index_.emplace(std::pair{line.point, line.direction}, b);
            if (!fresh)
                invalid("the branches on " + at_line(claims_.branches[it->second].line) + " and " +
                        at_line(line.line) + " name the same state " + show_state(line));
        }
    }

    // Checks 3 to 5 of docs/certificates.md, for a complete certificate:
    // the rays' start states, then one walk of every stretch.
    void closure_and_targets() {
        if (claims_.min_intensity)
            return check_intensity_closure(scene_, claims_, claim_of_, index_);
        for (std::size_t r = 0; r < scene_.rays.size(); ++r) {
            const Ray& ray = scene_.rays[r];
            const Label bound{0, to_integer(r + 1)};
            const std::string what = "ray " + std::to_string(r + 1) + "'s start state " +
                                     show(ray.start, dim_) + " " + show(ray.direction, dim_);
            const auto it = index_.find({ray.start, ray.direction});
            if (it == index_.end()) invalid(what + " has no branch line");
            const BranchLine& line = claims_.branches[it->second];
            if (bound < line.label)
                invalid(what + ": the branch on " + at_line(line.line) + " has label " +
                        show(line.label) + ", more than " + show(bound));
        }
        for (const BranchLine& line : claims_.branches) walk(line);
    }

    // Check 6: the verdict's lines (for a partial certificate as well).
    Verdict verdict() const {
        Integer largest = 0;
        bool all_lit = true;
        std::size_t lit = 0;
        for (const TargetLine& t : claims_.targets) {
            if (t.claim != TargetLine::Claim::lit) {
                all_lit = false;
                continue;
            }
            ++lit;
            if (t.label.reflections > largest) largest = t.label.reflections;
        }
        const char* answer = claims_.partial ? "unknown" : all_lit ? "yes" : "no";
        const char* reason = claims_.partial ? "limit" : all_lit ? "lit" : "unlit";
        if (claims_.answer != answer)
            invalid("verdict: answer " + claims_.answer + ", but the target lines give " + answer);
        if (to_string(claims_.reason) != std::string_view(reason))
            invalid(std::string("verdict: reason ") + to_string(claims_.reason) +
                    ", but the target lines give " + reason);
        if (claims_.reflections != largest)
            invalid("verdict: reflections " + claims_.reflections.get_str() +
                    ", but the largest lit target's count is " + largest.get_str());
        const Integer lines = to_integer(claims_.branches.size());
        if (claims_.states != lines)
            invalid("verdict: states " + claims_.states.get_str() + ", but there are " +
                    lines.get_str() + " branch lines");
        if (claims_.partial)
            return {false, "partial certificate: " + std::to_string(lit) +
                               " lit targets' witnesses checked, no answer proven"};
        const std::string above =
            claims_.min_intensity ? " above intensity " + claims_.min_intensity->get_str() : "";
        return {true, std::string("valid: ") + reason + above + ", " + largest.get_str() +
                          " reflections, " + lines.get_str() + " states"};
    }

private:
    std::string show_state(const BranchLine& line) const {
        return show(line.point, dim_) + " " + show(line.direction, dim_);
    }

    // Walks the stretch of one branch line: every segment against every
    // target (the first pass counts: later ones come after more
    // reflections), and the branch event at its end against the lines.
    void walk(const BranchLine& line) {
        const std::size_t n = scene_.targets.size();
        std::vector<bool> passed(n, false);
        const std::string from = "the stretch of the branch on " + at_line(line.line);
        const StretchEnd end =
            walk_stretch(scene_, line.point, line.direction, [&](const StretchSegment& s) {
                for (std::size_t i = 0; i < n; ++i) {
                    if (passed[i] || !on_ray(scene_.targets[i], s.p, s.v, s.to, dim_)) continue;
                    passed[i] = true;
                    target_met(line, from, i, s);
                }
                return true;
            });
        if (end.kind != StretchEnd::Kind::branch) return;
        const Vector& q = end.point;
        for (const Vector& c : end.outgoing) {
            const Label bound{line.label.reflections + to_integer(end.reflections) +
                                  (same(c, end.incoming, dim_) ? 0 : 1),
                              line.label.ray};
            const auto it = index_.find({q, c});
            if (it == index_.end())
                invalid(from + " ends at the splitter event " + show(q, dim_) +
                        ", but its outgoing state " + show(q, dim_) + " " + show(c, dim_) +
                        " has no branch line");
            const BranchLine& next = claims_.branches[it->second];
            if (bound < next.label)
                invalid(from + " reaches " + show(q, dim_) + " " + show(c, dim_) + " with label " +
                        show(bound) + ", less than the label " + show(next.label) +
                        " of its branch on " + at_line(next.line));
        }
    }

    void target_met(const BranchLine& line, const std::string& from, std::size_t i,
                    const StretchSegment& s) {
        const TargetLine& claim = claims_.targets[*claim_of_[i]];
        const std::string target =
            "target " + std::to_string(i + 1) + " (" + at_line(claim.line) + ")";
        if (claim.claim == TargetLine::Claim::unlit)
            invalid(target + " is claimed unlit, but " + from + " passes it on the segment from " +
                    show(s.p, dim_) + " along " + show(s.v, dim_));
        if (claim.claim != TargetLine::Claim::lit) return;
        const Label reached{line.label.reflections + to_integer(s.reflections), line.label.ray};
        if (reached < claim.label)
            invalid(target + " is claimed lit with " + show(claim.label) + ", but " + from +
                    " passes it with " + show(reached) + " on the segment from " + show(s.p, dim_) +
                    " along " + show(s.v, dim_));
    }

    const Scene& scene_;
    const int dim_;
    const IlluminationClaims& claims_;
    std::vector<std::optional<std::size_t>> claim_of_; // target -> its line in claims_.targets
    StateIndex index_;                                 // state -> its line in claims_.branches
};

} // namespace

Verdict verify_illumination(const Scene& scene, CertificateReader& in) {
    WitnessCheck witnesses(scene);
    const IlluminationClaims claims = parse_illumination(in, scene.dim, witnesses);
    if (scene.single_trajectory() && !claims.min_intensity)
        return {false, "invalid: the scene has one ray, one target and no splitter: its "
                       "certificate lists the path's points, not illumination"};
    try {
        IlluminationCheck check(scene, claims);
        check.shape();
        if (witnesses.failure()) return {false, *witnesses.failure()};
        if (!claims.partial) check.closure_and_targets();
        return check.verdict();
    } catch (const Invalid& failure) {
        return {false, failure.message};
    }
}

} // namespace orthoray::certify
