#include "certify/induction_certificate_parse.hpp"

namespace orthoray::certify::induction_check {
namespace {

Integer read_integer(const CertificateReader& in, std::size_t index) {
    const Rational q = in.number(index);
    if (q.get_den() != 1) in.fail(index, "an integer");
    return q.get_num();
}

int read_sign(const CertificateReader& in, std::size_t index) {
    const Integer v = read_integer(in, index);
    if (v == 1) return 1;
    if (v == -1) return -1;
    in.fail(index, "1 or -1");
}

} // namespace

// The `piece` statements from the one `in` is on; at least one.
std::vector<PieceSpec> parse_pieces(CertificateReader& in) {
    std::vector<PieceSpec> pieces;
    while (in.keyword() == "piece") {
        if (in.size() < 5)
            in.fail(in.size(), in.size() == 4 ? "a non-negative integer" : "a value");
        PieceSpec piece;
        piece.start = in.count(1);
        piece.length = in.count(2);
        if (in.token(3) == "reflect")
            piece.kind = Kind::reflect;
        else if (in.token(3) == "escape")
            piece.kind = Kind::escape;
        else if (in.token(3) == "absorbed")
            piece.kind = Kind::absorbed;
        else if (in.token(3) == "cut")
            piece.kind = Kind::cut;
        else
            in.fail(3, "reflect, escape, absorbed or cut");
        piece.image = in.count(4);
        std::size_t next = 5; // `cut` has its join here
        if (piece.kind == Kind::cut) {
            if (in.size() < 6) in.fail(5, "a non-negative integer");
            piece.join = in.count(5);
            next = 6;
        }
        if (in.size() > next + 1) in.fail(next + 1, in.end_of_statement());
        if (in.size() == next + 1) {
            if (in.token(next) != "hit")
                in.fail(next, std::string("'hit' or ") + in.end_of_statement());
            piece.hit = true;
        }
        pieces.push_back(std::move(piece));
        in.advance();
    }
    if (pieces.empty()) in.fail(0, "'piece'");
    return pieces;
}

// Everything up to the last piece; `in` is left on the statement after it.
Parsed parse_exchange(CertificateReader& in, int dim) {
    Parsed p;
    in.expect("method", 1, "'induction'");
    if (in.token(1) != "induction") in.fail(1, "'induction'");
    in.advance();
    in.expect("direction", dim, "a number");
    p.v1 = in.vector(1, dim);
    in.advance();
    in.expect("scale", 2, "a number");
    p.sx = in.number(1);
    p.sy = in.number(2);
    in.advance();
    in.expect("modulus", 1, "a non-negative integer");
    p.modulus = in.count(1);
    in.advance();
    while (in.keyword() == "transversal") {
        in.expect("transversal", 6, "an integer");
        TransversalSpec t;
        const Integer a = read_integer(in, 1);
        if (a != 0 && a != 1) in.fail(1, "0 or 1 (the line X = C or Y = C)");
        t.a = a == 0 ? 0 : 1;
        t.c = read_integer(in, 2);
        t.lo = read_integer(in, 3);
        t.hi = read_integer(in, 4);
        t.dx = read_sign(in, 5);
        t.dy = read_sign(in, 6);
        p.transversals.push_back(std::move(t));
        in.advance();
    }
    if (p.transversals.empty()) in.fail(0, "'transversal'");
    in.expect("first", 2, "a non-negative integer");
    p.first_t = in.count(1);
    p.first_i = in.count(2);
    in.advance();
    p.pieces = parse_pieces(in);
    return p;
}

// The `step` statement `in` is on.
StepSpec parse_step(const CertificateReader& in) {
    if (in.size() < 2) in.fail(1, "top, bottom, equal, invariant, top-cycle or bottom-cycle");
    StepSpec s;
    const std::string_view kind = in.token(1);
    std::size_t operands = 2;
    if (kind == "top")
        s.kind = StepKind::top;
    else if (kind == "bottom")
        s.kind = StepKind::bottom;
    else if (kind == "equal")
        s.kind = StepKind::equal;
    else if (kind == "invariant")
        s.kind = StepKind::invariant, operands = 1;
    else if (kind == "top-cycle")
        s.kind = StepKind::top_cycle;
    else if (kind == "bottom-cycle")
        s.kind = StepKind::bottom_cycle;
    else
        in.fail(1, "top, bottom, equal, invariant, top-cycle or bottom-cycle");
    if (in.size() < operands + 2) in.fail(in.size(), "a non-negative integer");
    if (in.size() > operands + 2) in.fail(operands + 2, in.end_of_statement());
    s.first = in.count(2);
    if (operands == 2) s.second = in.count(3);
    return s;
}

// The verdict, from `answer` to `end`.
void parse_verdict(CertificateReader& in, Parsed& p) {
    if (in.keyword() != "answer") in.fail(0, "'step' or 'answer'");
    in.expect("answer", 1, "yes, no or unknown");
    p.answer = std::string(in.token(1));
    if (p.answer != "yes" && p.answer != "no" && p.answer != "unknown")
        in.fail(1, "yes, no or unknown");
    in.advance();
    in.expect("reason", 1, "hit, escape, absorbed, cycle or limit");
    {
        static constexpr Reason all[] = {Reason::hit, Reason::escape, Reason::absorbed,
                                         Reason::cycle, Reason::limit};
        bool known = false;
        for (Reason r : all)
            if (in.token(1) == to_string(r)) {
                p.reason = r;
                known = true;
            }
        if (!known) in.fail(1, "hit, escape, absorbed, cycle or limit");
    }
    in.advance();
    in.expect("reflections", 1, "a non-negative integer");
    p.reflections = in.count(1);
    if (p.reason == Reason::cycle) {
        in.advance();
        in.expect("period", 1, "a non-negative integer");
        p.period = in.count(1);
    }
    if (p.reason == Reason::limit) { // the solver was stopped while writing the steps
        in.advance();
        in.expect("partial", 0, in.end_of_statement());
    }
    in.advance();
    in.expect("end", 0, in.end_of_statement());
    if (in.next()) in.fail(0, "end of file (nothing may follow 'end')");
}

} // namespace orthoray::certify::induction_check
