// The derivation's kept states (lib/src/realistic/kept_states.hpp): one
// number per distinct state, contexts of one point and direction chained,
// and every state decoded back exactly.
#include "orthoray/parse.hpp"
#include "realistic/kept_states.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;
using realistic::KeptStates;
using realistic::WalkState;

TEST_CASE("kept states: each once, every context of a point apart, decoded exactly",
          "[realistic]") {
    const Scene scene =
        read_scene("dim 2\nsplitter x 2 y 1 3\nray 0 0 1 1 intensity 5\ntarget 9 9\n");
    KeptStates kept(scene);
    const Vector p{Rational(2), Rational(5, 3)}, q{Rational(2), Rational(7, 3)};
    const WalkState a{p, {Rational(-1), Rational(1)}, 0, 2, Rational(1, 2)};
    WalkState other_factor = a, other_previous = a, other_direction = a, other_point = a;
    other_factor.factor = Rational(1, 3);
    other_previous.previous = 3;
    other_direction.v = {Rational(1), Rational(1)};
    other_point.p = q;

    CHECK(kept.insert(a) == 0u);
    CHECK(!kept.insert(a));
    CHECK(kept.insert(other_factor) == 1u);
    CHECK(kept.insert(other_previous) == 2u);
    CHECK(kept.insert(other_direction) == 3u);
    CHECK(kept.insert(other_point) == 4u);
    for (const WalkState& s : {a, other_factor, other_previous, other_direction, other_point})
        CHECK(!kept.insert(s));
    CHECK(kept.size() == 5);
    CHECK(kept.state(0) == a);
    CHECK(kept.state(1) == other_factor);
    CHECK(kept.state(2) == other_previous);
    CHECK(kept.state(3) == other_direction);
    CHECK(kept.state(4) == other_point);
}
