// A cap on the bytes a search holds in its own containers. Every buffer is
// grown through it, and a growth that would pass the cap is refused before
// anything changes, so the search can end with Limit::memory instead of
// meeting std::bad_alloc halfway through an update.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace orthoray::engine {

class ByteBudget {
public:
    explicit ByteBudget(std::optional<std::size_t> max_bytes) : max_(max_bytes) {}

    // Room for `more` elements at the end of v, doubling its capacity when
    // it is full. False, with v unchanged, when the new buffer and the old
    // one (both alive while the elements move) would pass the cap.
    template <class T>
    bool make_room(std::vector<T>& v, std::size_t more = 1) {
        if (v.size() + more <= v.capacity()) return true;
        const std::size_t old_capacity = v.capacity();
        const std::size_t capacity = std::max({old_capacity * 2, v.size() + more, std::size_t{16}});
        if (!fits(capacity * sizeof(T))) return false;
        v.reserve(capacity);
        used_ += (v.capacity() - old_capacity) * sizeof(T);
        return true;
    }

    // Whether a new buffer of `bytes` fits beside everything held now.
    bool fits(std::size_t bytes) const {
        return !max_ || (used_ <= *max_ && bytes <= *max_ - used_);
    }
    // A buffer of `bytes` was allocated (after fits()) or freed.
    void allocated(std::size_t bytes) { used_ += bytes; }
    void freed(std::size_t bytes) { used_ -= bytes; }
    // Bytes held now: the capacity of every buffer grown through the budget.
    std::size_t used() const { return used_; }

private:
    std::optional<std::size_t> max_;
    std::size_t used_ = 0;
};

} // namespace orthoray::engine
