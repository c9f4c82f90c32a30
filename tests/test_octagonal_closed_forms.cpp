// Octagonal scenes (docs/octagonal.md) whose trajectories are worked out by
// hand, through solve() with the reference tracer.
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;

namespace {

// The diamond with corners (2, 0), (4, 2), (2, 4), (0, 2).
const std::string diamond = "dim 2\n"
                            "mirror \\ 0 2 2 0\n"
                            "mirror / 2 0 4 2\n"
                            "mirror / 0 2 2 4\n"
                            "mirror \\ 2 4 4 2\n";

Answer by_reference(const std::string& text) {
    SolveOptions options;
    options.engine = Engine::reference;
    options.max_steps = 1000;
    return solve(read_scene(text), options);
}

} // namespace

TEST_CASE("a ray along y = 1 in the diamond goes round a square", "[octagonal][closed-form]") {
    // (2, 1) right to (3, 1) on '/', up to (3, 3) on '\', left to (1, 3) on
    // '/', down to (1, 1) on '\', right to (3, 1) again: period 4.
    const std::string ray = "ray 2 1 1 0\n";
    Answer no = by_reference(diamond + ray + "target 2 2\n");
    CHECK(no.reason == Reason::cycle);
    CHECK(no.reflections == 4);
    CHECK(no.tail == 0);
    // (2, 3) lies on the third segment, after two reflections.
    Answer yes = by_reference(diamond + ray + "target 2 3\n");
    CHECK(yes.reason == Reason::hit);
    CHECK(yes.reflections == 2);
    // Its first corner: (1, 1), the fourth reflection point.
    CHECK(by_reference(diamond + ray + "target 1 1\n").reflections == 3);
}

TEST_CASE("a ray into the diamond's corner comes straight back", "[octagonal][closed-form]") {
    // From the centre along x: the corners (4, 2) and (0, 2) join the two
    // slopes, so each sends the ray back: period 2.
    Answer a = by_reference(diamond + "ray 2 2 1 0\ntarget 9 9\n");
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 2);
    CHECK(a.tail == 0);
}

TEST_CASE("a skew ray in the diamond", "[octagonal][closed-form]") {
    // From (2, 2) along (1, 2): '\' at (8/3, 10/3) turns it to (-2, -1),
    // the corner (0, 2) sends it back along (2, 1), '\' at (8/3, 10/3)
    // again turns it to (-1, -2), '\' at (4/3, 2/3) to (2, 1), the corner
    // (4, 2) back to (-2, -1), '\' at (4/3, 2/3) to (1, 2), and it is at
    // (8/3, 10/3) going (-2, -1) once more: period 6.
    const std::string ray = "ray 2 2 1 2\n";
    Answer no = by_reference(diamond + ray + "target 3 2\n");
    CHECK(no.reason == Reason::cycle);
    CHECK(no.reflections == 6);
    CHECK(no.tail == 0);
    CHECK(by_reference(diamond + ray + "target 0 2\n").reflections == 1);
    CHECK(by_reference(diamond + ray + "target 4 2\n").reflections == 4);
    CHECK(by_reference(diamond + ray + "target 2 2\n").reflections == 0);
}

TEST_CASE("a cycle entered after a tail, without one-sided elements", "[octagonal][closed-form]") {
    // Left along y = 4 to '/' (0 3 2 5) at (1, 4), down along x = 1 past
    // the x-mirror (parallel) to (1, 1) on '/' (0 0 2 2), which alone turns
    // it left; the wall x = -1 sends it back to (1, 1), where the diagonal
    // and the x-mirror's end both act: back left. The state at (1, 4) is
    // never seen again: tail 1, period 2.
    Answer a = by_reference("dim 2\n"
                            "mirror / 0 3 2 5\n"
                            "mirror / 0 0 2 2\n"
                            "mirror x 1 y 1 3\n"
                            "mirror x -1 y 0 5\n"
                            "ray 3 4 -1 0\ntarget 9 9\n");
    CHECK(a.reason == Reason::cycle);
    CHECK(a.tail == 1);
    CHECK(a.period() == 2);
    CHECK(a.reflections == 3);
}

TEST_CASE("diagonals let a ray escape or stop it", "[octagonal][closed-form]") {
    // '/' at (2, 0) turns (1, 0) up; nothing above.
    const std::string turn = "dim 2\nmirror / 1 -1 3 1\nray 0 0 1 0\n";
    Answer up = by_reference(turn + "target 2 5\n");
    CHECK(up.reason == Reason::hit);
    CHECK(up.reflections == 1);
    Answer away = by_reference(turn + "target 5 0\n");
    CHECK(away.reason == Reason::escape);
    CHECK(away.reflections == 1);
    // Then a '\' absorber across its way up, at (2, 3).
    Answer stop = by_reference(turn.substr(0, turn.size() - 12) +
                               "absorber \\ 1 4 3 2\nray 0 0 1 0\ntarget 9 9\n");
    CHECK(stop.reason == Reason::absorbed);
    CHECK(stop.reflections == 1);
    // The absorber's point itself is lit.
    CHECK(by_reference(turn + "absorber \\ 1 4 3 2\ntarget 2 3\n").reason == Reason::hit);
}

TEST_CASE("a diagonal splitter in the diamond", "[octagonal][closed-form][optics]") {
    // The '/' side of the diamond from (2, 0) to (4, 2) made a splitter. The
    // ray along y = 1 meets it at (3, 1): straight on it leaves the diamond
    // (escape), reflected it goes round the square (3, 3), (1, 3), (1, 1)
    // and back to (3, 1) along x, where both of its branches repeat.
    const std::string scene = "dim 2\n"
                              "mirror \\ 0 2 2 0\n"
                              "splitter / 2 0 4 2\n"
                              "mirror / 0 2 2 4\n"
                              "mirror \\ 2 4 4 2\n"
                              "ray 2 1 1 0\n"
                              "target 2 3\ntarget 6 1\ntarget 1 2\ntarget 3 0\n";
    for (const Engine engine : {Engine::automatic, Engine::reference, Engine::graph}) {
        SolveOptions options;
        options.engine = engine;
        const Answer a = solve(read_scene(scene), options);
        REQUIRE(a.targets.size() == 4);
        using Status = TargetAnswer::Status;
        CHECK(a.targets[0].status == Status::lit); // on (3, 3) -> (1, 3)
        CHECK(a.targets[0].reflections == 2);
        CHECK(a.targets[1].status == Status::lit); // straight through
        CHECK(a.targets[1].reflections == 0);
        CHECK(a.targets[2].status == Status::lit); // on (1, 3) -> (1, 1)
        CHECK(a.targets[2].reflections == 3);
        CHECK(a.targets[3].status == Status::unlit);
        CHECK(a.reason == Reason::unlit);
        // Every state is explored: the start, the two leaving (3, 1), and
        // those leaving (3, 3), (1, 3) and (1, 1).
        CHECK(a.states == 6);
    }
}
