#include "render/frame.hpp"

#include <algorithm>
#include <cmath>

namespace orthoray::render {
namespace {

// If the longest side is more than this many times the shortest, each axis
// is scaled on its own.
constexpr double max_aspect = 8;

} // namespace

Frame::Frame(const Scene& scene) : dim_(scene.dim) {
    auto include = [&](const Vector& p, bool first) {
        for (int j = 0; j < dim_; ++j) {
            if (first || p[j] < lo[j]) lo[j] = p[j];
            if (first || p[j] > hi[j]) hi[j] = p[j];
        }
    };
    include(scene.ray().start, true);
    for (const Ray& ray : scene.rays) include(ray.start, false);
    for (const Vector& target : scene.targets) include(target, false);
    for (const Element& e : scene.elements) {
        include(e.lo, false);
        include(e.hi, false);
    }
    Rational longest = 0;
    for (int j = 0; j < dim_; ++j) longest = std::max<Rational>(longest, hi[j] - lo[j]);
    if (longest == 0) longest = 1;
    std::array<double, 3> span{1, 1, 1};
    double max_span = 0, min_span = HUGE_VAL;
    for (int j = 0; j < dim_; ++j) {
        if (hi[j] == lo[j]) {
            lo[j] -= longest / 2;
            hi[j] += longest / 2;
        }
        span[j] = Rational(hi[j] - lo[j]).get_d();
        max_span = std::max(max_span, span[j]);
        min_span = std::min(min_span, span[j]);
    }
    separate_scales = !(max_span <= max_aspect * min_span) || !std::isfinite(max_span);
    for (int j = 0; j < dim_; ++j) {
        const Rational pad = (separate_scales ? Rational(hi[j] - lo[j]) : longest) / 25;
        lo[j] -= pad;
        hi[j] += pad;
        width_[j] = hi[j] - lo[j];
        span[j] = width_[j].get_d();
        // Beyond this a double cannot hold the side, or its reciprocal.
        exact_ratio_[j] = !(span[j] >= 1e-280 && span[j] <= 1e280);
        separate_scales = separate_scales || exact_ratio_[j];
    }
    max_span = *std::max_element(span.begin(), span.begin() + dim_);
    for (int j = 0; j < dim_; ++j) {
        unit_[j] = separate_scales ? 1 / span[j] : 1 / max_span;
        extent[j] = exact_ratio_[j] ? 1 : span[j] * unit_[j];
    }
}

// Usually (p - lo) is exact and its double is scaled; a side too long or too
// short for a double is divided out exactly first.
Point3 Frame::normalised(const Vector& p) const {
    Point3 n{0, 0, 0};
    for (int j = 0; j < dim_; ++j) {
        mpq_sub(difference_.get_mpq_t(), p[j].get_mpq_t(), lo[j].get_mpq_t());
        if (exact_ratio_[j]) {
            mpq_div(difference_.get_mpq_t(), difference_.get_mpq_t(), width_[j].get_mpq_t());
            n[j] = difference_.get_d();
        } else {
            n[j] = difference_.get_d() * unit_[j];
        }
    }
    return n;
}

// Divided out exactly: the scene's numbers may be beyond what a double holds.
double Frame::normalised_component(const Rational& v, int axis) const {
    return Rational(v / width_[axis]).get_d() * extent[axis];
}

} // namespace orthoray::render
