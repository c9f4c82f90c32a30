// Next-hit queries without walking: a grid on the cross-section of each
// direction's bundle of parallel lines.
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
// Each direction has its own bundle, so one-sided elements cost nothing at
// query time: a bundle registers only the elements that act on its
// direction (LatticeElement::acting), and the others are never seen.
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
    Int cell_side(unsigned negative, int j) const { return Int(1) << bundles_[negative].shift[j]; }
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
        std::uint32_t item_and_axis; // item << 2 | normal axis
    };
    // The lines of one direction: a grid over their cross-section.
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
        bool empty = true;       // no element acts on this direction
        // Cell c's row, rows[c * (slabs + 1) ..]: for slab i the first member
        // not behind the slab's least depth (for slab 0, the cell's first
        // member), then the cell's end.
        std::vector<std::uint32_t> rows;
        std::vector<Member> members; // of each cell, sorted by key

        std::size_t cell_begin(std::size_t c) const { return rows[c * (slabs + 1)]; }
        std::size_t cell_end(std::size_t c) const { return rows[c * (slabs + 1) + slabs]; }
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
    };

    std::vector<Item> items_;
    std::array<Bundle, (1u << M)> bundles_;
    [[no_unique_address]] Counter counter_;

    static Int sigma(unsigned negative, int j) {
        return Int(1 - 2 * static_cast<int>((negative >> j) & 1u));
    }

    void build(Bundle& bundle, unsigned negative, std::int64_t cells_per_element,
               const lattice::SetupPoll& poll);
};

template <class Int, int M, class Counter>
CrossSectionGrid<Int, M, Counter>::CrossSectionGrid(const LatticeScene& scene,
                                                    std::int64_t cells_per_element,
                                                    const lattice::SetupPoll& poll) {
    // A member names its element in 30 bits (Member::item_and_axis); a scene
    // of 2^30 elements would not fit in memory anyway.
    if (scene.elements.size() >= (std::size_t{1} << 30)) throw std::bad_alloc();
    items_.reserve(scene.elements.size());
    for (const LatticeElement& e : scene.elements) {
        poll();
        items_.emplace_back(e, static_cast<std::uint32_t>(items_.size()));
    }
    // Elements in Z-order of their low corners: a cell's members, and the
    // ray's successive hits, are spatial neighbours, so they then share cache
    // lines instead of being scattered over the scene's declaration order.
    if (!items_.empty()) {
        constexpr int bits = 64 / M;
        Integer lo[M], extent[M];
        for (int j = 0; j < M; ++j) {
            lo[j] = scene.elements[0].lo[j];
            Integer hi = scene.elements[0].hi[j];
            for (const LatticeElement& e : scene.elements) {
                if (e.lo[j] < lo[j]) lo[j] = e.lo[j];
                if (hi < e.hi[j]) hi = e.hi[j];
            }
            extent[j] = hi - lo[j] + 1;
        }
        std::vector<std::pair<std::uint64_t, std::uint32_t>> order(items_.size());
        for (std::uint32_t e = 0; e < items_.size(); ++e) {
            poll();
            std::uint64_t key = 0;
            for (int j = 0; j < M; ++j) {
                // floor((lo - min) * 2^bits / extent) < 2^bits, exactly.
                const Integer q = ((scene.elements[e].lo[j] - lo[j]) << bits) / extent[j];
                const std::uint64_t i = q.get_ui();
                for (int bit = 0; bit < bits; ++bit) key |= ((i >> bit) & 1u) << (bit * M + j);
            }
            order[e] = {key, e};
        }
        std::sort(order.begin(), order.end());
        std::vector<Item> sorted;
        sorted.reserve(items_.size());
        for (const auto& [key, e] : order) sorted.push_back(std::move(items_[e]));
        items_ = std::move(sorted);
    }
    for (unsigned negative = 0; negative < bundles_.size(); ++negative)
        build(bundles_[negative], negative, cells_per_element, poll);
}

