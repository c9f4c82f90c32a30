// INEXACT COMPARISON BASELINE -- NOT PART OF ORTHORAY. See the header.
//
// Written plainly, as a graphics programmer would, on purpose: every test
// below is a floating-point comparison with a tolerance, which is exactly
// what the exact engine avoids. Do not "fix" it with exact arithmetic; it is
// the thing being compared against.
#include "float_grid_tracer.hpp"

#include "bench_util.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

namespace orthoray::bench {

class FloatGridTracer::Impl {
public:
    virtual ~Impl() = default;
    virtual FloatAnswer trace(std::uint64_t max_steps) const = 0;
    double setup_seconds = 0;
    std::size_t cells = 0;
};

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

template <int D>
class Tracer final : public FloatGridTracer::Impl {
public:
    Tracer(const Scene& scene, double epsilon) {
        const auto begin = std::chrono::steady_clock::now();
        double size = 1;
        auto grow = [&](double x) { size = std::max(size, std::fabs(x)); };
        for (const Element& e : scene.elements) {
            Elem f;
            f.axis = e.axis;
            f.absorber = e.kind == ElementKind::absorber;
            f.c = to_double(e.offset());
            for (int j = 0; j < D; ++j) {
                f.lo[j] = to_double(e.lo[j]);
                f.hi[j] = to_double(e.hi[j]);
                grow(f.lo[j]);
                grow(f.hi[j]);
            }
            elems_.push_back(f);
        }
        double length = 0;
        for (int j = 0; j < D; ++j) {
            start_[j] = to_double(scene.ray().start[j]);
            target_[j] = to_double(scene.target()[j]);
            dir_[j] = to_double(scene.ray().direction[j]);
            length += dir_[j] * dir_[j];
            grow(start_[j]);
            grow(target_[j]);
        }
        length = std::sqrt(length);
        for (int j = 0; j < D; ++j) dir_[j] /= length; // unit direction: t is a distance
        eps_ = epsilon * size;
        build_grid();
        setup_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    }

    FloatAnswer trace(std::uint64_t max_steps) const override {
        FloatAnswer answer;
        answer.setup_seconds = setup_seconds;
        double p[D], v[D], first_p[D] = {}, first_v[D] = {};
        for (int j = 0; j < D; ++j) p[j] = start_[j], v[j] = dir_[j];
        for (std::uint64_t reflections = 0;;) {
            const Hit hit = shoot(p, v);
            if (reaches_target(p, v, hit)) return done(answer, Reason::hit, reflections);
            if (!hit.found) return done(answer, Reason::escape, reflections);
            for (int j = 0; j < D; ++j) p[j] += hit.t * v[j];
            if (hit.absorber) return done(answer, Reason::absorbed, reflections);
            if (reflections == max_steps) return done(answer, Reason::limit, reflections);
            for (int j = 0; j < D; ++j)
                if ((hit.flip >> j) & 1u) v[j] = -v[j];
            ++reflections;
            if (reflections == 1) {
                for (int j = 0; j < D; ++j) first_p[j] = p[j], first_v[j] = v[j];
            } else if (same_state(p, v, first_p, first_v)) {
                return done(answer, Reason::cycle, reflections - 1);
            }
        }
    }

private:
    struct Elem {
        double c;            // the plane x[axis] = c
        double lo[D], hi[D]; // the element's box
        int axis;
        bool absorber;
    };
    struct Hit {
        bool found = false, absorber = false;
        unsigned flip = 0;
        double t = infinity;
    };

    std::vector<Elem> elems_;
    double start_[D], target_[D], dir_[D];
    double eps_ = 0;
    double lo_[D], hi_[D], h_[D]; // grid box and cell size
    int n_[D];                    // cells per axis
    std::vector<std::uint32_t> offsets_, members_;

    static FloatAnswer done(FloatAnswer& a, Reason reason, std::uint64_t reflections) {
        a.reason = reason;
        a.reflections = reflections;
        return a;
    }

    int cell_of(double x, int j) const {
        const int c = static_cast<int>(std::floor((x - lo_[j]) / h_[j]));
        return std::clamp(c, 0, n_[j] - 1);
    }

    std::size_t index(const int (&c)[D]) const {
        std::size_t i = 0;
        for (int j = D - 1; j >= 0; --j) i = i * static_cast<std::size_t>(n_[j]) + c[j];
        return i;
    }

    // A uniform grid of about two cells per element; an element goes into
    // every cell its (epsilon-padded) box overlaps.
    void build_grid() {
        for (int j = 0; j < D; ++j) lo_[j] = -1, hi_[j] = 1;
        if (!elems_.empty()) {
            for (int j = 0; j < D; ++j) lo_[j] = infinity, hi_[j] = -infinity;
            for (const Elem& e : elems_)
                for (int j = 0; j < D; ++j) {
                    lo_[j] = std::min(lo_[j], e.lo[j] - eps_);
                    hi_[j] = std::max(hi_[j], e.hi[j] + eps_);
                }
        }
        const double want = 2.0 * static_cast<double>(std::max<std::size_t>(elems_.size(), 1));
        const int k = std::max(1, static_cast<int>(std::ceil(std::pow(want, 1.0 / D))));
        std::size_t total = 1;
        for (int j = 0; j < D; ++j) {
            n_[j] = k;
            h_[j] = (hi_[j] - lo_[j]) / k;
            total *= static_cast<std::size_t>(k);
        }
        cells = total;
        offsets_.assign(total + 1, 0);
        auto for_each_cell = [&](const Elem& e, auto&& visit) {
            int first[D], last[D], c[D];
            for (int j = 0; j < D; ++j) {
                first[j] = cell_of(e.lo[j] - eps_, j);
                last[j] = cell_of(e.hi[j] + eps_, j);
                c[j] = first[j];
            }
            while (true) {
                visit(index(c));
                int j = 0;
                while (j < D && c[j] == last[j]) c[j] = first[j], ++j;
                if (j == D) break;
                ++c[j];
            }
        };
        for (const Elem& e : elems_) for_each_cell(e, [&](std::size_t c) { ++offsets_[c + 1]; });
        for (std::size_t c = 1; c <= total; ++c) offsets_[c] += offsets_[c - 1];
        members_.resize(offsets_[total]);
        std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
        for (std::uint32_t i = 0; i < elems_.size(); ++i)
            for_each_cell(elems_[i], [&](std::size_t c) { members_[fill[c]++] = i; });
    }

