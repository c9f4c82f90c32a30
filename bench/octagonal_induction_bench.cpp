// octagonal_induction_bench: the induction engine on octagonal mazes
// (docs/induction.md, section 6) for bench/RESULTS.md, and the search for
// exchanges on which Rauzy-Zorich induction takes many steps against
// k log2 N (issue 14, item 4). Not a test. Run:
// build/bench/octagonal_induction_bench [--quick | --climb ROUNDS |
//   --mazes N... | --grid-mazes N...]
#include <orthoray/orthoray.hpp>

#include "parse_options.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace orthoray;

namespace {

double log2_of(const Integer& n) {
    return static_cast<double>(mpz_sizeinbase(n.get_mpz_t(), 2));
}

struct Run {
    Answer answer;
    double seconds = 0; // median
};

Run timed(const Scene& scene, int repeats) {
    SolveOptions o;
    o.engine = Engine::induction;
    std::vector<double> times;
    Run run;
    for (int i = 0; i < repeats; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        run.answer = solve(scene, o);
        times.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(times.begin(), times.end());
    run.seconds = times[times.size() / 2];
    return run;
}

// The reference tracer on the same scene, when its answer is short enough
// to wait for: the baseline of the same run.
std::string baseline(const Scene& scene, const Answer& induced) {
    if (induced.reflections > 200'000) return "";
    SolveOptions o;
    o.engine = Engine::reference;
    const auto t0 = std::chrono::steady_clock::now();
    const Answer a = solve(scene, o);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char text[64];
    std::snprintf(text, sizeof text, " ref %.4f s%s", s,
                  a.reason == induced.reason && a.reflections == induced.reflections ? ""
                                                                                     : " DIFFERS");
    return text;
}

void report(const std::string& name, const Run& run, const std::string& extra = "") {
    const auto& st = run.answer.stats.induction;
    const double klogn = static_cast<double>(st.pieces) * log2_of(st.states);
    const std::string label =
        run.answer.tail > 0 ? name + " tail " + run.answer.tail.get_str() : name;
    std::printf("%-34s %-8s %24s %8zu %6.0f %9llu %6.3f %9.4f%s\n", label.c_str(),
                to_string(run.answer.reason), run.answer.reflections.get_str().c_str(), st.pieces,
                log2_of(st.states), static_cast<unsigned long long>(st.steps),
                klogn > 0 ? static_cast<double>(st.steps) / klogn : 0.0, run.seconds,
                extra.c_str());
}

Scene diamond(const Rational& n, const Integer& m) {
    Scene s;
    s.add_diagonal(ElementKind::mirror, 0, n, n, 0);
    s.add_diagonal(ElementKind::mirror, -n, 0, 0, n);
    s.add_diagonal(ElementKind::mirror, 0, -n, n, 0);
    s.add_diagonal(ElementKind::mirror, -n, 0, 0, -n);
    s.ray().start = {Rational(1, 2), Rational(1, 2), 0};
    s.ray().direction = {1, Rational(m), 0};
    s.target() = {2 * n, 2 * n, 0};
    return s;
}

Scene triangle(const Rational& n, const Integer& m) {
    Scene s;
    s.add_mirror(0, 0, {{0, n}});
    s.add_mirror(1, 0, {{0, n}});
    s.add_diagonal(ElementKind::mirror, 0, n, n, 0);
    s.ray().start = {Rational(1, 3), Rational(1, 7), 0};
    s.ray().direction = {1, Rational(m), 0};
    s.target() = {2 * n, 2 * n, 0};
    return s;
}

// A box [0, w] x [0, h] with its corners cut by diagonals of leg c.
Scene octagon(const Rational& w, const Rational& h, const Rational& c, const Vector& direction) {
    Scene s;
    s.add_mirror(0, 0, {{c, h - c}});
    s.add_mirror(0, w, {{c, h - c}});
    s.add_mirror(1, 0, {{c, w - c}});
    s.add_mirror(1, h, {{c, w - c}});
    s.add_diagonal(ElementKind::mirror, 0, c, c, 0);
    s.add_diagonal(ElementKind::mirror, w - c, 0, w, c);
    s.add_diagonal(ElementKind::mirror, 0, h - c, c, h);
    s.add_diagonal(ElementKind::mirror, w - c, h, w, h - c);
    s.ray().start = {Rational(1, 3), c + Rational(1, 7), 0};
    s.ray().direction = direction;
    s.target() = {2 * w, 2 * h, 0};
    return s;
}

// n random axis and diagonal mirrors (some absorbers) of length up
// to 2% of a 10^18 box with mirror walls; direction (3, 7).
Scene random_maze(int n, int absorber_percent, std::mt19937_64& rng,
                  const Vector& direction = {3, 7, 0}) {
    const std::int64_t b = 1'000'000'000'000'000'000;
    auto r = [&] { return Rational(Integer(std::to_string(uniform(rng, 0, b)))); };
    Scene s;
    for (int i = 0; i < n; ++i) {
        const auto kind =
            uniform(rng, 1, 100) <= absorber_percent ? ElementKind::absorber : ElementKind::mirror;
        const Rational lo = r(), len = Rational(Integer(std::to_string(uniform(rng, 1, b / 50))));
        const auto t = uniform(rng, 0, 3);
        if (t < 2) {
            s.add(kind, static_cast<int>(t), r(), {{lo, lo + len}});
        } else {
            const Rational y = r();
            s.add_diagonal(kind, lo, y, lo + len, t == 2 ? Rational(y + len) : Rational(y - len));
        }
    }
    const Rational lo = -1, hi = Rational(Integer(std::to_string(b))) + 1;
    s.add_mirror(0, lo, {{lo - 1, hi + 1}});
    s.add_mirror(0, hi, {{lo - 1, hi + 1}});
    s.add_mirror(1, lo, {{lo - 1, hi + 1}});
    s.add_mirror(1, hi, {{lo - 1, hi + 1}});
    s.ray().start = {r(), r(), 0};
    s.ray().direction = direction;
    s.target() = {r(), r(), 0};
    return s;
}

// n random elements on a 1000 x 1000 grid of spacing 10^15 (lengths of 1
// to 20 cells, 5% absorbers) in a mirror box, the ray leaving a grid point
// along `direction` (an axis or a diagonal): rays slide along diagonals into
// vertices, so two states step to one and the induction walks between the
// collisions (rho_walk.hpp).
Scene random_grid_maze(int n, const Vector& direction, std::mt19937_64& rng) {
    const Integer g("1000000000000000");
    auto at = [&](std::int64_t lo, std::int64_t hi) {
        return Rational(g * Integer(std::to_string(uniform(rng, lo, hi))));
    };
    Scene s;
    for (int i = 0; i < n; ++i) {
        const auto kind = uniform(rng, 1, 100) <= 5 ? ElementKind::absorber : ElementKind::mirror;
        const Rational lo = at(1, 979), len = at(1, 20), c = at(1, 999);
        const auto t = uniform(rng, 0, 3);
        if (t < 2)
            s.add(kind, static_cast<int>(t), c, {{lo, lo + len}});
        else
            s.add_diagonal(kind, lo, c, lo + len, t == 2 ? Rational(c + len) : Rational(c - len));
    }
    const Rational hi(g * 1000);
    s.add_mirror(0, 0, {{0, hi}});
    s.add_mirror(0, hi, {{0, hi}});
    s.add_mirror(1, 0, {{0, hi}});
    s.add_mirror(1, hi, {{0, hi}});
    s.ray().start = {at(1, 999), at(1, 999), 0};
    s.ray().direction = direction;
    s.target() = {at(1, 999), at(1, 999), 0};
    return s;
}

// The box [0, w] x [0, h] with a diagonal mirror of length sqrt(2) leaving
// the bottom wall at (x0, 0), and a ray along (1, 1): a 45-degree billiard
// whose orbit runs about w + h reflections before it meets the little
// mirror. A ray sliding down along the mirror's line meets the wall alone at
// (x0, 0); one arriving there along (1, -1) meets both and is sent back: two
// states step to one, and the orbit may enter its cycle after a tail.
Scene slide_box(const Integer& w, const Integer& h, const Integer& x0, const Rational& x,
                const Rational& y) {
    Scene s;
    s.add_diagonal(ElementKind::mirror, Rational(x0), 0, Rational(x0 + 1), 1);
    s.add_mirror(0, 0, {{0, Rational(h)}});
    s.add_mirror(0, Rational(w), {{0, Rational(h)}});
    s.add_mirror(1, 0, {{0, Rational(w)}});
    s.add_mirror(1, Rational(h), {{0, Rational(w)}});
    s.ray().start = {x, y, 0};
    s.ray().direction = {1, 1, 0};
    s.target() = {Rational(2 * w), Rational(2 * h), 0};
    return s;
}

// An exchange of the given lengths (piece 0, x, has length 1) whose images
// come in `order`.
IntervalExchange exchange_of_lengths(const std::vector<Integer>& lengths,
                                     const std::vector<std::size_t>& order) {
    IntervalExchange e;
    Integer at = 0;
    for (const Integer& l : lengths) {
        ExchangePiece p;
        p.start = at;
        p.length = l;
        at += l;
        e.pieces.push_back(p);
    }
    e.size = at;
    Integer image = 0;
    for (std::size_t i : order) {
        e.pieces[i].image = image;
        image += lengths[i];
    }
    return e;
}

double ratio_of(const IntervalExchange& e) {
    const InducedOrbit orbit = induce(e);
    return static_cast<double>(orbit.steps) /
           (static_cast<double>(e.pieces.size()) * log2_of(e.size));
}

// Random exchanges of k pieces of up to 2^bits states, and a hill climb
// that mutates lengths and the image order of the worst one found.
void step_bound_search(std::mt19937_64& rng, int climb) {
    std::printf("\n# steps / (k log2 N): random exchanges, then a hill climb from the worst\n");
    std::printf("%4s %5s %9s %9s %9s %9s\n", "k", "bits", "median", "max", "climbed", "samples");
    for (int k : {3, 4, 6, 8, 16, 64, 256}) {
        for (int bits : {20, 60}) {
            std::vector<double> ratios;
            std::vector<Integer> worst_lengths;
            std::vector<std::size_t> worst_order;
            double worst = 0;
            const int samples = k <= 16 ? 400 : 60;
            auto random_length = [&] {
                return Integer(std::to_string(uniform(rng, 1, (std::int64_t{1} << bits) - 1)));
            };
            for (int i = 0; i < samples; ++i) {
                std::vector<Integer> lengths(static_cast<std::size_t>(k), 1);
                for (int j = 1; j < k; ++j) lengths[static_cast<std::size_t>(j)] = random_length();
                std::vector<std::size_t> order(static_cast<std::size_t>(k));
                std::iota(order.begin(), order.end(), std::size_t{0});
                for (std::size_t j = order.size() - 1; j > 0; --j)
                    std::swap(order[j], order[static_cast<std::size_t>(
                                            uniform(rng, 0, static_cast<std::int64_t>(j)))]);
                const double r = ratio_of(exchange_of_lengths(lengths, order));
                ratios.push_back(r);
                if (r > worst) worst = r, worst_lengths = lengths, worst_order = order;
            }
            // Hill climb: change one length (or swap two images), keep it if
            // the ratio does not drop.
            double climbed = worst;
            const int rounds = k <= 16 ? climb : climb / 10;
            for (int i = 0; i < rounds; ++i) {
                auto lengths = worst_lengths;
                auto order = worst_order;
                if (uniform(rng, 0, 3) == 0) {
                    std::swap(order[static_cast<std::size_t>(uniform(rng, 0, k - 1))],
                              order[static_cast<std::size_t>(uniform(rng, 0, k - 1))]);
                } else {
                    auto& l = lengths[static_cast<std::size_t>(uniform(rng, 1, k - 1))];
                    l = uniform(rng, 0, 1)
                            ? random_length()
                            : Integer(std::max<Integer>(Integer(1), l + uniform(rng, -3, 3)));
                }
                const double r = ratio_of(exchange_of_lengths(lengths, order));
                if (r >= climbed) climbed = r, worst_lengths = lengths, worst_order = order;
            }
            std::sort(ratios.begin(), ratios.end());
            std::printf("%4d %5d %9.3f %9.3f %9.3f %9d\n", k, bits, ratios[ratios.size() / 2],
                        worst, climbed, samples);
        }
    }
    // The slowest family found: lengths growing geometrically by 1.618 from
    // 2^bits, images in reversed order (the hyperelliptic permutation), x
    // first. Its ratio grows with k: no constant bounds steps / (k log2 N).
    std::printf("\n# geometric lengths (ratio 1.618 from 2^bits), images reversed\n");
    std::printf("%5s %5s %7s %11s %7s %9s\n", "k", "bits", "log2N", "steps", "ratio", "seconds");
    for (int k : {16, 64, 256, 1024})
        for (int bits : {40, 2000, 8000}) {
            std::vector<Integer> lengths(static_cast<std::size_t>(k), 1);
            Integer f = Integer(1) << bits;
            for (int i = 1; i < k; ++i) {
                f = f * 1618 / 1000;
                lengths[static_cast<std::size_t>(i)] = f + i % 3;
            }
            std::vector<std::size_t> order(static_cast<std::size_t>(k));
            std::iota(order.begin(), order.end(), std::size_t{0});
            std::reverse(order.begin(), order.end());
            const IntervalExchange e = exchange_of_lengths(lengths, order);
            const auto t0 = std::chrono::steady_clock::now();
            const InducedOrbit orbit = induce(e);
            const double s =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::printf("%5d %5d %7.0f %11llu %7.2f %9.3f\n", k, bits, log2_of(e.size),
                        static_cast<unsigned long long>(orbit.steps),
                        static_cast<double>(orbit.steps) / (k * log2_of(e.size)), s);
        }
    // Rotations by a / N near the golden ratio: Euclid's worst case.
    Integer f0 = 1, f1 = 1;
    while (mpz_sizeinbase(f1.get_mpz_t(), 2) < 200) {
        const Integer f2 = f0 + f1;
        f0 = f1;
        f1 = f2;
    }
    IntervalExchange rotation;
    rotation.size = f1;
    auto piece = [](const Integer& start, const Integer& length, const Integer& image) {
        ExchangePiece p;
        p.start = start;
        p.length = length;
        p.image = image;
        return p;
    };
    rotation.pieces = {piece(0, 1, f0), piece(1, f1 - f0 - 1, f0 + 1), piece(f1 - f0, f0, 0)};
    std::printf("rotation by F(n-1) on F(n) points (2^200): %.3f\n", ratio_of(rotation));
}

} // namespace

int main(int argc, char** argv) {
    // --quick: one run of each family; --climb R: R hill-climb rounds per
    // small k (default 3,000).
    bool quick = false;
    int climb = 3000;
    std::vector<int> mazes, grid_mazes;
    CLI::App app{"octagonal_induction_bench: the induction engine on scenes with diagonal mirrors"};
    app.add_flag("--quick", quick, "one run of each family");
    app.add_option("--climb", climb, "hill-climb rounds per small k")->capture_default_str();
    app.add_option("--mazes", mazes,
                   "only time random mazes of these sizes (5% absorbers, 3 a size, 1 from "
                   "10^5 on): the "
                   "exchange build's crossings at 10^4 and 10^5 elements");
    app.add_option("--grid-mazes", grid_mazes,
                   "only time random grid-aligned mazes of these sizes, rays along an axis and "
                   "a diagonal (10 a size and direction), against the reference tracer");
    orthoray::bench::parse_options(app, "octagonal_induction_bench", argc, argv);
    const int repeats = quick ? 1 : 5;
    std::printf("%-34s %-8s %24s %8s %6s %9s %6s %9s\n", "family", "reason", "reflections",
                "pieces", "log2N", "steps", "ratio", "seconds");
    if (!mazes.empty()) {
        std::mt19937_64 rng(14'005);
        for (int n : mazes)
            for (int seed = 0; seed < (n < 100000 ? 3 : 1); ++seed) {
                const Run run = timed(random_maze(n, 5, rng), 1);
                report("maze n=" + std::to_string(n) + " abs 5% (" + to_string(run.answer.engine) +
                           ")",
                       run);
            }
        return 0;
    }
    if (!grid_mazes.empty()) {
        std::mt19937_64 rng(14'006);
        for (int n : grid_mazes)
            for (const Vector& d : {Vector{1, 0, 0}, Vector{1, 1, 0}})
                for (int seed = 0; seed < 10; ++seed) {
                    const Scene scene = random_grid_maze(n, d, rng);
                    const Run run = timed(scene, 3);
                    report("grid n=" + std::to_string(n) + " (" + d[0].get_str() + ", " +
                               d[1].get_str() + ") " + to_string(run.answer.engine) +
                               (exchange_of(scene) ? "" : " walk"),
                           run, baseline(scene, run.answer));
                }
        return 0;
    }
    const Rational big(Integer("1000000000000000000"));
    auto family = [&](const std::string& name, const Scene& scene) {
        const Run run = timed(scene, repeats);
        report(name, run, baseline(scene, run.answer));
    };
    for (const char* m : {"1001", "1000000001", "1000000000000000001"}) {
        family(std::string("diamond 1e18, (1, ") + m + ")", diamond(big, Integer(m)));
        family(std::string("triangle 1e18, (1, ") + m + ")", triangle(big, Integer(m)));
    }
    const Rational w(Integer("1000000000000000003")), h(Integer("999999999999999989"));
    for (const Vector& d : {Vector{3, 7, 0}, Vector{1, 1000000001, 0}, Vector{1, 1, 0}})
        family("octagon ~1e18, (" + d[0].get_str() + ", " + d[1].get_str() + ")",
               octagon(w, h, Rational(Integer("123456789012345678")), d));
    // Collisions: the walk between special states (rho_walk.hpp).
    for (const char* side : {"1000", "1000000", "1000000000000000000"}) {
        const Integer n(side);
        family(std::string("slide box ~") + side + ", (1, 1)",
               slide_box(n + 3, n - 11, n / 3 + 1, Rational(n / 2 + 5), Rational(n / 7 + 2)));
    }
    std::mt19937_64 rng(14'004);
    for (int absorbers : {5, 0})
        for (int n : {100, 300, 1000}) {
            std::vector<double> times;
            for (int seed = 0; seed < (quick ? 1 : 5); ++seed) {
                const Scene scene = random_maze(n, absorbers, rng);
                const Run run = timed(scene, 1);
                report("maze n=" + std::to_string(n) + " abs " + std::to_string(absorbers) + "%",
                       run, baseline(scene, run.answer));
                times.push_back(run.seconds);
            }
            std::sort(times.begin(), times.end());
            std::printf("  n=%d, %d%% absorbers: median %.3f s, max %.3f s\n", n, absorbers,
                        times[times.size() / 2], times.back());
        }
    if (!quick) step_bound_search(rng, climb);
}
