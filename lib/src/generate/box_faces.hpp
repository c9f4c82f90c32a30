// The faces of a closed axis-aligned mirror box, shared by the families
// that enclose their scenes.
#pragma once

#include "orthoray/scene.hpp"

#include <vector>

namespace orthoray::generate {

// The 2 * dim mirrors bounding [0, sides[0]] x ... x [0, sides[dim - 1]].
inline void add_box_faces(Scene& scene, const std::vector<Rational>& sides) {
    for (int axis = 0; axis < scene.dim; ++axis)
        for (const Rational& offset : {Rational(0), sides[static_cast<std::size_t>(axis)]}) {
            std::vector<std::pair<Rational, Rational>> extent;
            for (int j = 0; j < scene.dim; ++j)
                if (j != axis) extent.emplace_back(0, sides[static_cast<std::size_t>(j)]);
            scene.add_mirror(axis, offset, extent);
        }
}

} // namespace orthoray::generate
