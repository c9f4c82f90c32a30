// Decides a 2 x 1 mirror box shot from a corner: the ray reaches the corner
// (2, 0) after 1 reflection. Through the umbrella header, so that every
// installed header (the generated version.hpp too) must be there. Exit 0
// only if the library says so.
#include <orthoray/orthoray.hpp>

#include <iostream>
#include <string>

int main() {
    const orthoray::Scene scene = orthoray::read_scene("dim 2\n"
                                                       "mirror x 0 y 0 1\nmirror x 2 y 0 1\n"
                                                       "mirror y 0 x 0 2\nmirror y 1 x 0 2\n"
                                                       "ray 0 0 1 1\ntarget 2 0\n");
    const orthoray::Answer answer = orthoray::solve(scene);
    std::cout << "orthoray " << orthoray::version << ": " << orthoray::answer_word(answer) << ' '
              << orthoray::to_string(answer.reason) << ' ' << answer.reflections << '\n';
    // The macros and the string come from the same project(VERSION).
    const bool versioned = std::to_string(ORTHORAY_VERSION_MAJOR) + "." +
                               std::to_string(ORTHORAY_VERSION_MINOR) + "." +
                               std::to_string(ORTHORAY_VERSION_PATCH) ==
                           orthoray::version;
    return versioned && answer.yes() && answer.reflections == 1 ? 0 : 1;
}
