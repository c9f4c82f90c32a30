// The acting rule of docs/optics.md at every kind of event point: which
// elements act, absorbers, and the outgoing directions R <= F <= R + S.
#include "engine/event_rule.hpp"
#include "engine/reference_step.hpp"
#include "orthoray/parse.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace orthoray;
using engine::acts_on;
using engine::event_outcome;

namespace {

Element element(ElementKind kind, int axis, Side side = Side::both) {
    Element e;
    e.kind = kind;
    e.axis = axis;
    e.side = side;
    return e;
}

bool has_direction(const engine::EventOutcome& o, const Vector& v, bool reflection) {
    return std::any_of(o.outgoing.begin(), o.outgoing.end(), [&](const engine::Outgoing& out) {
        return out.direction == v && out.reflection == reflection;
    });
}

} // namespace

TEST_CASE("a one-sided element acts only on rays from its side", "[event-rule]") {
    const Element plus = element(ElementKind::mirror, 0, Side::plus);
    const Element minus = element(ElementKind::mirror, 0, Side::minus);
    const Element both = element(ElementKind::mirror, 0);
    const Vector left{-1, 2, 0}, right{1, 2, 0}, along{0, 1, 0};
    CHECK(acts_on(plus, left));
    CHECK_FALSE(acts_on(plus, right));
    CHECK(acts_on(minus, right));
    CHECK_FALSE(acts_on(minus, left));
    CHECK(acts_on(both, left));
    CHECK(acts_on(both, right));
    // Parallel to the plane: never acted on, whatever the side.
    CHECK_FALSE(acts_on(both, along));
    CHECK_FALSE(acts_on(plus, along));
}

TEST_CASE("mirrors reflect, absorbers stop, splitters fork", "[event-rule]") {
    const Vector v{1, 2, 0};
    const Element mx = element(ElementKind::mirror, 0), sx = element(ElementKind::splitter, 0);
    const Element sy = element(ElementKind::splitter, 1), my = element(ElementKind::mirror, 1);
    const Element ax = element(ElementKind::absorber, 0);

    auto mirror = event_outcome(2, {&mx}, v);
    REQUIRE(mirror.outgoing.size() == 1);
    CHECK(has_direction(mirror, {-1, 2, 0}, true));

    auto splitter = event_outcome(2, {&sx}, v);
    REQUIRE(splitter.outgoing.size() == 2);
    CHECK(splitter.outgoing.front().direction == v); // F = R first: straight on
    CHECK_FALSE(splitter.outgoing.front().reflection);
    CHECK(has_direction(splitter, {-1, 2, 0}, true));

    // A mirror and a splitter of the same axis: the mirror wins.
    auto same_axis = event_outcome(2, {&sx, &mx}, v);
    REQUIRE(same_axis.outgoing.size() == 1);
    CHECK(has_direction(same_axis, {-1, 2, 0}, true));

    // A corner where a mirror (x) meets a splitter (y): x always flips,
    // y flips or not.
    auto corner = event_outcome(2, {&mx, &sy}, v);
    REQUIRE(corner.outgoing.size() == 2);
    CHECK(has_direction(corner, {-1, 2, 0}, true));
    CHECK(has_direction(corner, {-1, -2, 0}, true));

    // Two splitters at a corner: all four sign patterns, one straight on.
    auto both = event_outcome(2, {&sx, &sy}, v);
    REQUIRE(both.outgoing.size() == 4);
    CHECK(has_direction(both, {1, 2, 0}, false));
    CHECK(has_direction(both, {-1, 2, 0}, true));
    CHECK(has_direction(both, {1, -2, 0}, true));
    CHECK(has_direction(both, {-1, -2, 0}, true));

    // A mirror corner reflects both components in one reflection.
    auto mirror_corner = event_outcome(2, {&mx, &my}, v);
    REQUIRE(mirror_corner.outgoing.size() == 1);
    CHECK(has_direction(mirror_corner, {-1, -2, 0}, true));

    // An absorber among them stops the ray, whatever else acts.
    auto absorbed = event_outcome(2, {&sx, &ax, &my}, v);
    CHECK(absorbed.absorbed);
    CHECK(absorbed.outgoing.empty());
}

TEST_CASE("three splitting axes give eight outgoing rays", "[event-rule]") {
    const Element sx = element(ElementKind::splitter, 0), sy = element(ElementKind::splitter, 1),
                  sz = element(ElementKind::splitter, 2);
    auto o = event_outcome(3, {&sx, &sy, &sz}, Vector{1, 1, 1});
    REQUIRE(o.outgoing.size() == 8);
    CHECK(std::count_if(o.outgoing.begin(), o.outgoing.end(),
                        [](const engine::Outgoing& out) { return out.reflection; }) == 7);
}

TEST_CASE("the first event skips elements seen from their back", "[event-rule]") {
    // x+ at 2 acts only on rays moving toward -x; the ray moving +x passes
    // it and meets the two-sided mirror at 5, at its edge y = 1.
    const Scene s = read_scene("dim 2\nmirror x+ 2 y -1 1\nmirror x 5 y 0 1\n"
                               "ray 0 0 1 1/5\ntarget 9 9\n");
    engine::ReferenceEvent e = engine::reference_step(s, s.ray().start, s.ray().direction);
    REQUIRE_FALSE(e.escape);
    CHECK(e.point == Vector{5, 1, 0});
    CHECK(e.direction == Vector{-1, Rational(1, 5), 0});
    // Coming back it reaches x = 2 at y = 8/5, beyond the one-sided
    // mirror's end, and escapes.
    engine::ReferenceEvent back = engine::reference_step(s, e.point, e.direction);
    CHECK(back.escape);
    // A ray from the front is reflected by it, at its edge.
    engine::ReferenceEvent front = engine::reference_step(s, Vector{4, 0, 0}, Vector{-2, -1, 0});
    REQUIRE_FALSE(front.escape);
    CHECK(front.point == Vector{2, -1, 0});
    CHECK(front.direction == Vector{2, -1, 0});
}
