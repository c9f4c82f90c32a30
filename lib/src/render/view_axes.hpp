// The axes drawn around a view's plot area.
#pragma once

#include "render/frame.hpp"
#include "render/svg_writer.hpp"
#include "render/view_layout.hpp"

namespace orthoray::render {

// Ticks and tick labels in scene coordinates below and left of a
// projection, and the axis names.
void write_axes(SvgWriter& svg, const ViewPlacement& v, const Frame& frame);

// The oblique view's key: three short arrows with the axis names, in the
// margin left of the plot area.
void write_oblique_axis_key(SvgWriter& svg, const ViewPlacement& v);

} // namespace orthoray::render
