// The closure of an intensity certificate; see intensity_closure.hpp.
//
// Why it proves the answer. Let m be the least of the lit targets' claimed
// intensities and the threshold EPS when a target is claimed unlit (m =
// EPS then). Every factor is at most 1 and I -> floor(I f) is monotone, so
// a branch that is ever at or below m stays there, and passes no target
// above what the target's line claims: such a branch needs no line. Every
// other branch starts at a ray's start state, which has a line of at least
// the ray's intensity, and reaches each later branch state from the
// stretch of the state before; the checker walked that stretch from the
// line's intensity, which is at least the branch's (by induction), so by
// monotonicity it offered the next state at least the branch's intensity
// there, and a line of at least that much exists. So on every segment a
// branch passes while above m, the walk of some line passed the same
// segment at least as intensely; the walks found no segment above EPS
// passing an unlit target and none passing a lit target above its claim,
// and the witness (witness_check.cpp) shows the claim is reached.
#include "certify/intensity_closure.hpp"

#include "certify/intensity_rule.hpp"
#include "certify/path_geometry.hpp"
#include "certify/stretch_walk.hpp"

#include <string>

namespace orthoray::certify {
namespace {

class IntensityClosure {
public:
    IntensityClosure(const Scene& scene, const IlluminationClaims& claims,
                     const std::vector<std::optional<std::size_t>>& claim_of,
                     const StateIndex& index)
        : scene_(scene), dim_(scene.dim), claims_(claims), claim_of_(claim_of), index_(index),
          eps_(*claims.min_intensity), faint_(faintest_claim()) {}

    void run() {
        for (std::size_t r = 0; r < scene_.rays.size(); ++r) {
            const Ray& ray = scene_.rays[r];
            const std::string what = "ray " + std::to_string(r + 1);
            if (!ray.intensity)
                invalid(what + " has no intensity, which an intensity certificate needs");
            offered(ray.start, ray.direction, *ray.intensity, what + "'s start");
        }
        for (const BranchLine& line : claims_.branches) walk(line);
    }

private:
    // m of the proof above.
    Integer faintest_claim() const {
        Integer least = -1;
        for (const TargetLine& t : claims_.targets) {
            const Integer& bound = t.claim == TargetLine::Claim::lit ? t.intensity : eps_;
            if (least < 0 || bound < least) least = bound;
        }
        return least < 0 ? eps_ : least;
    }

    // A branch may be at state (p, v) with intensity `i`: it needs a line of
    // at least i, unless i is at most m.
    void offered(const Vector& p, const Vector& v, const Integer& i, const std::string& from) {
        if (i <= faint_) return;
        const std::string state = show(p, dim_) + " " + show(v, dim_);
        const auto it = index_.find({p, v});
        if (it == index_.end())
            invalid(from + " reaches " + state + " with intensity " + i.get_str() +
                    ", above every target's claim, but the state has no branch line");
        const BranchLine& line = claims_.branches[it->second];
        if (line.intensity < i)
            invalid(from + " reaches " + state + " with intensity " + i.get_str() +
                    ", more than the " + line.intensity.get_str() + " of its branch on " +
                    at_line(line.line));
    }

    // Walks a line's stretch from its intensity, flooring after each event
    // it passes, while the intensity is above the threshold.
    void walk(const BranchLine& line) {
        const std::string from = "the stretch of the branch on " + at_line(line.line);
        Integer i = line.intensity;
        const StretchEnd end =
            walk_stretch(scene_, line.point, line.direction, [&](const StretchSegment& s) {
                if (i <= eps_) return false;
                for (std::size_t t = 0; t < scene_.targets.size(); ++t)
                    if (on_ray(scene_.targets[t], s.p, s.v, s.to, dim_)) target_met(from, t, s, i);
                if (s.to.met && !s.to.absorbed) {
                    const std::vector<Vector> out = outgoing(s.v, s.to, dim_);
                    if (out.size() == 1)
                        i = attenuate(i, intensity_factor(scene_, advance(s.p, s.v, s.to.t, dim_),
                                                          s.v, out.front()));
                }
                return true;
            });
        if (end.kind != StretchEnd::Kind::branch) return;
        for (const Vector& c : end.outgoing)
            offered(end.point, c,
                    attenuate(i, intensity_factor(scene_, end.point, end.incoming, c)), from);
    }

    void target_met(const std::string& from, std::size_t t, const StretchSegment& s,
                    const Integer& i) {
        const TargetLine& claim = claims_.targets[*claim_of_[t]];
        const std::string target =
            "target " + std::to_string(t + 1) + " (" + at_line(claim.line) + ")";
        const std::string where =
            " on the segment from " + show(s.p, dim_) + " along " + show(s.v, dim_);
        if (claim.claim == TargetLine::Claim::unlit)
            invalid(target + " is claimed unlit, but " + from + " passes it with intensity " +
                    i.get_str() + ", above min-intensity " + eps_.get_str() + "," + where);
        if (claim.claim == TargetLine::Claim::lit && claim.intensity < i)
            invalid(target + " is claimed lit with intensity " + claim.intensity.get_str() +
                    ", but " + from + " passes it with " + i.get_str() + where);
    }

    const Scene& scene_;
    const int dim_;
    const IlluminationClaims& claims_;
    const std::vector<std::optional<std::size_t>>& claim_of_;
    const StateIndex& index_;
    const Integer eps_;
    const Integer faint_; // m
};

} // namespace

void check_intensity_closure(const Scene& scene, const IlluminationClaims& claims,
                             const std::vector<std::optional<std::size_t>>& claim_of,
                             const StateIndex& index) {
    IntensityClosure(scene, claims, claim_of, index).run();
}

} // namespace orthoray::certify
