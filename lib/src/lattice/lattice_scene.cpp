#include "lattice/lattice_scene.hpp"

#include "engine/event_rule.hpp"
#include "lattice/scaling.hpp"

#include <algorithm>
#include <vector>

namespace orthoray::lattice {
namespace {

Integer abs_of(const Integer& a) {
    return a < 0 ? Integer(-a) : a;
}

} // namespace

LatticeScene make_lattice(const Scene& scene, const SetupPoll& poll, std::size_t ray_index) {
    LatticeScene out;
    out.scene = &scene;
    const Ray& ray = scene.rays.at(ray_index);
    out.ray = &ray;
    const Vector& v = ray.direction;

    // Primitive integer direction u and L = lcm |u_j|.
    Integer vden = 1;
    for (int j = 0; j < scene.dim; ++j) vden = lcm(vden, v[j].get_den());
    Coords u;
    Integer g = 0;
    for (int j = 0; j < scene.dim; ++j) {
        u[j] = v[j].get_num() * (vden / v[j].get_den());
        mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), u[j].get_mpz_t());
    }
    Integer L = 1;
    for (int j = 0; j < scene.dim; ++j) {
        if (u[j] == 0) continue;
        u[j] /= g;
        L = lcm(L, abs_of(u[j]));
        out.active[out.dim++] = j;
    }

    // Which elements the ray can meet at all.
    auto spans_start = [&](const Element& e) {
        if (v[e.axis] == 0) return false; // moving parallel to its plane
        for (int j = 0; j < scene.dim; ++j)
            if (v[j] == 0 && (ray.start[j] < e.lo[j] || e.hi[j] < ray.start[j])) return false;
        return true;
    };

    // D: the lcm of all denominators on active axes.
    Integer D = 1;
    auto take_denominators = [&](const Vector& x) {
        for (int i = 0; i < out.dim; ++i)
            if (!is_integer(x[out.active[i]])) D = lcm(D, x[out.active[i]].get_den());
    };
    take_denominators(ray.start);
    take_denominators(scene.target());
    for (const Element& e : scene.elements) {
        poll();
        if (!spans_start(e)) continue;
        take_denominators(e.lo);
        take_denominators(e.hi);
    }
    for (int i = 0; i < out.dim; ++i) out.scale[i] = D * L / abs_of(u[out.active[i]]);

    // x * scale[i] is integral: every denominator divides D, which divides
    // scale[i] (the axes past dim have scale 0).
    std::vector<Scaling> scaling;
    for (const Integer& scale : out.scale) scaling.emplace_back(scale);
    auto scaled = [&](const Rational& x, int i) { return scaling[i](x); };
    auto track = [&](const Integer& x) {
        if (mpz_cmpabs(x.get_mpz_t(), out.magnitude.get_mpz_t()) > 0) out.magnitude = abs_of(x);
    };
    for (int i = 0; i < out.dim; ++i) {
        out.start[i] = scaled(ray.start[out.active[i]], i);
        track(out.start[i]);
        if (v[out.active[i]] < 0) out.start_direction |= 1u << i;
    }
    out.target_reachable = out.to_lattice(scene.target(), out.target);
    if (out.target_reachable)
        for (int i = 0; i < out.dim; ++i) track(out.target[i]);
    // Mask bit i negates active axis i of the ray's direction.
    for (unsigned d = 0; d < (1u << out.dim); ++d) {
        Vector x;
        for (int i = 0; i < out.dim; ++i) {
            const Rational& c = v[out.active[i]];
            x[out.active[i]] = ((d >> i) & 1u) ? Rational(-abs(c)) : Rational(abs(c));
        }
        out.directions.push_back(std::move(x));
    }
    const std::vector<Vector>& directions = out.directions;
    out.elements.reserve(scene.elements.size());
    for (const Element& e : scene.elements) {
        poll();
        if (!spans_start(e)) continue;
        LatticeElement le;
        le.source = static_cast<std::uint32_t>(&e - scene.elements.data());
        le.absorber = e.kind == ElementKind::absorber;
        for (int i = 0; i < out.dim; ++i) {
            if (out.active[i] == e.axis) le.axis = i;
            le.lo[i] = scaled(e.lo[out.active[i]], i);
            le.hi[i] = scaled(e.hi[out.active[i]], i);
            track(le.lo[i]);
            track(le.hi[i]);
        }
        // Scaling is by positive factors, so a mask's bit i set means a
        // negative component on scene axis active[i]: the acting rule is
        // asked about the scene direction itself, not a copy of it.
        le.acting = 0;
        for (unsigned d = 0; d < directions.size(); ++d)
            if (engine::acts_on(e, directions[d])) le.acting |= 1u << d;
        if (le.acting != (1u << (1u << out.dim)) - 1) out.one_sided = true;
        out.elements.push_back(std::move(le));
    }
    return out;
}

Vector LatticeScene::point(const Coords& p) const {
    Vector x;
    point_into(p, x);
    return x;
}

void LatticeScene::point_into(const Coords& p, Vector& x) const {
    for (int j = 0; j < scene->dim; ++j) // inactive coordinates never change
        if (ray->direction[j] == 0) x[j] = ray->start[j];
    for (int i = 0; i < dim; ++i) {
        const mpq_ptr q = x[active[i]].get_mpq_t();
        mpz_set(mpq_numref(q), p[i].get_mpz_t());
        mpz_set(mpq_denref(q), scale[i].get_mpz_t());
        mpq_canonicalize(q);
    }
}

bool LatticeScene::to_lattice(const Vector& x, Coords& out) const {
    for (int j = 0; j < scene->dim; ++j)
        if (ray->direction[j] == 0 && x[j] != ray->start[j]) return false;
    for (int i = 0; i < dim; ++i) {
        Rational r = x[active[i]] * scale[i];
        if (r.get_den() != 1) return false;
        out[i] = r.get_num();
    }
    return true;
}

} // namespace orthoray::lattice
