#include "engine/lattice_stepper.hpp"

#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <chrono>
#include <new>
#include <optional>
#include <stdexcept>

namespace orthoray::engine {

namespace {

using lattice::LatticeScene;

// Cells per element, as the lattice engine's grid has them: 2 in the plane;
// in space a ray crosses more cells per element met, and 32 pay off there
// (docs/shooting.md).
std::int64_t cells_per_element(int dim) {
    return dim <= 2 ? 2 : 32;
}

template <class Int, int M>
class RayLatticeOn final : public RayLattice {
public:
    RayLatticeOn(LatticeScene ls, const lattice::SetupPoll& poll)
        : ls_(std::move(ls)), grid_(ls_, cells_per_element(M), poll) {
        // The grid keeps what it shoots with; per element only what the
        // acting rule needs is kept besides.
        element_.reserve(ls_.elements.size());
        for (const lattice::LatticeElement& e : ls_.elements)
            element_.push_back({e.source, static_cast<std::uint8_t>(e.acting)});
        ls_.elements = {};
    }

    std::optional<ReferenceEvent> next(const Vector& p, const Vector& v) const override {
        const Scene& scene = *ls_.scene;
        // v must be the ray's direction with some active components negated
        // (the inactive ones are 0 for both); bit i of the mask is set where
        // v moves towards -infinity.
        unsigned negative = 0;
        for (int j = 0, i = 0; j < scene.dim; ++j) {
            const Rational& u = ls_.ray->direction[j];
            if (i < M && ls_.active[i] == j) {
                if (v[j] != u && v[j] != -u) return std::nullopt;
                if (v[j] < 0) negative |= 1u << i;
                ++i;
            } else if (v[j] != 0) {
                return std::nullopt;
            }
        }
        lattice::Coords at;
        if (!ls_.to_lattice(p, at)) return std::nullopt;
        // Int was chosen for the numbers of this ray's scene (its start and
        // the elements): another ray's start on the same lattice may lie
        // beyond them, and is that ray's lattice's to answer.
        for (int i = 0; i < M; ++i)
            if (mpz_cmpabs(at[i].get_mpz_t(), ls_.magnitude.get_mpz_t()) > 0) return std::nullopt;
        Int q[M];
        for (int i = 0; i < M; ++i) q[i] = lattice::from_integer<Int>(at[i]);

        const shoot::Shot<Int> shot = grid_.shoot(q, negative);
        if (shot.escape) {
            ReferenceEvent escape;
            escape.direction = v;
            return escape;
        }
        for (int i = 0; i < M; ++i) {
            q[i] += ((negative >> i) & 1u) ? Int(-shot.t) : shot.t;
            at[i] = lattice::to_integer(q[i]);
        }
        // Every element acting there, each once (a cell lists an element once).
        std::vector<const Element*> acting;
        bool splitter_here = false;
        grid_.for_each_element_at(q, [&](std::uint32_t k) {
            const Element& e = scene.elements[element_[k].source];
            splitter_here = splitter_here || e.kind == ElementKind::splitter;
            if ((element_[k].acting >> negative) & 1u) acting.push_back(&e);
        });
        Vector point = ls_.point(at);
        const int j = ls_.active[0];
        Rational t = (point[j] - p[j]) / v[j];
        ReferenceEvent event =
            event_at(scene.dim, std::move(t), std::move(point), std::move(acting), v);
        if (splitter_here && !event.absorbed && !event.junction) {
            // Another arrival may split here: every element on the point
            // counts, acting on v or not. The lattice leaves out only
            // elements that act on no direction of this ray's, which split
            // nothing; and without diagonals no arrival is swapped.
            std::vector<const Element*> present;
            grid_.for_each_element_at(q, [&](std::uint32_t k) {
                present.push_back(&scene.elements[element_[k].source]);
            });
            event.junction = is_junction(scene.dim, present, v, false);
        }
        return event;
    }

