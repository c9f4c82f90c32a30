// Files for tests: a scratch directory per test case, reading a file whole,
// quoting a path for the shell, and the curated instances.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace orthoray::test {

// A fresh directory for the files one test case writes; removed afterwards.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string path(const std::string& name) const { return (path_ / name).string(); }

    // Writes `content` byte for byte and returns the file's path.
    std::string write(const std::string& name, const std::string& content) const;

private:
    std::filesystem::path path_;
};

// 'text', for a command line run by the shell.
std::string quote(const std::string& text);

// The whole file, byte for byte.
std::string slurp(const std::string& path);

// The path of instances/NAME in the source tree.
std::string instance(const std::string& name);

// Every .scene file under instances/, sorted.
std::vector<std::filesystem::path> instance_files();

} // namespace orthoray::test
