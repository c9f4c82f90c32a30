// The `random` family: random mirrors and absorbers (axis-aligned, or in 2D
// also diagonal), optionally boxed, and a target either random or placed on
// the trajectory.
#include "engine/reference_step.hpp"
#include "generate/box_faces.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

#include <span>
#include <stdexcept>
#include <string>

namespace orthoray {
namespace {

// k / q with q drawn from 1..denominator and k from [lo * q, hi * q].
Rational random_number(std::mt19937_64& rng, const RandomFamily& f, std::int64_t lo,
                       std::int64_t hi) {
    const std::int64_t q = uniform(rng, 1, f.denominator);
    Rational x(Integer(static_cast<long>(uniform(rng, lo * q, hi * q))),
               Integer(static_cast<long>(q)));
    x.canonicalize();
    return x;
}

// Whether x lies on the closed segment [a, b] (or, with `ray`, on the ray from
// a through b): x - a = lambda (b - a) with lambda in [0, 1] (or >= 0).
bool on_segment(const Vector& x, const Vector& a, const Vector& b, int dim, bool ray) {
    std::optional<Rational> lambda;
    for (int j = 0; j < dim; ++j) {
        const Rational d = b[j] - a[j], e = x[j] - a[j];
        if (d == 0) {
            if (e != 0) return false;
            continue;
        }
        const Rational l = e / d;
        if (lambda && *lambda != l) return false;
        lambda = l;
    }
    return lambda && *lambda >= 0 && (ray || *lambda <= 1);
}

// The house form of a bad value: "found ..., expected ...".
[[noreturn]] void refuse(const std::string& found, const std::string& expected) {
    throw std::invalid_argument("found " + found + ", expected " + expected);
}

void check_count(std::int64_t value, const std::string& what, std::int64_t least, std::int64_t most,
                 const std::string& expected) {
    if (value < least || value > most) refuse(std::to_string(value) + " for " + what, expected);
}

void check(const RandomFamily& f) {
    check_count(f.dim, "the dimension", 2, 3, "2 or 3");
    check_count(f.mirrors, "the number of mirrors", 0, RandomFamily::max_mirrors,
                "a whole number from 0 to 10^6");
    auto check_chance = [](const Rational& chance, const std::string& what) {
        if (chance < 0 || chance > 1 || chance.get_den() > RandomFamily::max_denominator)
            refuse(chance.get_str() + " for the " + what + " fraction",
                   "a fraction from 0 to 1 with a denominator up to 2^20");
    };
    check_chance(f.absorbers, "absorber");
    check_chance(f.splitters, "splitter");
    check_chance(f.one_sided, "one-sided");
    check_chance(f.diagonals, "diagonal");
    if (f.diagonals > 0 && f.dim != 2)
        refuse("diagonal elements in dimension 3", "dimension 2: diagonals are 2D only");
    check_count(f.rays, "the number of rays", 1, RandomFamily::max_rays,
                "a whole number from 1 to 1000");
    check_count(f.targets, "the number of targets", 1, RandomFamily::max_targets,
                "a whole number from 1 to 1000");
    if (f.target_after && (f.rays > 1 || f.targets > 1 || f.splitters > 0))
        refuse("a target on the trajectory with " + std::to_string(f.rays) + " rays, " +
                   std::to_string(f.targets) + " targets and the splitter fraction " +
                   f.splitters.get_str(),
               "one ray, one target and no splitters: it places one target on one path");
    check_count(f.denominator, "the denominator bound", 1, RandomFamily::max_denominator,
                "a whole number from 1 to 2^20");
    // Numerators k in [0, range * q] must fit in 64 bits: ranges of 10^18
    // with integer coordinates are fine (the induction engine's benchmark).
    const std::int64_t widest = RandomFamily::max_range / f.denominator;
    check_count(f.range, "the coordinate range", 2, widest,
                "a whole number from 2 to 2^62 / the denominator bound = " +
                    std::to_string(widest));
    check_count(f.direction_size, "the direction size", 1, RandomFamily::max_direction_size,
                "a whole number from 1 to 2^40");
    if (f.target_after)
        check_count(*f.target_after, "the target's segment", 0, RandomFamily::max_target_after,
                    "a whole number from 0 to 10^6");
    // The reference tracer scans every element at every reflection.
    if (f.target_after && (*f.target_after + 1) * (f.mirrors + 6) > 1'000'000'000)
        refuse(std::to_string((*f.target_after + 1) * (f.mirrors + 6)) +
                   " for (the target's segment + 1) * (mirrors + 6)",
               "at most 10^9: tracing that many reflections among this many mirrors would take "
               "too long");
}

// True with probability `chance` (a fraction with a small denominator), by
// one draw; nothing is drawn for a chance of 0, so options left at 0 do not
// disturb the sequence the other numbers come from.
bool happens(std::mt19937_64& rng, const Rational& chance) {
    if (chance == 0) return false;
    const std::int64_t den = chance.get_den().get_si();
    return uniform(rng, 0, den - 1) < chance.get_num().get_si();
}

// A start in [0, range]^dim and a direction of nonzero integers in [-D, D].
Ray random_ray(std::mt19937_64& rng, const RandomFamily& f) {
    Ray ray;
    for (int j = 0; j < f.dim; ++j) ray.start[j] = random_number(rng, f, 0, f.range);
    for (int j = 0; j < f.dim; ++j) {
        std::int64_t d = uniform(rng, 1, f.direction_size);
        if (uniform(rng, 0, 1) == 0) d = -d;
        ray.direction[j] = Rational(Integer(static_cast<long>(d)));
    }
    return ray;
}

} // namespace

GeneratedScene generate_random(const RandomFamily& f) {
    check(f);
    std::mt19937_64 rng(f.seed);
    GeneratedScene out;
    Scene& scene = out.scene;
    scene.dim = f.dim;
    if (f.box) generate::add_box_faces(scene, std::vector<Rational>(3, Rational(f.range)));
    const std::size_t first_random = scene.elements.size();

    // Mirrors about as long as the gaps between them: side s = range /
    // floor(n^(1/dim)), lengths in [s/2, s], so crossings stay rare.
    const std::int64_t side = std::max<std::int64_t>(
        2, f.range / integer_root(std::max<std::int64_t>(1, f.mirrors), f.dim));
    const Integer absorb_num = f.absorbers.get_num(), absorb_den = f.absorbers.get_den();
    // A length in [side / 2, side] and where it starts, inside [0, range].
    auto random_extent = [&]() {
        Rational length = random_number(rng, f, side / 2, side);
        if (length == 0) length = 1;
        if (length > f.range) length = f.range;
        const Rational room = f.range - length;
        Integer floor_room;
        mpz_fdiv_q(floor_room.get_mpz_t(), room.get_num_mpz_t(), room.get_den_mpz_t());
        const Rational lo = random_number(rng, f, 0, floor_room.get_si());
        return std::make_pair(lo, Rational(lo + length));
    };
    auto random_kind = [&]() {
        const bool absorber =
            Integer(static_cast<long>(uniform(rng, 0, absorb_den.get_si() - 1))) < absorb_num;
        // Drawn whether or not the element absorbs, so each element takes
        // the same number of draws whatever its kind.
        const bool splitter = happens(rng, f.splitters);
        return absorber   ? ElementKind::absorber
               : splitter ? ElementKind::splitter
                          : ElementKind::mirror;
    };
    for (std::int64_t i = 0; i < f.mirrors; ++i) {
        if (happens(rng, f.diagonals)) {
            // A diagonal (docs/octagonal.md): its x-extent, then where its
            // lower end lies in y, then its slope; always two-sided.
            const auto [x0, x1] = random_extent();
            const Rational length = x1 - x0, room = f.range - length;
            Integer floor_room;
            mpz_fdiv_q(floor_room.get_mpz_t(), room.get_num_mpz_t(), room.get_den_mpz_t());
            const Rational y0 = random_number(rng, f, 0, floor_room.get_si());
            const Rational y1 = y0 + length;
            const bool rising = uniform(rng, 0, 1) == 0;
            scene.add_diagonal(random_kind(), x0, rising ? y0 : y1, x1, rising ? y1 : y0);
            continue;
        }
        const int axis = static_cast<int>(uniform(rng, 0, f.dim - 1));
        const Rational offset = random_number(rng, f, 0, f.range);
        std::vector<std::pair<Rational, Rational>> extent;
        for (int j = 0; j < f.dim; ++j)
            if (j != axis) extent.push_back(random_extent());
        const ElementKind kind = random_kind();
        Side facing = Side::both;
        if (happens(rng, f.one_sided)) facing = uniform(rng, 0, 1) == 0 ? Side::plus : Side::minus;
        scene.add(kind, axis, offset, extent, facing);
    }
    scene.rays.clear();
    for (std::int64_t r = 0; r < f.rays; ++r) scene.rays.push_back(random_ray(rng, f));
    out.notes.push_back(
        "random: " + std::to_string(f.mirrors) + " elements" +
        (f.box ? " inside the mirror box [0, " + std::to_string(f.range) + "]" : ""));
    if (f.splitters > 0 || f.one_sided > 0 || f.diagonals > 0) {
        std::size_t counts[3] = {0, 0, 0}, one_sided = 0, diagonal = 0;
        for (const Element& e : std::span(scene.elements).subspan(first_random)) {
            ++counts[static_cast<int>(e.kind)];
            one_sided += e.one_sided();
            diagonal += e.is_diagonal();
        }
        out.notes.push_back("kinds of the random elements: " + std::to_string(counts[0]) +
                            " mirrors, " + std::to_string(counts[2]) + " splitters, " +
                            std::to_string(counts[1]) + " absorbers; " + std::to_string(one_sided) +
                            " one-sided" +
                            (f.diagonals > 0 ? "; " + std::to_string(diagonal) + " diagonal" : ""));
    }

    if (!f.target_after) {
        scene.targets.clear();
        for (std::int64_t t = 0; t < f.targets; ++t) {
            Vector target;
            for (int j = 0; j < f.dim; ++j) target[j] = random_number(rng, f, 0, f.range);
            scene.targets.push_back(target);
        }
        out.notes.push_back(f.targets == 1
                                ? "target: a random point (answer not known in advance)"
                                : "targets: random points (answers not known in advance)");
        if (!scene.single_trajectory())
            out.notes.push_back(std::to_string(f.rays) + " rays, " + std::to_string(f.targets) +
                                " targets: the illumination question (docs/optics.md)");
        return out;
    }

    // The trajectory's first k + 1 reflections, from the reference tracer
    // (independent of the default engine the expectation is tested against).
    const std::uint64_t steps = static_cast<std::uint64_t>(*f.target_after) + 1;
    PathRecorder path;
    bool escaped = false;
    if (scene.has_one_sided()) {
        // solve() streams no path for one-sided elements: walk the tracer's
        // steps here. A tail and cycle need no care: segment k is on the
        // trajectory whatever came before it.
        path.visit(scene.ray().start, scene.ray().direction);
        for (std::uint64_t i = 0; i < steps; ++i) {
            const engine::ReferenceEvent e =
                engine::reference_step(scene, path.points.back(), path.directions.back());
            escaped = e.escape;
            if (escaped) break;
            path.visit(e.point, e.direction);
            if (e.absorbed) break;
        }
    } else {
        SolveOptions options;
        options.engine = Engine::reference;
        options.max_steps = steps;
        options.path = &path;
        Scene probe = scene;
        probe.target() = Vector{Rational(-1, 3) - f.range, Rational(-1, 7) - f.range, 0};
        escaped = solve(probe, options).reason == Reason::escape;
    }
    // Segment i runs from points[i] to points[i + 1]; after an escape the last
    // one is the final ray. Take segment k, or the last there is.
    const std::size_t segments = path.points.size() - (escaped ? 0 : 1);
    if (segments == 0) throw std::logic_error("generate_random: the trajectory has no segment");
    const std::size_t k =
        std::min<std::size_t>(static_cast<std::size_t>(*f.target_after), segments - 1);
    const bool final_ray = escaped && k + 1 == path.points.size();
    const Vector& a = path.points[k];
    for (int j = 0; j < f.dim; ++j)
        scene.target()[j] = final_ray ? Rational(a[j] + path.directions[k][j])
                                      : Rational((a[j] + path.points[k + 1][j]) / 2);
    for (int j = 0; j < f.dim; ++j) scene.target()[j].canonicalize();

    // The ray first reaches the target on the first segment holding it: the
    // answer is yes, with that segment's number of reflections.
    std::size_t first = k;
    for (std::size_t i = 0; i < k; ++i) {
        if (on_segment(scene.target(), path.points[i], path.points[i + 1], f.dim, false)) {
            first = i;
            break;
        }
    }
    out.expect = Expectation{Reason::hit, Integer(static_cast<unsigned long>(first))};
    out.notes.push_back(
        "target: the " +
        std::string(final_ray ? "point at t = 1 on the final ray" : "midpoint of segment ") +
        (final_ray ? "" : std::to_string(k)) + " of the trajectory" +
        (first < k ? ", first met on segment " + std::to_string(first) : ""));
    return out;
}

} // namespace orthoray
