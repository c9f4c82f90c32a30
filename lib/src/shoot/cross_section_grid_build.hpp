// The cross-section grid's construction (cross_section_grid.hpp): the
// elements in Z-order, then for each pair of opposite directions the layout
// of its cells, its members sorted by key and the slab rows of both scans.
#pragma once

#include "shoot/cross_section_grid.hpp"

namespace orthoray::shoot {

template <class Int, int M, class Counter>
CrossSectionGrid<Int, M, Counter>::CrossSectionGrid(const LatticeScene& scene,
                                                    std::int64_t cells_per_element,
                                                    const lattice::SetupPoll& poll) {
    // A member names its element in 28 bits (Member::packed); a scene of
    // 2^28 elements (some 50 GB as a lattice scene) would not fit anyway.
    if (scene.elements.size() >= (std::size_t{1} << 28)) throw std::bad_alloc();
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
    for (unsigned i = 0; i < bundles_.size(); ++i)
        build(bundles_[i], 2 * i, cells_per_element, poll);
}

template <class Int, int M, class Counter>
void CrossSectionGrid<Int, M, Counter>::build(Bundle& bundle, unsigned negative,
                                              std::int64_t cells_per_element,
                                              const lattice::SetupPoll& poll) {
    bundle.rows.assign(4, 0);
    bundle.cell_total = 1;
    // The elements the rays of sigma or -sigma can meet: those acting on
    // either direction.
    const unsigned opposite = negative ^ all_axes;
    std::vector<std::uint32_t> acting;
    for (std::uint32_t e = 0; e < items_.size(); ++e)
        if (items_[e].acts_on(negative) || items_[e].acts_on(opposite)) acting.push_back(e);
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

    // The cells some line of which meets an element, as boxes of cells
    // (first[j] .. last[j] on each axis j), disjoint. An element normal to
    // axis 0 casts a box: a_j = x_j - r_j c. One normal to axis a > 0 casts
    // a sheared box: a_a = c - r_a x_0 fixes x_0 to a short range in each
    // cell column of axis a, and only the cells the other a_j = x_j - r_j x_0
    // reach over that range can meet it. Its bounding box also holds the
    // corners the shear leaves empty (for an element as long on axis 0 as
    // on its other axis, half of the box): registering those cells only made
    // longer lists whose extra members fail the box test.
    auto for_each_block = [&](const Item& it, auto&& block) {
        std::int64_t first[M], last[M];
        for (int j = 0; j < S; ++j) {
            Int lo, hi;
            shadow(it, j + 1, lo, hi);
            first[j] = to_index(Int(Int(lo - bundle.origin[j]) >> bundle.shift[j]));
            last[j] = to_index(Int(Int(hi - bundle.origin[j]) >> bundle.shift[j]));
        }
        const int a = it.axis;
        if (a == 0 || S < 2) {
            block(first, last);
            return;
        }
        // u = r_a x_0 over the element, and over the cells of column i of
        // axis a: a_a = c - u in [A, A + h - 1] means u in [c - A - h + 1, c - A].
        const Int ra = sigma(negative, a) * s0;
        const Int u1 = ra * it.lo[0], u2 = ra * it.hi[0];
        const Int u_min = u1 < u2 ? u1 : u2, u_max = u1 < u2 ? u2 : u1;
        const std::int64_t column_first = first[a - 1], column_last = last[a - 1];
        for (std::int64_t i = column_first; i <= column_last; ++i) {
            const Int cell_lo = bundle.origin[a - 1] + (Int(i) << bundle.shift[a - 1]);
            const Int cell_hi = cell_lo + (Int(1) << bundle.shift[a - 1]) - 1;
            const Int from = it.lo[a] - cell_hi, to = it.lo[a] - cell_lo;
            const Int lo_u = u_min < from ? from : u_min, hi_u = to < u_max ? to : u_max;
            // r_j x_0 = r_j r_a u over [lo_u, hi_u]; a_j = x_j - r_j x_0.
            for (int j = 0; j < S; ++j) {
                if (j == a - 1) continue;
                const bool same = sigma(negative, j + 1) * s0 == ra;
                const Int least = same ? lo_u : Int(-hi_u), most = same ? hi_u : Int(-lo_u);
                first[j] =
                    to_index(Int(Int(it.lo[j + 1] - most - bundle.origin[j]) >> bundle.shift[j]));
                last[j] =
                    to_index(Int(Int(it.hi[j + 1] - least - bundle.origin[j]) >> bundle.shift[j]));
            }
            first[a - 1] = last[a - 1] = i;
            block(first, last);
        }
    };
    // Every cell some line of which meets an element, with the element's
    // smallest possible depth there.
    auto for_each_cell = [&](std::uint32_t e, auto&& visit) {
        poll();
        const Item& it = items_[e];
        // The element's own depth range, sigma_0 * x_0 over its box.
        const Int d_lo = s0 * it.lo[0] < s0 * it.hi[0] ? Int(s0 * it.lo[0]) : Int(s0 * it.hi[0]);
        const int a = it.axis;
        for_each_block(it, [&](const std::int64_t(&first)[M], const std::int64_t(&last)[M]) {
            std::int64_t i[M];
            for (int j = 0; j < S; ++j) i[j] = first[j];
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
                        const Int d1 = sa * Int(it.lo[a] - cell_lo),
                                  d2 = sa * Int(it.lo[a] - cell_hi);
                        const Int d = d1 < d2 ? d1 : d2;
                        if (key < d) key = d;
                    }
                visit(c, key);
                int j = 0;
                while (j < S && i[j] == last[j]) i[j] = first[j], ++j;
                if (j >= S) break;
                ++i[j];
            }
        });
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
    // limit of 5 an element cut the members again (37 MB less peak memory
    // at 10^5 random mirrors) and was faster, while at 10^4 it cost 10%;
    // with members only in the cells of exact shadows, 3 an element takes
    // 17 MB less again at equal stepping speed (six alternating runs at
    // 10^5: median 2.26 s against 2.25 s for 3M reflections).
    // A small scene may always take 2^15 registrations (512 KB a pair of
    // directions, the memory that sharing a bundle between sigma and -sigma
    // freed): the finer grids that allows (10^2 random mirrors: 900 cells a
    // pair instead of 225; 10^3: 3,481 instead of 900) were 1.1-1.3x faster,
    // with fewer instructions and a fifth to a quarter fewer mispredicted
    // branches. The count of a layout is the sum over the elements of the
    // cells their shadows meet, one product a block of for_each_block.
    const std::size_t per_element = acting.size() > (std::size_t{1} << 15) ? 3 : 10;
    const std::size_t allowed = std::max(per_element * acting.size(), std::size_t{1} << 15);
    auto registrations = [&] {
        std::size_t sum = 0;
        for (const std::uint32_t e : acting) {
            poll();
            for_each_block(items_[e],
                           [&](const std::int64_t(&first)[M], const std::int64_t(&last)[M]) {
                               std::size_t spanned = 1;
                               for (int j = 0; j < S; ++j)
                                   spanned *= static_cast<std::size_t>(last[j] - first[j] + 1);
                               sum += spanned;
                           });
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
                const std::uint32_t acts = (it.acts_on(negative) ? acts_forward : 0u) |
                                           (it.acts_on(opposite) ? acts_reverse : 0u);
                bundle.members[fill[c]++] = Member{
                    Int(sigma(negative, it.axis) * it.lo[it.axis]),
                    static_cast<std::uint32_t>(bundle.quantum_of(key)), e << 4 | acts | it.axis};
            });
    }
    // Ties broken by the element, so that the order does not depend on the sort.
    for (std::size_t c = 0; c + 1 < offsets.size(); ++c)
        std::sort(bundle.members.begin() + offsets[c], bundle.members.begin() + offsets[c + 1],
                  [](const Member& x, const Member& y) {
                      return x.key < y.key || (x.key == y.key && x.packed < y.packed);
                  });
    // About members_per_slab members a slab on average, at most max_slabs.
    const std::size_t per_cell = bundle.members.size() / bundle.cell_total;
    unsigned slab_bits = 0;
    while ((std::size_t{members_per_slab} << slab_bits) < per_cell && slab_bits < max_slab_bits)
        ++slab_bits;
    bundle.slabs = std::size_t{1} << slab_bits;
    bundle.slab_shift = depth_bits > slab_bits ? depth_bits - slab_bits : 0;
    const std::size_t width = bundle.width(), half = bundle.slabs + 1;
    bundle.rows.assign(bundle.cell_total * width, 0);
    for (std::size_t c = 0; c < bundle.cell_total; ++c) {
        poll();
        std::uint32_t* row = bundle.rows.data() + c * width;
        const std::uint32_t begin = offsets[c], end = offsets[c + 1];
        std::uint32_t forward = begin, reverse = begin;
        row[0] = row[half] = begin;
        for (std::size_t slab = 1; slab < bundle.slabs; ++slab) {
            const Int least =
                bundle.base + (Int(static_cast<std::int64_t>(slab)) << bundle.slab_shift);
            // sigma: behind every point of the slab, key + reach <= its least depth.
            const std::uint64_t behind = bundle.quanta_at_most(Int(least - bundle.reach));
            while (forward != end && bundle.members[forward].key < behind) ++forward;
            row[slab] = forward;
            // -sigma: the first member whose key is surely >= the least depth.
            const std::uint64_t below = bundle.quanta_below(least);
            while (reverse != end && bundle.members[reverse].key < below) ++reverse;
            row[half + slab] = reverse;
        }
        row[bundle.slabs] = row[half + bundle.slabs] = end;
    }
}

} // namespace orthoray::shoot
