// The crossings of an octagonal maze's segments (docs/induction.md,
// section 6): the vertices of its arrangement besides the segments' ends.
#pragma once

#include "induction/octagonal_geometry.hpp"

#include <functional>
#include <vector>

namespace orthoray::induction::octagonal {

// Appends to `out` every point where a segment of orientation `a` meets one
// of orientation `b` (a != b), in O((n + crossings) log n); `poll` is
// called once an event of the sweep.
template <class Int>
void crossings_of(const std::vector<Segment<Int>>& segs, Orientation a, Orientation b,
                  std::vector<Point<Int>>& out, const std::function<void()>& poll);

} // namespace orthoray::induction::octagonal
