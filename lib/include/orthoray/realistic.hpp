// Realistic scenes (Isobe et al. 2005; docs/realistic-scenes.md): light
// loses intensity along a ray path, every object passes on a monotone
// share of what reaches it, and the question is whether some path from the
// source object reaches the receiver with intensity above eps. Given which
// object triples O1 -> O2 -> O3 a ray path can take, a Dijkstra-like
// dynamic program over (previous object, current object) pairs decides it
// in polynomial time.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace orthoray {

// What an object passes on toward the next one, as a function of the
// intensity i in N that reaches it. Both kinds are non-decreasing (more
// light in, at least as much out) and never exceed i (intensity never grows
// along a path); the reader refuses any other.
struct Transfer {
    enum class Kind { scale, table };
    Kind kind = Kind::scale;
    // scale: floor(i * p / q), 0 <= p <= q.
    Integer p = 1, q = 1;
    // table: the value of the largest threshold <= i, 0 below the first;
    // thresholds strictly increasing, values non-decreasing, each value at
    // most its threshold.
    std::vector<Integer> thresholds, values;

    Integer operator()(const Integer& i) const;
};

// A ray path can go from object `from` over `via` to `to`; `via` passes on
// `transfer` of what reaches it.
struct Triple {
    std::size_t from = 0, via = 0, to = 0;
    Transfer transfer;
};

struct RealisticModel {
    std::vector<std::string> objects;
    std::size_t source = 0, receiver = 0;
    Integer emitted; // the intensity the source sends out
    Integer eps;
    // The first legs: objects a ray path from the source reaches directly
    // (each with `emitted`).
    std::vector<std::size_t> first_legs;
    std::vector<Triple> triples;
};

// Reads the text format of docs/realistic-scenes.md; bad input throws
// InputError (orthoray/parse.hpp) with its file, line and column.
RealisticModel read_realistic(const std::string& text, const std::string& file = "<input>");

struct RealisticAnswer {
    bool yes = false;              // some path arrives at the receiver with more than eps
    Integer best = -1;             // the most intensity arriving at the receiver (-1: none arrives)
    std::vector<std::size_t> path; // a path achieving `best`: source, ..., receiver
    std::vector<Integer> intensities; // what reaches each object of `path` after the source
    // The dynamic program's value of every (previous, current) pair it
    // reached: the most intensity reaching `current` from `previous`. These
    // are the bounds a certificate lists.
    struct PairBound {
        std::size_t previous, current;
        Integer intensity;
    };
    std::vector<PairBound> bounds;
};

// The model of a mirror scene (docs/realistic-scenes.md, "From mirror
// scenes"): objects "S" (the ray's start, the source, emitting the ray's
// intensity), "R" (target number `target` + 1, the receiver) and "e1", "e2",
// ... (the elements in file order); first legs and triples are the legs of
// every reachable state of the ray, each triple's transfer the exact factor
// of the event at its middle object. The scene must have one ray, with an
// intensity (UnsupportedScene otherwise). Deriving the model walks every
// reachable state, keeping only those that leave a junction (a point where
// a ray may split, docs/optics.md): past `max_states` of them it stops with
// StatesExceeded, a limit and not bad input. The kept states are numbered in
// 32 bits, so a cap above max_kept_states stops there. A ray that never
// splits is walked in constant memory, however long its orbit.
inline constexpr std::size_t max_kept_states = 0xffff'fffe; // 2^32 - 2
RealisticModel realistic_model_of_scene(const Scene& scene, std::size_t target, const Integer& eps,
                                        std::size_t max_states = 1'000'000);

class StatesExceeded : public std::runtime_error {
public:
    explicit StatesExceeded(std::size_t max_states);
    std::size_t max_states() const { return max_states_; }

private:
    std::size_t max_states_;
};

// The model in the text format read_realistic reads.
std::string write_realistic(const RealisticModel& model);

// The dynamic program, run as Boost.Graph's dijkstra_shortest_paths over the
// graph of object pairs with "more intensity" as the order and each
// triple's transfer as the edge's combine.
RealisticAnswer solve_realistic(const RealisticModel& model);

// The certificate: the answer, a path achieving the best intensity, and an
// upper bound on every reachable pair that is closed under the triples.
void write_realistic_certificate(std::ostream& out, const RealisticModel& model,
                                 const RealisticAnswer& answer);

struct RealisticVerdict {
    bool valid = false;
    std::string message;
};

// Re-evaluates a certificate against the model with code that shares
// nothing with the dynamic program. A malformed certificate throws
// InputError.
RealisticVerdict verify_realistic_certificate(const RealisticModel& model, std::istream& in,
                                              const std::string& name = "<certificate>");

} // namespace orthoray
