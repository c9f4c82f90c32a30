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

struct AxisTicks {
    std::vector<Tick> ticks;
    // Empty, or the exact value subtracted from every label: far from the
    // origin (ticks 1 apart near 10^40), 6 significant digits would give
    // every tick the same label, so the labels count from this round value
    // instead and the axis names it once ("x - 1e40").
    std::string offset;
    bool offset_negative = false;
};

// About `count` ticks between lo and hi (lo < hi), inclusive.
AxisTicks axis_ticks(const Rational& lo, const Rational& hi, int count);

} // namespace orthoray::render
