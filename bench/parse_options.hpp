// The benchmark programs' common end of option parsing (CLI11): --help
// prints and exits 0; a bad option prints why and exits 2, as the CLI does
// on a usage error.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>

namespace orthoray::bench {

inline void parse_options(CLI::App& app, const char* program, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        std::exit(app.exit(e));
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: %s\nsee bench/README.md or --help\n", program, e.what());
        std::exit(2);
    }
}

} // namespace orthoray::bench
