// Tick marks for an axis of a picture: round values (1, 2 or 5 times a
// power of ten) chosen and placed exactly, so a label names the very
// coordinate its tick stands at.
#pragma once

#include "orthoray/number.hpp"

#include <string>
#include <vector>

namespace orthoray::render {

struct Tick {
    double fraction = 0; // (value - lo) / (hi - lo), for placing the tick on the page
    std::string label;
};

// About `count` ticks between lo and hi (lo < hi), inclusive.
std::vector<Tick> axis_ticks(const Rational& lo, const Rational& hi, int count);

} // namespace orthoray::render
