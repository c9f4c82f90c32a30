// The average-case model of docs/average-case.md for orthoray's grids, in
// FLOATING POINT: a statistical prediction to hold the measured counts of
// bench/grid_average.cpp against. It decides nothing and is not part of
// orthoray.
//
// Elements are boxes with one zero side (segments in 2D, rectangles in 3D),
// spread uniformly over the scene's box of volume V; the faces of the box are
// elements too. A shot is a diagonal ray from a reflection point on the
// lattice, t its parameter (every coordinate moves by t).
//
//   hit rate          lambda = sum_e w_e area(e) / V  (area: the product of
//                     the nonzero sides; box faces count half, w_e = 1/2,
//                     since a ray inside meets each face from one side only)
//   free path         E[T] = 1 / lambda
//   uniform grid      cells  = 1 + E[T] * sum_j 1 / h_j - phi
//                     (phi: the faces' share of the hits; a face lies on a
//                     grid wall, so a shot that starts or ends on one
//                     crosses half a wall fewer on that axis, on average)
//                     m      = sum_e prod_j (ext_j(e) / h_j + 1) / cells in V
//                     tests  = 1 + m * cells
//   cross-section     mu     = sum_e w_e prod_{j >= 1} (ext_j + ext_0 + h_j) / V
//                     tests  = 1 + mu * (E[T] + reach)
#pragma once

#include "lattice/lattice_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace orthoray::bench {

// The element sizes the model needs, read once from the lattice scene.
struct ModelScene {
    int dim = 0;
    std::array<double, 3> box{};               // extent of the bounding box on each axis
    std::vector<std::array<double, 3>> extent; // each element's box sides
    std::vector<double> weight;                // 1, or 1/2 for a face of the box
    double volume = 1, lambda = 0;
    double face_share = 0;  // the faces' share of lambda
    double mean_length = 0; // mean side of the inner elements (their nonzero sides)

    explicit ModelScene(const lattice::LatticeScene& ls) : dim(ls.dim) {
        std::array<double, 3> lo{}, hi{};
        for (int j = 0; j < dim; ++j) {
            lo[j] = hi[j] = ls.elements.front().lo[j].get_d();
            for (const lattice::LatticeElement& e : ls.elements) {
                lo[j] = std::min(lo[j], e.lo[j].get_d());
                hi[j] = std::max(hi[j], e.hi[j].get_d());
            }
            box[j] = hi[j] - lo[j];
            volume *= box[j];
        }
        double sides = 0, count = 0;
        for (const lattice::LatticeElement& e : ls.elements) {
            std::array<double, 3> x{};
            bool face = true;
            double area = 1;
            for (int j = 0; j < dim; ++j) {
                x[j] = Integer(e.hi[j] - e.lo[j]).get_d();
                if (j == e.axis) continue;
                area *= x[j];
                face = face && x[j] == box[j];
            }
            extent.push_back(x);
            weight.push_back(face ? 0.5 : 1);
            lambda += weight.back() * area;
            if (face) face_share += weight.back() * area;
            if (!face)
                for (int j = 0; j < dim; ++j)
                    if (j != e.axis) sides += x[j], ++count;
        }
        face_share /= lambda;
        lambda /= volume;
        mean_length = sides / count;
    }
    double free_path() const { return 1 / lambda; }
};

struct Prediction {
    double cells = 0, tests = 0;
};

// The uniform grid with cell sides h (one per axis).
inline Prediction predict_uniform(const ModelScene& s, const std::array<double, 3>& h) {
    double registrations = 0, cells = 1, walls = 0;
    for (std::size_t e = 0; e < s.extent.size(); ++e) {
        double r = 1;
        for (int j = 0; j < s.dim; ++j) r *= s.extent[e][j] / h[j] + 1;
        registrations += r;
    }
    for (int j = 0; j < s.dim; ++j) {
        cells *= s.box[j] / h[j];
        walls += 1 / h[j];
    }
    Prediction p;
    p.cells = 1 + s.free_path() * walls - s.face_share;
    p.tests = 1 + registrations / cells * p.cells;
    return p;
}

// The cross-section grid of one direction, with cell sides h[0 .. dim-2] on
// the cross-section's axes (its axes 1 .. dim-1 of the scene).
inline Prediction predict_section(const ModelScene& s, const std::array<double, 3>& h) {
    double mu = 0, reach = 0;
    for (std::size_t e = 0; e < s.extent.size(); ++e) {
        double r = s.weight[e];
        for (int j = 1; j < s.dim; ++j) r *= s.extent[e][j] + s.extent[e][0] + h[j - 1];
        mu += r;
    }
    mu /= s.volume;
    for (int j = 0; j + 1 < s.dim; ++j) reach = std::max(reach, h[j] - 1);
    Prediction p;
    p.cells = 1;
    p.tests = 1 + mu * (s.free_path() + reach);
    return p;
}

// The least-squares fit time = c0 + c_cell * cells + c_test * tests over the
// rows of a resolution sweep (the normal equations, solved by Cramer's rule).
struct CostModel {
    double c0 = 0, c_cell = 0, c_test = 0;
    double at(double cells, double tests) const { return c0 + c_cell * cells + c_test * tests; }
};

inline CostModel fit_cost(const std::vector<std::array<double, 3>>& rows) {
    // rows: {cells, tests, time}
    double a[3][3] = {}, b[3] = {};
    for (const auto& r : rows) {
        const double x[3] = {1, r[0], r[1]};
        for (int i = 0; i < 3; ++i) {
            b[i] += x[i] * r[2];
            for (int j = 0; j < 3; ++j) a[i][j] += x[i] * x[j];
        }
    }
    auto det = [](const double(&m)[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    double c[3];
    for (int k = 0; k < 3; ++k) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : a[i][j];
        c[k] = det(m) / d;
    }
    return {c[0], c[1], c[2]};
}

// The cells per element, on a fine logarithmic scale from 1/16 to 256, at
// which the fitted cost of the predicted counts is least: the resolution the
// formula recommends. Cells are taken cubic, k a side with k^dim = c n.
inline double recommended_cells_per_element(const ModelScene& s, std::size_t n,
                                            const CostModel& cost) {
    double best_c = 1, best = 0;
    for (int i = -32; i <= 64; ++i) {
        const double c = std::pow(2.0, i / 8.0);
        const double k = std::pow(c * static_cast<double>(n), 1.0 / s.dim);
        std::array<double, 3> h{};
        for (int j = 0; j < s.dim; ++j) h[j] = s.box[j] / k;
        const Prediction p = predict_uniform(s, h);
        const double t = cost.at(p.cells, p.tests);
        if (i == -32 || t < best) best = t, best_c = c;
    }
    return best_c;
}

} // namespace orthoray::bench
