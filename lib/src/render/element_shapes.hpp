// The elements drawn into every view as compact SVG path data.
#pragma once

#include "orthoray/scene.hpp"
#include "render/frame.hpp"
#include "render/view.hpp"

#include <cstddef>
#include <vector>

namespace orthoray::render {

// Draws the scene's elements into each view, at most `max_shapes` in all
// (shared among the views), and returns how many elements every view shows
// (all of them unless a view reached its share of the cap).
std::size_t draw_elements(const Scene& scene, const Frame& frame, std::vector<View>& views,
                          std::size_t max_shapes);

} // namespace orthoray::render
