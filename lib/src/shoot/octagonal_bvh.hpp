// Next-hit queries in a 2D scene with diagonal elements: an exact bounding
// volume hierarchy over the elements' bounding boxes, on the lattice of
// lattice/octagonal_lattice.hpp.
//
// The ray is P + t w with w one of the (up to) eight directions, not a
// diagonal, so the boxes are tested in scaled time: T = t |w_x| |w_y| (t
// itself when a component is 0, the other then being ±1). Reaching
// coordinate X on an axis j with w_j != 0 takes T = (X - P_j) sgn(w_j)
// |w_other|, an integer, so the slab test is integer. An axis with w_j = 0
// holds the ray iff lo_j <= P_j <= hi_j. A node is visited when its slab
// interval [enter, leave] is not empty, leave > 0 and enter <= the scaled
// time of the best hit so far: ties are visited, so every element met at
// the least t is seen, as a scan of all elements would.
//
// An element is met where P + t w crosses its line f(q) = k (f one of x, y,
// x - y, x + y): t = (k - f(P)) / f(w), an exact integer division (the
// lattice's point), then the point must lie in its box (on its line, the
// box is the segment). Elements that do not act on the direction (parallel,
// or a one-sided one seen from its back) are skipped by their `acting` bits.
//
// Bounds: coordinates are at most B, |w_j| at most W; a hit's |t w_j| is a
// difference of two coordinates (<= 2B), scaled times are at most 2 B W,
// a candidate's t is at most 4B and its point at most 5 B W: within the
// 8 B W that OctagonalLattice::magnitude promises.
#pragma once

#include "lattice/lattice_int.hpp"
#include "lattice/octagonal_lattice.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace orthoray::shoot {

// What the ray meets next: nothing (escape), or at parameter t > 0 a point
// where elements of these orientations (bit o, lattice::Orientation) act.
template <class Int>
struct OctagonalShot {
    bool escape = true;
    Int t{};
    std::uint8_t mirrors = 0, absorbers = 0;

    void record(const Int& at, unsigned orientation, bool absorber) {
        if (escape || at < t) {
            escape = false;
            t = at;
            mirrors = absorbers = 0;
        }
        (absorber ? absorbers : mirrors) |= static_cast<std::uint8_t>(1u << orientation);
    }
};

template <class Int>
class OctagonalBvh {
public:
    // `poll` is called once an element (it may throw lattice::SetupStopped).
    explicit OctagonalBvh(const lattice::OctagonalLattice& lattice,
                          const lattice::SetupPoll& poll = {});

    // From the lattice point p along direction d (an index of the lattice).
    OctagonalShot<Int> shoot(const Int (&p)[2], unsigned d) const;

    // Calls f(k, acting) for every element k (its index in the lattice's
    // elements) that the lattice point q lies on, with its acting bits
    // (OctagonalElement::acting): the boxes holding q are walked down, and
    // an element holds q when q is in its box and on its line. O(log n)
    // plus the boxes holding q, so the elements at an event come without a
    // scan of all of them.
    template <class F>
    void for_each_at(const Int (&q)[2], F&& f) const;

    static constexpr std::uint32_t leaf_size = 2;

private:
    struct Item {
        Int lo[2], hi[2];
        Int offset; // k of its line
        std::uint8_t orientation, acting;
        bool absorber;
        std::uint32_t source; // index in the lattice's elements (fits the padding)
    };
    struct Node {
        Int lo[2], hi[2];
        std::uint32_t first; // leaf: first item; interior: index of the right child
        std::uint32_t count; // leaf: number of items (> 0); interior: 0
    };
    std::vector<Item> items_; // in leaf order
    std::vector<Node> nodes_; // depth first; nodes_[0] is the root
    Int w_[lattice::direction_count][2];
    // f(w) for each direction and orientation: x, y, x - y, x + y of w.
    Int step_[lattice::direction_count][4];

    std::uint32_t build(std::vector<std::uint32_t>& order, std::uint32_t begin, std::uint32_t end,
                        const std::vector<Item>& items);

    // Per direction, what the slab test needs: a code `way` (bit j: the ray
    // moves on axis j; bit 2 + j: towards -infinity) that selects a
    // traversal with those signs fixed at compile time, and per axis the
    // factor turning a coordinate difference into scaled time (|w_other|,
    // or 1).
    unsigned way_[lattice::direction_count]{};
    Int factor_[lattice::direction_count][2];