template <class Int, int M, class Counter>
void CrossSectionGrid<Int, M, Counter>::build(Bundle& bundle, unsigned negative,
                                              std::int64_t cells_per_element,
                                              const lattice::SetupPoll& poll) {
    bundle.rows.assign(2, 0);
    bundle.cell_total = 1;
    // The elements this direction's rays can meet: those acting on it.
    std::vector<std::uint32_t> acting;
    for (std::uint32_t e = 0; e < items_.size(); ++e)
        if (items_[e].acts_on(negative)) acting.push_back(e);
    if (acting.empty()) return;
    bundle.empty = false;
    const Int s0 = sigma(negative, 0);
    // The shadow of an element on the cross-section: a_j = x_j - r_j x_0 with
    // r_j = sigma_j sigma_0, over the element's box; its bounding box is
    // [lo_j - max(r_j x_0), hi_j - min(r_j x_0)].
    auto shadow = [&](const Item& it, int j, Int& lo, Int& hi) {
        const Int r = sigma(negative, j) * s0;
        const Int x_lo = r * it.lo[0], x_hi = r * it.hi[0];
        lo = it.lo[j] - (x_lo < x_hi ? x_hi : x_lo);
        hi = it.hi[j] - (x_lo < x_hi ? x_lo : x_hi);
    };
    for (int j = 0; j < S; ++j)
        for (std::size_t k = 0; k < acting.size(); ++k) {
            poll();
            Int lo, hi;
            shadow(items_[acting[k]], j + 1, lo, hi);
            if (k == 0 || lo < bundle.origin[j]) bundle.origin[j] = lo;
            if (k == 0 || bundle.limit[j] < hi) bundle.limit[j] = hi;
        }
    // k cells a side with k^S >= cells_per_element * n; each side a power of two.
    std::int64_t k = 1;
    const std::int64_t want = cells_per_element * static_cast<std::int64_t>(acting.size());
    while (true) {
        std::int64_t p = 1;
        for (int j = 0; j < S; ++j) p *= k;
        if (p >= want || S == 0) break;
        ++k;
    }
    std::int64_t total = 1;
    auto lay_out = [&] {
        total = 1;
        bundle.reach = 0;
        for (int j = 0; j < S; ++j) {
            const Int points = bundle.limit[j] - bundle.origin[j] + 1;
            // The least shift with k 2^shift >= points. Below bits(points) -
            // bits(k) it is too small (k 2^shift < 2^(bits(points) - 1)), so
            // the search starts there: one or two rounds, where counting up
            // from 0 took one round a bit, each on a number of that many
            // bits (minutes at 10^6 digits).
            const unsigned points_bits = lattice::bit_length(points);
            const unsigned k_bits = lattice::bit_length(Int(k));
            unsigned shift = points_bits > k_bits ? points_bits - k_bits : 0;
            while (Int(Int(k) << shift) < points) ++shift;
            bundle.shift[j] = shift;
            bundle.cells[j] = to_index(Int(Int(points - 1) >> shift)) + 1;
            total *= bundle.cells[j];
            if (bundle.reach < Int(Int(1) << shift) - 1) bundle.reach = Int(Int(1) << shift) - 1;
        }
    };
    lay_out();

    // Every cell an element's shadow box covers, with the element's smallest
    // possible depth there.
    auto for_each_cell = [&](std::uint32_t e, auto&& visit) {
        poll();
        const Item& it = items_[e];
        std::int64_t first[M], last[M], i[M];
        for (int j = 0; j < S; ++j) {
            Int lo, hi;
            shadow(it, j + 1, lo, hi);
            first[j] = to_index(Int(Int(lo - bundle.origin[j]) >> bundle.shift[j]));
            last[j] = to_index(Int(Int(hi - bundle.origin[j]) >> bundle.shift[j]));
            i[j] = first[j];
        }
        // The element's own depth range, sigma_0 * x_0 over its box.
        const Int d_lo = s0 * it.lo[0] < s0 * it.hi[0] ? Int(s0 * it.lo[0]) : Int(s0 * it.hi[0]);
        const int a = it.axis;
        while (true) {
            std::int64_t c = 0;
            for (int j = S - 1; j >= 0; --j) c = c * bundle.cells[j] + i[j];
            Int key = d_lo;
            if constexpr (S > 0)
                if (a != 0) {
                    // Depth sigma_a (c - a_a), over the cell's a_a in [A, A + h - 1].
                    const Int cell_lo =
                        bundle.origin[a - 1] + (Int(i[a - 1]) << bundle.shift[a - 1]);
                    const Int cell_hi = cell_lo + (Int(1) << bundle.shift[a - 1]) - 1;
                    const Int sa = sigma(negative, a);
                    const Int d1 = sa * Int(it.lo[a] - cell_lo), d2 = sa * Int(it.lo[a] - cell_hi);
                    const Int d = d1 < d2 ? d1 : d2;
                    if (key < d) key = d;
                }
            visit(c, key);
            int j = 0;
            while (j < S && i[j] == last[j]) i[j] = first[j], ++j;
            if (j >= S) break;
            ++i[j];
        }
    };
    // The depths of the elements: keys lie in [base, far - 1].
    for (std::size_t n = 0; n < acting.size(); ++n) {
        poll();
        const Item& it = items_[acting[n]];
        const Int x_lo = s0 * it.lo[0], x_hi = s0 * it.hi[0];
        const Int d_lo = x_lo < x_hi ? x_lo : x_hi, d_hi = x_lo < x_hi ? x_hi : x_lo;
        if (n == 0 || d_lo < bundle.base) bundle.base = d_lo;
        if (n == 0 || bundle.far < d_hi) bundle.far = d_hi;
    }
    bundle.far += 1;
    const unsigned depth_bits = lattice::bit_length(Int(bundle.far - bundle.base));
    bundle.key_shift = depth_bits > 32 ? depth_bits - 32 : 0;
    // Registrations grow with the elements' shadows measured in cells. When
    // they pass 10 an element, fewer, larger cells (a quarter as many in 3D)
    // hold the same lines in far less memory: at 10^5 random mirrors this
    // cut the members from 10.8M to 4.3M at equal speed, while up to 10^4
    // the finer grid stays under the limit and is faster (docs/shooting.md).
    // Past 2^15 elements the members no longer fit in any cache, a shot
    // misses anyway, and the slabs keep long member lists cheap: there a
    // limit of 5 an element cuts the members again (37 MB less peak memory
    // at 10^5 random mirrors) and was faster, while at 10^4 it cost 10%.
    // A small scene may always take 2^13 registrations (128 KB a
    // direction): at 10^2 random mirrors the finer grid that allows is
    // 1.3x faster. The count of a layout is the sum over the elements of
    // the cells their shadow boxes span, one product each.
    const std::size_t per_element = acting.size() > (std::size_t{1} << 15) ? 5 : 10;
    const std::size_t allowed = std::max(per_element * acting.size(), std::size_t{1} << 13);
    auto registrations = [&] {
        std::size_t sum = 0;
        for (const std::uint32_t e : acting) {
            poll();
            std::size_t spanned = 1;
            for (int j = 0; j < S; ++j) {
                Int lo, hi;
                shadow(items_[e], j + 1, lo, hi);
                const std::int64_t first =
                    to_index(Int(Int(lo - bundle.origin[j]) >> bundle.shift[j]));
                const std::int64_t last =
                    to_index(Int(Int(hi - bundle.origin[j]) >> bundle.shift[j]));
                spanned *= static_cast<std::size_t>(last - first + 1);
            }
            sum += spanned;
        }
        return sum;
    };
    while (registrations() > allowed && k > 1) {
        k /= 2;
        lay_out();
    }
    std::vector<std::uint32_t> offsets(static_cast<std::size_t>(total) + 1, 0);
    for (const std::uint32_t e : acting)
        for_each_cell(e, [&](std::int64_t c, const Int&) { ++offsets[c + 1]; });
    for (std::size_t c = 1; c < offsets.size(); ++c) offsets[c] += offsets[c - 1];
    bundle.members.resize(offsets.back());
    bundle.cell_total = static_cast<std::size_t>(total);
    {
        std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
        for (const std::uint32_t e : acting)
            for_each_cell(e, [&](std::int64_t c, const Int& key) {
                const Item& it = items_[e];
                bundle.members[fill[c]++] =
                    Member{Int(sigma(negative, it.axis) * it.lo[it.axis]),
                           static_cast<std::uint32_t>(bundle.quantum_of(key)), e << 2 | it.axis};
            });
    }
    // Ties broken by the element, so that the order does not depend on the sort.
    for (std::size_t c = 0; c + 1 < offsets.size(); ++c)
        std::sort(bundle.members.begin() + offsets[c], bundle.members.begin() + offsets[c + 1],
                  [](const Member& x, const Member& y) {
                      return x.key < y.key || (x.key == y.key && x.item_and_axis < y.item_and_axis);
                  });
    // About members_per_slab members a slab on average, at most max_slabs.
    const std::size_t per_cell = bundle.members.size() / bundle.cell_total;
    unsigned slab_bits = 0;
    while ((std::size_t{members_per_slab} << slab_bits) < per_cell && slab_bits < max_slab_bits)
        ++slab_bits;
    bundle.slabs = std::size_t{1} << slab_bits;
    bundle.slab_shift = depth_bits > slab_bits ? depth_bits - slab_bits : 0;
    const std::size_t width = bundle.slabs + 1;
    bundle.rows.assign(bundle.cell_total * width, 0);
    for (std::size_t c = 0; c < bundle.cell_total; ++c) {
        poll();
        std::uint32_t first = offsets[c];
        const std::uint32_t end = offsets[c + 1];
        bundle.rows[c * width] = first;
        for (std::size_t slab = 1; slab < bundle.slabs; ++slab) {
            // Behind every point of the slab: key + reach <= its least depth.
            const Int least =
                bundle.base + (Int(static_cast<std::int64_t>(slab)) << bundle.slab_shift);
            const std::uint64_t behind = bundle.quanta_at_most(Int(least - bundle.reach));
            while (first != end && bundle.members[first].key < behind) ++first;
            bundle.rows[c * width + slab] = first;
        }
        bundle.rows[c * width + bundle.slabs] = end;
    }
}

