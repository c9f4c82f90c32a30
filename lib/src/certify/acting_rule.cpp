// The checkers' first acting event and outgoing directions; see
// acting_rule.hpp.
#include "certify/acting_rule.hpp"

namespace orthoray::certify {

namespace {

// A diagonal's normal: its line is { q : n . q = n . from }.
Vector normal_of(const Element& diagonal) {
    return {1, diagonal.diagonal == Diagonal::rising ? -1 : 1, 0};
}

Rational dot2(const Vector& a, const Vector& b) {
    return a[0] * b[0] + a[1] * b[1];
}

} // namespace

bool acts_on(const Element& element, const Vector& v) {
    if (element.is_diagonal()) return sgn(dot2(normal_of(element), v)) != 0;
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
    unsigned acting = 0; // orientations at the best point: bits 0-2 axes, 3-4 slopes
    Rational t, q;
    for (const Element& e : scene.elements) {
        if (!acts_on(e, v)) continue; // invisible: not even an event
        if (e.is_diagonal()) {
            // The line n . x = n . from, met where n . (p + t v) equals it;
            // the point is on the segment when its x lies between the ends'.
            const Vector n = normal_of(e);
            q = dot2(n, e.from()) - dot2(n, p);
            const Rational nv = dot2(n, v);
            if (sgn(q) * sgn(nv) <= 0) continue;
            t = q / nv;
            if (best.met && t > best.t) continue;
            q = p[0] + t * v[0];
            if (q < e.from()[0] || e.to()[0] < q) continue;
            if (!best.met || t < best.t) {
                best = Event{};
                splitter = {};
                acting = 0;
                best.met = true;
                best.t = t;
            }
            const int slope = e.diagonal == Diagonal::rising ? 0 : 1;
            acting |= 8u << slope;
            best.slope[slope] = true;
            best.absorbed = best.absorbed || e.kind == ElementKind::absorber;
            best.slope_mirror[slope] = best.slope_mirror[slope] || e.kind == ElementKind::mirror;
            continue;
        }
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
            acting = 0;
            best.met = true;
            best.t = t;
        }
        acting |= 1u << k;
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
    for (; acting != 0; acting &= acting - 1) ++best.orientations;
    return best;
}

std::vector<Vector> outgoing(const Vector& v, const Event& event, int dim) {
    std::vector<Vector> result;
    if (!event.met || event.absorbed) return result;
    for (int slope = 0; slope < 2; ++slope) {
        if (!event.slope[slope]) continue;
        if (event.orientations > 1) return {{-v[0], -v[1], -v[2]}};
        // Mirrored in the line with normal n (n . n = 2): v - (v . n) n.
        const Vector n{1, slope == 0 ? -1 : 1, 0};
        const Rational along = dot2(v, n);
        const Vector mirrored{v[0] - along * n[0], v[1] - along * n[1], v[2]};
        if (!event.slope_mirror[slope]) result.push_back(v);
        result.push_back(mirrored);
        return result;
    }
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
