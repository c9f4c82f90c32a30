// An element as the next-hit structures store it: its closed box in the
// integer type they compute with, and what it does to a ray.
#pragma once

#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"

#include <cstdint>

namespace orthoray::shoot {

// The lattice vocabulary every next-hit structure is written in.
using lattice::floor_div;
using lattice::from_integer;
using lattice::LatticeElement;
using lattice::LatticeScene;
using lattice::to_index;
using lattice::to_integer;

template <class Int, int M>
struct ElementBox {
    Int lo[M], hi[M];    // closed box; lo == hi on the normal axis
    std::uint32_t index; // in the lattice scene
    std::uint8_t axis;   // normal axis
    bool absorber;
    std::uint8_t acting; // LatticeElement::acting: the direction masks it acts on

    ElementBox(const LatticeElement& e, std::uint32_t scene_index)
        : index(scene_index), axis(static_cast<std::uint8_t>(e.axis)), absorber(e.absorber),
          acting(static_cast<std::uint8_t>(e.acting)) {
        for (int j = 0; j < M; ++j) {
            lo[j] = from_integer<Int>(e.lo[j]);
            hi[j] = from_integer<Int>(e.hi[j]);
        }
    }

    bool acts_on(unsigned negative) const { return (acting >> negative) & 1u; }

    // Whether the point p + t * sigma lies in the box. When t was taken
    // from the element's plane the point is exactly the offset on the
    // normal axis, so testing every axis needs no exception for it; the
    // test has no branches, since which side fails is unpredictable.
    bool holds(const Int (&p)[M], const Int (&sigma)[M], const Int& t) const {
        int inside = 1;
        for (int j = 0; j < M; ++j) {
            const Int x = p[j] + sigma[j] * t;
            inside &= static_cast<int>(!(x < lo[j])) & static_cast<int>(!(hi[j] < x));
        }
        return inside != 0;
    }
};

} // namespace orthoray::shoot
