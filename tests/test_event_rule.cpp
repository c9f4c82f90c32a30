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

namespace {

Element diagonal(ElementKind kind, Diagonal slope) {
    Element e;
    e.kind = kind;
    e.axis = -1;
    e.diagonal = slope;
    return e;
}

// The first event of a scene's first ray.
engine::ReferenceEvent first_event(const std::string& text) {
    const Scene s = read_scene(text);
    return engine::reference_step(s, s.ray().start, s.ray().direction);
}

} // namespace

TEST_CASE("a diagonal acts on every ray not parallel to it", "[event-rule][octagonal]") {
    const Element rising = diagonal(ElementKind::mirror, Diagonal::rising);
    const Element falling = diagonal(ElementKind::mirror, Diagonal::falling);
    for (const Vector& along : {Vector{1, 1, 0}, Vector{-2, -2, 0}}) {
        CHECK_FALSE(acts_on(rising, along));
        CHECK(acts_on(falling, along));
    }
    for (const Vector& along : {Vector{1, -1, 0}, Vector{-3, 3, 0}}) {
        CHECK(acts_on(rising, along));
        CHECK_FALSE(acts_on(falling, along));
    }
    for (const Vector& v : {Vector{1, 0, 0}, Vector{0, -1, 0}, Vector{1, 2, 0}, Vector{-3, 1, 0}}) {
        CHECK(acts_on(rising, v));
        CHECK(acts_on(falling, v));
    }
}

TEST_CASE("one slope alone: mirrors swap, absorbers stop, splitters fork",
          "[event-rule][octagonal]") {
    const Vector v{1, 2, 0};
    const Element mr = diagonal(ElementKind::mirror, Diagonal::rising),
                  mf = diagonal(ElementKind::mirror, Diagonal::falling),
                  sr = diagonal(ElementKind::splitter, Diagonal::rising),
                  ar = diagonal(ElementKind::absorber, Diagonal::rising);
    // '/' is the mirror image across y = x, '\' across y = -x.
    auto rising = event_outcome(2, {&mr}, v);
    REQUIRE(rising.outgoing.size() == 1);
    CHECK(has_direction(rising, {2, 1, 0}, true));
    auto falling = event_outcome(2, {&mf}, v);
    REQUIRE(falling.outgoing.size() == 1);
    CHECK(has_direction(falling, {-2, -1, 0}, true));
    CHECK(event_outcome(2, {&mf}, Vector{1, 0, 0}).outgoing.front().direction == Vector{0, -1, 0});
    // A splitter: straight on first (not a reflection), then swapped.
    auto split = event_outcome(2, {&sr}, v);
    REQUIRE(split.outgoing.size() == 2);
    CHECK(split.outgoing.front().direction == v);
    CHECK_FALSE(split.outgoing.front().reflection);
    CHECK(has_direction(split, {2, 1, 0}, true));
    // A mirror and a splitter of the same slope: the mirror wins.
    auto same = event_outcome(2, {&sr, &mr}, v);
    REQUIRE(same.outgoing.size() == 1);
    CHECK(has_direction(same, {2, 1, 0}, true));
    // An absorber of the same slope stops it, whatever else lies there.
    CHECK(event_outcome(2, {&mr, &ar}, v).absorbed);
    CHECK(event_outcome(2, {&ar, &sr}, v).outgoing.empty());
}

