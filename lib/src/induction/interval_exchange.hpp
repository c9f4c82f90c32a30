// The first-return map of a 2D scene on its mirrors, as an integer interval
// exchange: a bijection T of [0, N) that is a translation on each of k
// pieces. docs/induction.md derives it; this is the data it ends up as.
//
// A state is a lattice point on a mirror with the diagonal direction
// (DX, DY) the ray leaves it in. Its transverse coordinate
//
//     w = DY * Y - DX * X
//
// is constant along a segment, and a reflection on the line X = c adds
// 2 * DX * c, one on Y = c subtracts 2 * DY * c: in w the step map is a pure
// translation. (A corner negates w; the builder gives each state that runs
// into a corner a piece of its own.)
// So every state of one orbit has w in one class modulo G = gcd(2c) over
// the mirror offsets c, and numbering the states of a line segment in that
// class by increasing w turns each piece of the piece tables into a
// translation of consecutive integers.
#pragma once

#include "orthoray/number.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace orthoray::induction {

// States on one axis-parallel line segment, with one direction: the points
// {coordinate axis = offset} x [lo, hi] whose w lies in the orbit's class,
// numbered 0 .. count - 1 by increasing w.
struct Transversal {
    int axis = 0; // 0: the line X = offset, 1: the line Y = offset
    Integer offset, lo, hi;
    unsigned negative = 0; // direction bits: bit j set moves towards -infinity on axis j
    Integer first, count;  // the least position in the class, and how many there are
    int w_slope = 1;       // w = w_slope * u + constant along the line
    Integer start;         // raw coordinate of its state number 0
};

enum class PieceKind : std::uint8_t {
    reflect,  // the ray reflects at the image state
    escape,   // the ray meets nothing: the image only closes the exchange
    absorbed, // the ray stops at an absorber: likewise
};

// [start, start + length) -> [image, image + length), in rotated coordinates.
struct ExchangePiece {
    Integer start, length, image;
    PieceKind kind = PieceKind::reflect;
    bool hit = false; // the segment after each of its states passes the target
};

struct IntervalExchange {
    Integer scale[2]; // lattice = scene coordinate * scale, per axis
    Integer modulus;  // G (0: w itself is invariant)
    std::vector<Transversal> transversals;
    std::size_t first_transversal = 0; // x, the state after reflection 1:
    Integer first_index;               // its transversal and number there
    Integer size;                      // N, the number of states
    // Rotated so that x is 0, sorted by start; pieces[0] is x alone.
    std::vector<ExchangePiece> pieces;
};

} // namespace orthoray::induction
