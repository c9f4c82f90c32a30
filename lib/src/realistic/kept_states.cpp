#include "realistic/kept_states.hpp"

#include "orthoray/realistic.hpp"

#include <stdexcept>

namespace orthoray::realistic {

namespace {

std::uint32_t narrow(std::size_t x) {
    if (x > max_kept_states) throw std::length_error("more than 2^32 - 2 kept states");
    return static_cast<std::uint32_t>(x);
}

} // namespace

KeptStates::KeptStates(const Scene& scene) : points_(scene, budget_) {}

std::optional<std::uint32_t> KeptStates::insert(const WalkState& s) {
    const std::optional<engine::BranchStateSet::Inserted> at = points_.insert(s.p, s.v);
    if (!at) throw std::length_error("more than 2^32 - 2 kept states");
    const auto [factor_at, new_factor] =
        factor_number_.try_emplace(s.factor, narrow(factors_.size()));
    if (new_factor) factors_.push_back(s.factor);
    const Context context{at->index, narrow(s.previous), narrow(s.current), factor_at->second,
                          none};
    if (at->added) {
        first_context_.push_back(none);
    } else {
        for (std::uint32_t c = first_context_[at->index]; c != none; c = contexts_[c].next_same)
            if (contexts_[c].previous == context.previous &&
                contexts_[c].current == context.current && contexts_[c].factor == context.factor)
                return std::nullopt;
    }
    const std::uint32_t number = narrow(contexts_.size());
    contexts_.push_back(context);
    contexts_.back().next_same = first_context_[at->index];
    first_context_[at->index] = number;
    return number;
}

WalkState KeptStates::state(std::uint32_t number) const {
    const Context& c = contexts_[number];
    WalkState s;
    points_.state(c.point_and_direction, s.p, s.v);
    s.previous = c.previous;
    s.current = c.current;
    s.factor = factors_[c.factor];
    return s;
}

} // namespace orthoray::realistic
