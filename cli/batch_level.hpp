// A Lazor level (.bff) as an instance of `orthoray batch`: the placement
// search of `puzzle solve` on one thread, under the instance's limits, its
// result line carrying the members `puzzle solve --json` prints
// (docs/batch.md, "Lazor levels").
#pragma once

#include "batch_instance.hpp"
#include "orthoray/puzzle.hpp"

#include <chrono>
#include <string>

namespace orthoray::cli {

// Searches `level` and builds its result line after `head` (path and hash).
// --timeout counts from `begin`; --max-steps bounds the search nodes.
Outcome decide_level(const LazorLevel& level, const std::string& head, const BatchArgs& args,
                     std::chrono::steady_clock::time_point begin);

} // namespace orthoray::cli
