// Check 3 of docs/induction-certificates.md: the pieces' domains and images
// tile [0, N), and each piece's claim (next state, escape, absorption, hit
// flag) holds for all its states at once, in O(elements) per piece whatever
// its length (induction_piece_geometry.hpp). Checker code only.
#pragma once

#include "certify/induction_certificate_parse.hpp"
#include "certify/induction_exchange_check.hpp"

#include <vector>

namespace orthoray::certify::induction_check {

// The domains tile [0, n) in order, piece 0 is [0, 1), and the images tile
// [0, n): throws CheckFailure otherwise.
void check_tiling(const std::vector<PieceSpec>& pieces, const Integer& n);

// Throws CheckFailure at the first piece whose claim fails.
void check_pieces(const LatticeExchange& exchange, const std::vector<PieceSpec>& pieces);

} // namespace orthoray::certify::induction_check
