// Decides a 2 x 1 mirror box shot from a corner: the ray reaches the corner
// (2, 0) after 1 reflection. Exit 0 only if the library says so.
#include <orthoray/parse.hpp>
#include <orthoray/solve.hpp>

#include <iostream>

int main() {
    const orthoray::Scene scene = orthoray::read_scene("dim 2\n"
                                                       "mirror x 0 y 0 1\nmirror x 2 y 0 1\n"
                                                       "mirror y 0 x 0 2\nmirror y 1 x 0 2\n"
                                                       "ray 0 0 1 1\ntarget 2 0\n");
    const orthoray::Answer answer = orthoray::solve(scene);
    std::cout << orthoray::answer_word(answer) << ' ' << orthoray::to_string(answer.reason) << ' '
              << answer.reflections << '\n';
    return answer.yes() && answer.reflections == 1 ? 0 : 1;
}
