// Next-hit queries on the lattice: a uniform grid walked with an exact
// integer DDA.
//
// The ray is diagonal (see lattice_scene.hpp), so from point p in direction
// sigma in {±1}^M it is p + t*sigma, and it crosses cell walls at integer t.
// Each element is registered in every cell whose CLOSED box meets the
// element's closed box, so a point where the ray meets an element is always
// found in the cell being walked when the ray is there, even on a cell wall
// or corner. Walking cells in order of t, the first cell that holds a hit
// with 0 < t <= t_exit(cell) holds the smallest such t over the whole scene,
// and all elements met at that t (they all contain the hit point, which lies
// in the cell's closed box).
//
// One-sided elements act on half of the directions only (LatticeElement::
// acting). When the scene has any, each cell keeps one member list for every
// direction, holding only the elements that act on it, beside the list of
// all elements (which the piece tables' construction walks): the filter is
// applied once, when the lists are built, and a shot reads the lists of its
// own direction with no test per element.
//
// `Counter` (shot_counter.hpp) is told each cell walked and each member
// tested; the default counts nothing and costs nothing.
#pragma once

#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "lattice/setup_poll.hpp"
#include "shoot/element_box.hpp"
#include "shoot/shot_counter.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace orthoray::shoot {

// What the ray meets next: nothing (escape), or at parameter t > 0 a point
// where `flip` holds the normal axes of the mirrors met (bit i: active axis i)
// and `absorber` says whether an absorber is met too.
template <class Int>
struct Shot {
    bool escape = true;
    bool absorber = false;
    unsigned flip = 0;
    Int t{};
    std::uint32_t mirror = 0; // one of the mirrors met (when flip != 0): index in the scene
    unsigned met = 0;         // normal axes of every element met, absorbers included
    // False only when the shooter knows that the segment to the hit cannot
    // contain the target (the piece tables mark the few pieces whose
    // segments can), so that the stepper may skip its target test.
    bool near_target = true;

    // Adds element `index` (normal `axis`), met at parameter `at` <= t: a
    // smaller parameter replaces what was found, an equal one joins it, so
    // that every element met at the first point counts.
    void record(const Int& at, int axis, bool is_absorber, std::uint32_t index) {
        if (escape || at < t) {
            escape = false;
            t = at;
            flip = 0;
            met = 0;
            absorber = false;
        }
        met |= 1u << axis;
        if (is_absorber) {
            absorber = true;
        } else {
            flip |= 1u << axis;
            mirror = index;
        }
    }
};

template <class Int, int M, class Counter = NoCounting>
class UniformGrid {
public:
    // About `cells_per_element` cells for every `per_elements` elements: more
    // cells mean fewer elements tested per cell but more cell walls crossed
    // per shot (docs/average-case.md derives the trade-off). `poll` is called
    // once an element in each pass (it may throw lattice::SetupStopped).
    explicit UniformGrid(const LatticeScene& scene, std::int64_t cells_per_element = 2,
                         const lattice::SetupPoll& poll = {}, std::int64_t per_elements = 1);

    // `negative` bit i set: the ray moves towards -infinity on axis i.
    // Only elements that act on that direction are met.
    Shot<Int> shoot(const Int (&p)[M], unsigned negative) const {
        return shoot_in(p, negative, list_base_[negative]);
    }
    // The same over every element, whichever directions it acts on.
    Shot<Int> shoot_any(const Int (&p)[M], unsigned negative) const {
        return shoot_in(p, negative, 0);
    }

    std::size_t cell_count() const { return static_cast<std::size_t>(cells_); }
    // The side of a cell on axis j, in lattice units.
    const Int& cell_side(int j) const { return h_[j]; }
    // What the shots cost so far (shot_counter.hpp).
    const Counter& counter() const { return counter_; }

    // Calls visit(index) for every element whose closed box contains p (an
    // element may be visited more than once).
    template <class Visit>
    void for_each_element_at(const Int (&p)[M], Visit&& visit) const;

    // Calls visit(index) for every element registered in a cell that element
    // `e` is registered in: a superset of the elements whose boxes meet e's.
    template <class Visit>
    void for_each_neighbour(std::uint32_t e, Visit&& visit) const;

    std::size_t size() const { return items_.size(); }
    // Element e as the grid holds it: its box in Int, its axis and sides.
    const ElementBox<Int, M>& element(std::uint32_t e) const { return items_[e]; }

    // The Z-order (Morton) index of the cell holding p, clamped to the grid:
    // points with close keys lie in nearby cells, so work sorted by it walks
    // the grid (and whatever is laid out in that order) with few cache misses.
    std::uint64_t locality_key(const Int (&p)[M]) const {
        std::uint64_t key = 0;
        if (items_.empty()) return key;
        for (int j = 0; j < M; ++j) {
            const std::int64_t i = std::clamp<std::int64_t>(
                to_index(floor_div(Int(p[j] - lo_[j]), h_[j])), 0, n_[j] - 1);
            for (int bit = 0; bit < 64 / M; ++bit)
                key |= ((static_cast<std::uint64_t>(i) >> bit) & 1u) << (bit * M + j);
        }
        return key;
    }

