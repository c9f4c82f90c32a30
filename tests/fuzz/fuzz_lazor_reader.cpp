// libFuzzer target: the Lazor level reader (docs/puzzles.md). Any bytes give
// a level or an InputError at a real line and column; a level survives its
// own writer unchanged, and its scene reads back as the same scene.
#include "orthoray/parse.hpp"
#include "orthoray/puzzle.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const orthoray::LazorLevel level = orthoray::read_lazor_level(text, "fuzz");
        const std::string written = orthoray::write_lazor_level(level);
        if (orthoray::write_lazor_level(orthoray::read_lazor_level(written, "again")) != written)
            std::abort();
        const std::string scene = orthoray::write_scene(orthoray::lazor_scene(level));
        if (orthoray::write_scene(orthoray::read_scene(scene, "scene")) != scene) std::abort();
    } catch (const orthoray::InputError& e) {
        if (e.line() < 1 || e.column() < 1) std::abort();
    }
    return 0;
}
