// Random lattice scenes and query points for the next-hit structures' tests:
// coincident and overlapping elements, absorbers, and rays that start on
// element corners, on element planes, on box walls and outside the bounding
// box. Shared so that every structure is checked on the same kind of input.
#pragma once

#include "engine/event_rule.hpp"
#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "support/portable_random.hpp"

#include <algorithm>
#include <random>

namespace orthoray::test {

// Up to `max_elements` elements with coordinates in [-range, range] times
// `scale`, some of them copies of earlier ones (maybe turned into absorbers).
template <int M>
lattice::LatticeScene random_lattice_scene(std::mt19937_64& rng, int max_elements, int& range,
                                           const Integer& scale = 1) {
    lattice::LatticeScene ls;
    ls.dim = M;
    range = pick(rng, 2, 30);
    const int n = pick(rng, 1, max_elements);
    for (int i = 0; i < n; ++i) {
        if (i > 0 && pick(rng, 0, 7) == 0) {
            lattice::LatticeElement e = ls.elements[pick(rng, 0, i - 1)];
            if (pick(rng, 0, 1)) e.absorber = !e.absorber;
            ls.elements.push_back(e);
            continue;
        }
        lattice::LatticeElement e;
        e.axis = pick(rng, 0, M - 1);
        e.absorber = pick(rng, 0, 5) == 0;
        for (int j = 0; j < M; ++j) {
            const int a = pick(rng, -range, range), b = pick(rng, -range, range);
            e.lo[j] = Integer(scale * std::min(a, b));
            e.hi[j] = j == e.axis ? e.lo[j] : Integer(scale * (std::max(a, b) + (a == b)));
        }
        ls.elements.push_back(e);
    }
    return ls;
}

// A query point for `ls`: anywhere near the scene, on an element's corner,
// on an element's plane, or on walls of element boxes; sometimes shifted by
// one lattice unit.
template <class Int, int M>
void random_query_point(std::mt19937_64& rng, const lattice::LatticeScene& ls, int range,
                        const Integer& scale, Int (&p)[M]) {
    using lattice::from_integer;
    const int n = static_cast<int>(ls.elements.size());
    const int kind = pick(rng, 0, 3);
    for (int j = 0; j < M; ++j)
        p[j] = from_integer<Int>(Integer(scale * pick(rng, -range - 3, range + 3)));
    if (kind == 0) {
        const lattice::LatticeElement& e = ls.elements[pick(rng, 0, n - 1)];
        for (int j = 0; j < M; ++j) p[j] = from_integer<Int>(pick(rng, 0, 1) ? e.lo[j] : e.hi[j]);
    } else if (kind == 1) {
        const lattice::LatticeElement& e = ls.elements[pick(rng, 0, n - 1)];
        p[e.axis] = from_integer<Int>(e.lo[e.axis]);
    } else if (kind == 2) {
        for (int j = 0; j < M; ++j) {
            const lattice::LatticeElement& e = ls.elements[pick(rng, 0, n - 1)];
            p[j] = from_integer<Int>(pick(rng, 0, 1) ? e.lo[j] : e.hi[j]);
        }
    }
    if (pick(rng, 0, 9) == 0) p[pick(rng, 0, M - 1)] += pick(rng, 0, 1) ? Int(1) : Int(-1);
}

// A closed box [0, size]^M of mirrors with `obstacles` random elements inside
// (about one in eleven an absorber), for following whole trajectories.
template <int M>
lattice::LatticeScene random_box_scene(std::mt19937_64& rng, int obstacles, int size = 1000) {
    lattice::LatticeScene ls;
    ls.dim = M;
    for (int a = 0; a < M; ++a)
        for (int side = 0; side < 2; ++side) {
            lattice::LatticeElement wall;
            wall.axis = a;
            for (int j = 0; j < M; ++j) {
                wall.lo[j] = j == a ? side * size : 0;
                wall.hi[j] = j == a ? side * size : size;
            }
            ls.elements.push_back(wall);
        }
    for (int i = 0; i < obstacles; ++i) {
        lattice::LatticeElement e;
        e.axis = pick(rng, 0, M - 1);
        e.absorber = pick(rng, 0, 10) == 0;
        for (int j = 0; j < M; ++j) {
            const int a = pick(rng, 1, size - 1), b = std::min(size - 1, a + pick(rng, 1, 120));
            e.lo[j] = a;
            e.hi[j] = j == e.axis ? a : b;
        }
        ls.elements.push_back(e);
    }
    return ls;
}

// Makes about `percent` percent of the elements one-sided (either sign),
// their acting masks asked of engine/event_rule's acts_on with the
// direction of each mask (the lattice's axes are the scene's here).
template <int M>
void make_one_sided(std::mt19937_64& rng, lattice::LatticeScene& ls, int percent) {
    for (lattice::LatticeElement& e : ls.elements) {
        if (!chance(rng, percent)) continue;
        Element element;
        element.axis = e.axis;
        element.side = chance(rng, 50) ? Side::plus : Side::minus;
        e.acting = 0;
        for (unsigned d = 0; d < (1u << M); ++d) {
            Vector v;
            for (int j = 0; j < M; ++j) v[j] = ((d >> j) & 1u) ? -1 : 1;
            if (engine::acts_on(element, v)) e.acting |= 1u << d;
        }
        ls.one_sided = true;
    }
}

} // namespace orthoray::test