TEST_CASE("a diagonal with another orientation sends the ray back", "[event-rule][octagonal]") {
    const Vector v{1, 2, 0}, back{-1, -2, 0};
    const Element mr = diagonal(ElementKind::mirror, Diagonal::rising),
                  mf = diagonal(ElementKind::mirror, Diagonal::falling),
                  sr = diagonal(ElementKind::splitter, Diagonal::rising),
                  sf = diagonal(ElementKind::splitter, Diagonal::falling),
                  af = diagonal(ElementKind::absorber, Diagonal::falling);
    const Element mx = element(ElementKind::mirror, 0), my = element(ElementKind::mirror, 1),
                  sx = element(ElementKind::splitter, 0), ax = element(ElementKind::absorber, 0),
                  minus_y = element(ElementKind::mirror, 1, Side::minus);
    // Crossing diagonals, a diagonal meeting an x- or y-mirror, a splitter
    // or a one-sided mirror: one outgoing ray, back along -v.
    for (const auto& acting : std::vector<std::vector<const Element*>>{{&mr, &mf},
                                                                       {&sr, &sf},
                                                                       {&mr, &mx},
                                                                       {&mf, &my},
                                                                       {&sr, &sx},
                                                                       {&sf, &minus_y},
                                                                       {&mr, &mx, &my},
                                                                       {&mr, &sr, &sx}}) {
        auto o = event_outcome(2, acting, v);
        CHECK_FALSE(o.absorbed);
        REQUIRE(o.outgoing.size() == 1);
        CHECK(has_direction(o, back, true));
    }
    // An absorber among them, of either orientation, stops the ray.
    CHECK(event_outcome(2, {&mr, &ax}, v).absorbed);
    CHECK(event_outcome(2, {&sr, &af}, v).absorbed);
    CHECK(event_outcome(2, {&af, &mx}, v).absorbed);
}

TEST_CASE("the first event on diagonals, exactly", "[event-rule][octagonal]") {
    const std::string tail = "target 9 9\n";
    // Into the middle of '/' (y = x - 2): (1, 0) turns to (0, 1).
    auto middle = first_event("dim 2\nmirror / 1 -1 3 1\nray 0 0 1 0\n" + tail);
    REQUIRE_FALSE(middle.escape);
    CHECK(middle.point == Vector{2, 0, 0});
    CHECK(middle.direction == Vector{0, 1, 0});
    // A skew ray meets '\' (x + y = 3) at t = 1/3, off the lattice of units.
    auto skew = first_event("dim 2\nmirror \\ 0 3 3 0\nray 0 0 7 2\n" + tail);
    REQUIRE_FALSE(skew.escape);
    CHECK(skew.t == Rational(1, 3));
    CHECK(skew.point == Vector{Rational(7, 3), Rational(2, 3), 0});
    CHECK(skew.direction == Vector{-2, -7, 0});
    // A diagonal's endpoint belongs to it; just past it the ray escapes.
    auto end = first_event("dim 2\nmirror / 2 0 4 2\nray 0 0 1 0\n" + tail);
    REQUIRE_FALSE(end.escape);
    CHECK(end.point == Vector{2, 0, 0});
    CHECK(end.direction == Vector{0, 1, 0});
    CHECK(first_event("dim 2\nmirror / 2 0 4 2\nray 0 -1/2 1 0\n" + tail).escape);
    // Two diagonals crossing at (1, 1): back the way it came.
    auto cross = first_event("dim 2\nmirror / 0 0 2 2\nmirror \\ 0 2 2 0\nray -1 1 1 0\n" + tail);
    REQUIRE_FALSE(cross.escape);
    CHECK(cross.point == Vector{1, 1, 0});
    CHECK(cross.direction == Vector{-1, 0, 0});
    // Along one of two crossing diagonals only the other acts.
    auto along_cross =
        first_event("dim 2\nmirror / 0 0 2 2\nmirror \\ 0 2 2 0\nray 0 0 1 1\n" + tail);
    REQUIRE_FALSE(along_cross.escape);
    CHECK(along_cross.point == Vector{1, 1, 0});
    CHECK(along_cross.direction == Vector{-1, -1, 0});
    // A ray running along a diagonal passes it and stops at the wall beyond.
    auto along = first_event("dim 2\nmirror / 0 0 3 3\nabsorber y 5 x 0 9\nray 1 1 1 1\n" + tail);
    REQUIRE_FALSE(along.escape);
    CHECK(along.point == Vector{5, 5, 0});
    CHECK(along.absorbed);
}

