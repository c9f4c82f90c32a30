// Brent's method over the states of a stretch; see stretch_walk.hpp.
#include "certify/stretch_walk.hpp"

#include "certify/path_geometry.hpp"

#include <utility>

namespace orthoray::certify {

StretchEnd walk_stretch(const Scene& scene, const Vector& start, const Vector& direction,
                        const std::function<bool(const StretchSegment&)>& visit) {
    const int dim = scene.dim;
    Vector p = start, v = direction;  // the hare: the state being left
    Vector saved_p = p, saved_v = v;  // the tortoise
    std::uint64_t power = 1, lam = 1; // Brent: the tortoise jumps at powers of two
    std::uint64_t reflections = 0;
    StretchEnd end;
    for (;;) {
        const Event e = first_met(scene, p, v);
        if (!visit(StretchSegment{p, v, e, reflections})) {
            end.kind = StretchEnd::Kind::stopped;
            return end;
        }
        if (!e.met) return end; // escape
        if (e.absorbed) {
            end.kind = StretchEnd::Kind::absorbed;
            return end;
        }
        std::vector<Vector> out = outgoing(v, e, dim);
        Vector q = advance(p, v, e.t, dim);
        if (out.size() >= 2) {
            end.kind = StretchEnd::Kind::branch;
            end.point = std::move(q);
            end.incoming = v;
            end.outgoing = std::move(out);
            end.reflections = reflections;
            return end;
        }
        if (!same(out[0], v, dim)) ++reflections;
        p = std::move(q);
        v = std::move(out[0]);
        if (same(p, saved_p, dim) && same(v, saved_v, dim)) {
            end.kind = StretchEnd::Kind::cycle;
            end.reflections = reflections;
            return end;
        }
        if (power == lam) {
            saved_p = p;
            saved_v = v;
            power *= 2;
            lam = 0;
        }
        ++lam;
    }
}

} // namespace orthoray::certify
