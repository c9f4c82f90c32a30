// The checkers' own geometry (docs/certificates.md): the "first element met"
// scan and the reflection rule in plain rationals, shared by the path checker
// (verifier.cpp) and the induction checker (induction_verifier.cpp). Checker
// code only: nothing here comes from, or is used by, a solver.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>

namespace orthoray::certify {

// --------------------------------------------------------------- geometry --

// What the ray from a point meets first (at the smallest t > 0).
struct Event {
    bool met = false;
    Rational t;
    bool absorbed = false;      // an absorber is among the elements met at t
    std::array<bool, 3> flip{}; // normal axes of the mirrors met at t
};

inline Event first_met(const Scene& scene, const Vector& p, const Vector& v) {
    Event best;
    Rational t, q;
    for (const Element& e : scene.elements) {
        const int k = e.axis;
        // A ray parallel to the element's plane never meets it, even inside it.
        if (sgn(v[k]) == 0) continue;
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
            best.met = true;
            best.t = t;
        }
        // Every element met at the same t acts: any absorber stops the ray,
        // mirrors of one axis negate that component once.
        if (e.kind == ElementKind::absorber)
            best.absorbed = true;
        else
            best.flip[k] = true;
    }
    return best;
}

inline Vector advance(const Vector& p, const Vector& v, const Rational& t, int dim) {
    Vector q;
    for (int j = 0; j < dim; ++j) q[j] = p[j] + t * v[j];
    return q;
}

inline bool same(const Vector& a, const Vector& b, int dim) {
    for (int j = 0; j < dim; ++j)
        if (a[j] != b[j]) return false;
    return true;
}

// Does `target` = p + tau v hold for some 0 <= tau <= stop.t (any tau >= 0
// when nothing is met)? Axes where v is zero must match exactly.
inline bool on_ray(const Vector& target, const Vector& p, const Vector& v, const Event& stop,
                   int dim) {
    std::optional<Rational> tau;
    for (int j = 0; j < dim; ++j) {
        if (sgn(v[j]) == 0) {
            if (target[j] != p[j]) return false;
            continue;
        }
        Rational s = (target[j] - p[j]) / v[j];
        if (tau && *tau != s) return false;
        tau = std::move(s);
    }
    if (!tau) return true; // v == 0 cannot come from a valid scene; then only p itself
    return sgn(*tau) >= 0 && (!stop.met || *tau <= stop.t);
}

inline std::string show(const Vector& a, int dim) {
    std::string text = "(";
    for (int j = 0; j < dim; ++j) text += (j ? ", " : "") + to_string(a[j]);
    return text + ")";
}

} // namespace orthoray::certify
