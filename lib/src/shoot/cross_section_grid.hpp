// Next-hit queries without walking: a grid on the cross-section of the
// bundle of parallel lines of each pair of opposite directions.
//
// On the lattice the ray moves along one of the 2^M diagonal directions
// sigma in {±1}^M (lattice_scene.hpp). Fix sigma. Every line of direction
// sigma is named by its M - 1 cross-section coordinates
//
//     a_j = x_j - sigma_j * sigma_0 * x_0        (j = 1 .. M-1),
//
// which do not change along the line (x_j moves by sigma_j * t and x_0 by
// sigma_0 * t), and a point on it by its depth D = sigma_0 * x_0, which grows
// by exactly t. So "the first element met after p" is a question about one
// line: among the elements the line a(p) meets, the one with the smallest
// hit depth D > D(p). A grid over the (M-1)-dimensional cross-section lists,
// for each cell, the elements that some line of the cell meets, sorted by the
// smallest depth at which a line of the cell can meet them. A query looks up
// one cell (two shifts: cell sides are powers of two) and scans a short run
// of that list; unlike the uniform grid of uniform_grid.hpp it walks no cells
// and takes no branch on which wall the ray crosses next.
//
// Why the scan can start late and stop early. For an element with normal axis
// k and offset c, the hit depth on the line a is sigma_0 * c when k = 0, and
// sigma_k * (c - a_k) otherwise (from a_k = c - sigma_k sigma_0 x_0). Across
// one cell a_k varies by less than the cell side h_k, so every hit depth of a
// member lies in [key, key + h_k - 1], where key is the member's smallest
// possible depth in the cell (clamped to the element's own depth range, so
// key <= the element's largest depth). Members sorted by key: those with
// key + h - 1 <= D(p) (h the largest side) lie behind p, and once a hit at
// depth D* is known, members with key > D* cannot be met at or before it.
//
// Keys are stored in 32 bits, as the quantum q = floor((key - base) / 2^s)
// (base: the least depth of the bundle's elements, so no key is below it;
// s: just enough that the depth range fits). Only these two filters read them, and a quantum bounds
// the key on both sides, base + q 2^s <= key <= base + (q + 1) 2^s - 1, so a member is skipped as
// behind when even its upper bound is, and the scan stops when even the lower bound passes D*:
// every decision stays exact, the filters only let through a few more members (s is 0 when the
// depths fit in 32 bits; 8 on the benchmark's 3D boxes, whose depths reach 10^12). With the plane
// kept inline, an entry is 16 bytes for int64.
//
// Long member lists (some 70 a cell at 10^5 mirrors) are not counted
// through from their start: each cell row also lists, for every slab of
// depth [base + i 2^w, base + (i + 1) 2^w), the first member not behind the
// slab's least depth. A query starts at its depth's slab; the members behind
// it all come before the next slab's start, so it counts them over its own
// slab only, without branches. All arithmetic is exact integer arithmetic
// on values bounded as in lattice_int.hpp (|a_j| <= 2B, offsets into the
// grid <= 4B, keys <= 3B).
//
// Opposite directions sigma and -sigma share one bundle: their lines are
// the same (a_j does not change when every sigma_j does), and on a line the
// depth of -sigma is minus that of sigma. So the bundle of sigma, with
// sigma_0 = +1, also answers -sigma by a reverse scan of the same cell: from
// the last member that may lie before p (key < D(p)) down to the first,
// keeping the largest hit depth below D(p), and stopping at the first
// member whose largest possible depth, key + h - 1, is below the best hit
// (with the quantum's upper bound for key, so again exact). Each cell row
// indexes the slabs twice, once for each scan. Half the bundles hold every
// registration once instead of twice (at 10^5 mirrors 17 MB instead of 35).
//
// One-sided elements cost little at query time: a bundle registers the
// elements that act on either of its directions (LatticeElement::acting),
// and each member carries one bit a direction, tested beside t > 0.
//
// `Counter` (shot_counter.hpp) is told the cell read and each member scanned;
// the default counts nothing and costs nothing.
#pragma once

#include "shoot/element_box.hpp"
#include "shoot/shot_counter.hpp"
#include "shoot/uniform_grid.hpp" // Shot

#include <algorithm>
#include <array>
#include <cstdint>
#include <new>
#include <vector>

