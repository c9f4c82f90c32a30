// orthoray version [--json]: this build's version and what it is made of,
// for bug reports (the library's build_info()).
#include "commands.hpp"

#include "orthoray/build_info.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace orthoray::cli {

Command add_version(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "version",
        "Print the versions of orthoray and of the GMP, Boost and compiler it\n"
        "was built with. Also the git commit it was built from (\"unknown\" when\n"
        "not built from a git checkout). The short form: orthoray --version.\n\n"
        "Example:\n"
        "  orthoray version --json\n"
        "  {\"boost\":\"1.74.0\",...,\"commit\":\"a78e605c1d2e\",...,\"orthoray\":\"0.1.0\"}");
    auto json = std::make_shared<bool>(false);
    cmd->add_flag("--json", *json, "one JSON object instead of text");
    return [json] {
        const BuildInfo info = build_info();
        if (*json) {
            const nlohmann::json out{{"orthoray", info.orthoray}, {"commit", info.commit},
                                     {"gmp", info.gmp},           {"boost", info.boost},
                                     {"compiler", info.compiler}, {"build_type", info.build_type}};
            std::cout << out.dump() << '\n';
        } else {
            std::cout << "orthoray   " << info.orthoray << "\ncommit     " << info.commit
                      << "\nGMP        " << info.gmp << "\nBoost      " << info.boost
                      << "\ncompiler   " << info.compiler << "\nbuild type " << info.build_type
                      << '\n';
        }
        return yes;
    };
}

} // namespace orthoray::cli