template <class Int, int M, class Counter>
Shot<Int> CrossSectionGrid<Int, M, Counter>::shoot(const Int (&p)[M], unsigned negative) const {
    Shot<Int> shot;
    const Bundle& bundle = bundles_[negative];
    if (bundle.empty) return shot;
    Int s[M];
    for (int j = 0; j < M; ++j) s[j] = sigma(negative, j);
    std::int64_t c = 0;
    for (int j = S - 1; j >= 0; --j) {
        const Int a = p[j + 1] - s[j + 1] * s[0] * p[0];
        // A line outside every shadow meets nothing.
        if (a < bundle.origin[j] || bundle.limit[j] < a) return shot;
        c = c * bundle.cells[j] + to_index(Int(Int(a - bundle.origin[j]) >> bundle.shift[j]));
    }
    counter_.cell();
    const Int depth = s[0] * p[0];
    // Start at the depth's slab, whose earlier members lie behind p.
    std::size_t slab = 0;
    if (bundle.base < depth) {
        const Int i = Int(depth - bundle.base) >> bundle.slab_shift;
        slab = i < Int(static_cast<std::int64_t>(bundle.slabs))
                   ? static_cast<std::size_t>(to_index(i))
                   : bundle.slabs - 1;
    }
    const std::uint32_t* row = bundle.rows.data() + c * (bundle.slabs + 1);
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
    // t = sigma_a (c - p_a) = plane - sigma_a p_a.
    Int sp[M];
    for (int j = 0; j < M; ++j) sp[j] = s[j] * p[j];
    // The best hit's depth; until one is found, past every member's depth.
    Int best = bundle.far;
    std::uint64_t beyond = bundle.quantum_of(best);
    for (; first != last && !(beyond < first->key); ++first) {
        counter_.member();
        const int a = static_cast<int>(first->item_and_axis & 3u);
        const Int t = first->plane - sp[a];
        if (t <= 0 || best < Int(depth + t)) continue;
        counter_.box_test();
        const Item& it = items_[first->item_and_axis >> 2];
        if (it.holds(p, s, t)) {
            shot.record(t, a, it.absorber, it.index);
            best = depth + shot.t;
            beyond = bundle.quantum_of(best);
        }
    }
    return shot;
}

} // namespace orthoray::shoot
