// Every curated instance (instances/**/*.scene), read once, by its name
// relative to instances/: the scenes the certificate tests certify.
#pragma once

#include "support/run_cli.hpp" // source_path
#include "support/test_files.hpp"

#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace orthoray::test {

struct CuratedScene {
    std::string name; // relative to instances/, e.g. "2d/ping-pong-cycle.scene"
    Scene scene;
};

inline const std::vector<CuratedScene>& curated_scenes() {
    static const std::vector<CuratedScene> all = [] {
        const std::filesystem::path root = source_path("instances");
        std::vector<CuratedScene> result;
        for (const std::filesystem::path& file : instance_files())
            result.push_back({std::filesystem::relative(file, root).generic_string(),
                              load_scene(file.string())});
        return result;
    }();
    return all;
}

} // namespace orthoray::test
