// The interval exchange of a 2D scene, as the induction engine builds and
// induces it (docs/induction.md), for studying, exporting and inducing it
// without solving.
//
// The first-return map of a 2D scene on its mirrors is an integer interval
// exchange: a bijection T of [0, N) that is a translation on each of k
// pieces. A state is a lattice point on a mirror with the diagonal direction
// (DX, DY) the ray leaves it in. Its transverse coordinate
//
//     w = DY * Y - DX * X
//
// is constant along a segment, and a reflection on the line X = c adds
// 2 * DX * c, one on Y = c subtracts 2 * DY * c: in w the step map is a pure
// translation. (A corner negates w; each state that runs into a corner gets
// a piece of its own.) So every state of one orbit has w in one class modulo
// G = gcd(2c) over the mirror offsets c, and numbering the states of a line
// segment in that class by increasing w turns each piece of the piece tables
// into a translation of consecutive integers.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <vector>

namespace orthoray {

// States on one axis-parallel line segment, with one direction: the points
// {coordinate axis = offset} x [lo, hi] whose w lies in the orbit's class,
// numbered 0 .. count - 1 by increasing w. Coordinates are lattice ones
// (scene coordinate * IntervalExchange::scale).
struct Transversal {
    int axis = 0; // 0: the line X = offset, 1: the line Y = offset
    Integer offset, lo, hi;
    unsigned negative = 0; // direction bits: bit j set moves towards -infinity on axis j
    Integer first, count;  // the least position in the class, and how many there are
    int w_slope = 1;       // w = w_slope * u + constant along the line
    Integer start;         // raw coordinate of its state number 0
};

// States of an octagonal scene (docs/induction-certificates.md, "Octagonal
// scenes") on one line, with one direction: the lattice points
// (x0 + i * step_x, y0 + i * step_y), i in [0, count), leaving along
// (dx, dy), numbered by i. Lattice coordinates are scene ones times the
// exchange's scale (the same on both axes).
struct LiftedTransversal {
    Integer x0, y0, step_x, step_y, count, dx, dy;
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
    // Octagonal scenes only (empty otherwise): the lifted states as lattice
    // points, laid end to end in raw coordinates (x is state first_index of
    // lifted[first_transversal]), and on a double cover x's other lift.
    std::vector<LiftedTransversal> lifted;
    std::optional<std::size_t> twin_transversal;
    Integer twin_index;
    // Octagonal scenes where two states step to one (docs/induction.md,
    // "Two states stepping to one"): (state, join) in rotated coordinates
    // for every state cut out of the exchange; its piece is a dead end
    // here, though the ray steps to the join.
    std::vector<std::pair<Integer, Integer>> cuts;
};

// The exchange the induction engine builds for `scene`: nothing unless the
// scene is 2D, its direction has two nonzero components, the ray reflects at
// least once, it can meet no one-sided element (two states could step to
// one), and the piece tables stay within the engine's size cap. For a
// scene with diagonal elements it is the exchange on the eight-sheeted
// cover (docs/induction.md, section 6), any direction allowed, with no
// `transversals` (its states are lifted states: `lifted` lists them) and
// one scale for both axes; nothing when two states step to one there, or
// when the scene has one-sided elements.
std::optional<IntervalExchange> exchange_of(const Scene& scene);

// The exchange as another interval-exchange library reads it
// (docs/induction.md, "Exporting the exchange"): its size, each piece
// (label, start, length, image, what happens there), and the two rows of
// labels in the order of the pieces' domains and of their images, which
// with the lengths are the usual two-row description of an exchange.
enum class ExchangeFormat { text, json };
void write_exchange(const IntervalExchange& exchange, std::ostream& out, ExchangeFormat format);

// Sees an induction: the exchange, then every step in the words of
// docs/induction-certificates.md (an accelerated step, a "cycle", is one
// call). Every callback does nothing unless overridden.
class InductionObserver {
public:
    virtual ~InductionObserver() = default;
    // The exchange, before the steps. Taking it in may be long (a
    // certificate writes every number in decimal: seconds at 10^6 digits),
    // so an observer asks `stopped` now and then and returns false as soon as
    // it says true, having kept nothing; the run then ends with that limit.
    virtual bool begin(const IntervalExchange&, const std::function<bool()>& /*stopped*/) {
        return true;
    }
    virtual void top(std::size_t /*d*/, std::size_t /*r*/) {}
    virtual void bottom(std::size_t /*r*/, std::size_t /*d*/) {}
    virtual void equal(std::size_t /*r*/, std::size_t /*d*/) {}
    virtual void invariant(std::size_t /*d*/) {}
    virtual void top_cycle(std::size_t /*d*/, const Integer& /*rounds*/) {}
    virtual void bottom_cycle(std::size_t /*r*/, const Integer& /*rounds*/) {}
    // Octagonal double covers only: the lifted orbit of x closed without an
    // event, and a second induction follows on the same exchange with x's
    // twin split off as a piece of its own and the only event
    // (docs/induction-certificates.md); its steps come next.
    virtual void twin_search() {}
    // Octagonal scenes where two states step to one: a new induction of the
    // walk between special states, on the exchange re-rooted at `from`
    // (rotated coordinates), marking every special state but `from` and the
    // target's states, or only the state `only`; its steps come next.
    virtual void walk_search(const Integer& /*from*/, const std::optional<Integer>& /*only*/) {}
};

// What comes first on the orbit of x.
enum class ExchangeEvent : std::uint8_t { none, hit, escape, absorbed };

// The orbit of x = 0 as the induction decides it. The event at T^offset(x)
// happens at the state after reflection offset + 1 of the ray; with no
// event, the orbit is a cycle of `period` reflections.
struct InducedOrbit {
    ExchangeEvent event = ExchangeEvent::none;
    Integer offset;           // the event happens at T^offset(x)
    Integer period;           // the return time of x (meaningful without an event)
    std::uint64_t steps = 0;  // steps taken, an accelerated one counting once
    std::uint64_t rounds = 0; // of which accelerated
    ArithmeticUsed arithmetic = ArithmeticUsed::int64; // the integers it ran on
};

// Rauzy induction with Zorich acceleration on `exchange` (docs/induction.md),
// calling `observer` (if any) with begin() and then every step.
InducedOrbit induce(const IntervalExchange& exchange, InductionObserver* observer = nullptr);

} // namespace orthoray
