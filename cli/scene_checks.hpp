// What a question asks of a scene beyond its syntax, checked where the file
// is known, so that a scene that cannot be asked is bad input at its line
// (`FILE:LINE:COL: found ..., expected ...`, exit 2), the same from every
// command that asks it.
#pragma once

#include "orthoray/scene.hpp"

#include <string>

namespace orthoray::cli {

// The intensity question (--min-intensity): every ray says how intense it
// starts.
void require_intensities(const Scene& scene, const std::string& file);

// A realistic model derived from a scene (realistic --from-scene) has one
// source: exactly one ray, and it carries an intensity.
void require_one_intense_ray(const Scene& scene, const std::string& file);

} // namespace orthoray::cli