namespace orthoray::shoot {

template <class Int, int M, class Counter = NoCounting>
class CrossSectionGrid {
public:
    // About `cells_per_element` cells for each element in each direction's
    // cross-section: more cells mean shorter member lists but more
    // registrations (an element is listed in every cell its shadow covers).
    // `poll` is called once an element in each pass (it may throw
    // lattice::SetupStopped).
    explicit CrossSectionGrid(const LatticeScene& scene, std::int64_t cells_per_element = 1,
                              const lattice::SetupPoll& poll = {});

    // Same contract as UniformGrid::shoot: the first elements met at t > 0.
    Shot<Int> shoot(const Int (&p)[M], unsigned negative) const;

    // Registrations over all directions: the structure's size.
    std::size_t member_count() const {
        std::size_t total = 0;
        for (const Bundle& b : bundles_) total += b.members.size();
        return total;
    }
    // The most members any one cell holds: large when elements crowd into a
    // small part of the scene.
    std::size_t fullest_cell() const {
        std::size_t most = 0;
        for (const Bundle& b : bundles_)
            for (std::size_t c = 0; c < b.cell_total; ++c)
                most = std::max<std::size_t>(most, b.cell_end(c) - b.cell_begin(c));
        return most;
    }
    // The side of a cell of direction `negative`'s cross-section on its
    // axis j (0 .. M-2), in lattice units.
    Int cell_side(unsigned negative, int j) const {
        return Int(1) << bundles_[bundle_of(negative)].shift[j];
    }
    // What the shots cost so far (shot_counter.hpp).
    const Counter& counter() const { return counter_; }
    std::size_t cell_count() const {
        std::size_t total = 0;
        for (const Bundle& b : bundles_) total += b.cell_total;
        return total;
    }

private:
    static constexpr int S = M - 1; // cross-section dimension
    // Slabs a cell row indexes: about this many members a slab, at most
    // 2^max_slab_bits slabs.
    static constexpr std::size_t members_per_slab = 4;
    static constexpr unsigned max_slab_bits = 6;

    using Item = ElementBox<Int, M>;
    // A registration of an element in a cell: 16 bytes for int64. The
    // plane's axis and offset are copied in, so that members met behind p
    // or beyond the best hit so far are rejected without loading the
    // element.
    struct Member {
        Int plane;         // the element's plane x_axis = c, as sigma_axis * c
        std::uint32_t key; // quantum of the smallest depth at which a line of the cell can meet it
        // item << 4 | acts on -sigma << 3 | acts on sigma << 2 | normal axis
        std::uint32_t packed;
    };
    static constexpr std::uint32_t acts_forward = 4, acts_reverse = 8;
    // The lines of the directions sigma (sigma_0 = +1) and -sigma: a grid
    // over their cross-section.
    struct Bundle {
        Int origin[M];           // smallest a_j over all elements
        Int limit[M];            // largest a_j
        unsigned shift[M]{};     // cell side on axis j is 2^shift[j]
        std::int64_t cells[M]{}; // cells on axis j
        std::size_t cell_total = 0;
        Int reach{};             // largest cell side minus one
        Int far{};               // larger than every element's depth
        Int base{};              // no key is smaller
        unsigned key_shift = 0;  // a key's quantum is floor((key - base) / 2^key_shift)
        unsigned slab_shift = 0; // slab i holds the depths base + [i, i + 1) 2^slab_shift
        std::size_t slabs = 1;   // slabs a cell row indexes
        bool empty = true;       // no element acts on either direction
        // Cell c's row, rows[c * 2 (slabs + 1) ..]: for sigma's scan, for
        // slab i the first member not behind the slab's least depth L_i (for
        // slab 0, the cell's first member), then the cell's end; for -sigma's
        // scan, for slab i the first member whose key is surely >= L_i (for
        // slab 0, the cell's first member), then the cell's end.
        std::vector<std::uint32_t> rows;
        std::vector<Member> members; // of each cell, sorted by key

