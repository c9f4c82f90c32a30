#include "support/random_optics.hpp"

#include "engine/reference_step.hpp"
#include "support/portable_random.hpp"

namespace orthoray::test {

Vector point_on_a_branch(std::mt19937_64& rng, const Scene& scene) {
    const Ray& ray = scene.rays[static_cast<std::size_t>(
        uniform(rng, 0, static_cast<std::int64_t>(scene.rays.size()) - 1))];
    Vector p = ray.start, v = ray.direction;
    const std::int64_t events = uniform(rng, 0, 6);
    for (std::int64_t i = 0;; ++i) {
        const engine::ReferenceEvent e = engine::reference_step(scene, p, v);
        if (e.escape) {
            // Denominator first on every compiler (gcc's order of the arguments).
            const long den = static_cast<long>(uniform(rng, 1, 3));
            Rational tau(static_cast<long>(uniform(rng, 0, 5)), den);
            tau.canonicalize();
            Vector x;
            for (int j = 0; j < scene.dim; ++j) x[j] = p[j] + tau * v[j];
            return x;
        }
        if (i == events || e.absorbed) {
            const Rational fractions[] = {0, 1, Rational(1, 2), Rational(1, 3)};
            const Rational& l = fractions[uniform(rng, 0, 3)];
            Vector x;
            for (int j = 0; j < scene.dim; ++j) x[j] = p[j] + l * (e.point[j] - p[j]);
            return x;
        }
        const auto& out = e.outgoing[static_cast<std::size_t>(
            uniform(rng, 0, static_cast<std::int64_t>(e.outgoing.size()) - 1))];
        p = e.point;
        v = out.direction;
    }
}

RandomOpticsShape dense_one_sided_shape(int i) {
    RandomOpticsShape shape;
    shape.splitter_percent = 50;
    shape.one_sided_percent = 60;
    shape.scene.max_elements = 12;
    shape.scene.range = 4;
    shape.scene.dim = i % 3 == 0 ? 3 : 2;
    shape.scene.max_denominator = i % 4 == 0 ? 2 : 1;
    return shape;
}

Scene random_optics_scene(std::mt19937_64& rng, const RandomOpticsShape& shape) {
    Scene scene = random_scene(rng, shape.scene);
    for (Element& e : scene.elements) {
        if (e.kind == ElementKind::mirror && chance(rng, shape.splitter_percent))
            e.kind = ElementKind::splitter;
        if (chance(rng, shape.one_sided_percent))
            e.side = chance(rng, 50) ? Side::plus : Side::minus;
    }
    // Extra rays borrow random_scene's choices of start and direction.
    const std::int64_t rays = uniform(rng, 1, shape.max_rays);
    for (std::int64_t r = 1; r < rays; ++r)
        scene.rays.push_back(random_scene(rng, shape.scene).ray());
    scene.targets.clear();
    const std::int64_t targets = uniform(rng, 1, shape.max_targets);
    for (std::int64_t t = 0; t < targets; ++t)
        scene.targets.push_back(chance(rng, 50) ? point_on_a_branch(rng, scene)
                                                : random_point(rng, shape.scene));
    return scene;
}

namespace {

const Rational factors[] = {Rational(1),     Rational(1, 2), Rational(2, 3),
                            Rational(9, 10), Rational(0),    Rational(3, 4)};

Rational random_factor(std::mt19937_64& rng) {
    return factors[pick_index(rng, 0, std::size(factors) - 1)];
}

} // namespace

void add_random_attenuation(std::mt19937_64& rng, Scene& scene, int max_intensity) {
    for (Element& e : scene.elements) {
        if (e.kind == ElementKind::absorber) continue;
        if (chance(rng, 70)) e.reflectance = random_factor(rng);
        if (e.kind == ElementKind::splitter && chance(rng, 70))
            e.transmittance = random_factor(rng);
    }
    for (Ray& r : scene.rays) r.intensity = Integer(pick(rng, 0, max_intensity));
}

} // namespace orthoray::test
