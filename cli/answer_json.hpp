// An answer as the members of a JSON object: the fields `solve --json`
// prints, shared with `batch`, which puts them after the instance's path.
#pragma once

#include "orthoray/answer.hpp"

#include <string>

namespace orthoray::cli {

// `"answer":...,"reason":...,...,"seconds":...` without the braces.
// `reflections`, `tail`, `period` and the targets' counts are JSON integers
// written from their decimal text, so they are exact however large.
std::string answer_json_members(const Answer& answer, const std::string& engine, double seconds);

} // namespace orthoray::cli
