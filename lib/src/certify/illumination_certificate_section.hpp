// The illumination part of a certificate (docs/certificates.md, "The
// illumination question"): the `illumination` line, one `branch` line per
// branch state with its label, each target's `lit` (with its `step` lines),
// `unlit` or `unknown`, then the verdict. The engine hands everything over
// through IlluminationObserver once its search is done; nothing is kept
// here, so memory stays O(1) whatever the number of lines.
#pragma once

#include "orthoray/certificate.hpp"

#include <cstdint>
#include <optional>
#include <utility>

namespace orthoray {

//
// For the intensity question (docs/intensity.md) the same section carries a
// `min-intensity EPS` line after `illumination`, each branch line the
// state's intensity instead of a label, and each lit line the target's
// greatest intensity besides the branch's reflections and ray.
class CertificateWriter::IlluminationSection : public IlluminationObserver,
                                               public IntensityObserver {
public:
    // `min_intensity` set: the section of an intensity certificate.
    IlluminationSection(CertificateWriter& writer, std::optional<Integer> min_intensity)
        : writer_(writer), min_intensity_(std::move(min_intensity)) {}

    void branch(const Vector& point, const Vector& direction, std::size_t ray,
                std::uint64_t reflections) override;
    void lit(std::size_t target, std::uint64_t reflections, std::size_t ray) override;
    void branch(const Vector& point, const Vector& direction, const Integer& intensity) override;
    void lit(std::size_t target, std::uint64_t reflections, std::size_t ray,
             const Integer& intensity) override;
    void step(const Vector& point, const Vector& direction) override;
    void unlit(std::size_t target) override;
    void unknown(std::size_t target) override;

    // The verdict and `end`. When the engine reported nothing (it stopped
    // before it could), every target is unknown.
    void finish(const Answer& answer);

private:
    bool json() const;
    void begin();
    void branch_state(const Vector& point, const Vector& direction);
    void target_line(const char* word, std::size_t target);

    CertificateWriter& writer_;
    std::optional<Integer> min_intensity_;
    bool begun_ = false;
    bool listed_ = false;        // some target line is written
    std::uint64_t branches_ = 0; // branch lines written
};

} // namespace orthoray
