#include "support/random_octagonal.hpp"

#include "support/portable_random.hpp"
#include "support/random_optics.hpp"

namespace orthoray::test {
namespace {

// k / 2 for a uniform k in [2 lo, 2 hi]: the half-integer grid.
Rational half_step(std::mt19937_64& rng, int lo, int hi) {
    Rational r(pick(rng, 2 * lo, 2 * hi), 2);
    r.canonicalize();
    return r;
}

ElementKind random_kind(std::mt19937_64& rng, const RandomOctagonalShape& shape) {
    if (chance(rng, shape.absorber_percent)) return ElementKind::absorber;
    return chance(rng, shape.splitter_percent) ? ElementKind::splitter : ElementKind::mirror;
}

// The wall x_axis = at, across [0, box] on the other axis: whole, or with a
// gap, and sometimes partly absorbing.
void add_wall(Scene& scene, std::mt19937_64& rng, const RandomOctagonalShape& shape, int axis,
              const Rational& at) {
    const Rational zero(0), box(shape.box);
    const ElementKind kind =
        chance(rng, shape.absorber_percent) ? ElementKind::absorber : ElementKind::mirror;
    if (!chance(rng, shape.gap_percent)) {
        scene.add(kind, axis, at, {{zero, box}});
        return;
    }
    Rational a = half_step(rng, 0, shape.box), b = half_step(rng, 0, shape.box);
    if (b < a) std::swap(a, b);
    if (zero < a) scene.add(kind, axis, at, {{zero, a}});
    if (b < box) scene.add(ElementKind::mirror, axis, at, {{b, box}});
}

void add_diagonal(Scene& scene, std::mt19937_64& rng, const RandomOctagonalShape& shape) {
    // Lengths and positions in half-units, inside the box.
    const int span = 2 * shape.box;
    const int length = pick(rng, 1, span);
    const int x0 = pick(rng, 0, span - length), y0 = pick(rng, 0, span - length);
    const Rational x(x0, 2), y(y0, 2), end_x(x0 + length, 2), end_y(y0 + length, 2);
    const ElementKind kind = random_kind(rng, shape);
    if (chance(rng, 50))
        scene.add_diagonal(kind, x, y, end_x, end_y);
    else
        scene.add_diagonal(kind, x, end_y, end_x, y);
}

void add_axis_element(Scene& scene, std::mt19937_64& rng, const RandomOctagonalShape& shape) {
    const int axis = pick(rng, 0, 1);
    const Rational at = half_step(rng, 0, shape.box);
    Rational a = half_step(rng, 0, shape.box), b = half_step(rng, 0, shape.box);
    while (a == b) b = half_step(rng, 0, shape.box);
    if (b < a) std::swap(a, b);
    Side side = Side::both;
    if (chance(rng, shape.one_sided_percent)) side = chance(rng, 50) ? Side::plus : Side::minus;
    scene.add(random_kind(rng, shape), axis, at, {{a, b}}, side);
}

// Along an axis, along a diagonal (parallel to half the diagonals), or a
// small direction of neither kind.
Vector random_direction(std::mt19937_64& rng) {
    const int sx = chance(rng, 50) ? 1 : -1, sy = chance(rng, 50) ? 1 : -1;
    const int kind = pick(rng, 0, 2);
    if (kind == 0) return chance(rng, 50) ? Vector{sx, 0, 0} : Vector{0, sy, 0};
    if (kind == 1) return {sx, sy, 0};
    int a = pick(rng, 1, 3), b = pick(rng, 1, 3);
    while (a == b) b = pick(rng, 1, 3);
    return {sx * a, sy * b, 0};
}

} // namespace

Scene random_octagonal_scene(std::mt19937_64& rng, const RandomOctagonalShape& shape) {
    Scene scene;
    scene.dim = 2;
    for (int axis = 0; axis < 2; ++axis) {
        add_wall(scene, rng, shape, axis, Rational(0));
        add_wall(scene, rng, shape, axis, Rational(shape.box));
    }
    const int inside = pick(rng, 1, shape.max_elements);
    for (int i = 0; i < inside; ++i) {
        if (chance(rng, shape.diagonal_percent))
            add_diagonal(scene, rng, shape);
        else
            add_axis_element(scene, rng, shape);
    }
    scene.rays.clear();
    const int rays = pick(rng, 1, shape.max_rays);
    for (int r = 0; r < rays; ++r) {
        // Starts on the half-integer grid: on walls and element ends now
        // and then.
        Ray ray;
        ray.start = {half_step(rng, 0, shape.box), half_step(rng, 0, shape.box), Rational(0)};
        ray.direction = random_direction(rng);
        scene.rays.push_back(ray);
    }
    scene.targets.clear();
    const int targets = pick(rng, 1, shape.max_targets);
    for (int t = 0; t < targets; ++t)
        scene.targets.push_back(chance(rng, 50)
                                    ? point_on_a_branch(rng, scene)
                                    : Vector{half_step(rng, -1, shape.box + 1),
                                             half_step(rng, -1, shape.box + 1), Rational(0)});
    return scene;
}

} // namespace orthoray::test
