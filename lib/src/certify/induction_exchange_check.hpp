// Checks 1 and 2 of docs/induction-certificates.md: the header (point 1 and
// its direction, the scale) and the transversals (non-empty, pairwise
// disjoint state sets, every state on a mirror, `first` naming state 1).
// What they establish is returned in lattice coordinates for the piece
// checks. Checker code only.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include "certify/induction_certificate_parse.hpp"
#include "certify/induction_piece_geometry.hpp"
#include "certify/induction_verifier.hpp"

#include <vector>

namespace orthoray::certify::induction_check {

// The certificate's exchange in lattice coordinates, once checked.
struct LatticeExchange {
    int first_dx = 1, first_dy = 1; // the diagonal direction the ray leaves point 1 in
    Integer first_x, first_y;       // point 1
    Integer target_x, target_y;
    Integer first_class; // w = DY * Y - DX * X of point 1: every state's w is in its class
    Integer modulus;     // G, the class's modulus (0: w itself)
    std::vector<LatticeElement> elements;
    std::vector<Transversal> transversals; // in certificate order, with their offsets
    Integer state_count;                   // N
    Integer first_raw;                     // x's raw number (transversal offset + index)
};

// The lattice coordinate u of state `index` of `t`.
Integer state_position(const Transversal& t, const Integer& index, const Integer& modulus);

// Checks 1 and 2; throws CheckFailure at the first failure.
LatticeExchange check_header_and_transversals(const Scene& scene, const PathPrefix& prefix,
                                              const Parsed& parsed);

} // namespace orthoray::certify::induction_check
