// orthoray_docgen DIR: writes the man pages (DIR/man1/*.1) and the bash
// completion script (DIR/completions/orthoray) from the same CLI::App the
// program parses with, at build time (cli/CMakeLists.txt).
#include "app.hpp"
#include "bash_completion.hpp"
#include "man_page.hpp"

#include "orthoray/version.hpp"

#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: orthoray_docgen DIR\n";
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    CLI::App app;
    orthoray::cli::build_cli(app);
    std::filesystem::create_directories(dir / "man1");
    std::filesystem::create_directories(dir / "completions");
    orthoray::cli::write_man_pages(app, dir / "man1", orthoray::version);
    std::ofstream completion(dir / "completions" / "orthoray");
    orthoray::cli::write_bash_completion(app, completion);
    return completion ? 0 : 1;
}
