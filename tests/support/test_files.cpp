#include "support/test_files.hpp"

#include "support/run_cli.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace orthoray::test {

namespace fs = std::filesystem;

TempDir::TempDir() {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("orthoray-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

std::string TempDir::write(const std::string& name, const std::string& content) const {
    std::ofstream out(path(name), std::ios::binary);
    out << content;
    return path(name);
}

std::string quote(const std::string& text) {
    return "'" + text + "'";
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string instance(const std::string& name) {
    return source_path("instances/" + name);
}

std::vector<fs::path> instance_files() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(source_path("instances")))
        if (entry.is_regular_file() && entry.path().extension() == ".scene")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace orthoray::test
