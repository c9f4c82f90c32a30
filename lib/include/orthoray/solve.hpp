// Deciding an instance: the entry point of the library.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace orthoray {

enum class Engine {
    automatic, // default: lattice simulation; in 2D, induction once a short run has not answered
    lattice,   // simulation on integer lattice states with exact next-hit queries
    induction, // 2D: Rauzy-Zorich induction on the piece tables' interval exchange
               // (docs/induction.md); other dimensions are simulated
    reference, // naive O(n)-per-reflection scan in rationals: the test oracle
    graph,     // explicit state graph of every lattice state (small scenes only)
};

// The engines by the names the command line and the Python module take
// ("auto", "lattice", "induction", "reference", "graph").
const std::map<std::string, Engine>& engine_names();

// How the engines notice that the trajectory is periodic. Both use O(1) memory.
enum class CycleDetector {
    first_state, // compare with the state after reflection 1 (needs an injective step map)
    brent,       // Brent's power-of-two checkpoints (works for any deterministic map)
};

// Which integers the lattice engine computes with. A narrower type is only
// ever used where a bound computed from the scene proves it cannot overflow;
// asking for one the bound rules out gives the next wider type.
enum class Arithmetic {
    automatic, // the narrowest safe type: int64, then int128, then GMP
    int128,    // at least 128-bit machine integers (GMP when they could overflow)
    wide,      // always GMP
};

// How the lattice engine finds the next hit.
enum class Shooter {
    automatic, // 3D: the cross-section grid, or the BVH when elements cluster;
               // 2D: the uniform grid, then piece tables once a short run has
               // not answered
    grid,      // always the uniform grid
    bvh,       // always the bounding volume hierarchy
    pieces,    // 2D: piece tables from the start (the grid where there are none)
    section,   // always the cross-section grid (no cell walking)
};

// Receives the trajectory as it is computed: first the start point, then
// every reflection point, then (for absorbed) the absorption point, each with
// the direction the ray leaves it in. Used to stream certificates.
class PathSink {
public:
    virtual ~PathSink() = default;
    virtual void visit(const Vector& point, const Vector& direction) = 0;
    // A cycle entered after a tail (one-sided elements, docs/optics.md):
    // the state the cycle starts at, s_(tail + 1), reported once after the
    // last visit, when a second pass has found it. Called for every cycle
    // of a scene with one-sided elements (tail 0 included), never for a
    // two-sided scene, whose cycles start at the first reflection.
    virtual void cycle_start(const Vector& /*point*/, const Vector& /*direction*/) {}
};

class InductionObserver; // orthoray/exchange.hpp

// Sees the evidence behind an illumination answer (docs/optics.md,
// docs/certificates.md): after the search, the engine reports every branch
// state it stored with its label, then each target in order: lit (followed
// by the steps of one branch lighting it), unlit, or unknown (at a limit).
// Rays and targets are numbered from 1. Used to write certificates.
class IlluminationObserver {
public:
    virtual ~IlluminationObserver() = default;
    // A branch state (a ray's start, or a state leaving an event with two or
    // more outgoing directions) and its label: the least reflections of a
    // branch reaching it, then the least ray achieving that. At a limit the
    // labels of states not yet expanded are upper bounds only.
    virtual void branch(const Vector& point, const Vector& direction, std::size_t ray,
                        std::uint64_t reflections) = 0;
    // Target `target` is lit after `reflections` by ray `ray`; step() then
    // gives the ray's start and direction, then every event point of the
    // branch with the direction it leaves in, up to the segment through it.
    virtual void lit(std::size_t target, std::uint64_t reflections, std::size_t ray) = 0;
    virtual void step(const Vector& point, const Vector& direction) = 0;
    virtual void unlit(std::size_t target) = 0;
    virtual void unknown(std::size_t target) = 0;
};

// Sees the evidence behind an answer to the intensity question
// (docs/intensity.md, docs/certificates.md): after the search, every branch
// state it expanded with the greatest intensity reaching it, then each
// target in order: lit (with the greatest intensity passing it, then the
// steps of one branch achieving it, as for IlluminationObserver), unlit,
// or unknown (at a limit). Rays and targets are numbered from 1.
class IntensityObserver {
public:
    virtual ~IntensityObserver() = default;
    virtual void branch(const Vector& point, const Vector& direction, const Integer& intensity) = 0;
    virtual void lit(std::size_t target, std::uint64_t reflections, std::size_t ray,
                     const Integer& intensity) = 0;
    virtual void step(const Vector& point, const Vector& direction) = 0;
    virtual void unlit(std::size_t target) = 0;
    virtual void unknown(std::size_t target) = 0;
};

// A PathSink that keeps everything it is given. Its memory grows with the
// path, so it suits short runs and tests; certificates stream instead.
class PathRecorder : public PathSink {
public:
    std::vector<Vector> points, directions;
    void visit(const Vector& point, const Vector& direction) override {
        points.push_back(point);
        directions.push_back(direction);
    }
};

// Watches a run from outside. The engines call poll() between chunks of work,
// sized to take about 10 ms each, so that a limit it reports (a deadline, a
// signal) stops the run well within 100 ms. The monitor is never called from
// inside a chunk: the stepping loops stay free of checks.
class RunMonitor {
public:
    virtual ~RunMonitor() = default;
    // `reflections` performed so far. A limit ends the run with Reason::limit,
    // that limit, and the reflections performed.
    virtual std::optional<Limit> poll(std::uint64_t reflections) = 0;
};

struct SolveOptions {
    Engine engine = Engine::automatic;
    CycleDetector cycle_detector = CycleDetector::first_state;
    Arithmetic arithmetic = Arithmetic::automatic;
    Shooter shooter = Shooter::automatic;
    // Uniform grid cells per element; 0 picks the default for the dimension.
    std::int64_t grid_density = 0;
    // Stop with Reason::limit rather than perform more than this many reflections.
    std::optional<std::uint64_t> max_steps;
    // The illumination question: stop with Limit::memory rather than let the
    // stored branch states (their set, labels and queue) take more bytes.
    // Lit targets whose count is already final are kept; the rest are unknown.
    std::optional<std::size_t> max_state_bytes;
    // Engine::graph refuses (Reason::limit) scenes with more lattice states.
    std::uint64_t max_graph_states = 2'000'000;
    PathSink* path = nullptr;
    RunMonitor* monitor = nullptr;
    // Sees the exchange and every step when the induction engine decides
    // (only once its answer stands within max_steps); the path so far is
    // then the prefix up to the first reflection. A CertificateWriter
    // attaches itself as both (CertificateWriter::attach).
    InductionObserver* induction_observer = nullptr;
    // Sees the branch states, labels and witnesses of an illumination answer
    // (then every reachable branch state is explored, even when all targets
    // are lit early). A CertificateWriter attaches itself.
    IlluminationObserver* illumination_observer = nullptr;
    // Set: the intensity question (docs/intensity.md) instead: is each
    // target reached by a branch with intensity greater than this? Every
    // ray must carry an intensity.
    std::optional<Integer> min_intensity;
    // Sees the evidence of an answer to the intensity question. A
    // CertificateWriter attaches itself when min_intensity is set.
    IntensityObserver* intensity_observer = nullptr;
};

// Running out of memory while solving is a limit too (Reason::limit,
// Limit::memory), not an exception.
Answer solve(const Scene& scene, const SolveOptions& options = {});

} // namespace orthoray
