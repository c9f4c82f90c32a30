#include "engine/event_rule.hpp"

namespace orthoray::engine {

bool acts_on(const Element& element, const Vector& v) {
    return element.acts_on_sign(sgn(v[element.axis]));
}

EventOutcome event_outcome(int dim, const std::vector<const Element*>& acting, const Vector& v) {
    EventOutcome outcome;
    unsigned reflecting = 0, splitting = 0;
    for (const Element* e : acting) {
        switch (e->kind) {
        case ElementKind::absorber:
            outcome.absorbed = true;
            break;
        case ElementKind::mirror:
            reflecting |= 1u << e->axis;
            break;
        case ElementKind::splitter:
            splitting |= 1u << e->axis;
            break;
        }
    }
    if (outcome.absorbed) return outcome;
    // A mirror on an axis wins over a splitter on the same axis.
    splitting &= ~reflecting;
    // Every subset of the splitting axes, the empty one first.
    for (unsigned extra = 0;; extra = (extra - splitting) & splitting) {
        const unsigned flipped = reflecting | extra;
        Outgoing out{v, flipped != 0};
        for (int j = 0; j < dim; ++j)
            if (flipped & (1u << j)) out.direction[j] = -v[j];
        outcome.outgoing.push_back(out);
        if (extra == splitting) break;
    }
    return outcome;
}

} // namespace orthoray::engine
