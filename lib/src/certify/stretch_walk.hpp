// The checker's walk of one stretch (docs/certificates.md, illumination):
// from a branch state, the deterministic motion up to the next event with
// two or more outgoing directions, an escape, an absorption, or forever.
// "Forever" is found with Brent's cycle detection, which keeps two states
// and two counters, so a stretch of any length is walked in O(1) memory;
// every state of its rho (tail and cycle) is visited before the detection,
// so every segment of the stretch is shown to the visitor at least once.
#pragma once

#include "orthoray/scene.hpp"

#include "certify/acting_rule.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace orthoray::certify {

// One segment of a stretch: from p along v up to the event `to` (to
// infinity when !to.met; up to and including the absorption point when
// to.absorbed), after `reflections` direction changes into the stretch.
struct StretchSegment {
    const Vector& p;
    const Vector& v;
    const Event& to;
    std::uint64_t reflections;
};

struct StretchEnd {
    // stopped: the visitor asked to stop (an intensity fallen to the
    // threshold: nothing after it matters).
    enum class Kind { escape, absorbed, branch, cycle, stopped };
    Kind kind = Kind::escape;
    // For a branch end: the event point, the direction arriving there, the
    // two or more directions leaving it, and the reflections before it.
    Vector point, incoming;
    std::vector<Vector> outgoing;
    std::uint64_t reflections = 0;
};

// `visit` sees each segment and returns whether to go on.
StretchEnd walk_stretch(const Scene& scene, const Vector& start, const Vector& direction,
                        const std::function<bool(const StretchSegment&)>& visit);

} // namespace orthoray::certify
