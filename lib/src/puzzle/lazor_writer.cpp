// Writing a level back as .bff text, and reading a solved grid as a
// placement of a level's blocks.
#include "orthoray/parse.hpp"
#include "orthoray/puzzle.hpp"

namespace orthoray {

std::string write_lazor_grid(const LazorLevel& level) {
    std::string out = "GRID START\n";
    for (int row = 0; row < level.height; ++row) {
        for (int column = 0; column < level.width; ++column) {
            if (column > 0) out += ' ';
            out += lazor_letter(level.at(column, row));
        }
        out += '\n';
    }
    return out + "GRID STOP\n";
}

std::string write_lazor_level(const LazorLevel& level, const std::string& title) {
    std::string out = title.empty() ? "" : "# " + title + "\n";
    out += write_lazor_grid(level);
    bool counts = false;
    for (std::size_t kind = 0; kind < lazor_blocks.size(); ++kind) {
        if (level.blocks[kind] == 0) continue;
        if (!counts) out += '\n';
        counts = true;
        out += std::string(1, lazor_letter(lazor_blocks[kind])) + " " +
               std::to_string(level.blocks[kind]) + "\n";
    }
    out += '\n';
    for (const LazorLaser& l : level.lasers)
        out += "L " + std::to_string(l.x) + " " + std::to_string(l.y) + " " + std::to_string(l.dx) +
               " " + std::to_string(l.dy) + "\n";
    out += '\n';
    for (const LazorPoint& p : level.points)
        out += "P " + std::to_string(p.x) + " " + std::to_string(p.y) + "\n";
    return out;
}

LazorLevel apply_lazor_placement(const LazorLevel& level, const LazorLevel& solved,
                                 const std::string& solved_file) {
    auto fail_at = [&](std::size_t cell, const std::string& message) {
        const auto [line, column] = solved.cell_positions.at(cell);
        throw InputError(solved_file, line, column, message);
    };
    if (solved.width != level.width || solved.height != level.height) {
        const auto [line, column] = solved.cell_positions.front();
        throw InputError(solved_file, line, column,
                         "found a grid of " + std::to_string(solved.width) + " x " +
                             std::to_string(solved.height) + " blocks, expected the level's " +
                             std::to_string(level.width) + " x " + std::to_string(level.height));
    }
    LazorLevel placed = level;
    std::array<int, 3> used{};
    for (std::size_t i = 0; i < level.cells.size(); ++i) {
        const LazorCell want = level.cells[i], got = solved.cells[i];
        const std::string where = "row " + std::to_string(i / level.width + 1) + ", column " +
                                  std::to_string(i % level.width + 1);
        if (want != LazorCell::open) {
            if (got != want)
                fail_at(i, std::string("found '") + lazor_letter(got) + "' at " + where +
                               ", expected the level's fixed '" + lazor_letter(want) + "'");
            continue;
        }
        if (got == LazorCell::blocked)
            fail_at(i, "found 'x' at " + where + ", expected an open cell (o) or a placed block");
        placed.cells[i] = got;
        for (std::size_t kind = 0; kind < lazor_blocks.size(); ++kind) {
            if (got != lazor_blocks[kind]) continue;
            if (++used[kind] > level.blocks[kind])
                fail_at(i, std::string("found a placed '") + lazor_letter(got) +
                               "' beyond the level's " + std::to_string(level.blocks[kind]) +
                               ", expected exactly " + std::to_string(level.blocks[kind]));
        }
    }
    for (std::size_t kind = 0; kind < lazor_blocks.size(); ++kind) {
        if (used[kind] == level.blocks[kind]) continue;
        const auto [line, column] = solved.cell_positions.back();
        throw InputError(solved_file, line, column + 1,
                         "found the end of the grid with " + std::to_string(used[kind]) + " '" +
                             lazor_letter(lazor_blocks[kind]) +
                             "' placed on open cells, expected exactly " +
                             std::to_string(level.blocks[kind]));
    }
    placed.blocks = {};
    return placed;
}

} // namespace orthoray
