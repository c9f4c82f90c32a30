#include "support/random_scene.hpp"

#include "orthoray/solve.hpp"
#include "support/portable_random.hpp"

#include <vector>

namespace orthoray::test {
namespace {

Rational coordinate(std::mt19937_64& rng, const RandomSceneShape& s) {
    int den = pick(rng, 1, s.max_denominator);
    Rational x(pick(rng, -s.range * den, s.range * den), den);
    x.canonicalize(); // gmpxx leaves a/b as given; comparisons need lowest terms
    return x;
}

} // namespace

Vector random_point(std::mt19937_64& rng, const RandomSceneShape& shape) {
    Vector p;
    for (int j = 0; j < shape.dim; ++j) p[j] = coordinate(rng, shape);
    return p;
}

Scene random_scene(std::mt19937_64& rng, const RandomSceneShape& shape) {
    Scene scene;
    scene.dim = shape.dim;
    const int d = shape.dim;
    auto extent_pair = [&]() {
        Rational a = coordinate(rng, shape), b = coordinate(rng, shape);
        while (a == b) b = coordinate(rng, shape);
        return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
    };
    if (chance(rng, shape.box_percent)) {
        // An enclosing box [-R-1, R+1]^d; sometimes one face absorbs or has a gap.
        Rational r = shape.range + 1;
        int special_face = chance(rng, 30) ? pick(rng, 0, 2 * d - 1) : -1;
        bool gap = chance(rng, 50);
        for (int face = 0; face < 2 * d; ++face) {
            int axis = face / 2;
            Rational offset = face % 2 ? r : Rational(-r);
            std::vector<std::pair<Rational, Rational>> extent(d - 1, {-r, r});
            ElementKind kind = ElementKind::mirror;
            if (face == special_face) {
                if (gap)
                    extent[0].second = 0; // half the face is missing
                else
                    kind = ElementKind::absorber;
            }
            scene.add(kind, axis, offset, extent);
        }
    }
    int n = pick(rng, 0, shape.max_elements);
    for (int i = 0; i < n; ++i) {
        std::vector<std::pair<Rational, Rational>> extent;
        for (int j = 0; j < d - 1; ++j) extent.push_back(extent_pair());
        ElementKind kind = chance(rng, 15) ? ElementKind::absorber : ElementKind::mirror;
        // One draw a statement: the order of a call's arguments is unspecified
        // (gcc takes them right to left, clang left to right), and a seeded
        // scene must be the same on both. This is the order gcc always used.
        const Rational offset = coordinate(rng, shape);
        scene.add(kind, pick(rng, 0, d - 1), offset, extent);
    }

    scene.ray().start = random_point(rng, shape);
    if (!scene.elements.empty() && chance(rng, 15)) {
        // Start on an element: any point of its box.
        const Element& e = scene.elements[pick(rng, 0, int(scene.elements.size()) - 1)];
        for (int j = 0; j < d; ++j) scene.ray().start[j] = chance(rng, 30) ? e.lo[j] : e.hi[j];
        scene.ray().start[e.axis] = e.offset();
    }
    bool zero = true;
    int parallel_axis = chance(rng, 15) ? pick(rng, 0, d - 1) : -1;
    while (zero) {
        for (int j = 0; j < d; ++j) {
            if (parallel_axis >= 0 && j != parallel_axis) {
                scene.ray().direction[j] = 0;
                continue;
            }
            int den = chance(rng, 20) ? 2 : 1;
            scene.ray().direction[j] =
                Rational(pick(rng, -shape.max_direction, shape.max_direction), den);
            scene.ray().direction[j].canonicalize();
            if (chance(rng, 15)) scene.ray().direction[j] = 0;
            zero = zero && scene.ray().direction[j] == 0;
        }
    }
    scene.target() = random_point(rng, shape);
    return scene;
}

Vector target_on_trajectory(std::mt19937_64& rng, const Scene& scene) {
    PathRecorder path;
    SolveOptions options;
    options.engine = Engine::reference;
    options.max_steps = static_cast<std::uint64_t>(pick(rng, 0, 6));
    options.path = &path;
    Scene probe = scene;
    probe.target() = Vector{Rational(1, 3) << 200, 0, 0}; // far away: not met early
    solve(probe, options);
    std::size_t i = static_cast<std::size_t>(pick(rng, 0, int(path.points.size()) - 1));
    const Vector& p = path.points[i];
    Vector x;
    if (i + 1 < path.points.size()) {
        // A point of the closed segment p_i .. p_{i+1}: an end or an inner point.
        Rational lambda[] = {0, 1, Rational(1, 2), Rational(1, 3)};
        Rational l = lambda[pick(rng, 0, 3)];
        for (int j = 0; j < scene.dim; ++j) x[j] = p[j] + l * (path.points[i + 1][j] - p[j]);
    } else {
        // The last segment (escape or limit): somewhere along the direction.
        const int den = pick(rng, 1, 3); // drawn first on every compiler, as gcc did
        Rational tau(pick(rng, 0, 5), den);
        tau.canonicalize();
        for (int j = 0; j < scene.dim; ++j) x[j] = p[j] + tau * path.directions[i][j];
    }
    return x;
}

Vector random_target(std::mt19937_64& rng, const Scene& scene, const RandomSceneShape& shape) {
    return chance(rng, 50) ? target_on_trajectory(rng, scene) : random_point(rng, shape);
}

} // namespace orthoray::test
