#include "batch_inputs.hpp"

#include "commands.hpp"
#include "orthoray/parse.hpp"
#include "run_monitor.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <system_error>
#include <unordered_map>
#include <unordered_set>

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
    return ends_with(path, ".scene") || ends_with(path, ".json") || ends_with(path, ".grid") ||
           is_level_file(path);
}

bool is_level_file(const std::string& path) {
    return ends_with(path, ".bff");
}

std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs) {
    // A manifest may be standard input or a FIFO that waits for its writer,
    // and a directory may be large: SIGINT and SIGTERM stop the listing as
    // an interrupted read (ReadInterrupted, exit 3), before the results file
    // is touched. read_file turns a read cut by the signal into that too.
    const InterruptGuard interrupts;
    std::vector<std::string> out;
    for (const std::string& input : inputs) {
        if (InterruptGuard::requested()) throw ReadInterrupted(input);
        if (input == "-") {
            std::istringstream in(read_file("-"));
            read_manifest(in, out);
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
    if (InterruptGuard::requested()) throw ReadInterrupted(inputs.back());
    // A path named twice is one instance, decided once: its result's key is
    // its path and content, so a second line could never be told apart,
    // and --resume would find it done (a fresh run and a resumed one must
    // leave the same lines).
    std::unordered_set<std::string> seen;
    std::erase_if(out, [&](const std::string& path) { return !seen.insert(path).second; });
    return out;
}

InstanceList::InstanceList(std::vector<std::string> paths) : paths_(std::move(paths)) {
    for (std::size_t i = paths_.size(); i-- > 0;) places_[paths_[i]] = i;
}

InstanceList::InstanceList(std::uint64_t first_seed, std::uint64_t last_seed)
    : generated_(true), first_seed_(first_seed), last_seed_(last_seed) {}

std::size_t InstanceList::size() const {
    return generated_ ? static_cast<std::size_t>(last_seed_ - first_seed_ + 1) : paths_.size();
}

std::string InstanceList::name(std::size_t i) const {
    return generated_ ? std::to_string(first_seed_ + i) : paths_[i];
}

std::size_t InstanceList::position(const std::string& name) const {
    if (!generated_) {
        const auto it = places_.find(name);
        return it == places_.end() ? size() : it->second;
    }
    if (name.empty() || name.size() > 20 ||
        name.find_first_not_of("0123456789") != std::string::npos)
        return size();
    const std::uint64_t seed = std::stoull(name);
    return seed < first_seed_ || seed > last_seed_ ? size()
                                                   : static_cast<std::size_t>(seed - first_seed_);
}

std::pair<std::uint64_t, std::uint64_t> seed_range(const std::string& text) {
    auto seed = [&](const std::string& digits) {
        if (digits.empty() || digits.size() > 20 ||
            digits.find_first_not_of("0123456789") != std::string::npos ||
            (digits.size() == 20 && digits > "18446744073709551615"))
            throw UsageError("found --seeds '" + text +
                             "', expected A..B or A, whole numbers from 0 to 2^64 - 1");
        return static_cast<std::uint64_t>(std::stoull(digits));
    };
    const std::size_t dots = text.find("..");
    const std::uint64_t first = seed(text.substr(0, dots));
    const std::uint64_t last = dots == std::string::npos ? first : seed(text.substr(dots + 2));
    if (first > last) throw UsageError("found --seeds '" + text + "', expected A..B with A <= B");
    if (last - first >= std::uint64_t{1} << 40)
        throw UsageError("found --seeds '" + text + "', expected at most 2^40 seeds");
    return {first, last};
}

} // namespace orthoray::cli
