// Seeded random scenes with what docs/optics.md adds: some elements turned
// into splitters, some made one-sided, and extra rays and targets.
#pragma once

#include "support/random_scene.hpp"

namespace orthoray::test {

struct RandomOpticsShape {
    RandomSceneShape scene;
    int splitter_percent = 20;  // per element (absorbers stay absorbers)
    int one_sided_percent = 30; // per element
    int max_rays = 3, max_targets = 3;
};

Scene random_optics_scene(std::mt19937_64& rng, const RandomOpticsShape& shape);

} // namespace orthoray::test
