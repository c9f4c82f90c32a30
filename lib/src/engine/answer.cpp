#include "orthoray/answer.hpp"

namespace orthoray {

const char* to_string(Reason reason) {
    switch (reason) {
    case Reason::hit:
        return "hit";
    case Reason::escape:
        return "escape";
    case Reason::absorbed:
        return "absorbed";
    case Reason::cycle:
        return "cycle";
    case Reason::limit:
        return "limit";
    case Reason::lit:
        return "lit";
    case Reason::unlit:
        return "unlit";
    }
    return "?";
}

const char* to_string(Limit limit) {
    switch (limit) {
    case Limit::steps:
        return "steps";
    case Limit::time:
        return "time";
    case Limit::memory:
        return "memory";
    case Limit::interrupt:
        return "interrupt";
    }
    return "?";
}

const char* to_string(EngineUsed engine) {
    switch (engine) {
    case EngineUsed::none:
        return "";
    case EngineUsed::lattice:
        return "lattice";
    case EngineUsed::induction:
        return "induction";
    case EngineUsed::reference:
        return "reference";
    case EngineUsed::branches:
        return "branches";
    case EngineUsed::graph:
        return "graph";
    }
    return "?";
}

const char* to_string(ArithmeticUsed arithmetic) {
    switch (arithmetic) {
    case ArithmeticUsed::none:
        return "none";
    case ArithmeticUsed::int64:
        return "int64";
    case ArithmeticUsed::int128:
        return "int128";
    case ArithmeticUsed::gmp:
        return "gmp";
    case ArithmeticUsed::rational:
        return "rational";
    }
    return "?";
}

const char* to_string(ShooterUsed shooter) {
    switch (shooter) {
    case ShooterUsed::none:
        return "";
    case ShooterUsed::grid:
        return "grid";
    case ShooterUsed::bvh:
        return "bvh";
    case ShooterUsed::section:
        return "section";
    case ShooterUsed::pieces:
        return "pieces";
    }
    return "?";
}

const char* answer_word(const Answer& answer) {
    if (!answer.decided()) return "unknown";
    return answer.yes() ? "yes" : "no";
}

} // namespace orthoray