        std::size_t width() const { return 2 * (slabs + 1); }
        std::size_t cell_begin(std::size_t c) const { return rows[c * width()]; }
        std::size_t cell_end(std::size_t c) const { return rows[c * width() + slabs]; }
        // floor((x - base + 1) / 2^key_shift) clamped to [0, 2^32]: the
        // members whose quantum is below it all have key <= x (the upper
        // bound base + (q + 1) 2^key_shift - 1 of a quantum q is <= x).
        std::uint64_t quanta_at_most(const Int& x) const {
            const Int q = Int(x - base + 1) >> key_shift;
            if (q < 0) return 0;
            if (Int(std::int64_t{1} << 32) < q) return std::uint64_t{1} << 32;
            return static_cast<std::uint64_t>(to_index(q));
        }
        // floor((x - base) / 2^key_shift) for x >= base, clamped to 2^32: a
        // member whose quantum exceeds it has key > x.
        std::uint64_t quantum_of(const Int& x) const {
            const Int q = Int(x - base) >> key_shift;
            if (q < 0) return 0;
            if (Int(std::int64_t{1} << 32) < q) return std::uint64_t{1} << 32;
            return static_cast<std::uint64_t>(to_index(q));
        }
        // ceil((x - base) / 2^key_shift) clamped to [0, 2^32]: a member whose
        // quantum is at least it has key >= x (its lower bound
        // base + q 2^key_shift is).
        std::uint64_t quanta_below(const Int& x) const {
            const Int q = Int(x - base + ((Int(1) << key_shift) - 1)) >> key_shift;
            if (q < 0) return 0;
            if (Int(std::int64_t{1} << 32) < q) return std::uint64_t{1} << 32;
            return static_cast<std::uint64_t>(to_index(q));
        }
    };

    std::vector<Item> items_;
    // Bundle i serves the direction masks 2i (sigma_0 = +1) and its
    // opposite 2i ^ (2^M - 1).
    std::array<Bundle, (1u << S)> bundles_;
    [[no_unique_address]] Counter counter_;

    static constexpr unsigned all_axes = (1u << M) - 1;
    static unsigned bundle_of(unsigned negative) {
        return ((negative & 1u) ? negative ^ all_axes : negative) >> 1;
    }
    static Int sigma(unsigned negative, int j) {
        return Int(1 - 2 * static_cast<int>((negative >> j) & 1u));
    }

    // The scans of a cell for sigma (depth grows along the ray) and for
    // -sigma (it falls); `sp` holds sigma_j p_j, `s` sigma.
    Shot<Int> scan_forward(const Bundle& bundle, const std::uint32_t* row, std::size_t slab,
                           const Int& depth, const Int (&p)[M], const Int (&s)[M],
                           const Int (&sp)[M]) const;
    Shot<Int> scan_reverse(const Bundle& bundle, const std::uint32_t* row, std::size_t slab,
                           const Int& depth, const Int (&p)[M], const Int (&s)[M],
                           const Int (&sp)[M]) const;

