// The orthoray subcommands. Each registers its options on the app and returns
// the function that runs it; main() maps exceptions to exit statuses.
#pragma once

#include <CLI/CLI.hpp>

#include "orthoray/scene.hpp"
#include "usage_error.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>

namespace orthoray::cli {

// Exit statuses of the command-line contract.
// write_failed: an output could not be written completely (docs/limits.md).
enum Exit : int { yes = 0, no = 1, bad_input = 2, limit = 3, internal_error = 4, write_failed = 5 };

using Command = std::function<int()>;

Command add_solve(CLI::App& app);
Command add_verify(CLI::App& app);
Command add_pieces(CLI::App& app);
Command add_exchange(CLI::App& app);
Command add_generate(CLI::App& app);
Command add_bounds(CLI::App& app);
Command add_convert(CLI::App& app);
Command add_render(CLI::App& app);
Command add_puzzle(CLI::App& app);
// The subcommands of `puzzle`.
Command add_puzzle_scene(CLI::App& puzzle);
Command add_puzzle_solve(CLI::App& puzzle);
Command add_puzzle_generate(CLI::App& puzzle);
Command add_realistic(CLI::App& app);
Command add_batch(CLI::App& app);
Command add_version(CLI::App& app);

struct GenerateArgs;

// The scenes of one `orthoray generate` command line, one a seed, without
// writing them: what `batch --generate` decides.
class SceneGenerator {
public:
    // `words`: the family and its options as `generate` takes them, without
    // --seed and -o ("random --dim 2 --mirrors 1000 --box"). Bad words are a
    // UsageError with generate's own message.
    explicit SceneGenerator(const std::string& words);
    Scene scene(std::uint64_t seed) const;

private:
    std::shared_ptr<CLI::App> parser_;
    std::shared_ptr<GenerateArgs> args_;
    CLI::App* cmd_ = nullptr;
};

} // namespace orthoray::cli
