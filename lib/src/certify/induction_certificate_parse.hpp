// The statements of an induction certificate after `method`, read into
// plain data (docs/induction-certificates.md): the exchange, the steps one
// at a time, and the verdict. Pure parsing: the checks are in
// induction_verifier.cpp.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include "certify/certificate_reader.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace orthoray::certify::induction_check {

// `cut` (octagonal walk certificates only): a state of its own that the
// exchange closes like a dead end, though the ray steps to `join`.
enum class Kind { reflect, escape, absorbed, cut };

enum class StepKind { top, bottom, equal, invariant, top_cycle, bottom_cycle };

struct TransversalSpec {
    int a = 0; // 0: the line X = C, 1: the line Y = C
    Integer c, lo, hi;
    int dx = 1, dy = 1;
};

struct PieceSpec {
    Integer start, length, image;
    Integer join; // a cut piece's
    Kind kind = Kind::reflect;
    bool hit = false;
};

struct StepSpec {
    StepKind kind = StepKind::top;
    Integer first, second;
};

// The step as written, for messages.
inline std::string step_text(const StepSpec& s) {
    static constexpr const char* names[] = {"top",       "bottom",    "equal",
                                            "invariant", "top-cycle", "bottom-cycle"};
    // Appended piece by piece: inlined into a caller, GCC 12 misreads
    // std::string + std::string as an overlapping copy (-Wrestrict).
    std::string text = "step ";
    text += names[static_cast<int>(s.kind)];
    text += ' ';
    text += s.first.get_str();
    if (s.kind != StepKind::invariant) {
        text += ' ';
        text += s.second.get_str();
    }
    return text;
}

struct Parsed {
    Vector v1;
    Rational sx, sy;
    Integer modulus;
    std::vector<TransversalSpec> transversals;
    Integer first_t, first_i;
    std::vector<PieceSpec> pieces;
    std::size_t steps = 0; // how many `step` lines were read
    std::string answer;
    Reason reason = Reason::cycle;
    Integer reflections, period;
};

// Everything up to the last piece; `in` is left on the statement after it.
Parsed parse_exchange(CertificateReader& in, int dim);
// The `piece` statements from the one `in` is on (at least one); `in` is
// left on the statement after them.
std::vector<PieceSpec> parse_pieces(CertificateReader& in);
// The `step` statement `in` is on.
StepSpec parse_step(const CertificateReader& in);
// The verdict from `answer` to `end` (the stream must end there) into `p`.
void parse_verdict(CertificateReader& in, Parsed& p);

} // namespace orthoray::certify::induction_check
