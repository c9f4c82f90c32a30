// libFuzzer target: the grid maze reader (docs/grid-mazes.md). Any bytes
// give a maze or an InputError at a real line and column (at most one past
// the end of that line). A maze's scene survives the scene writer and
// reader unchanged, and its first beam, traced alone by the reference
// tracer, leaves the grid or is absorbed: a beam from outside a maze of
// two-sided mirrors and absorbers never goes round for ever.
#include "orthoray/grid.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

// Whether (line, column) lies in `text`: an existing line, and a column
// from 1 to one past that line's last byte.
bool real_position(std::string_view text, int line, int column) {
    if (line < 1 || column < 1) return false;
    std::size_t begin = 0;
    for (int l = 1; l < line; ++l) {
        begin = text.find('\n', begin);
        if (begin == std::string_view::npos) return false;
        ++begin;
    }
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    return static_cast<std::size_t>(column) <= end - begin + 1;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        orthoray::GridMaze maze = orthoray::read_grid_maze(text, "fuzz");
        const std::string scene = orthoray::write_scene(orthoray::grid_scene(maze));
        if (orthoray::write_scene(orthoray::read_scene(scene, "scene")) != scene) std::abort();
        maze.beams.resize(1);
        maze.targets.clear();
        const orthoray::Scene one = orthoray::grid_scene(maze);
        if (one.elements.size() > 200) return 0; // the reference scan is quadratic
        orthoray::SolveOptions options;
        options.engine = orthoray::Engine::reference;
        // Each (cell, direction) is entered at most once.
        options.max_steps = 4 * static_cast<std::uint64_t>(maze.width) * maze.height + 4;
        const orthoray::Answer a = orthoray::solve(one, options);
        if (a.reason != orthoray::Reason::escape && a.reason != orthoray::Reason::absorbed)
            std::abort();
    } catch (const orthoray::InputError& e) {
        if (!real_position(text, e.line(), e.column())) std::abort();
    }
    return 0;
}
