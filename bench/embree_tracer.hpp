// INEXACT COMPARISON BASELINE -- NOT PART OF ORTHORAY.
//
// A mirror tracer built on Intel Embree 3 (single-precision BVH ray
// queries), the way a renderer would bounce a ray: every element becomes an
// Embree quad (a 2D segment is extruded along z over a slab as wide as the
// scene and the ray stays in the plane z = 0), each bounce is one
// rtcIntersect1 from the last hit point with a tnear epsilon, and the mirror
// reflects by negating the direction component along the hit normal's
// largest axis. One thread. Two scene flags: RTC_SCENE_FLAG_NONE (Embree's
// default) and RTC_SCENE_FLAG_ROBUST (watertight-er, slower traversal). It
// exists only so that bench/orthoray_bench can time Embree next to the exact
// engine and measure where its path leaves the exact one; nothing in
// orthoray uses it, and it must never decide anything. Built only when CMake
// finds Embree (ORTHORAY_BENCH_EMBREE).
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace orthoray::bench {

struct EmbreeAnswer {
    Reason reason = Reason::limit;
    // As in orthoray::Answer: reflections before the target, the escape or
    // the absorption; the period for a cycle; the number performed for limit.
    std::uint64_t reflections = 0;
    double setup_seconds = 0; // converting the scene to floats, building Embree's BVH
};

// Why the Embree tracer cannot take this scene (splitters, one-sided or
// diagonal elements: a renderer's bounce loop has none of them), or "".
std::string embree_unsupported(const Scene& scene);

class EmbreeTracer {
public:
    // tnear: the ray's minimum distance, relative to the scene's size (the
    // largest |coordinate|), so that a bounce does not find its own origin.
    EmbreeTracer(const Scene& scene, bool robust, double tnear = 1e-6);
    ~EmbreeTracer();
    EmbreeTracer(const EmbreeTracer&) = delete;
    EmbreeTracer& operator=(const EmbreeTracer&) = delete;

    // After each reflection, `visit(point, element)` (if given) sees the hit
    // point (3 doubles, z = 0 in 2D) and the index of the element hit in
    // scene.elements; returning false stops the trace (Reason::limit).
    using Visit = std::function<bool(const double* point, std::uint32_t element)>;
    EmbreeAnswer trace(std::uint64_t max_steps, const Visit& visit = {}) const;
    double setup_seconds() const;

    class Impl;

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace orthoray::bench
