// average_case: the lecture's average-case result on ray shooting with a
// uniform grid, measured (docs/average-case.md). A STATISTICAL EXPERIMENT IN
// FLOATING POINT: it decides nothing and is not part of orthoray.
//
// Spheres of radius r have centres from a homogeneous Poisson process (here:
// n uniform points on a torus of side L, which is the Poisson process given
// its count, without boundary effects). A uniform grid with cells of
// diagonal s is walked along a random ray, cell by cell in order; in each
// cell the ray is tested against every sphere that overlaps the cell and
// was not tested before on this ray (a mailbox), and the walk stops in the
// first cell that holds the nearest hit found so far. The claim: a tested
// sphere is hit with probability about q = (r / (r + s))^2, independently,
// so the number of tests up to and including the first hit is geometric with
// mean 1/q = (1 + s/r)^2, whatever n.
//
// Output: a markdown table on stdout and the raw rows as CSV (--csv FILE).
#include <CLI/CLI.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <unordered_set>
#include <vector>

namespace {

using Vec = std::array<double, 3>;

struct World {
    double side = 0, radius = 1;
    std::vector<Vec> centres;
    // A coarse grid of cells of side >= 2r, to find the spheres near a fine
    // cell without materialising the fine grid (at s = r/10 a sphere spans
    // tens of thousands of fine cells).
    int coarse = 1;
    double coarse_side = 0;
    std::vector<std::vector<int>> coarse_cells;

    int wrap(int i, int n) const { return ((i % n) + n) % n; }
    std::size_t coarse_index(int x, int y, int z) const {
        return (static_cast<std::size_t>(wrap(x, coarse)) * coarse + wrap(y, coarse)) * coarse +
               wrap(z, coarse);
    }
};

World make_world(std::size_t n, double density, double radius, std::mt19937_64& rng) {
    World w;
    w.radius = radius;
    w.side = std::cbrt(static_cast<double>(n) / density);
    w.coarse = std::max(1, static_cast<int>(w.side / (2 * radius)));
    w.coarse_side = w.side / w.coarse;
    w.coarse_cells.resize(static_cast<std::size_t>(w.coarse) * w.coarse * w.coarse);
    std::uniform_real_distribution<double> u(0, w.side);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec c{u(rng), u(rng), u(rng)};
        w.centres.push_back(c);
        w.coarse_cells[w.coarse_index(static_cast<int>(c[0] / w.coarse_side),
                                      static_cast<int>(c[1] / w.coarse_side),
                                      static_cast<int>(c[2] / w.coarse_side))]
            .push_back(static_cast<int>(i));
    }
    return w;
}

// The nearest offset of `x` from `c` on the torus.
double torus_delta(double x, double c, double side) {
    double d = x - c;
    d -= side * std::round(d / side);
    return d;
}

// The ray parameter where the ray meets the sphere centred at c (the image
// of a centre next to the cell being walked, in the ray's unwrapped
// coordinates), or -1.
double hit(const World& w, const Vec& o, const Vec& d, const Vec& c) {
    Vec oc;
    for (int j = 0; j < 3; ++j) oc[j] = o[j] - c[j];
    const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
    const double cc = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - w.radius * w.radius;
    const double disc = b * b - cc;
    if (disc < 0) return -1;
    const double t = -b - std::sqrt(disc);
    return t >= 0 ? t : -1;
}