TEST_CASE("a diagonal where axis elements end", "[event-rule][octagonal]") {
    const std::string scene = "dim 2\nmirror / 0 0 2 2\nmirror x 1 y 1 3\nmirror y 1 x -3 0\n";
    // Across the x-mirror's end at (1, 1): both act, back along -x.
    auto across = first_event(scene + "ray -1 1 1 0\ntarget 9 9\n");
    CHECK(across.point == Vector{1, 1, 0});
    CHECK(across.direction == Vector{-1, 0, 0});
    // Sliding down the x-mirror (parallel, so it does not act) to the same
    // point: the diagonal alone turns the ray, onto the same -x. Two states
    // step to one: the reason diagonal scenes can have tails.
    auto sliding = first_event(scene + "ray 1 3 0 -1\ntarget 9 9\n");
    CHECK(sliding.point == Vector{1, 1, 0});
    CHECK(sliding.direction == Vector{-1, 0, 0});
    // The same with a y-mirror ending on the diagonal at (1, 1): sliding
    // along it the ray is turned by the diagonal alone, across it both act.
    const std::string y_end = "dim 2\nmirror / 0 0 2 2\nmirror y 1 x 1 3\n";
    auto slide_y = first_event(y_end + "ray 3 1 -1 0\ntarget 9 9\n");
    CHECK(slide_y.point == Vector{1, 1, 0});
    CHECK(slide_y.direction == Vector{0, -1, 0});
    auto across_y = first_event(y_end + "ray 1 3 0 -1\ntarget 9 9\n");
    CHECK(across_y.point == Vector{1, 1, 0});
    CHECK(across_y.direction == Vector{0, 1, 0});
}

TEST_CASE("a one-sided mirror on a diagonal, from either side", "[event-rule][octagonal]") {
    // y+ at y = 1 acts on rays moving down. At (1, 1) on '/' (0 0 2 2):
    // from above, moving (-1, -2), both act: back along (1, 2).
    const std::string scene = "dim 2\nmirror / 0 0 2 2\nmirror y+ 1 x 0 2\n";
    auto front = first_event(scene + "ray 2 3 -1 -2\ntarget 9 9\n");
    CHECK(front.point == Vector{1, 1, 0});
    CHECK(front.direction == Vector{1, 2, 0});
    // From below, moving (1, 2), the y+ mirror is invisible: the diagonal
    // swaps the components.
    auto back = first_event(scene + "ray 0 -1 1 2\ntarget 9 9\n");
    CHECK(back.point == Vector{1, 1, 0});
    CHECK(back.direction == Vector{2, 1, 0});
}

TEST_CASE("a junction is a point where some arrival splits", "[event-rule]") {
    using engine::is_junction;
    const Vector v{1, 2, 0};
    const Element mx = element(ElementKind::mirror, 0), my = element(ElementKind::mirror, 1);
    const Element sx = element(ElementKind::splitter, 0);
    const Element sy_plus = element(ElementKind::splitter, 1, Side::plus); // acts from above
    const Element mx_minus = element(ElementKind::mirror, 0, Side::minus);
    // No splitter: never, whatever acts.
    CHECK_FALSE(is_junction(2, {&mx, &my}, v, false));
    // A two-sided splitter splits every arrival not parallel to it.
    CHECK(is_junction(2, {&sx}, v, false));
    // One-sided: v moves up, so it arrives from below and is not split,
    // but -v's y component arrives from above.
    CHECK(is_junction(2, {&sy_plus, &mx}, v, false));
    // A splitter that every arrival moves parallel to splits none of them.
    CHECK_FALSE(is_junction(2, {&sx, &my}, Vector{0, 1, 0}, false));
    // A two-sided mirror of the same axis always wins over the splitter; a
    // one-sided one leaves the arrivals from its back to the splitter.
    CHECK_FALSE(is_junction(2, {&sx, &mx}, v, false));
    CHECK(is_junction(2, {&sx, &mx_minus}, v, false));
    // v = (1, 0) never crosses a y-splitter; swapped (0, 1), it does.
    const Vector flat{1, 0, 0};
    const Element sy = element(ElementKind::splitter, 1);
    CHECK_FALSE(is_junction(2, {&sy}, flat, false));
    CHECK(is_junction(2, {&sy}, flat, true));
}
