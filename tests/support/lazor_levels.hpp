// The public Lazor levels (../shared/puzzles/lazor beside the source tree,
// as CI clones it) and a small checker of placed levels that shares no code
// with the library: the Lazor rules read plainly, for the tests to hold the
// search and the translated scene to.
#pragma once

#include "orthoray/puzzle.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace orthoray::test {

// The folder of the public levels, or nothing when it is not there.
std::optional<std::filesystem::path> lazor_folder();
// The same for a test that needs the folder: when it is not there, the test
// is reported skipped (support/skip_test.hpp) and must return.
std::optional<std::filesystem::path> lazor_folder_or_skip();
// The same for a test that also runs without the folder, on fewer levels:
// when it is not there, the test's output says that its levels were left
// out, so that a run on fewer cases is never silent.
std::optional<std::filesystem::path> lazor_folder_or_warn();

// The .bff files directly in `folder`, sorted.
std::vector<std::filesystem::path> bff_files(const std::filesystem::path& folder);

// Which points of a level whose blocks are all placed (or fixed) some laser
// branch passes, by the rules of docs/puzzles.md written out directly.
std::vector<bool> lazor_lit_by_rules(const LazorLevel& level);

// Calls `visit` with every placement of the level's blocks on its open
// cells (each returned level has them fixed), in row-major order of cells.
void each_placement(const LazorLevel& level, const std::function<void(const LazorLevel&)>& visit);

} // namespace orthoray::test
