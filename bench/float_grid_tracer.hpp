// INEXACT COMPARISON BASELINE -- NOT PART OF ORTHORAY.
//
// A double-precision mirror tracer written the way a graphics programmer
// would write it ("what people use today"): the scene converted to doubles,
// the direction normalised, a uniform grid over the elements walked with the
// 3D-DDA of Amanatides and Woo (1987), ray-plane intersection t = (c - p)/v,
// an epsilon for "is this a hit" and "is this point on the element", and
// reflection by negating direction components. It exists only so that
// bench/orthoray_bench can compare the exact engine's speed and answers with
// it. Its answers can be wrong (bench/RESULTS.md shows one); nothing in
// orthoray uses it, and it must never decide anything.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace orthoray::bench {

struct FloatAnswer {
    Reason reason = Reason::limit;
    // As in orthoray::Answer: reflections before the target is reached, or
    // before the escape or absorption; the period for a cycle; the number
    // performed for limit.
    std::uint64_t reflections = 0;
    double setup_seconds = 0; // building the grid
};

struct FloatOptions {
    // Tolerance, relative to the scene's size (the largest |coordinate|):
    // hits closer than epsilon * size to the ray's origin are ignored, points
    // within it of an element count as on it, hits within it of the nearest
    // one count as simultaneous (a corner), and the target or the first
    // reflection state counts as reached within it.
    double epsilon = 1e-9;
    std::uint64_t max_steps = 1'000'000;
};

class FloatGridTracer {
public:
    explicit FloatGridTracer(const Scene& scene, double epsilon = FloatOptions{}.epsilon);
    ~FloatGridTracer();
    FloatGridTracer(const FloatGridTracer&) = delete;
    FloatGridTracer& operator=(const FloatGridTracer&) = delete;

    FloatAnswer trace(std::uint64_t max_steps) const;
    double setup_seconds() const;
    std::size_t cells() const;

    class Impl;

private:
    std::unique_ptr<Impl> impl_;
};

// Builds the grid and traces: one call.
FloatAnswer float_trace(const Scene& scene, const FloatOptions& options = {});

} // namespace orthoray::bench
