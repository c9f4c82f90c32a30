// PNG pictures: the SVG text goes to rsvg-convert (Debian librsvg2-bin) on
// its standard input and the PNG comes back on its standard output, so no
// file but the target is ever written and the target, through OutputFile,
// is only ever replaced whole.
#pragma once

#include <ostream>
#include <string>

namespace orthoray::cli {

// Runs `rsvg-convert --format png` without a shell and writes the PNG it
// prints to `png`. Throws UsageError when rsvg-convert is not installed or
// fails, and WriteError from a write to `png` that failed.
void svg_to_png(const std::string& svg, std::ostream& png);

} // namespace orthoray::cli