    std::size_t cells() const override { return grid_.cell_count(); }

private:
    struct Source {
        std::uint32_t source; // index in Scene::elements
        std::uint8_t acting;  // LatticeElement::acting
    };
    LatticeScene ls_;
    shoot::UniformGrid<Int, M> grid_;
    std::vector<Source> element_; // by lattice index, as the grid reports them
};

template <class Int>
std::unique_ptr<RayLattice> on_int(LatticeScene ls, const lattice::SetupPoll& poll) {
    switch (ls.dim) {
    case 1:
        return std::make_unique<RayLatticeOn<Int, 1>>(std::move(ls), poll);
    case 2:
        return std::make_unique<RayLatticeOn<Int, 2>>(std::move(ls), poll);
    default:
        return std::make_unique<RayLatticeOn<Int, 3>>(std::move(ls), poll);
    }
}

} // namespace

std::size_t lattice_bytes(std::size_t elements, int dim, bool int128, bool wide) {
    // Bytes an element: 2D then 3D, on 64-bit, 128-bit and GMP integers.
    static constexpr std::size_t per_element[2][3] = {{120, 200, 350}, {400, 650, 1100}};
    return 4096 + per_element[dim == 3 ? 1 : 0][wide ? 2 : int128 ? 1 : 0] * elements;
}

std::unique_ptr<RayLattice> axis_ray_lattice(const Scene& scene, std::size_t ray,
                                             const lattice::SetupPoll& poll,
                                             const LatticeAfford& afford) {
    LatticeScene ls = lattice::make_lattice(scene, poll, ray);
    const Integer magnitude = ls.magnitude;
    return build_narrowest(magnitude, ls.elements.size(), scene.dim, afford,
                           [&](auto zero) { return on_int<decltype(zero)>(std::move(ls), poll); });
}

LatticeStepper::LatticeStepper(const Scene& scene, const lattice::SetupPoll& poll,
                               std::optional<std::size_t> max_bytes)
    : scene_(scene), octagonal_(scene.has_diagonal()), scan_(scene) {
    const auto begin = std::chrono::steady_clock::now();
    std::size_t room = max_bytes.value_or(default_max_bytes);
    const LatticeAfford afford = [&](std::size_t bytes) {
        if (lattices_.empty() && !max_bytes) return true; // the first, uncapped
        if (bytes > room) return false;
        room -= bytes;
        return true;
    };
    for (std::size_t r = 0; r < scene.rays.size(); ++r) {
        const Ray& ray = scene.rays[r];
        std::vector<std::size_t>& same_key = by_key_[key_of(ray.start, ray.direction)];
        // A ray whose start state an earlier lattice holds has all its
        // branches there too.
        const bool held = std::any_of(same_key.begin(), same_key.end(), [&](std::size_t i) {
            return lattices_[i]->next(ray.start, ray.direction).has_value();
        });
        if (held) continue;
        std::unique_ptr<RayLattice> lattice;
        try {
            lattice = octagonal_ ? octagonal_ray_lattice(scene, r, poll, afford)
                                 : axis_ray_lattice(scene, r, poll, afford);
        } catch (const std::bad_alloc&) {
            // A lattice's numbers are worked out before its size is known,
            // and under a cap memory may run out there: that ray, and every
            // later one, is scanned instead. Without a cap it is the run's
            // memory limit, as anywhere.
            if (!max_bytes) throw;
            room = 0;
        }
        if (!lattice) {
            scans_ = true;
            continue;
        }
        same_key.push_back(lattices_.size());
        cells_ += lattice->cells();
        lattices_.push_back(std::move(lattice));
    }
    setup_seconds_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

std::size_t LatticeStepper::lattice_bytes_of(const Scene& scene, std::size_t ray) {
    std::size_t bytes = 0;
    const LatticeAfford measure = [&](std::size_t b) {
        bytes = b;
        return false;
    };
    if (scene.has_diagonal())
        octagonal_ray_lattice(scene, ray, {}, measure);
    else
        axis_ray_lattice(scene, ray, {}, measure);
    return bytes;
}

LatticeStepper::LatticeKey LatticeStepper::key_of(const Vector& p, const Vector& v) const {
    LatticeKey key;
    if (octagonal_) {
        key = {abs(v[0]), abs(v[1])};
        if (key[1] < key[0]) std::swap(key[0], key[1]);
        return key;
    }
    key.reserve(2 * static_cast<std::size_t>(scene_.dim));
    for (int j = 0; j < scene_.dim; ++j) {
        key.push_back(abs(v[j]));
        key.push_back(v[j] == 0 ? p[j] : Rational(0));
    }
    return key;
}

void LatticeStepper::describe(Answer& answer) const {
    answer.shooter = octagonal_ ? ShooterUsed::bvh : ShooterUsed::grid;
    answer.stats.setup.seconds = setup_seconds_;
    answer.stats.setup.cells = cells_;
}

LatticeStepper::~LatticeStepper() = default;

ReferenceEvent LatticeStepper::next(const Vector& p, const Vector& v) const {
    if (!lattices_.empty())
        if (std::optional<ReferenceEvent> e = lattices_[last_]->next(p, v)) return std::move(*e);
    if (const auto same_key = by_key_.find(key_of(p, v)); same_key != by_key_.end())
        for (std::size_t i : same_key->second)
            if (i != last_)
                if (std::optional<ReferenceEvent> e = lattices_[i]->next(p, v)) {
                    last_ = i;
                    return std::move(*e);
                }
    // A ray whose lattice was left unbuilt: its branches are scanned.
    if (scans_) return scan_.next(p, v);
    // Every branch stays on its ray's lattice (see the header), so a state
    // that no lattice holds did not come from the search.
    throw std::logic_error("LatticeStepper: a state off every ray's lattice");
}

std::unique_ptr<EventStepper> fastest_stepper(const Scene& scene, const lattice::SetupPoll& poll,
                                              std::optional<std::size_t> max_state_bytes) {
    if (!LatticeStepper::applies(scene)) return std::make_unique<ReferenceStepper>(scene);
    std::optional<std::size_t> max_bytes;
    if (max_state_bytes) max_bytes = *max_state_bytes / 3;
    return std::make_unique<LatticeStepper>(scene, poll, max_bytes);
}

} // namespace orthoray::engine
