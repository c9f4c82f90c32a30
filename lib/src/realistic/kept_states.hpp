// The states the derivation of a realistic model keeps (scene_model.cpp):
// those leaving junctions, each with the context its legs depend on.
#pragma once

#include "engine/branch_state_set.hpp"
#include "engine/byte_budget.hpp"
#include "orthoray/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace orthoray::realistic {

// A state of the walk: the segment from p along v leaves object `current`,
// reached from `previous`, with `factor` of the event there. The legs from
// it on depend on all five, so it is the unit both of the walk and of what
// is kept.
struct WalkState {
    Vector p, v;
    std::size_t previous = 0, current = 0;
    Rational factor;
    bool operator==(const WalkState&) const = default;
};

// The kept states, compactly. The point and direction go into the
// illumination search's exact byte-string set (engine/branch_state_set.hpp:
// about 80-100 bytes a state, against some 700 for a WalkState of GMP
// rationals in a std::set). The context beside them takes 20 bytes: the
// two objects, and the factor as its number among the distinct factors met,
// which are few (each is one element's reflectance or transmittance). A
// point and direction met with several contexts (branches merging with
// different histories) chain one context each.
class KeptStates {
public:
    explicit KeptStates(const Scene& scene);
    KeptStates(const KeptStates&) = delete;
    KeptStates& operator=(const KeptStates&) = delete;

    // Keeps s: its number, or nullopt when it was kept already. Throws
    // std::length_error past max_kept_states states (the numbering's
    // limit; the model builder stops with StatesExceeded before it).
    std::optional<std::uint32_t> insert(const WalkState& s);
    std::size_t size() const { return contexts_.size(); }
    // State `number`, decoded.
    WalkState state(std::uint32_t number) const;

private:
    static constexpr std::uint32_t none = ~std::uint32_t{0};
    struct Context {
        std::uint32_t point_and_direction; // the number in `points_`
        std::uint32_t previous, current, factor;
        std::uint32_t next_same; // the next context of the same point and direction
    };

    engine::ByteBudget budget_{std::nullopt}; // the set wants one; the cap is a count
    engine::BranchStateSet points_;
    std::vector<std::uint32_t> first_context_; // by number in `points_`
    std::vector<Context> contexts_;
    std::map<Rational, std::uint32_t> factor_number_;
    std::vector<Rational> factors_;
};

} // namespace orthoray::realistic
