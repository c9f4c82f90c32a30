// The options `solve` and `batch` share: which engine runs and how, and the
// limits of one instance. They are registered in one place, so both
// commands accept the same words and refuse the same values.
#pragma once

#include "orthoray/answer_json.hpp"

#include "orthoray/answer.hpp"
#include "orthoray/solve.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace orthoray::cli {

struct SolveChoices {
    std::string engine = "auto", detector = "first-state", arithmetic = "auto", shooter = "auto";
    std::uint64_t max_steps = 0, max_memory = 0;
    double timeout = 0; // seconds; 0: no timeout
    // --min-intensity EPS (docs/intensity.md), as written; empty: not asked.
    std::string min_intensity;
    const CLI::Option* max_steps_option = nullptr;

    // Refuses what the intensity question does not take: an EPS that is not
    // a natural number, the graph and induction engines (UsageError).
    void check() const;
    // The library's options for these choices (no observers attached).
    // The options of one run; `sharing`: how many runs share --max-memory.
    SolveOptions options(unsigned sharing = 1) const;
    // `begin` plus the timeout, when there is one.
    std::optional<std::chrono::steady_clock::time_point>
    deadline(std::chrono::steady_clock::time_point begin) const;
};

// Registers --engine, --cycle-detector, --arithmetic, --shooter,
// --max-steps, --timeout, --max-memory and --min-intensity on `cmd`. `max_memory_help` says
// what the memory limit covers (one solve, or the whole batch).
void add_solve_choices(CLI::App* cmd, SolveChoices& choices, const std::string& max_memory_help);

} // namespace orthoray::cli
