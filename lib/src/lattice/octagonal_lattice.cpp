#include "lattice/octagonal_lattice.hpp"

#include "engine/event_rule.hpp"
#include "lattice/scaling.hpp"

#include <algorithm>
#include <stdexcept>

namespace orthoray::lattice {
namespace {

Integer abs_of(const Integer& a) {
    return a < 0 ? Integer(-a) : a;
}

// Direction d applied to any pair: swap (bit 2), then negate x (bit 0), y (bit 1).
template <class T>
std::array<T, 2> oriented(const T& x, const T& y, unsigned d) {
    std::array<T, 2> r = (d & 4u) ? std::array<T, 2>{y, x} : std::array<T, 2>{x, y};
    if (d & 1u) r[0] = -r[0];
    if (d & 2u) r[1] = -r[1];
    return r;
}

Orientation orientation_of(const Element& e) {
    if (e.diagonal == Diagonal::rising) return rising;
    if (e.diagonal == Diagonal::falling) return falling;
    return e.axis == 0 ? normal_x : normal_y;
}

// Whether a line of this orientation is crossed by direction w (not parallel).
bool crosses(Orientation o, const std::array<Integer, 2>& w) {
    switch (o) {
    case normal_x:
        return w[0] != 0;
    case normal_y:
        return w[1] != 0;
    case rising:
        return w[0] != w[1];
    case falling:
        return w[0] != -w[1];
    }
    return false;
}

// An element of each orientation and kind, for asking the event rule.
Element representative(Orientation o, ElementKind kind) {
    Element e;
    e.kind = kind;
    if (o == rising || o == falling) {
        e.axis = -1;
        e.diagonal = o == rising ? Diagonal::rising : Diagonal::falling;
    } else {
        e.axis = o == normal_x ? 0 : 1;
    }
    return e;
}

} // namespace

OctagonalLattice make_octagonal_lattice(const Scene& scene, const SetupPoll& poll,
                                        std::size_t ray_index) {
    if (scene.dim != 2) throw std::invalid_argument("diagonal elements are 2D only");
    OctagonalLattice out;
    out.scene = &scene;
    out.ray = &scene.rays.at(ray_index);
    const Vector& v = out.ray->direction;

    // The primitive integer direction u = (a, b).
    const Integer vden = lcm(v[0].get_den(), v[1].get_den());
    Integer a = v[0].get_num() * (vden / v[0].get_den());
    Integer b = v[1].get_num() * (vden / v[1].get_den());
    const Integer g = gcd(a, b);
    a /= g;
    b /= g;
    for (unsigned d = 0; d < direction_count; ++d) out.w[d] = oriented(a, b, d);
    for (unsigned d = 0; d < direction_count; ++d) {
        unsigned least = 0;
        while (out.w[least] != out.w[d]) ++least;
        out.canonical[d] = static_cast<std::uint8_t>(least);
        if (least == d) ++out.distinct_directions;
    }

    // N: every f(w) divides it (see the header).
    Integer N = 1;
    for (const Integer& f : {a, b, Integer(a - b), Integer(a + b)})
        if (f != 0) N = lcm(N, abs_of(f));
    // D: the lcm of every denominator in the scene.
    Integer D = 1;
    auto take = [&](const Vector& x) {
        for (int j = 0; j < 2; ++j)
            if (!is_integer(x[j])) D = lcm(D, x[j].get_den());
    };
    take(out.ray->start);
    take(scene.target());
    for (const Element& e : scene.elements) {
        poll();
        take(e.lo);
        take(e.hi);
    }
    out.modulus = N;
    out.scale = N * D;

    Integer largest = 0;
    const Scaling scaling(out.scale);
    auto scaled = [&](const Rational& x) {
        Integer r = scaling(x);
        if (mpz_cmpabs(r.get_mpz_t(), largest.get_mpz_t()) > 0) largest = abs_of(r);
        return r;
    };
    for (int j = 0; j < 2; ++j) {
        out.start[j] = scaled(out.ray->start[j]);
        out.target[j] = scaled(scene.target()[j]);
    }
    // The eight directions, built once: each element is asked about every
    // one of them, and a direction is a vector of rationals.
    std::array<Vector, direction_count> directions;
    for (unsigned d = 0; d < direction_count; ++d) directions[d] = out.direction(d);
    out.elements.reserve(scene.elements.size());
    for (const Element& e : scene.elements) {
        poll();
        OctagonalElement le;
        le.absorber = e.kind == ElementKind::absorber;
        le.orientation = orientation_of(e);
        for (int j = 0; j < 2; ++j) {
            le.lo[j] = scaled(e.lo[j]);
            le.hi[j] = scaled(e.hi[j]);
        }
        switch (le.orientation) {
        case normal_x:
            le.offset = le.lo[0];
            break;
        case normal_y:
            le.offset = le.lo[1];
            break;
        case rising: // through (lo.x, lo.y): x - y
            le.offset = le.lo[0] - le.lo[1];
            break;
        case falling: // through (lo.x, hi.y): x + y
            le.offset = le.lo[0] + le.hi[1];
            break;
        }
        // The scale is positive, so the acting rule is asked about the
        // scene's own direction d.
        for (unsigned d = 0; d < direction_count; ++d)
            if (engine::acts_on(e, directions[d])) le.acting |= 1u << d;
        out.elements.push_back(std::move(le));
    }
    out.magnitude = largest * std::max(abs_of(a), abs_of(b));
    return out;
}

// Every combination of orientations that cross direction d, asked of the
// acting rule with one representative element of each.
OctagonalOutcomes::OctagonalOutcomes(const OctagonalLattice& lattice) {
    std::array<Element, 4> mirror, absorber;
    for (unsigned o = 0; o < 4; ++o) {
        mirror[o] = representative(Orientation(o), ElementKind::mirror);
        absorber[o] = representative(Orientation(o), ElementKind::absorber);
    }
    table_.fill(absorbed);
    for (unsigned d = 0; d < direction_count; ++d) {
        unsigned crossing = 0;
        for (unsigned o = 0; o < 4; ++o)
            if (crosses(Orientation(o), lattice.w[d])) crossing |= 1u << o;
        const Vector v = lattice.direction(d);
        for (unsigned m = 0; m < 16; ++m)
            for (unsigned a = 0; a < 16; ++a) {
                if ((m | a) == 0 || ((m | a) & ~crossing) != 0) continue;
                std::vector<const Element*> acting;
                for (unsigned o = 0; o < 4; ++o) {
                    if (m & (1u << o)) acting.push_back(&mirror[o]);
                    if (a & (1u << o)) acting.push_back(&absorber[o]);
                }
                const engine::EventOutcome outcome = engine::event_outcome(2, acting, v);
                if (outcome.absorbed) continue;
                const Vector& leaving = outcome.outgoing.front().direction;
                for (unsigned e = 0; e < direction_count; ++e)
                    if (lattice.direction(e) == leaving) {
                        table_[(d * 16 + m) * 16 + a] = lattice.canonical[e];
                        break;
                    }
            }
    }
}

Vector OctagonalLattice::point(const Coords& p) const {
    Vector x;
    for (int j = 0; j < 2; ++j) {
        x[j] = Rational(p[j], scale);
        x[j].canonicalize();
    }
    return x;
}

Vector OctagonalLattice::direction(unsigned d) const {
    const Vector& v = ray->direction;
    const std::array<Rational, 2> r = oriented(v[0], v[1], d);
    return {r[0], r[1], Rational(0)};
}

} // namespace orthoray::lattice