    // The nearest element hit from p along v: Amanatides-Woo grid walk.
    Hit shoot(const double (&p)[D], const double (&v)[D]) const {
        Hit hit;
        double inv[D];
        for (int j = 0; j < D; ++j) inv[j] = v[j] != 0 ? 1.0 / v[j] : infinity;

        // Clip the ray to the grid box.
        double t_in = 0, t_out = infinity;
        for (int j = 0; j < D; ++j) {
            if (v[j] == 0) {
                if (p[j] < lo_[j] || p[j] > hi_[j]) return hit;
                continue;
            }
            double a = (lo_[j] - p[j]) * inv[j], b = (hi_[j] - p[j]) * inv[j];
            if (a > b) std::swap(a, b);
            t_in = std::max(t_in, a);
            t_out = std::min(t_out, b);
        }
        if (t_in > t_out) return hit;

        int c[D], step[D];
        double t_max[D], t_delta[D];
        for (int j = 0; j < D; ++j) {
            c[j] = cell_of(p[j] + t_in * v[j], j);
            if (v[j] > 0) {
                step[j] = 1;
                t_max[j] = (lo_[j] + (c[j] + 1) * h_[j] - p[j]) * inv[j];
                t_delta[j] = h_[j] * inv[j];
            } else if (v[j] < 0) {
                step[j] = -1;
                t_max[j] = (lo_[j] + c[j] * h_[j] - p[j]) * inv[j];
                t_delta[j] = -h_[j] * inv[j];
            } else {
                step[j] = 0;
                t_max[j] = t_delta[j] = infinity;
            }
        }

        while (true) {
            int next = 0;
            for (int j = 1; j < D; ++j)
                if (t_max[j] < t_max[next]) next = j;
            const double t_exit = t_max[next];
            const std::size_t cell = index(c);
            for (std::uint32_t k = offsets_[cell]; k < offsets_[cell + 1]; ++k) {
                const Elem& e = elems_[members_[k]];
                const int a = e.axis;
                if (v[a] == 0) continue; // parallel to the plane
                const double t = (e.c - p[a]) * inv[a];
                if (t <= eps_ || t > t_exit + eps_ || t > hit.t + eps_) continue;
                bool on = true;
                for (int j = 0; j < D && on; ++j) {
                    if (j == a) continue;
                    const double x = p[j] + t * v[j];
                    on = x >= e.lo[j] - eps_ && x <= e.hi[j] + eps_;
                }
                if (!on) continue;
                if (t < hit.t - eps_) { // strictly nearer: forget the others
                    hit.flip = 0;
                    hit.absorber = false;
                }
                hit.found = true;
                hit.t = std::min(hit.t, t);
                if (e.absorber)
                    hit.absorber = true;
                else
                    hit.flip |= 1u << a;
            }
            if (hit.found) return hit;
            c[next] += step[next];
            if (c[next] < 0 || c[next] >= n_[next]) return hit; // left the grid
            t_max[next] += t_delta[next];
        }
    }

    // Whether the target is within epsilon of the segment p .. p + t v (the
    // whole ray when nothing is hit).
    bool reaches_target(const double (&p)[D], const double (&v)[D], const Hit& hit) const {
        double d[D], tau = 0;
        for (int j = 0; j < D; ++j) {
            d[j] = target_[j] - p[j];
            tau += d[j] * v[j];
        }
        if (tau < -eps_ || (hit.found && tau > hit.t + eps_)) return false;
        double distance2 = 0;
        for (int j = 0; j < D; ++j) {
            const double e = d[j] - tau * v[j];
            distance2 += e * e;
        }
        return distance2 <= eps_ * eps_;
    }

    bool same_state(const double (&p)[D], const double (&v)[D], const double (&q)[D],
                    const double (&w)[D]) const {
        for (int j = 0; j < D; ++j)
            if (v[j] != w[j] || std::fabs(p[j] - q[j]) > eps_) return false;
        return true;
    }
};

} // namespace

FloatGridTracer::FloatGridTracer(const Scene& scene, double epsilon) {
    if (scene.dim == 2)
        impl_ = std::make_unique<Tracer<2>>(scene, epsilon);
    else
        impl_ = std::make_unique<Tracer<3>>(scene, epsilon);
}

FloatGridTracer::~FloatGridTracer() = default;

FloatAnswer FloatGridTracer::trace(std::uint64_t max_steps) const {
    return impl_->trace(max_steps);
}

double FloatGridTracer::setup_seconds() const {
    return impl_->setup_seconds;
}

std::size_t FloatGridTracer::cells() const {
    return impl_->cells;
}

FloatAnswer float_trace(const Scene& scene, const FloatOptions& options) {
    const FloatGridTracer tracer(scene, options.epsilon);
    return tracer.trace(options.max_steps);
}

} // namespace orthoray::bench
