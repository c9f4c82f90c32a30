// A brute-force induction certificate writer for the tests, independent of
// the induction engine.
//
// Test-only, and deliberately naive. For a small 2D scene it lists every
// lattice state on a mirror (one transversal a merged mirror interval and
// direction), finds each state's next state by a plain scan, closes the holes,
// cuts the exchange into maximal pieces and runs Rauzy induction on explicit
// positions, with cycle steps at random. It writes certificates the checker
// must accept, whose verdict the tests compare with the reference tracer.
#pragma once

#include "orthoray/scene.hpp"

#include <cstddef>
#include <optional>
#include <random>
#include <string>

namespace orthoray::test {

struct Brute {
    std::string text;
    std::string verdict; // "valid: <reason>, <n> reflections"
    int steps = 0, cycle_steps = 0;
};

// The certificate of `scene`'s ray, or nothing when the scene is out of the
// writer's reach (3D, an axis-parallel ray, more than `max_states` states, a
// ray absorbed or escaping at once).
std::optional<Brute> brute_certificate(const Scene& scene, std::mt19937_64& rng,
                                       std::size_t max_states);

} // namespace orthoray::test