    // The most elements any one cell holds: large when elements cluster in a
    // small part of the box, where a grid degrades and a hierarchy does not.
    std::size_t fullest_cell() const {
        std::size_t most = 0;
        for (std::size_t c = 0; c < static_cast<std::size_t>(cells_); ++c)
            most = std::max<std::size_t>(most, offsets_[c + 1] - offsets_[c]);
        return most;
    }

private:
    using Item = ElementBox<Int, M>;
    std::vector<Item> items_;
    Int lo_[M], hi_[M], h_[M]; // bounding box, cell size
    std::int64_t n_[M]{};      // cells per axis
    std::int64_t cells_ = 0;   // cells in the grid
    // CSR: list slot -> [offsets_[c], offsets_[c+1]) in members_. Slots
    // 0 .. cells_-1 list every element; with one-sided elements, slots
    // (1 + d) * cells_ + c list those acting on direction d.
    std::vector<std::uint32_t> offsets_;
    std::vector<std::uint32_t> members_;
    std::int64_t list_base_[1u << M]{}; // direction -> its first slot
    [[no_unique_address]] Counter counter_;

    Shot<Int> shoot_in(const Int (&p)[M], unsigned negative, std::int64_t base) const;

    // Cells i along axis j whose closed box [lo + i h, lo + (i+1) h] meets
    // [a, b]: floor((a - lo - 1) / h) <= i <= floor((b - lo) / h), clamped.
    void cell_range(const Item& it, int j, std::int64_t& first, std::int64_t& last) const {
        first = std::max<std::int64_t>(0, to_index(floor_div(Int(it.lo[j] - lo_[j] - 1), h_[j])));
        last =
            std::min<std::int64_t>(n_[j] - 1, to_index(floor_div(Int(it.hi[j] - lo_[j]), h_[j])));
    }

    template <class Visit>
    void for_each_cell(const Item& it, Visit&& visit) const {
        std::int64_t first[M], last[M], i[M];
        for (int j = 0; j < M; ++j) {
            cell_range(it, j, first[j], last[j]);
            i[j] = first[j];
        }
        while (true) {
            visit(cell_index(i));
            int j = 0;
            while (j < M && i[j] == last[j]) i[j] = first[j], ++j;
            if (j == M) break;
            ++i[j];
        }
    }

    std::int64_t cell_index(const std::int64_t (&i)[M]) const {
        std::int64_t c = 0;
        for (int j = M - 1; j >= 0; --j) c = c * n_[j] + i[j];
        return c;
    }
};

template <class Int, int M, class Counter>
UniformGrid<Int, M, Counter>::UniformGrid(const LatticeScene& scene, std::int64_t cells_per_element,
                                          const lattice::SetupPoll& poll,
                                          std::int64_t per_elements) {
    items_.reserve(scene.elements.size());
    for (const LatticeElement& e : scene.elements) {
        poll();
        items_.emplace_back(e, static_cast<std::uint32_t>(items_.size()));
    }
    if (items_.empty()) {
        offsets_.assign(1, 0);
        return;
    }
    for (int j = 0; j < M; ++j) {
        lo_[j] = items_[0].lo[j];
        hi_[j] = items_[0].hi[j];
        for (const Item& it : items_) {
            if (it.lo[j] < lo_[j]) lo_[j] = it.lo[j];
            if (hi_[j] < it.hi[j]) hi_[j] = it.hi[j];
        }
    }
    // k cells per axis with k^M >= cells_per_element * n / per_elements,
    // fewer on an axis whose extent has fewer lattice points.
    std::int64_t k = 1, want = (cells_per_element * static_cast<std::int64_t>(items_.size()) +
                                per_elements - 1) /
                               per_elements;
    while (true) {
        std::int64_t p = 1;
        for (int j = 0; j < M; ++j) p *= k;
        if (p >= want) break;
        ++k;
    }
    std::int64_t total = 1;
    for (int j = 0; j < M; ++j) {
        Int points = hi_[j] - lo_[j] + 1;
        Int cells = points < Int(k) ? points : Int(k);
        h_[j] = floor_div(points + cells - 1, cells);
        n_[j] = to_index(floor_div(points + h_[j] - 1, h_[j]));
        total *= n_[j];
    }
    cells_ = total;
    const std::int64_t lists = scene.one_sided ? 1 + (std::int64_t{1} << M) : 1;
    for (unsigned d = 0; d < (1u << M); ++d) list_base_[d] = scene.one_sided ? (1 + d) * total : 0;
    // List 0 holds every element, list 1 + d those acting on direction d.
    auto in_list = [](const Item& it, std::int64_t list) {
        return list == 0 || it.acts_on(static_cast<unsigned>(list - 1));
    };
    offsets_.assign(static_cast<std::size_t>(lists * total) + 1, 0);
    for (std::int64_t list = 0; list < lists; ++list)
        for (const Item& it : items_) {
            poll();
            if (in_list(it, list))
                for_each_cell(it, [&](std::int64_t c) { ++offsets_[list * total + c + 1]; });
        }
    for (std::size_t c = 1; c < offsets_.size(); ++c) offsets_[c] += offsets_[c - 1];
    members_.resize(offsets_.back());
    std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::int64_t list = 0; list < lists; ++list)
        for (std::uint32_t e = 0; e < items_.size(); ++e) {
            poll();
            if (in_list(items_[e], list))
                for_each_cell(items_[e],
                              [&](std::int64_t c) { members_[fill[list * total + c]++] = e; });
        }
}

