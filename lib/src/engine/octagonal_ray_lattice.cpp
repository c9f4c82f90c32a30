// The lattice stepper's lattice for a 2D scene with diagonal elements: the
// octagonal lattice of one ray (lattice/octagonal_lattice.hpp) and the
// octagonal engine's bounding volume hierarchy on it.
//
// Why a search's states are lattice points there (docs/octagonal.md): every
// direction a branch of the ray can take is the ray's direction with its
// components negated and perhaps swapped, one of the lattice's eight, and
// a splitter's outgoing beams are such directions too (event_rule.hpp).
// Scaled by the lattice's N * D, every event point of the ray's branches is
// an integer point on a line cross(w, q) = c with c a multiple of N, as
// the header shows for a single ray: a splitter only adds branches, each
// of which is a reflection or a pass-through of the same kind. So a state
// (p, v) is this lattice's when v is one of its directions, p scaled is
// integral and within the numbers the integer type was chosen for, and
// cross(w, p) is a multiple of N; the hierarchy then shoots exactly.
#include "engine/ray_lattice.hpp"

#include "lattice/lattice_int.hpp"
#include "lattice/octagonal_lattice.hpp"
#include "shoot/octagonal_bvh.hpp"

#include <algorithm>
#include <vector>

namespace orthoray::engine {
namespace {

using lattice::OctagonalLattice;

template <class Int>
class OctagonalRayLattice final : public RayLattice {
public:
    // `bound`: the largest scaled coordinate of the elements, the ray's
    // start and the target, which every state of the ray's branches obeys.
    OctagonalRayLattice(OctagonalLattice ol, Integer bound, const lattice::SetupPoll& poll)
        : ol_(std::move(ol)), bound_(std::move(bound)), bvh_(ol_, poll),
          modulus_(lattice::from_integer<Int>(ol_.modulus)) {
        for (unsigned d = 0; d < lattice::direction_count; ++d) {
            direction_[d] = ol_.direction(d);
            for (int j = 0; j < 2; ++j) w_[d][j] = lattice::from_integer<Int>(ol_.w[d][j]);
        }
        // The hierarchy keeps what it shoots with.
        ol_.elements = {};
    }

    std::optional<ReferenceEvent> next(const Vector& p, const Vector& v) const override {
        // v: the first of the eight directions naming it, as the hierarchy's
        // tables are indexed.
        unsigned d = 0;
        while (d < lattice::direction_count && direction_[d] != v) ++d;
        if (d == lattice::direction_count) return std::nullopt;
        Int q[2];
        for (int j = 0; j < 2; ++j) {
            const Rational x = p[j] * ol_.scale;
            if (x.get_den() != 1 || mpz_cmpabs(x.get_num_mpz_t(), bound_.get_mpz_t()) > 0)
                return std::nullopt;
            q[j] = lattice::from_integer<Int>(x.get_num());
        }
        if (Int(w_[d][0] * q[1] - w_[d][1] * q[0]) % modulus_ != 0) return std::nullopt;

        const shoot::OctagonalShot<Int> shot = bvh_.shoot(q, d);
        if (shot.escape) {
            ReferenceEvent escape;
            escape.direction = v;
            return escape;
        }
        const Int hit[2] = {Int(q[0] + shot.t * w_[d][0]), Int(q[1] + shot.t * w_[d][1])};
        // Every element on the hit point, and those acting on v, in the
        // scene's order as the reference scan lists them.
        const Scene& scene = *ol_.scene;
        std::vector<const Element*> acting, present;
        bool splitter_here = false;
        bvh_.for_each_at(hit, [&](std::uint32_t k, std::uint8_t acts) {
            const Element& e = scene.elements[k];
            present.push_back(&e);
            splitter_here = splitter_here || e.kind == ElementKind::splitter;
            if ((acts >> d) & 1u) acting.push_back(&e);
        });
        std::sort(acting.begin(), acting.end());
        lattice::Coords at;
        for (int j = 0; j < 2; ++j) at[j] = lattice::to_integer(hit[j]);
        Vector point = ol_.point(at);
        const int j = v[0] != 0 ? 0 : 1;
        Rational t = (point[j] - p[j]) / v[j];
        ReferenceEvent event = event_at(2, std::move(t), std::move(point), std::move(acting), v);
        if (splitter_here && !event.absorbed && !event.junction)
            // Another arrival may split here, in any of the eight
            // directions (event_rule.hpp: with diagonals, swaps too).
            event.junction = is_junction(2, present, v, true);
        return event;
    }

    // A hierarchy has no grid cells: the answer's `grid_cells` stays 0, as
    // the octagonal engine reports it.
    std::size_t cells() const override { return 0; }

private:
    OctagonalLattice ol_;
    Integer bound_;
    shoot::OctagonalBvh<Int> bvh_;
    Int modulus_;
    Vector direction_[lattice::direction_count]; // in scene units
    Int w_[lattice::direction_count][2];         // in lattice units
};

} // namespace

std::unique_ptr<RayLattice> octagonal_ray_lattice(const Scene& scene, std::size_t ray,
                                                  const lattice::SetupPoll& poll,
                                                  const LatticeAfford& afford) {
    OctagonalLattice ol = lattice::make_octagonal_lattice(scene, poll, ray);
    // magnitude = the largest scaled coordinate times max(|a|, |b|) of the
    // primitive direction (a, b) = w[0].
    const Integer magnitude = ol.magnitude;
    const Integer a = abs(ol.w[0][0]), b = abs(ol.w[0][1]);
    Integer bound = magnitude / (a < b ? b : a);
    return build_narrowest(magnitude, ol.elements.size(), 2, afford,
                           [&](auto zero) -> std::unique_ptr<RayLattice> {
                               return std::make_unique<OctagonalRayLattice<decltype(zero)>>(
                                   std::move(ol), std::move(bound), poll);
                           });
}

} // namespace orthoray::engine
