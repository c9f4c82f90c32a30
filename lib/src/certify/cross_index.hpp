// Which elements can meet the rays of a run of states, for the octagonal
// piece check (octagonal_piece_check.cpp). Checker code only.
#pragma once

#include "orthoray/number.hpp"

#include "certify/octagonal_piece_check.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace orthoray::certify::induction_check {

// The elements by their range of cross(d, X) over their points X, for one
// direction d: the ray from Q moves on the line cross(d, X) = cross(d, Q),
// so only elements whose range holds that value can meet it. Sorted by the
// range's low end, with a tree of the largest high end over each block, a
// query lists the elements whose range meets [lo, hi] in
// O((1 + answers) log n), where trying every element cost O(n) a run.
class CrossIndex {
public:
    CrossIndex(const std::vector<OctagonalElement>& elements, const Integer& dx,
               const Integer& dy) {
        for (std::size_t e = 0; e < elements.size(); ++e) {
            const OctagonalElement& el = elements[e];
            // The element's ends from n . X = c and m . X in {lo, hi}: cross(d, X)
            // is affine along the element, so its range is between the ends'.
            Integer ends[2];
            for (int k = 0; k < 2; ++k) {
                const Integer& along = k == 0 ? el.lo : el.hi;
                // X = (c n + along m) / (n . n) (n and m orthogonal, |n| = |m|).
                const Integer x = el.c * el.nx + along * el.mx;
                const Integer y = el.c * el.ny + along * el.my;
                ends[k] = dx * y - dy * x; // times n . n > 0: order kept
            }
            const Integer norm = el.nx * el.nx + el.ny * el.ny;
            if (ends[1] < ends[0]) std::swap(ends[0], ends[1]);
            spans_.push_back({std::move(ends[0]), std::move(ends[1]), norm, e});
        }
        std::sort(spans_.begin(), spans_.end(),
                  [](const Span& a, const Span& b) { return a.lo * b.norm < b.lo * a.norm; });
        size_ = 1;
        while (size_ < spans_.size()) size_ *= 2;
        top_.assign(2 * size_, std::nullopt);
        for (std::size_t i = 0; i < spans_.size(); ++i)
            top_[size_ + i] = exact(spans_[i].hi, spans_[i].norm);
        for (std::size_t i = size_ - 1; i >= 1; --i) top_[i] = larger(top_[2 * i], top_[2 * i + 1]);
    }

    // The elements whose range meets [lo, hi] (in plain cross units).
    void query(const Integer& lo, const Integer& hi, std::vector<std::size_t>& out) const {
        out.clear();
        if (spans_.empty()) return;
        // The spans with low end <= hi form a prefix.
        const auto end =
            std::upper_bound(spans_.begin(), spans_.end(), hi,
                             [](const Integer& v, const Span& s) { return v * s.norm < s.lo; });
        collect(1, 0, size_, static_cast<std::size_t>(end - spans_.begin()), exact(lo, 1), out);
    }

private:
    struct Span {
        Integer lo, hi, norm; // the range is [lo / norm, hi / norm]
        std::size_t element;
    };
    static Rational exact(const Integer& num, const Integer& den) {
        Rational q(num, den);
        q.canonicalize();
        return q;
    }
    static std::optional<Rational> larger(const std::optional<Rational>& a,
                                          const std::optional<Rational>& b) {
        if (!a) return b;
        if (!b) return a;
        return *a < *b ? b : a;
    }
    void collect(std::size_t node, std::size_t from, std::size_t to, std::size_t limit,
                 const Rational& lo, std::vector<std::size_t>& out) const {
        if (from >= limit || !top_[node] || *top_[node] < lo) return;
        if (to - from == 1) {
            out.push_back(spans_[from].element);
            return;
        }
        const std::size_t mid = (from + to) / 2;
        collect(2 * node, from, mid, limit, lo, out);
        collect(2 * node + 1, mid, to, limit, lo, out);
    }

    std::vector<Span> spans_;
    std::size_t size_ = 1;
    std::vector<std::optional<Rational>> top_;
};

} // namespace orthoray::certify::induction_check
