// The realistic model of a mirror scene (docs/realistic-scenes.md, "From
// mirror scenes"). Every reachable state of the scene's ray, all branches
// at once, is walked on the ray's lattice (or with the rational scan where
// diagonals leave it), keeping only the states that leave junctions. Each
// segment is a leg from the object of the event it leaves (the source for
// the first) to the object of the event it reaches, and to the receiver
// when it passes the target. Consecutive legs give the
// triples, the transfer of a triple being floor(i * f) with f the factor of
// the event at its middle object (event_rule.hpp, outgoing_factor). The
// legs are exact; what the model forgets is which state a leg came from, so
// the dynamic program may chain triples that no single ray follows.
#include "orthoray/realistic.hpp"

#include "engine/cycle_detector.hpp"
#include "engine/event_stepper.hpp"
#include "engine/lattice_stepper.hpp"
#include "realistic/kept_states.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>

namespace orthoray {
namespace {

constexpr std::size_t source_object = 0, receiver_object = 1;

using realistic::WalkState;

// The object an event belongs to: the first element acting there, in file
// order (a corner's elements share one event; docs say so).
std::size_t object_of(const Scene& scene, const std::vector<const Element*>& acting) {
    std::size_t first = scene.elements.size();
    for (const Element* e : acting)
        first = std::min(first, static_cast<std::size_t>(e - scene.elements.data()));
    return first + 2;
}

class ModelBuilder {
public:
    ModelBuilder(const Scene& scene, std::size_t target, std::size_t max_states)
        : scene_(scene), target_(scene.targets.at(target)),
          max_states_(std::min(max_states, max_kept_states)), kept_(scene) {
        if (engine::LatticeStepper::applies(scene))
            stepper_ = std::make_unique<engine::LatticeStepper>(scene);
        else
            stepper_ = std::make_unique<engine::ReferenceStepper>(scene);
    }

    RealisticModel build(const Integer& eps) {
        const Ray& ray = scene_.ray();
        walk({ray.start, ray.direction, source_object, source_object, Rational(1)});
        RealisticModel model;
        model.objects = {"S", "R"};
        for (std::size_t i = 0; i < scene_.elements.size(); ++i) {
            // Appended, not "e" + ...: GCC 12 warns falsely on that (-Wrestrict).
            std::string name(1, 'e');
            name.append(std::to_string(i + 1));
            model.objects.push_back(std::move(name));
        }
        model.source = source_object;
        model.receiver = receiver_object;
        model.emitted = *ray.intensity;
        model.eps = eps;
        model.first_legs.assign(first_legs_.begin(), first_legs_.end());
        for (const auto& [key, factor] : triples_) {
            Triple t;
            std::tie(t.from, t.via, t.to) = key;
            t.transfer.p = factor.get_num();
            t.transfer.q = factor.get_den();
            model.triples.push_back(std::move(t));
        }
        return model;
    }

private:
    // Every state reachable from `start`, all branches. Only the states
    // leaving a junction are kept, each once, so a branch that merges into
    // one already taken ends there; between junctions the ray is
    // deterministic, and follow() keeps O(1) states however long it runs.
    void walk(WalkState start) {
        std::vector<std::uint32_t> work; // kept states not yet walked
        follow(std::move(start), work);
        while (!work.empty()) {
            const std::uint32_t next = work.back();
            work.pop_back();
            follow(kept_.state(next), work);
        }
    }

    // The stretch from `item` (engine/stretch.hpp) up to an escape, an
    // absorption or a junction, whose ways out not kept before are kept and
    // join `work`. A stretch that never reaches one is a cycle, and Brent's
    // method notices it. It watches whole states, not points and directions
    // only: a state is a function of the one before, while its previous
    // object and factor are not functions of its point and direction. Legs
    // are sets, so the part of the cycle walked twice before the repeat is
    // seen adds nothing.
    void follow(WalkState item, std::vector<std::uint32_t>& work) {
        engine::BrentDetector<WalkState> cycle;
        for (std::uint64_t i = 1; !cycle.observe(item, i); ++i) {
            engine::ReferenceEvent e = stepper_->next(item.p, item.v);
            if (stepper_->passes(target_, item.p, item.v, e)) leg(item, receiver_object);
            if (e.escape) return;
            const std::size_t next = object_of(scene_, e.acting);
            leg(item, next);
            auto leaving = [&](engine::Outgoing& out) {
                Rational factor = engine::outgoing_factor(e.acting, item.v, out.direction);
                return WalkState{e.point, std::move(out.direction), item.current, next,
                                 std::move(factor)};
            };
            if (e.outgoing.empty()) return; // absorbed
            if (!e.junction) {
                item = leaving(e.outgoing.front());
                continue;
            }
            for (engine::Outgoing& out : e.outgoing) {
                const std::optional<std::uint32_t> kept = kept_.insert(leaving(out));
                if (!kept) continue;
                if (kept_.size() > max_states_) throw StatesExceeded(max_states_);
                work.push_back(*kept);
            }
            return;
        }
    }

    // The leg item.current -> to: a first leg from the source, else the
    // triple (previous, current, to) with the factor at `current`. The same
    // triple met at several events with different factors keeps the
    // greatest, so the model never passes on less than the scene.
    void leg(const WalkState& item, std::size_t to) {
        if (item.current == source_object) {
            first_legs_.insert(to);
            return;
        }
        const auto key = std::tuple{item.previous, item.current, to};
        const auto [it, added] = triples_.emplace(key, item.factor);
        if (!added && it->second < item.factor) it->second = item.factor;
    }

    const Scene& scene_;
    const Vector& target_;
    std::size_t max_states_;
    std::unique_ptr<engine::EventStepper> stepper_;
    realistic::KeptStates kept_; // the states leaving junctions, walked or waiting
    std::set<std::size_t> first_legs_;
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Rational> triples_;
};

} // namespace

StatesExceeded::StatesExceeded(std::size_t max_states)
    : std::runtime_error("the scene's ray reaches more than " + std::to_string(max_states) +
                         " states leaving junctions, the most the derivation of its realistic "
                         "model keeps"),
      max_states_(max_states) {}

RealisticModel realistic_model_of_scene(const Scene& scene, std::size_t target, const Integer& eps,
                                        std::size_t max_states) {
    if (scene.rays.size() != 1 || !scene.ray().intensity)
        throw UnsupportedScene("a realistic model is derived from a scene with exactly one ray, "
                               "which carries an intensity (docs/realistic-scenes.md)");
    if (target >= scene.targets.size())
        throw UnsupportedScene("the scene has " + std::to_string(scene.targets.size()) +
                               " targets, not " + std::to_string(target + 1));
    return ModelBuilder(scene, target, max_states).build(eps);
}

} // namespace orthoray
