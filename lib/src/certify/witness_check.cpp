// The lit witness check; see witness_check.hpp.
#include "certify/witness_check.hpp"

#include "certify/acting_rule.hpp"
#include "certify/intensity_rule.hpp"
#include "certify/path_geometry.hpp"

namespace orthoray::certify {

void WitnessCheck::begin(const TargetLine& lit, const std::optional<Integer>& min_intensity) {
    lit_ = lit;
    min_intensity_ = min_intensity;
    steps_ = 0;
    changes_ = 0;
    ++witnesses_;
    // Numbers out of range are reported by the claims check; such a
    // witness is not followed.
    checking_ = !failure_ && numbers_one_of(lit.target, scene_.targets.size()) &&
                numbers_one_of(lit.label.ray, scene_.rays.size());
    if (!checking_) return;
    target_ = lit.target.get_ui() - 1;
    ray_ = lit.label.ray.get_ui() - 1;
}

void WitnessCheck::step(const Vector& point, const Vector& direction) {
    const std::uint64_t k = steps_++;
    if (!checking_) return;
    const int dim = scene_.dim;
    const Ray& ray = scene_.rays[ray_];
    if (k == 0) {
        if (!same(point, ray.start, dim) || !same(direction, ray.direction, dim))
            return fail("step 0 is " + show(point, dim) + " " + show(direction, dim) +
                        ", not ray " + lit_.label.ray.get_str() + "'s start " +
                        show(ray.start, dim) + " " + show(ray.direction, dim));
        if (min_intensity_ && !ray.intensity)
            return fail("ray " + lit_.label.ray.get_str() +
                        " has no intensity, which an intensity certificate needs");
        if (min_intensity_) intensity_ = *ray.intensity;
        p_ = point;
        v_ = direction;
        return;
    }
    const std::string from = "step " + std::to_string(k - 1);
    const Event e = first_met(scene_, p_, v_);
    if (!e.met)
        return fail("the ray from " + from + " meets no acting element, yet a step follows");
    if (e.absorbed) return fail("the ray from " + from + " is absorbed, yet a step follows");
    const Vector q = advance(p_, v_, e.t, dim);
    if (!same(point, q, dim))
        return fail("step " + std::to_string(k) + " is at " + show(point, dim) +
                    ", but the first acting event from " + from + " is at " + show(q, dim));
    bool allowed = false;
    for (const Vector& c : outgoing(v_, e, dim)) allowed = allowed || same(c, direction, dim);
    if (!allowed)
        return fail("step " + std::to_string(k) + " leaves " + show(q, dim) + " along " +
                    show(direction, dim) + ", which the elements there do not allow");
    if (!same(direction, v_, dim)) changes_ += 1;
    if (min_intensity_)
        intensity_ = attenuate(intensity_, intensity_factor(scene_, q, v_, direction));
    p_ = point;
    v_ = direction;
}

void WitnessCheck::finish() {
    if (!checking_) return;
    const int dim = scene_.dim;
    if (steps_ == 0) return fail("no step lines: the witness must start at its ray's start");
    const Vector& target = scene_.targets[target_];
    const std::string last = "step " + std::to_string(steps_ - 1);
    if (!on_ray(target, p_, v_, first_met(scene_, p_, v_), dim))
        return fail("the target " + show(target, dim) + " is not on the segment after " + last);
    if (changes_ != lit_.label.reflections)
        return fail("the witness changes direction " + changes_.get_str() + " times, not " +
                    lit_.label.reflections.get_str());
    if (!min_intensity_) return;
    if (intensity_ != lit_.intensity)
        return fail("the witness passes the target with intensity " + intensity_.get_str() +
                    ", not " + lit_.intensity.get_str());
    if (intensity_ <= *min_intensity_)
        return fail("the witness's intensity " + intensity_.get_str() +
                    " is not above min-intensity " + min_intensity_->get_str());
}

void WitnessCheck::fail(const std::string& what) {
    checking_ = false;
    failure_ = "invalid: lit target " + lit_.target.get_str() + " (line " +
               std::to_string(lit_.line) + "): " + what;
}

} // namespace orthoray::certify