    void build(Bundle& bundle, unsigned negative, std::int64_t cells_per_element,
               const lattice::SetupPoll& poll);
};

template <class Int, int M, class Counter>
Shot<Int> CrossSectionGrid<Int, M, Counter>::shoot(const Int (&p)[M], unsigned negative) const {
    const Bundle& bundle = bundles_[bundle_of(negative)];
    if (bundle.empty) return {};
    // sigma of the bundle (sigma_0 = +1): the ray's direction or its opposite.
    const unsigned forward = (negative & 1u) ? negative ^ all_axes : negative;
    Int s[M];
    for (int j = 0; j < M; ++j) s[j] = sigma(forward, j);
    std::int64_t c = 0;
    for (int j = S - 1; j >= 0; --j) {
        const Int a = p[j + 1] - s[j + 1] * p[0];
        // A line outside every shadow meets nothing.
        if (a < bundle.origin[j] || bundle.limit[j] < a) return {};
        c = c * bundle.cells[j] + to_index(Int(Int(a - bundle.origin[j]) >> bundle.shift[j]));
    }
    counter_.cell();
    const Int& depth = p[0];
    std::size_t slab = 0;
    if (bundle.base < depth) {
        const Int i = Int(depth - bundle.base) >> bundle.slab_shift;
        slab = i < Int(static_cast<std::int64_t>(bundle.slabs))
                   ? static_cast<std::size_t>(to_index(i))
                   : bundle.slabs - 1;
    }
    // t = sigma_a (c - p_a) = plane - sigma_a p_a along sigma, and minus
    // that along -sigma.
    Int sp[M];
    for (int j = 0; j < M; ++j) sp[j] = s[j] * p[j];
    const std::uint32_t* row = bundle.rows.data() + static_cast<std::size_t>(c) * bundle.width();
    if (negative & 1u) return scan_reverse(bundle, row + bundle.slabs + 1, slab, depth, p, s, sp);
    return scan_forward(bundle, row, slab, depth, p, s, sp);
}

template <class Int, int M, class Counter>
Shot<Int> CrossSectionGrid<Int, M, Counter>::scan_forward(const Bundle& bundle,
                                                          const std::uint32_t* row,
                                                          std::size_t slab, const Int& depth,
                                                          const Int (&p)[M], const Int (&s)[M],
                                                          const Int (&sp)[M]) const {
    Shot<Int> shot;
    // Start at the depth's slab, whose earlier members lie behind p.
    const Member* first = bundle.members.data() + row[slab];
    const Member* last = bundle.members.data() + row[bundle.slabs];
    // Members whose every depth in the cell is <= depth lie behind p; all of
    // them come before the next slab's start (whose least depth exceeds p's),
    // so counting them over this slab's few members, without branches, finds
    // where the rest begins.
    const std::uint64_t behind = bundle.quanta_at_most(Int(depth - bundle.reach));
    const Member* slab_end = bundle.members.data() + row[slab + 1];
    std::ptrdiff_t skip = 0;
    for (const Member* m = first; m != slab_end; ++m) skip += m->key < behind;
    first += skip;
    // The best hit's depth; until one is found, past every member's depth.
    Int best = bundle.far;
    std::uint64_t beyond = bundle.quantum_of(best);
    for (; first != last && !(beyond < first->key); ++first) {
        counter_.member();
        const int a = static_cast<int>(first->packed & 3u);
        const Int t = first->plane - sp[a];
        if (t <= 0 || best < Int(depth + t) || !(first->packed & acts_forward)) continue;
        counter_.box_test();
        const Item& it = items_[first->packed >> 4];
        if (it.holds(p, s, t)) {
            shot.record(t, a, it.absorber, it.index);
            best = depth + shot.t;
            beyond = bundle.quantum_of(best);
        }
    }
    return shot;
}

template <class Int, int M, class Counter>
Shot<Int> CrossSectionGrid<Int, M, Counter>::scan_reverse(const Bundle& bundle,
                                                          const std::uint32_t* row,
                                                          std::size_t slab, const Int& depth,
                                                          const Int (&p)[M], const Int (&s)[M],
                                                          const Int (&sp)[M]) const {
    Shot<Int> shot;
    Int r[M]; // -sigma, the ray's direction
    for (int j = 0; j < M; ++j) r[j] = -s[j];
    // Along -sigma a hit lies at a depth below p's. Members whose key is
    // surely >= depth lie at or behind p; those from the slab's start on
    // have key >= L_slab, and from the next slab's start on key >= L_(slab + 1)
    // > depth, so counting the ones below depth over this slab's members
    // finds where the scan starts (one past its first member).
    const Member* begin = bundle.members.data() + row[0];
    const Member* first = bundle.members.data() + row[slab];
    const std::uint64_t below = bundle.quanta_below(depth);
    const Member* slab_end = bundle.members.data() + row[slab + 1];
    std::ptrdiff_t ahead = 0;
    for (const Member* m = first; m != slab_end; ++m) ahead += m->key < below;
    first += ahead;
    // The best hit's depth (the largest below p's); until one is found,
    // below every member's, so that nothing stops the scan. A member whose
    // every depth, key + h - 1 <= key + reach, is below the best cannot meet
    // the ray there: the scan stops at the first one whose quantum says so.
    Int best = bundle.base - 1;
    std::uint64_t short_of = 0;
    while (first != begin) {
        --first;
        if (first->key < short_of) break;
        counter_.member();
        const int a = static_cast<int>(first->packed & 3u);
        const Int t = sp[a] - first->plane;
        if (t <= 0 || Int(depth - t) < best || !(first->packed & acts_reverse)) continue;
        counter_.box_test();
        const Item& it = items_[first->packed >> 4];
        if (it.holds(p, r, t)) {
            shot.record(t, a, it.absorber, it.index);
            best = depth - shot.t;
            short_of = bundle.quanta_at_most(Int(best - bundle.reach - 1));
        }
    }
    return shot;
}

} // namespace orthoray::shoot

// The constructor and the layout of the bundles.
#include "shoot/cross_section_grid_build.hpp"
