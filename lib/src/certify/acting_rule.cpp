// The checkers' first acting event and outgoing directions; see
// acting_rule.hpp.
#include "certify/acting_rule.hpp"

namespace orthoray::certify {

bool acts_on(const Element& element, const Vector& v) {
    const int s = sgn(v[element.axis]);
    switch (element.side) {
    case Side::both:
        return s != 0;
    case Side::plus: // the + side faces rays moving toward -axis
        return s < 0;
    case Side::minus:
        return s > 0;
    }
    return false;
}

Event first_met(const Scene& scene, const Vector& p, const Vector& v) {
    Event best;
    std::array<bool, 3> splitter{};
    Rational t, q;
    for (const Element& e : scene.elements) {
        if (!acts_on(e, v)) continue; // invisible: not even an event
        const int k = e.axis;
        // Nothing happens at t = 0 (a start point on a mirror does not reflect):
        // t = (offset - p_k) / v_k must be positive, which its sign tells
        // before the division (about half the elements are behind the ray).
        q = e.lo[k] - p[k];
        if (sgn(q) * sgn(v[k]) <= 0) continue;
        t = q / v[k];
        if (best.met && t > best.t) continue;
        bool inside = true;
        for (int j = 0; j < scene.dim && inside; ++j) {
            if (j == k) continue; // on the element's plane by the choice of t
            q = p[j] + t * v[j];
            inside = e.lo[j] <= q && q <= e.hi[j]; // closed: edges and corners count
        }
        if (!inside) continue;
        if (!best.met || t < best.t) {
            best = Event{};
            splitter = {};
            best.met = true;
            best.t = t;
        }
        // Every acting element at the same t takes part: any absorber stops
        // the ray, mirrors of one axis negate that component once.
        switch (e.kind) {
        case ElementKind::absorber:
            best.absorbed = true;
            break;
        case ElementKind::mirror:
            best.flip[k] = true;
            break;
        case ElementKind::splitter:
            splitter[k] = true;
            break;
        }
    }
    // A mirror and a splitter of one axis at one point reflect, as the
    // mirror alone would: only axes without a mirror split.
    for (int j = 0; j < 3; ++j) best.split[j] = splitter[j] && !best.flip[j];
    return best;
}

std::vector<Vector> outgoing(const Vector& v, const Event& event, int dim) {
    std::vector<Vector> result;
    if (!event.met || event.absorbed) return result;
    Vector base = v;
    for (int j = 0; j < dim; ++j)
        if (event.flip[j]) base[j] = -base[j];
    result.push_back(base);
    // Each splitting axis doubles the list: the directions so far, and the
    // same with that axis negated (R <= F <= R + S, spec optics.md).
    for (int j = 0; j < dim; ++j) {
        if (!event.split[j]) continue;
        const std::size_t n = result.size();
        for (std::size_t i = 0; i < n; ++i) {
            Vector c = result[i];
            c[j] = -c[j];
            result.push_back(c);
        }
    }
    return result;
}

} // namespace orthoray::certify