template <class Int, int M, class Counter>
template <class Visit>
void UniformGrid<Int, M, Counter>::for_each_element_at(const Int (&p)[M], Visit&& visit) const {
    if (items_.empty()) return;
    std::int64_t i[M];
    for (int j = 0; j < M; ++j) {
        if (p[j] < lo_[j] || hi_[j] < p[j]) return;
        i[j] = std::min<std::int64_t>(n_[j] - 1, to_index(floor_div(Int(p[j] - lo_[j]), h_[j])));
    }
    // Every element containing p is registered in every cell whose closed box
    // contains p, so one such cell holds them all.
    const std::int64_t c = cell_index(i);
    for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
        const Item& it = items_[members_[k]];
        bool inside = true;
        for (int j = 0; j < M && inside; ++j) inside = !(p[j] < it.lo[j]) && !(it.hi[j] < p[j]);
        if (inside) visit(members_[k]);
    }
}

template <class Int, int M, class Counter>
template <class Visit>
void UniformGrid<Int, M, Counter>::for_each_neighbour(std::uint32_t e, Visit&& visit) const {
    for_each_cell(items_[e], [&](std::int64_t c) {
        for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) visit(members_[k]);
    });
}

template <class Int, int M, class Counter>
Shot<Int> UniformGrid<Int, M, Counter>::shoot_in(const Int (&p)[M], unsigned negative,
                                                 std::int64_t base) const {
    Shot<Int> shot;
    if (items_.empty()) return shot;
    // sigma_j = ±1: multiplying by it keeps the loops free of direction branches.
    Int sigma[M];
    for (int j = 0; j < M; ++j) sigma[j] = Int(1 - 2 * static_cast<int>((negative >> j) & 1u));

    // Clip the ray to the closed bounding box: t in [t_in, t_out].
    Int t_in = 0, t_out = 0;
    for (int j = 0; j < M; ++j) {
        const bool neg = (negative >> j) & 1u;
        Int enter = neg ? Int(p[j] - hi_[j]) : Int(lo_[j] - p[j]);
        Int leave = neg ? Int(p[j] - lo_[j]) : Int(hi_[j] - p[j]);
        if (t_in < enter) t_in = enter;
        if (j == 0 || leave < t_out) t_out = leave;
    }
    if (t_out < t_in || t_out <= 0) return shot;

    // The cell the ray is in just after t_in, and the t at which it crosses
    // the next wall on each axis.
    std::int64_t i[M], stride[M], c = 0;
    Int wall_t[M];
    for (int j = M - 1; j >= 0; --j) {
        const bool neg = (negative >> j) & 1u;
        Int rel = p[j] + sigma[j] * t_in - lo_[j];
        std::int64_t cell = to_index(neg ? floor_div(Int(rel - 1), h_[j]) : floor_div(rel, h_[j]));
        i[j] = std::clamp<std::int64_t>(cell, 0, n_[j] - 1);
        Int wall = lo_[j] + Int(i[j] + (neg ? 0 : 1)) * h_[j];
        wall_t[j] = sigma[j] * Int(wall - p[j]);
        c = c * n_[j] + i[j];
    }
    stride[0] = 1;
    for (int j = 1; j < M; ++j) stride[j] = stride[j - 1] * n_[j - 1];
    c += base; // the walk stays within one list: strides move between its cells

    while (true) {
        Int t_exit = wall_t[0];
        for (int j = 1; j < M; ++j)
            if (wall_t[j] < t_exit) t_exit = wall_t[j];
        counter_.cell();
        for (std::uint32_t k = offsets_[c]; k < offsets_[c + 1]; ++k) {
            counter_.member();
            const Item& it = items_[members_[k]];
            const int a = it.axis;
            const Int t = sigma[a] * Int(it.lo[a] - p[a]);
            if (t <= 0 || t_exit < t || (!shot.escape && shot.t < t)) continue;
            counter_.box_test();
            if (it.holds(p, sigma, t)) shot.record(t, a, it.absorber, it.index);
        }
        if (!shot.escape) return shot;
        for (int j = 0; j < M; ++j) {
            if (wall_t[j] != t_exit) continue;
            const bool neg = (negative >> j) & 1u;
            i[j] += neg ? -1 : 1;
            if (i[j] < 0 || i[j] >= n_[j]) return shot; // left the box: nothing more to meet
            c += neg ? -stride[j] : stride[j];
            wall_t[j] += h_[j];
        }
    }
}

} // namespace orthoray::shoot