    // [enter, leave] in scaled time; false when the box cannot hold a hit
    // (an axis the ray does not move on misses it, or it lies behind).
    template <unsigned Way>
    static bool slab(const Node& node, const Int (&p)[2], const Int (&factor)[2], Int& enter,
                     Int& leave) {
        bool first = true;
        for (int j = 0; j < 2; ++j) {
            const bool moving = (Way >> j) & 1u, negative = (Way >> (2 + j)) & 1u;
            if (!moving) {
                if (p[j] < node.lo[j] || node.hi[j] < p[j]) return false;
                continue;
            }
            const Int a = negative ? Int((p[j] - node.hi[j]) * factor[j])
                                   : Int((node.lo[j] - p[j]) * factor[j]);
            const Int b = negative ? Int((p[j] - node.lo[j]) * factor[j])
                                   : Int((node.hi[j] - p[j]) * factor[j]);
            if (first || enter < a) enter = a;
            if (first || b < leave) leave = b;
            first = false;
        }
        return !(leave < enter) && Int(0) < leave;
    }

    template <unsigned Way>
    OctagonalShot<Int> shoot_way(const Int (&p)[2], unsigned d) const;

    template <std::size_t... Way>
    static constexpr auto traversals(std::index_sequence<Way...>) {
        return std::array<OctagonalShot<Int> (OctagonalBvh::*)(const Int(&)[2], unsigned) const,
                          sizeof...(Way)>{&OctagonalBvh::shoot_way<Way>...};
    }
};

template <class Int>
OctagonalBvh<Int>::OctagonalBvh(const lattice::OctagonalLattice& lattice,
                                const lattice::SetupPoll& poll) {
    for (unsigned d = 0; d < lattice::direction_count; ++d) {
        const Int x = lattice::from_integer<Int>(lattice.w[d][0]);
        const Int y = lattice::from_integer<Int>(lattice.w[d][1]);
        w_[d][0] = x;
        w_[d][1] = y;
        step_[d][lattice::normal_x] = x;
        step_[d][lattice::normal_y] = y;
        step_[d][lattice::rising] = x - y;
        step_[d][lattice::falling] = x + y;
        for (int j = 0; j < 2; ++j) {
            const Int& other = w_[d][1 - j];
            if (w_[d][j] != 0) way_[d] |= 1u << j;
            if (w_[d][j] < 0) way_[d] |= 1u << (2 + j);
            factor_[d][j] = other == 0 ? Int(1) : other < 0 ? Int(-other) : other;
        }
    }
    const std::size_t n = lattice.elements.size();
    if (n == 0) return;
    std::vector<Item> items;
    items.reserve(n);
    for (const lattice::OctagonalElement& e : lattice.elements) {
        poll();
        Item it;
        it.source = static_cast<std::uint32_t>(items.size());
        for (int j = 0; j < 2; ++j) {
            it.lo[j] = lattice::from_integer<Int>(e.lo[j]);
            it.hi[j] = lattice::from_integer<Int>(e.hi[j]);
        }
        it.offset = lattice::from_integer<Int>(e.offset);
        it.orientation = e.orientation;
        it.acting = e.acting;
        it.absorber = e.absorber;
        items.push_back(it);
    }
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    nodes_.reserve(2 * ((n + leaf_size - 1) / leaf_size));
    build(order, 0, static_cast<std::uint32_t>(n), items);
    items_.reserve(n);
    for (std::uint32_t k : order) items_.push_back(items[k]);
}

// The subtree over order[begin, end), split at the median centre along the
// longer side of its box; returns its node's index.
template <class Int>
std::uint32_t OctagonalBvh<Int>::build(std::vector<std::uint32_t>& order, std::uint32_t begin,
                                       std::uint32_t end, const std::vector<Item>& items) {
    const auto self = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    {
        Node& node = nodes_.back();
        const Item& head = items[order[begin]];
        for (int j = 0; j < 2; ++j) {
            node.lo[j] = head.lo[j];
            node.hi[j] = head.hi[j];
        }
        for (std::uint32_t k = begin + 1; k < end; ++k)
            for (int j = 0; j < 2; ++j) {
                node.lo[j] = std::min(node.lo[j], items[order[k]].lo[j]);
                node.hi[j] = std::max(node.hi[j], items[order[k]].hi[j]);
            }
    }
    if (end - begin <= leaf_size) {
        nodes_[self].first = begin;
        nodes_[self].count = end - begin;
        return self;
    }
    const Node& node = nodes_[self];
    const int axis = node.hi[0] - node.lo[0] < node.hi[1] - node.lo[1] ? 1 : 0;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         return items[a].lo[axis] + items[a].hi[axis] <
                                items[b].lo[axis] + items[b].hi[axis];
                     });
    build(order, begin, mid, items); // the left child is self + 1
    const std::uint32_t right = build(order, mid, end, items);
    nodes_[self].first = right; // nodes_ may have grown: index again
    nodes_[self].count = 0;
    return self;
}

