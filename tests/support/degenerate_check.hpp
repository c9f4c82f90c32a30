// Hand-traced degenerate scenes (test_degenerate*.cpp): each is solved by
// every engine and option and must give its derived answer, with verified
// certificates and an injective state graph.
#pragma once

#include "orthoray/answer.hpp"

namespace orthoray::test {

// A hand-traced scene and its answer: `reason` and `reflections` (the period
// for a cycle). With `graph_fits` false the scene has too many lattice
// states for the graph engine, which must then refuse (Reason::limit)
// rather than answer.
struct Degenerate {
    const char* text;
    Reason reason;
    unsigned long reflections;
    bool graph_fits = true;
};

// Solves the scene with every engine, arithmetic and cycle detector and
// demands its answer; the certificates of the simulation engines must
// verify, and the state graph must be injective.
void expect(const Degenerate& degenerate);

} // namespace orthoray::test
