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

// Dense scenes with many one-sided splitters for case i of a property test:
// branches there often have an event at a junction (docs/optics.md) that
// does not split their own arrival. 3D every third case, halves as
// coordinates every fourth, whole numbers otherwise (more coincidences).
RandomOpticsShape dense_one_sided_shape(int i);

// docs/intensity.md's attributes on a scene: most mirrors and splitters get
// a reflectance, most splitters a transmittance (each from 0, 1/2, 2/3,
// 3/4, 9/10 and 1), and every ray an intensity in [0, max_intensity].
void add_random_attenuation(std::mt19937_64& rng, Scene& scene, int max_intensity);

// A point some branch passes: follow a random ray through a few events,
// taking a random outgoing direction at each, and pick a point of the
// segment reached (an end, an inner point, or a point of the final ray).
Vector point_on_a_branch(std::mt19937_64& rng, const Scene& scene);

} // namespace orthoray::test
