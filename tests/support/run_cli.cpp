#include "support/run_cli.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace orthoray::test {
namespace {

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

CliResult run_cli(const std::string& args, const std::string& input) {
    static int counter = 0;
    auto dir = std::filesystem::temp_directory_path() /
               ("orthoray-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(dir);
    std::string command = std::string("'") + ORTHORAY_CLI + "' " + args + " >'" +
                          (dir / "out").string() + "' 2>'" + (dir / "err").string() + "' <'" +
                          input + "'";
    int raw = std::system(command.c_str());
    CliResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(dir / "out");
    r.err = slurp(dir / "err");
    std::filesystem::remove_all(dir);
    return r;
}

std::string source_path(const std::string& relative) {
    return std::string(ORTHORAY_SOURCE_DIR) + "/" + relative;
}

} // namespace orthoray::test
