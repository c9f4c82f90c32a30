// An answer as JSON: the fields `solve --json` prints, in one place for
// every front end (the command line, `batch`, which puts them after the
// instance's path, and the Python module, which reads them into a dict).
#pragma once

#include "orthoray/answer.hpp"

#include <string>

namespace orthoray {

// `"answer":...,"reason":...,...,"seconds":...` without the braces.
// `reflections`, `tail`, `period` and the targets' counts are JSON integers
// written from their decimal text, so they are exact however large.
std::string answer_json_members(const Answer& answer, const std::string& engine, double seconds);

// The engine an answer names: the one that ran, or, when none did (a limit
// struck before any started), the one asked for ("auto", "lattice", ...).
std::string engine_name(const Answer& answer, const std::string& asked);

} // namespace orthoray
