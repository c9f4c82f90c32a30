// libFuzzer target: the JSON scene reader. Any bytes give a Scene or an
// InputError whose position lies inside the text; nothing else may happen.
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const orthoray::Scene scene = orthoray::read_scene_json(text, "fuzz");
        // A scene read back from its own JSON is the same scene, and so is
        // its .scene text.
        const std::string json = orthoray::write_scene_json(scene);
        if (orthoray::write_scene_json(orthoray::read_scene_json(json, "again")) != json)
            std::abort();
        if (orthoray::write_scene(orthoray::read_scene(orthoray::write_scene(scene), "text")) !=
            orthoray::write_scene(scene))
            std::abort();
    } catch (const orthoray::InputError& e) {
        if (e.line() < 1 || e.column() < 1) std::abort();
    }
    return 0;
}
