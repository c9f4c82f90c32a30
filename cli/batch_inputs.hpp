// What `orthoray batch` decides: the instance files its INPUT arguments
// name, in a fixed order (docs/batch.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace orthoray::cli {

// Whether `path` names an instance file by its ending: .scene or .json.
bool is_instance_file(const std::string& path);

// Expands the INPUT arguments, in order: an instance file stands for
// itself; a directory for every instance file below it, in byte order of
// their paths; `-` and any other file for a manifest, one path a line (as
// typed, so relative to the working directory; blank lines and lines
// starting with '#' skipped). A manifest line is taken as an instance even
// when the file is missing or unreadable: that becomes the instance's
// result, not the end of the batch. An argument that does not exist, or a
// manifest that cannot be read, is a usage error (UsageError).
std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs);

// An instance's place in `instances` (the first, for a path listed twice);
// a path not listed comes after all of them.
std::function<std::size_t(const std::string&)>
input_order(const std::vector<std::string>& instances);

} // namespace orthoray::cli
