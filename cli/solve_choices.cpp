#include "solve_choices.hpp"

#include "commands.hpp"
#include "option_checks.hpp"

#include <map>
#include <vector>

namespace orthoray::cli {
namespace {

const std::map<std::string, CycleDetector> detectors{{"first-state", CycleDetector::first_state},
                                                     {"brent", CycleDetector::brent}};
const std::map<std::string, Arithmetic> arithmetics{
    {"auto", Arithmetic::automatic}, {"int128", Arithmetic::int128}, {"wide", Arithmetic::wide}};
const std::map<std::string, Shooter> shooters{{"auto", Shooter::automatic},
                                              {"grid", Shooter::grid},
                                              {"bvh", Shooter::bvh},
                                              {"pieces", Shooter::pieces},
                                              {"section", Shooter::section}};

template <class T>
std::vector<std::string> names(const std::map<std::string, T>& choices) {
    std::vector<std::string> out;
    for (const auto& [name, value] : choices) out.push_back(name);
    return out;
}

} // namespace

void SolveChoices::check() const {
    if (min_intensity.empty()) return;
    if (min_intensity.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError("found --min-intensity " + min_intensity +
                         ", expected a natural number (0, 1, 2, ...)");
    if (engine == "graph" || engine == "induction")
        throw UsageError("found --engine " + engine +
                         " with --min-intensity, expected --engine auto, lattice or reference "
                         "(the intensity question has its own branch search)");
}

SolveOptions SolveChoices::options(unsigned sharing) const {
    SolveOptions options;
    // The illumination search keeps its branch states within three quarters
    // of the budget (its share, when `sharing` searches run at once), so it
    // ends with Limit::memory at a state boundary, lit targets kept, rather
    // than wherever an allocation fails; the last quarter is for everything
    // else (stepping, the answer, the certificate).
    if (max_memory > 0) options.max_state_bytes = (max_memory << 20) / 4 * 3 / sharing;
    options.engine = engine_names().at(engine);
    options.cycle_detector = detectors.at(detector);
    options.arithmetic = arithmetics.at(arithmetic);
    options.shooter = shooters.at(shooter);
    if (max_steps_option && max_steps_option->count() > 0) options.max_steps = max_steps;
    if (!min_intensity.empty()) options.min_intensity = Integer(min_intensity, 10);
    return options;
}

std::optional<std::chrono::steady_clock::time_point>
SolveChoices::deadline(std::chrono::steady_clock::time_point begin) const {
    if (timeout <= 0) return std::nullopt;
    return begin + std::chrono::duration_cast<std::chrono::nanoseconds>(
                       std::chrono::duration<double>(timeout));
}

void add_solve_choices(CLI::App* cmd, SolveChoices& c, const std::string& max_memory_help) {
    c.max_steps_option =
        cmd->add_option("--max-steps", c.max_steps,
                        "perform at most N reflections; without an answer by then, answer unknown "
                        "(reason limit) and exit 3")
            ->transform(whole_number_u64());
    cmd->add_option("--timeout", c.timeout,
                    "stop after SECONDS (a decimal, counted from the start) with answer unknown "
                    "(reason limit, limit time) and exit 3")
        ->check(timeout_seconds());
    cmd->add_option("--max-memory", c.max_memory, max_memory_help)
        ->transform(whole_number_in(1, std::uint64_t{1} << 40));
    cmd->add_option(
           "--engine", c.engine,
           "auto (default: simulate; in 2D, switch to induction once a short run has "
           "not answered), lattice (simulation on integer lattice states), induction "
           "(2D: Rauzy-Zorich induction on the piece tables, time growing with the "
           "pieces and log(reflections), polynomial as measured but not proven "
           "(docs/induction.md); other dimensions are simulated), reference (naive rational O(n) "
           "scan per reflection, the test oracle), graph (explicit state graph; small "
           "scenes only)")
        ->check(one_of(names(engine_names())));
    cmd->add_option("--cycle-detector", c.detector,
                    "first-state (default: compare with the state after reflection 1) or brent "
                    "(Brent's algorithm; needs no injectivity, so always used with one-sided "
                    "elements); both O(1) memory")
        ->check(one_of(names(detectors)));
    cmd->add_option("--arithmetic", c.arithmetic,
                    "auto (default: the narrowest integers a bound proves safe: int64, int128, "
                    "then GMP), int128 (at least 128-bit), or wide (always GMP)")
        ->check(one_of(names(arithmetics)));
    cmd->add_option(
           "--shooter", c.shooter,
           "how the lattice engine finds the next hit: auto (default: in 3D the "
           "cross-section grid, in 2D the uniform grid and then piece tables once "
           "max(16384, 32 n) reflections have not answered; a bounding volume hierarchy when "
           "elements cluster), grid (uniform grid), bvh, pieces (2D piece tables from the "
           "start) or section (cross-section grid); one it cannot use is refused (exit 2): "
           "pieces in 3D, and all but auto for the branch search of several rays or targets, "
           "splitters or --min-intensity")
        ->check(one_of(names(shooters)));
    cmd->add_option("--min-intensity", c.min_intensity,
                    "EPS, a natural number: is each target reached by a branch with intensity "
                    "greater than EPS? Rays carry intensities, elements reflectances and "
                    "transmittances, floored after every event (docs/intensity.md); every ray "
                    "needs 'intensity N'")
        ->check(not_empty("a natural number"));
}

} // namespace orthoray::cli
