#include "batch_inputs.hpp"

#include "commands.hpp"
#include "orthoray/parse.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <system_error>
#include <unordered_map>

namespace orthoray::cli {
namespace fs = std::filesystem;
namespace {

bool ends_with(const std::string& text, const std::string& end) {
    return text.size() >= end.size() &&
           text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// Every instance file below `dir`, sorted so that a batch over a directory
// lists its instances in the same order on every machine.
std::vector<std::string> instances_below(const std::string& dir) {
    std::vector<std::string> found;
    std::error_code error;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, error);
    for (; !error && it != fs::recursive_directory_iterator(); it.increment(error))
        if (it->is_regular_file(error) && is_instance_file(it->path().string()))
            found.push_back(it->path().string());
    if (error) throw UsageError("cannot read the directory '" + dir + "': " + error.message());
    std::sort(found.begin(), found.end());
    return found;
}

void read_manifest(std::istream& in, std::vector<std::string>& out) {
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line.front() == '#') continue;
        out.push_back(line);
    }
}

} // namespace

bool is_instance_file(const std::string& path) {
    return ends_with(path, ".scene") || ends_with(path, ".json");
}

std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs) {
    std::vector<std::string> out;
    for (const std::string& input : inputs) {
        if (input == "-") {
            read_manifest(std::cin, out);
            continue;
        }
        std::error_code error;
        const fs::file_status status = fs::status(input, error);
        if (error || !fs::exists(status))
            throw UsageError("found the input '" + input +
                             "', expected an existing instance "
                             "file, directory or manifest");
        if (fs::is_directory(status)) {
            const std::vector<std::string> below = instances_below(input);
            out.insert(out.end(), below.begin(), below.end());
        } else if (is_instance_file(input)) {
            out.push_back(input);
        } else {
            // Through the capped reader: a manifest is bounded like any input.
            std::string text;
            try {
                text = read_file(input);
            } catch (const InputError& e) {
                throw UsageError("cannot read the manifest: " + std::string(e.what()));
            }
            std::istringstream in(text);
            read_manifest(in, out);
        }
    }
    return out;
}

std::function<std::size_t(const std::string&)>
input_order(const std::vector<std::string>& instances) {
    auto places = std::make_shared<std::unordered_map<std::string, std::size_t>>();
    for (std::size_t i = instances.size(); i-- > 0;) (*places)[instances[i]] = i;
    return [places, after = instances.size()](const std::string& path) {
        const auto it = places->find(path);
        return it == places->end() ? after : it->second;
    };
}

} // namespace orthoray::cli
