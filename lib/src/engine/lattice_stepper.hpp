// The illumination search's fast stepper: the next event found on the ray's
// integer lattice by a shooter built on it, instead of by the reference
// scan of every element (docs/optics.md, "Stepping").
//
// Why every state of a search has a lattice: among axis-parallel elements an
// event negates components of the direction (a mirror, or a splitter's
// reflected beam) or keeps it (a splitter's transmitted beam), so every
// branch of ray r moves along r's direction with some components negated and
// meets elements at points of r's lattice (lattice/lattice_scene.hpp, Reif,
// Tygar and Yoshida 1994); the lattice engine's uniform grid finds the first
// acting element in O(1) expected cells. Diagonals (2D only) also swap the
// direction's components, and every event point is then a point of r's
// octagonal lattice (lattice/octagonal_lattice.hpp, docs/octagonal.md),
// where the octagonal engine's bounding volume hierarchy finds it in
// O(log n) expected boxes. Either way the elements acting at the point come
// from the shooter too, and the acting rule (event_rule.hpp) turns them
// into the outgoing directions, as in every other engine.
#pragma once

#include "engine/event_stepper.hpp"
#include "engine/ray_lattice.hpp"
#include "lattice/setup_poll.hpp"

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace orthoray::engine {

class LatticeStepper final : public EventStepper {
public:
    // Whether the scene suits this stepper: diagonal elements only in 2D,
    // as scenes have them.
    static bool applies(const Scene& scene) { return scene.dim == 2 || !scene.has_diagonal(); }

    // What the lattices after the first may take together when no cap is
    // given: each is O(n), so a scene with many rays on distinct lattices
    // would otherwise take O(rays n) memory before its first event.
    static constexpr std::size_t default_max_bytes = std::size_t{4} << 30;

    // Builds one lattice and shooter for every ray whose states no earlier
    // ray's lattice holds: O(n) memory and O(n) (grid) or O(n log n)
    // (hierarchy) time each, calling `poll` once an element (it may throw
    // lattice::SetupStopped). Each is built only while the lattices' bytes,
    // estimated once each one's integer type is known (lattice_bytes in
    // ray_lattice.hpp), stay within `max_bytes`; without it, the first is
    // always built and the others held to default_max_bytes. States on no
    // lattice built, the branches of the rays left over, are stepped by the
    // reference scan: exact as well, O(n) an event.
    explicit LatticeStepper(const Scene& scene, const lattice::SetupPoll& poll = {},
                            std::optional<std::size_t> max_bytes = {});
    // The bytes the lattice of ray number `ray` would be estimated at.
    static std::size_t lattice_bytes_of(const Scene& scene, std::size_t ray);
    ~LatticeStepper() override;

    ReferenceEvent next(const Vector& p, const Vector& v) const override;
    bool passes(const Vector& x, const Vector& p, const Vector& v,
                const ReferenceEvent& event) const override {
        return reference_passes(scene_, x, p, v, event);
    }
    void describe(Answer& answer) const override;

    // Lattices built, and whether some ray was left to the reference scan.
    std::size_t lattice_count() const { return lattices_.size(); }
    bool scans() const { return scans_; }

private:
    // What a state shares with every state of its ray's lattice: the
    // direction's components up to sign, and the coordinates on the axes it
    // does not move along; with diagonals, which swap components, the two
    // components' sizes in either order. (A lattice's other tests, that the
    // scaled point is integral and, with diagonals, on one of the ray's
    // lines, hold for every state a search reaches.) Lattices are found by
    // it, so a switch between rays costs a lookup, not a scan of every ray's
    // lattice.
    using LatticeKey = std::vector<Rational>;
    LatticeKey key_of(const Vector& p, const Vector& v) const;

    const Scene& scene_;
    const bool octagonal_; // the scene has diagonals: octagonal lattices
    std::vector<std::unique_ptr<RayLattice>> lattices_;
    // Indices in lattices_ by key; rays whose starts differ in denominators
    // may share a key but not a scale, so a key may name several.
    std::map<LatticeKey, std::vector<std::size_t>> by_key_;
    // The lattice that held the last state asked about: a stretch stays on
    // one, so it is tried first.
    mutable std::size_t last_ = 0;
    bool scans_ = false;       // a ray's lattice was left unbuilt: scan its states
    ReferenceStepper scan_;    // what steps them
    double setup_seconds_ = 0; // building every lattice and shooter
    std::size_t cells_ = 0;    // the grids' cells together (a hierarchy has none)
};

// The lattice stepper where it applies (every scene the reader accepts),
// else the reference scan. `max_state_bytes`: the search's own cap on its
// branch states (SolveOptions::max_state_bytes, three quarters of
// `--max-memory`), whose third, the rest of that memory, then caps the
// lattices after the first instead of LatticeStepper::default_max_bytes.
std::unique_ptr<EventStepper> fastest_stepper(const Scene& scene,
                                              const lattice::SetupPoll& poll = {},
                                              std::optional<std::size_t> max_state_bytes = {});

} // namespace orthoray::engine
