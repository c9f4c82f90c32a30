// Checks the witness of a lit target (docs/certificates.md, illumination
// check 3 without minimality) step by step as its lines are read, so a
// witness of any length takes O(1) memory: it must start at its ray's start
// state, each step must be the first acting event from the one before with
// a direction the rules allow there, the target must lie on the segment
// after the last step, and the direction changes must number the claim.
// In an intensity certificate the witness also carries its ray's intensity,
// floored after every event by the checker's own rule (intensity_rule.hpp),
// and must pass the target with exactly the intensity claimed, above the
// threshold.
#pragma once

#include "orthoray/scene.hpp"

#include "certify/illumination_claims.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace orthoray::certify {

class WitnessCheck {
public:
    explicit WitnessCheck(const Scene& scene) : scene_(scene) {}

    // `min_intensity` set: the witness of an intensity certificate.
    void begin(const TargetLine& lit, const std::optional<Integer>& min_intensity);
    void step(const Vector& point, const Vector& direction);
    void finish();

    // The first failure of any witness, as an "invalid: ..." message.
    const std::optional<std::string>& failure() const { return failure_; }
    std::uint64_t witnesses() const { return witnesses_; }

private:
    void fail(const std::string& what);

    const Scene& scene_;
    bool checking_ = false; // false once this witness failed or cannot be checked
    TargetLine lit_;
    std::size_t target_ = 0, ray_ = 0; // 0-based, valid when checking_
    std::uint64_t steps_ = 0;
    Integer changes_;
    Vector p_, v_;
    std::optional<Integer> min_intensity_;
    Integer intensity_; // along the witness, in an intensity certificate
    std::uint64_t witnesses_ = 0;
    std::optional<std::string> failure_;
};

} // namespace orthoray::certify
