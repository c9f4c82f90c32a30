// What `orthoray batch` decides: the instance files its INPUT arguments
// name, in a fixed order (docs/batch.md).
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace orthoray::cli {

// Whether `path` names an instance file by its ending: .scene, .json,
// .grid (a grid maze, read as its scene) or .bff (a Lazor level).
bool is_instance_file(const std::string& path);

// Whether `path` names a Lazor level (.bff), decided by the placement search.
bool is_level_file(const std::string& path);

// Expands the INPUT arguments, in order: an instance file stands for
// itself; a directory for every instance file below it, in byte order of
// their paths; `-` and any other file for a manifest, one path a line (as
// typed, so relative to the working directory; blank lines and lines
// starting with '#' skipped). A manifest line is taken as an instance even
// when the file is missing or unreadable: that becomes the instance's
// result, not the end of the batch. An argument that does not exist, or a
// manifest that cannot be read, is a usage error (UsageError).
std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs);

// The instances of one batch: files, or the seeds of a generator
// (`--generate WORDS --seeds A..B`), which are never written to disk.
class InstanceList {
public:
    explicit InstanceList(std::vector<std::string> paths);
    InstanceList(std::uint64_t first_seed, std::uint64_t last_seed);

    std::size_t size() const;
    bool generated() const { return generated_; }
    // The file's path, or the seed in decimal: what a result line names.
    std::string name(std::size_t i) const;
    // The place of the instance a result line names (the first, for a path
    // listed twice); size() for one not in the list.
    std::size_t position(const std::string& name) const;

private:
    bool generated_ = false;
    std::vector<std::string> paths_;
    std::uint64_t first_seed_ = 0, last_seed_ = 0;
    std::unordered_map<std::string, std::size_t> places_;
};

struct BatchArgs;
// What `batch` decides: INPUT expanded, or the seeds of --generate.
InstanceList list_instances(const BatchArgs& args);

// `A..B` (inclusive) or a single seed `A`, each 0 to 2^64 - 1, A <= B.
std::pair<std::uint64_t, std::uint64_t> seed_range(const std::string& text);

} // namespace orthoray::cli
