// The piece checks of an octagonal induction certificate
// (docs/induction-certificates.md, "Octagonal scenes"): the states of a
// transversal are lattice points Q(j) = Q0 + j * step with one direction d,
// so the time at which the ray from Q(j) meets an element's line is a
// ratio A(j) / B with A affine in j and B > 0 fixed, and the states meeting
// the element form an interval of j found by exact floor and ceiling
// divisions. Comparing two such times over an interval needs only its two
// ends. Checker code only.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include "certify/induction_certificate_parse.hpp"

#include <cstddef>
#include <vector>

namespace orthoray::certify::induction_check {

// `lifted X0 Y0 SX SY COUNT DX DY`: the states (X0 + i SX, Y0 + i SY),
// i in [0, COUNT), leaving along (DX, DY); `offset` is the raw coordinate
// of state 0.
struct LiftedSpec {
    Integer x0, y0, sx, sy, count, dx, dy;
    Integer offset;
};

// An element in lattice coordinates: the points X with n . X = c and
// m . X in [lo, hi] (m along the line). Orientation 0: x = c, 1: y = c,
// 2: '/' (y - x = c), 3: '\' (y + x = c).
struct OctagonalElement {
    int orientation = 0;
    Integer nx, ny, c, mx, my, lo, hi;
    bool absorber = false;
    const Element* source = nullptr;
};

struct OctagonalExchange {
    std::vector<OctagonalElement> elements;
    std::vector<LiftedSpec> transversals;
    Integer state_count, first_raw;
    Integer target_x, target_y;
};

// Tiling and every piece's claim; throws CheckFailure at the first failure.
void check_octagonal_pieces(const OctagonalExchange& exchange,
                            const std::vector<PieceSpec>& pieces);

} // namespace orthoray::certify::induction_check
