// Which closed intervals [lo, hi] of exact integers contain a value: a
// segment tree over the sorted endpoints, each interval stored at the
// O(log n) nodes that cover it, so a query walks one root-to-leaf path and
// reports what it meets: O(log n + reported).
//
// The octagonal shots use it per direction: a segment can only meet the
// ray's line when the line's transverse value lies between its ends' values,
// so a shot tests a few segments instead of all of them.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace orthoray::induction {

template <class Int>
class IntervalStabbing {
public:
    struct Interval {
        Int lo, hi;
        std::uint32_t id;
    };

    IntervalStabbing() = default;
    explicit IntervalStabbing(const std::vector<Interval>& intervals) {
        for (const Interval& i : intervals) {
            keys_.push_back(i.lo);
            keys_.push_back(i.hi);
        }
        std::sort(keys_.begin(), keys_.end());
        keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
        // Slot 2k + 1 is key k itself, slot 2k the open gap below it.
        slots_ = 2 * keys_.size() + 1;
        node_.resize(4 * slots_);
        for (const Interval& i : intervals)
            insert(1, 0, slots_ - 1, slot_of(i.lo), slot_of(i.hi), i.id);
    }

    // Calls report(id) for every interval containing c.
    template <class Report>
    void stab(const Int& c, Report&& report) const {
        if (keys_.empty()) return;
        const std::size_t s = slot_of(c);
        std::size_t at = 1, l = 0, r = slots_ - 1;
        while (true) {
            for (std::uint32_t id : node_[at]) report(id);
            if (l == r) return;
            const std::size_t m = (l + r) / 2;
            if (s <= m) {
                at = 2 * at;
                r = m;
            } else {
                at = 2 * at + 1;
                l = m + 1;
            }
        }
    }

private:
    std::size_t slot_of(const Int& c) const {
        const auto it = std::lower_bound(keys_.begin(), keys_.end(), c);
        const std::size_t k = static_cast<std::size_t>(it - keys_.begin());
        return it != keys_.end() && *it == c ? 2 * k + 1 : 2 * k;
    }
    void insert(std::size_t at, std::size_t l, std::size_t r, std::size_t from, std::size_t to,
                std::uint32_t id) {
        if (to < l || r < from) return;
        if (from <= l && r <= to) {
            node_[at].push_back(id);
            return;
        }
        const std::size_t m = (l + r) / 2;
        insert(2 * at, l, m, from, to, id);
        insert(2 * at + 1, m + 1, r, from, to, id);
    }

    std::vector<Int> keys_;
    std::size_t slots_ = 0;
    std::vector<std::vector<std::uint32_t>> node_;
};

} // namespace orthoray::induction
