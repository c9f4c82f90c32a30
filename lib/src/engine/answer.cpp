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

const char* answer_word(const Answer& answer) {
    if (!answer.decided()) return "unknown";
    return answer.yes() ? "yes" : "no";
}

} // namespace orthoray