template <class Int>
OctagonalShot<Int> OctagonalBvh<Int>::shoot(const Int (&p)[2], unsigned d) const {
    static constexpr auto table = traversals(std::make_index_sequence<16>{});
    return (this->*table[way_[d]])(p, d);
}

template <class Int>
template <unsigned Way>
OctagonalShot<Int> OctagonalBvh<Int>::shoot_way(const Int (&p)[2], unsigned d) const {
    OctagonalShot<Int> shot;
    if (nodes_.empty()) return shot;
    const Int(&w)[2] = w_[d];
    // Scaled time per unit t: |w_x w_y|, or 1 when a component is 0.
    const Int ax = w[0] < 0 ? Int(-w[0]) : w[0], ay = w[1] < 0 ? Int(-w[1]) : w[1];
    const Int per_t = ax == 0 || ay == 0 ? Int(1) : Int(ax * ay);
    const Int form[4] = {p[0], p[1], Int(p[0] - p[1]), Int(p[0] + p[1])};

    const Int(&factor)[2] = factor_[d];
    Int enter{}, bound{};
    if (!slab<Way>(nodes_[0], p, factor, enter, bound)) return shot;

    constexpr int stack_size = 64; // a median split: at most 33 levels below 2^32 elements
    std::uint32_t stack[stack_size];
    Int stack_enter[stack_size];
    int top = 0;
    std::uint32_t current = 0;
    while (true) {
        const Node& node = nodes_[current];
        if (node.count != 0) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
                const Item& it = items_[k];
                if (!((it.acting >> d) & 1u)) continue;
                const Int& f = step_[d][it.orientation];
                const Int num = it.offset - form[it.orientation];
                // t = num / f > 0, and no later than the best hit.
                if (num == 0 || (num < 0) != (f < 0)) continue;
                const Int t = num / f;
                if (!shot.escape && shot.t < t) continue;
                const Int x = p[0] + t * w[0], y = p[1] + t * w[1];
                if (x < it.lo[0] || it.hi[0] < x || y < it.lo[1] || it.hi[1] < y) continue;
                shot.record(t, it.orientation, it.absorber);
                bound = shot.t * per_t;
            }
        } else {
            // Both children; the one the ray enters first is visited first.
            const std::uint32_t left = current + 1, right = node.first;
            Int enter_l{}, leave_l{}, enter_r{}, leave_r{};
            const bool hit_l =
                slab<Way>(nodes_[left], p, factor, enter_l, leave_l) && !(bound < enter_l);
            const bool hit_r =
                slab<Way>(nodes_[right], p, factor, enter_r, leave_r) && !(bound < enter_r);
            const bool swap = hit_l && hit_r && enter_r < enter_l;
            if (hit_l && hit_r) {
                stack[top] = swap ? left : right;
                stack_enter[top] = swap ? enter_l : enter_r;
                ++top;
                current = swap ? right : left;
                continue;
            }
            if (hit_l || hit_r) {
                current = hit_l ? left : right;
                continue;
            }
        }
        // The next pending node that may still hold a hit no later than bound.
        while (true) {
            if (top == 0) return shot;
            --top;
            if (!(bound < stack_enter[top])) break;
        }
        current = stack[top];
    }
}

template <class Int>
template <class F>
void OctagonalBvh<Int>::for_each_at(const Int (&q)[2], F&& f) const {
    if (nodes_.empty()) return;
    const auto holds = [&](const Int(&lo)[2], const Int(&hi)[2]) {
        return !(q[0] < lo[0] || hi[0] < q[0] || q[1] < lo[1] || hi[1] < q[1]);
    };
    const Int form[4] = {q[0], q[1], Int(q[0] - q[1]), Int(q[0] + q[1])};
    constexpr int stack_size = 64; // as in shoot_way
    std::uint32_t stack[stack_size];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!holds(node.lo, node.hi)) continue;
        if (node.count == 0) {
            stack[top++] = node.first;                                            // right child
            stack[top++] = static_cast<std::uint32_t>(&node - nodes_.data()) + 1; // left
            continue;
        }
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            const Item& it = items_[k];
            if (holds(it.lo, it.hi) && form[it.orientation] == it.offset) f(it.source, it.acting);
        }
    }
}

} // namespace orthoray::shoot