// Tests until the first hit along one ray, walking fine cells of side a.
// The ray starts at o; positions are unwrapped (the torus is applied when
// comparing with a centre), so cell indices grow without bound.
int tests_until_hit(const World& w, double a, const Vec& o, const Vec& d) {
    std::array<long, 3> cell, step;
    std::array<double, 3> t_max, t_delta;
    for (int j = 0; j < 3; ++j) {
        cell[j] = static_cast<long>(std::floor(o[j] / a));
        step[j] = d[j] > 0 ? 1 : -1;
        const double boundary = (cell[j] + (d[j] > 0 ? 1 : 0)) * a;
        t_max[j] = d[j] != 0 ? (boundary - o[j]) / d[j] : INFINITY;
        t_delta[j] = d[j] != 0 ? a / std::fabs(d[j]) : INFINITY;
    }
    std::unordered_set<int> tested;
    int tests = 0;
    double nearest = INFINITY;
    for (int walked = 0; walked < 10'000'000; ++walked) {
        // The spheres overlapping this cell: centres within r of the box.
        const double lo[3] = {cell[0] * a, cell[1] * a, cell[2] * a};
        const int c0 = static_cast<int>(std::floor((lo[0] - w.radius) / w.coarse_side));
        const int c1 = static_cast<int>(std::floor((lo[1] - w.radius) / w.coarse_side));
        const int c2 = static_cast<int>(std::floor((lo[2] - w.radius) / w.coarse_side));
        const int e0 = static_cast<int>(std::floor((lo[0] + a + w.radius) / w.coarse_side));
        const int e1 = static_cast<int>(std::floor((lo[1] + a + w.radius) / w.coarse_side));
        const int e2 = static_cast<int>(std::floor((lo[2] + a + w.radius) / w.coarse_side));
        for (int x = c0; x <= e0; ++x)
            for (int y = c1; y <= e1; ++y)
                for (int z = c2; z <= e2; ++z)
                    for (const int s : w.coarse_cells[w.coarse_index(x, y, z)]) {
                        double gap2 = 0;
                        Vec image;
                        for (int j = 0; j < 3; ++j) {
                            const double mid = lo[j] + a / 2;
                            const double off = torus_delta(w.centres[s][j], mid, w.side);
                            image[j] = mid + off;
                            const double out = std::max(0.0, std::fabs(off) - a / 2);
                            gap2 += out * out;
                        }
                        if (gap2 > w.radius * w.radius || !tested.insert(s).second) continue;
                        ++tests;
                        const double t = hit(w, o, d, image);
                        if (t >= 0) nearest = std::min(nearest, t);
                    }
        const int axis =
            t_max[0] < t_max[1] ? (t_max[0] < t_max[2] ? 0 : 2) : (t_max[1] < t_max[2] ? 1 : 2);
        // The nearest hit lies in this cell or before it: done.
        if (nearest <= t_max[axis]) return tests;
        cell[axis] += step[axis];
        t_max[axis] += t_delta[axis];
    }
    return tests;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"average_case: tests per ray until the first hit in a uniform grid over Poisson "
                 "spheres, against (1 + s/r)^2 (a floating-point statistical experiment)"};
    int rays = 4000;
    std::string csv;
    std::uint64_t seed = 2005;
    app.add_option("--rays", rays, "rays per configuration (default 4000)");
    app.add_option("--csv", csv, "also write the rows to this CSV file");
    app.add_option("--seed", seed, "the experiment's seed");
    CLI11_PARSE(app, argc, argv);

    const double radius = 1;
    // Centres per unit volume: a mean free path of 20 r (lambda pi r^2 = 1/20).
    const double density = 1 / (20 * M_PI * radius * radius);
    std::mt19937_64 rng(seed);
    std::ofstream out;
    if (!csv.empty()) {
        out.open(csv);
        out << "spheres,s_over_r,rays,mean_tests,formula,ratio,p_one,q\n";
    }
    std::printf("| spheres | s/r | mean tests to first hit | (1 + s/r)^2 | measured / formula | "
                "P(tests = 1) | q = (r/(r+s))^2 |\n|---|---|---|---|---|---|---|\n");
    for (const std::size_t n : {1000ul, 10000ul, 100000ul}) {
        const World w = make_world(n, density, radius, rng);
        for (const double s_over_r : {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0}) {
            const double s = s_over_r * radius, a = s / std::sqrt(3.0);
            std::uniform_real_distribution<double> u(0, w.side), g(-1, 1);
            double sum = 0;
            int ones = 0;
            for (int k = 0; k < rays; ++k) {
                Vec d;
                double norm = 0;
                do {
                    d = {g(rng), g(rng), g(rng)};
                    norm = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                } while (norm > 1 || norm < 1e-6);
                for (double& x : d) x /= std::sqrt(norm);
                const int tests = tests_until_hit(w, a, {u(rng), u(rng), u(rng)}, d);
                sum += tests;
                ones += tests == 1;
            }
            const double mean = sum / rays, formula = std::pow(1 + s_over_r, 2);
            const double q = std::pow(1 / (1 + s_over_r), 2);
            std::printf("| %zu | %.1f | %.2f | %.2f | %.2f | %.3f | %.3f |\n", n, s_over_r, mean,
                        formula, mean / formula, static_cast<double>(ones) / rays, q);
            if (out)
                out << n << ',' << s_over_r << ',' << rays << ',' << mean << ',' << formula << ','
                    << mean / formula << ',' << static_cast<double>(ones) / rays << ',' << q
                    << '\n';
        }
    }
    return 0;
}
