// An illumination certificate (docs/certificates.md) built in the tests from
// the reference engine's step (engine::reference_step), to hold the
// verifier to the engines on random scenes: the branch states are found by
// walking every stretch, their least labels by Dijkstra over the stretches,
// and each lit target's witness by following the least labels back to a
// ray. Test code only; memory grows with the states visited, which is fine
// for the small scenes it is used on.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace orthoray::test {

struct BranchCertificate {
    std::string text;                      // the text format
    std::vector<TargetAnswer> targets;     // what it claims, target by target
    std::vector<std::size_t> branch_lines; // the line index (0-based) of each branch line
};

// Nullopt when the stretches take more than `max_events` events in all.
std::optional<BranchCertificate> branch_certificate(const Scene& scene, std::size_t max_events);

// The same statements as JSON Lines.
std::string as_json_lines(const std::string& text);

} // namespace orthoray::test
