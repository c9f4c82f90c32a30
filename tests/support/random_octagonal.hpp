// Seeded random octagonal scenes (docs/octagonal.md) for property tests: a
// 2D box of axis walls (now and then with a gap or an absorbing piece)
// holding random diagonal and axis-aligned mirrors, absorbers, splitters
// and one-sided axis mirrors, every coordinate a multiple of 1/2 in a small
// range, so that diagonals end on walls, cross each other and touch axis
// elements' ends often. Rays run along the axes, along the diagonals, or
// along other small directions.
#pragma once

#include "orthoray/scene.hpp"

#include <random>

namespace orthoray::test {

struct RandomOctagonalShape {
    int box = 4;               // the walls are x, y = 0 and = box
    int max_elements = 8;      // elements inside the box, besides the walls
    int diagonal_percent = 55; // per inside element
    int absorber_percent = 10; // per element (walls included)
    int splitter_percent = 0;  // per inside element that is not an absorber
    int one_sided_percent = 0; // per axis-aligned inside element
    int gap_percent = 15;      // per wall: a gap lets the ray escape
    int max_rays = 1, max_targets = 1;
};

Scene random_octagonal_scene(std::mt19937_64& rng, const RandomOctagonalShape& shape);

} // namespace orthoray::test
