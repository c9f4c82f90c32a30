#include "scenes.hpp"

#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace orthoray::bench {
namespace {

using Extent = std::vector<std::pair<Rational, Rational>>;

Rational whole(std::int64_t x) {
    return Rational(Integer(static_cast<long>(x)));
}

// The 2*dim faces of the closed box [0, side]^dim.
void add_box(Scene& scene, std::int64_t side) {
    for (int axis = 0; axis < scene.dim; ++axis)
        for (std::int64_t offset : {std::int64_t{0}, side})
            scene.add_mirror(axis, whole(offset), Extent(scene.dim - 1, {whole(0), whole(side)}));
}

bool on_element(const Scene& scene, const std::int64_t (&p)[3]) {
    for (const Element& e : scene.elements) {
        bool inside = true;
        for (int j = 0; j < scene.dim && inside; ++j)
            inside = e.lo[j] <= whole(p[j]) && whole(p[j]) <= e.hi[j];
        if (inside) return true;
    }
    return false;
}

void set_point(Vector& v, const std::int64_t (&p)[3], int dim) {
    for (int j = 0; j < 3; ++j) v[j] = j < dim ? whole(p[j]) : Rational(0);
}

} // namespace

Scene random_box(int dim, std::int64_t n, std::uint64_t seed, std::int64_t side) {
    if (side < 4) throw std::invalid_argument("random_box: the side must be at least 4");
    if (dim != 2 && dim != 3) throw std::invalid_argument("random_box: dim is 2 or 3");
    std::mt19937_64 rng(seed);
    Scene scene;
    scene.dim = dim;
    add_box(scene, side);
    const std::int64_t s = std::max<std::int64_t>(2, side / integer_root(n, dim));
    for (std::int64_t i = 0; i < n; ++i) {
        const int axis = static_cast<int>(uniform(rng, 0, dim - 1));
        const std::int64_t offset = uniform(rng, 1, side - 1);
        Extent extent;
        for (int j = 0; j < dim; ++j) {
            if (j == axis) continue;
            const std::int64_t length = uniform(rng, s / 2, s);
            const std::int64_t lo = uniform(rng, 0, side - length);
            extent.emplace_back(whole(lo), whole(lo + length));
        }
        scene.add_mirror(axis, whole(offset), extent);
    }
    std::int64_t start[3] = {0, 0, 0};
    do
        for (int j = 0; j < dim; ++j) start[j] = uniform(rng, 1, side - 1);
    while (on_element(scene, start));
    const std::int64_t direction[3] = {1001, 1000, dim == 3 ? 999 : 0};
    // The lattice factors f_j = lcm(u) / u_j, modulo 2.
    std::int64_t l = 1;
    for (int j = 0; j < dim; ++j) l = std::lcm(l, direction[j]);
    const std::int64_t f[2] = {(l / direction[0]) % 2, (l / direction[1]) % 2};
    if (f[0] == 0 && f[1] == 0) throw std::logic_error("random_box: f_0 and f_1 are both even");
    const int odd_axis = f[0] ? 0 : 1;
    std::int64_t target[3] = {0, 0, 0};
    for (int j = 0; j < dim; ++j) target[j] = uniform(rng, 2, side - 2);
    auto parity = [&](const std::int64_t(&x)[3]) { return (f[0] * x[0] + f[1] * x[1]) % 2; };
    if (parity(target) == parity(start)) ++target[odd_axis];
    set_point(scene.ray().start, start, dim);
    set_point(scene.target(), target, dim);
    set_point(scene.ray().direction, direction, 3);
    return scene;
}

// The library's `box` family with the far corner as target.
Scene box_corner(std::int64_t m, std::int64_t n) {
    BoxFamily f;
    f.sides = {Integer(static_cast<long>(m)), Integer(static_cast<long>(n))};
    f.target = BoxFamily::Target::far;
    return generate_box(f).scene;
}

Scene box_corner_3d(std::int64_t m, std::int64_t n, std::int64_t k) {
    BoxFamily f;
    f.sides = {Integer(static_cast<long>(m)), Integer(static_cast<long>(n)),
               Integer(static_cast<long>(k))};
    f.target = BoxFamily::Target::far;
    return generate_box(f).scene;
}

Scene unit_square(std::int64_t p, std::int64_t q) {
    Scene scene;
    scene.dim = 2;
    add_box(scene, 8);
    set_point(scene.ray().start, {4, 2, 0}, 2);
    set_point(scene.ray().direction, {q, p, 0}, 2);
    set_point(scene.target(), {4, 4, 0}, 2);
    return scene;
}

Scene random_small(std::mt19937_64& rng, int dim, const SmallShape& shape) {
    Scene scene;
    scene.dim = dim;
    const std::int64_t side = std::int64_t{1} << uniform(rng, shape.side_log_lo, shape.side_log_hi);
    if (shape.always_box || uniform(rng, 0, 1) == 0) {
        add_box(scene, side);
        if (shape.absorbers && uniform(rng, 0, 3) == 0) // the ray may end on this face
            scene.elements[static_cast<std::size_t>(uniform(rng, 0, 2 * dim - 1))].kind =
                ElementKind::absorber;
    }
    const std::int64_t n = uniform(rng, shape.min_elements, shape.max_elements);
    for (std::int64_t i = 0; i < n; ++i) {
        const int axis = static_cast<int>(uniform(rng, 0, dim - 1));
        const std::int64_t offset = uniform(rng, 1, side - 1);
        Extent extent;
        for (int j = 0; j < dim; ++j) {
            if (j == axis) continue;
            const std::int64_t length = uniform(rng, 1, side / 2);
            const std::int64_t lo = uniform(rng, 0, side - length);
            extent.emplace_back(whole(lo), whole(lo + length));
        }
        const bool absorber = shape.absorbers && uniform(rng, 0, 9) == 0;
        scene.add(absorber ? ElementKind::absorber : ElementKind::mirror, axis, whole(offset),
                  extent);
    }
    std::int64_t start[3] = {0, 0, 0}, direction[3] = {0, 0, 0};
    for (int j = 0; j < dim; ++j) start[j] = uniform(rng, 1, side - 1);
    for (int j = 0; j < dim; ++j) {
        do direction[j] = uniform(rng, -shape.max_direction, shape.max_direction);
        while (direction[j] == 0 && uniform(rng, 0, 7) != 0); // mostly no zero component
    }
    if (direction[0] == 0 && direction[1] == 0 && direction[2] == 0) direction[0] = 1;
    set_point(scene.ray().start, start, dim);
    set_point(scene.ray().direction, direction, 3);
    set_point(scene.target(), start, dim); // the caller chooses the target
    return scene;
}

Scene float_wrong_near_miss() {
    // At x = 999999 the ray y = 0.999999 x is at 999998.000001, just above
    // the mirror's top end 999998; it goes on to the target (10^6, 999999).
    Scene scene;
    scene.dim = 2;
    scene.add_mirror(0, whole(999'999), {{whole(0), whole(999'998)}});
    set_point(scene.ray().start, {0, 0, 0}, 2);
    set_point(scene.ray().direction, {1'000'000, 999'999, 0}, 2);
    set_point(scene.target(), {1'000'000, 999'999, 0}, 2);
    return scene;
}

} // namespace orthoray::bench
