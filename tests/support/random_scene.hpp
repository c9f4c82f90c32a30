// Seeded random scenes for property tests: small rational coordinates, 0 to
// 12 elements, some absorbers, sometimes an enclosing box (with a gap or an
// absorbing face now and then), starts on mirrors, axis-parallel directions
// and zero direction components. The target is placed by the caller.
#pragma once

#include "orthoray/scene.hpp"

#include <random>

namespace orthoray::test {

struct RandomSceneShape {
    int dim = 2;
    int max_elements = 12;
    int range = 6;           // coordinates are k / den with |k| <= range * den
    int max_denominator = 3; // 1: integer scenes (small lattices, state graph feasible)
    int max_direction = 3;   // direction components in [-max, max]
    int box_percent = 40;    // how often (in percent) an enclosing box keeps the ray in
};

Scene random_scene(std::mt19937_64& rng, const RandomSceneShape& shape);

// A target that lies on the trajectory: a point of one of the first few
// segments (found with the reference tracer), or, if none, a random point.
Vector target_on_trajectory(std::mt19937_64& rng, const Scene& scene);

// A random point in the scene's range (usually off the trajectory).
Vector random_point(std::mt19937_64& rng, const RandomSceneShape& shape);

// The property tests' target: half the time on the trajectory, otherwise
// a random point.
Vector random_target(std::mt19937_64& rng, const Scene& scene, const RandomSceneShape& shape);

} // namespace orthoray::test
