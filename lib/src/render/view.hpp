// A view of the page (view_layout.hpp) with what is drawn in it: element
// shapes by kind and the thinned path.
#pragma once

#include "render/path_thinner.hpp"
#include "render/view_layout.hpp"

#include <array>
#include <string>
#include <utility>

namespace orthoray::render {

// Element kinds, in ElementKind's order, as CSS class suffixes.
constexpr std::array<const char*, 3> kind_class{"mirror", "absorber", "splitter"};

// A view with what is drawn in it.
struct View : render::ViewPlacement {
    // SVG path data by element kind: edge-on shapes, faces (3D), and the
    // ticks on the acting side of one-sided elements.
    std::array<std::string, 3> edges, faces, ticks;
    std::size_t shapes = 0;
    render::PathThinner path;

    View(render::ViewPlacement placement, std::size_t max_vertices)
        : ViewPlacement(std::move(placement)), path(max_vertices) {}
};

} // namespace orthoray::render
