#include "support/lazor_levels.hpp"

#include "support/run_cli.hpp"
#include "support/skip_test.hpp"

#include <algorithm>
#include <set>
#include <tuple>

namespace orthoray::test {

namespace fs = std::filesystem;

std::optional<fs::path> lazor_folder() {
    const fs::path folder = fs::path(source_path("..")) / "shared" / "puzzles" / "lazor";
    if (fs::is_directory(folder)) return folder;
    return std::nullopt;
}

std::optional<fs::path> lazor_folder_or_skip() {
    std::optional<fs::path> folder = lazor_folder();
    if (!folder) skip_test("no ../shared/puzzles/lazor beside the source tree");
    return folder;
}

std::optional<fs::path> lazor_folder_or_warn() {
    std::optional<fs::path> folder = lazor_folder();
    if (!folder)
        WARN("../shared/puzzles/lazor is absent beside the source tree: its levels left out");
    return folder;
}

std::vector<fs::path> bff_files(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().extension() == ".bff")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<bool> lazor_lit_by_rules(const LazorLevel& level) {
    const int w = level.width, h = level.height;
    // The letter of cell (c, r), or ' ' outside the grid.
    auto letter = [&](int c, int r) {
        return c < 0 || c >= w || r < 0 || r >= h ? ' ' : lazor_letter(level.at(c, r));
    };
    using Beam = std::tuple<int, int, int, int>; // x, y, dx, dy
    std::set<Beam> seen;
    std::set<std::pair<int, int>> passed;
    std::vector<std::pair<Beam, bool>> todo; // the beam, and whether it is a laser's start
    for (const LazorLaser& l : level.lasers) todo.push_back({{l.x, l.y, l.dx, l.dy}, true});
    while (!todo.empty()) {
        const auto [beam, start] = todo.back();
        todo.pop_back();
        if (!seen.insert(beam).second) continue;
        const auto [x, y, dx, dy] = beam;
        passed.insert({x, y});
        // On a vertical edge (x even) the beam goes into the cell left or
        // right of it, on a horizontal one into the cell above or below.
        const bool vertical = x % 2 == 0;
        const char ahead = vertical ? letter(dx > 0 ? x / 2 : x / 2 - 1, y / 2)
                                    : letter(x / 2, dy > 0 ? y / 2 : y / 2 - 1);
        const char behind = vertical ? letter(dx > 0 ? x / 2 - 1 : x / 2, y / 2)
                                     : letter(x / 2, dy > 0 ? y / 2 - 1 : y / 2);
        const std::pair<int, int> straight{dx, dy};
        const std::pair<int, int> bounced = vertical ? std::pair{-dx, dy} : std::pair{dx, -dy};
        std::vector<std::pair<int, int>> out;
        if (ahead == 'A') out = {bounced};
        if (ahead == 'C') out = {straight, bounced};
        if (ahead != 'A' && ahead != 'B' && ahead != 'C') out = {straight};
        for (const auto& [ndx, ndy] : out) {
            // Sent back into a reflect or opaque block behind the start: ends.
            if (start && std::pair{ndx, ndy} == bounced && (behind == 'A' || behind == 'B'))
                continue;
            const int nx = x + ndx, ny = y + ndy;
            if (nx >= 0 && nx <= 2 * w && ny >= 0 && ny <= 2 * h)
                todo.push_back({{nx, ny, ndx, ndy}, false});
        }
    }
    std::vector<bool> lit;
    for (const LazorPoint& p : level.points) lit.push_back(passed.count({p.x, p.y}) > 0);
    return lit;
}

namespace {

void place_from(LazorLevel& level, std::size_t cell, std::array<int, 3>& left,
                const std::function<void(const LazorLevel&)>& visit) {
    if (left[0] + left[1] + left[2] == 0) {
        visit(level);
        return;
    }
    if (cell == level.cells.size()) return;
    if (level.cells[cell] != LazorCell::open) return place_from(level, cell + 1, left, visit);
    for (std::size_t k = 0; k < 3; ++k) {
        if (left[k] == 0) continue;
        --left[k];
        level.cells[cell] = lazor_blocks[k];
        place_from(level, cell + 1, left, visit);
        level.cells[cell] = LazorCell::open;
        ++left[k];
    }
    place_from(level, cell + 1, left, visit);
}

} // namespace

void each_placement(const LazorLevel& level, const std::function<void(const LazorLevel&)>& visit) {
    LazorLevel copy = level;
    std::array<int, 3> left = level.blocks;
    copy.blocks = {};
    place_from(copy, 0, left, visit);
}

} // namespace orthoray::test
