// The JSON members that describe a Lazor placement search's outcome, written
// in one place so that `puzzle solve --json` and the level lines of `batch`
// cannot differ (docs/puzzles.md, docs/batch.md).
#pragma once

#include "orthoray/puzzle.hpp"

#include <string>

namespace orthoray::cli {

// "solved", "unsolvable" or "unknown" (a limit stopped the search).
const char* lazor_answer_word(LazorSolution::Status status);

// The members, comma-separated, without the enclosing braces: answer, limit
// (only at a limit: `limit`), grid and points (when solved), solutions (with
// --all), nodes, jobs, seconds.
std::string lazor_json_members(const LazorSolution& solution, const std::string& limit,
                               unsigned jobs, double seconds);

} // namespace orthoray::cli
