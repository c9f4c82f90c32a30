// Deterministic benchmark scenes, built in code as orthoray::Scene.
//
// Every random choice comes from std::mt19937_64 (whose output sequence the
// C++ standard fixes) mapped to a range with integer arithmetic only, never
// through std::uniform_int_distribution (whose algorithm each standard
// library picks for itself). So one seed gives the same scene on every
// compiler and machine.
#pragma once

#include "orthoray/generate.hpp"
#include "orthoray/scene.hpp"

#include <cstdint>
#include <random>

namespace orthoray::bench {

// The side of the random boxes: coordinates are integers in [0, box_side].
inline constexpr std::int64_t box_side = 1'000'000;

// The library's deterministic integer sampling (orthoray/generate.hpp).
using orthoray::integer_root;
using orthoray::uniform;

// The closed mirror box [0, box_side]^dim (2*dim faces) plus n random
// mirrors with integer coordinates inside it. A mirror has a random normal
// axis, a random offset in [1, box_side - 1] and, on each other axis, a
// random length in [s/2, s] with s = box_side / floor(n^(1/dim)), so the
// mirrors are about as long as the gaps between them and crossings stay
// rare (in 2D about n/7 crossings are expected, against n^2/4 pairs). The
// ray starts at a random interior integer point on no mirror, with direction
// (1001, 1000) or (1001, 1000, 999): generic, and fine enough that the
// orbit's period exceeds the benchmark's step counts (with (3, 5) the 2D
// orbits close after only about 10^6 reflections for n >= 10^3).
//
// The target is an interior integer point that is provably never reached.
// Scaled to the lattice (docs/lattice.md), axis j is multiplied by
// f_j = lcm(u) / |u_j|, and along a diagonal ray X_0 + X_1 mod 2 never
// changes (each step moves every coordinate by the same t). The target is
// chosen with f_0 x_0 + f_1 x_1 of the other parity than the start's. With
// no absorbers either, a run only ends at its step cap (or in a cycle).
//
// `side` replaces box_side for benches whose coordinates grow (up to 10^18;
// the library's `random` family stops at 2^40).
Scene random_box(int dim, std::int64_t n, std::uint64_t seed, std::int64_t side = box_side);

// The m x n mirror box shot from the corner (0, 0) at 45 degrees, target
// (m, n). With gcd(m, n) = 1 the ray first meets a corner after m + n - 2
// reflections: (m, n) itself when m and n are both odd (a hit); otherwise
// another corner, where it turns back, and the answer is a cycle of period
// 2(m + n - 1) that never passes (m, n).
Scene box_corner(std::int64_t m, std::int64_t n);

// The 3D version: the m x n x k box from (0, 0, 0) along (1, 1, 1), target
// (m, n, k).
Scene box_corner_3d(std::int64_t m, std::int64_t n, std::int64_t k);

// The unit square scaled by 8 to [0, 8]^2, shot with slope p/q (direction
// (q, p)) from the generic point (4, 2) (that is (1/2, 1/4) in the unit
// square), target (4, 4). For odd q the ray meets no corner and never
// reaches the target; it cycles with period 2(p + q) when gcd(p, q) = 1.
Scene unit_square(std::int64_t p, std::int64_t q);

// A small random scene, for counting float-vs-exact disagreements: a side of
// 2^k with k in [side_log_lo, side_log_hi], min_elements to max_elements
// elements with integer coordinates and lengths up to side / 2 (one in ten
// an absorber if `absorbers`), a closed box [0, side]^dim around them half
// of the time or always (with `absorbers`, a quarter of the boxes have an
// absorbing face), a random integer start and a random integer direction
// with components in [-max_direction, max_direction] (rarely a zero one).
// The target is left at the start: the caller chooses it.
struct SmallShape {
    int side_log_lo = 4, side_log_hi = 10;
    std::int64_t max_direction = 10;
    std::int64_t min_elements = 2, max_elements = 30;
    bool always_box = false, absorbers = true;
};
Scene random_small(std::mt19937_64& rng, int dim, const SmallShape& shape);

// The classic failure of a float tracer with a scene-relative epsilon: the
// ray of slope 999999/1000000 passes 10^-6 above the top end of a mirror
// and reaches the target behind it (exact: yes, hit, 0 reflections), but
// 10^-6 is below the epsilon (10^-3 here), so the float tracer reflects off
// the mirror's end and escapes.
Scene float_wrong_near_miss();

} // namespace orthoray::bench
