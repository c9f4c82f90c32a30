// The `random` family: random mirrors and absorbers, optionally boxed, and a
// target either random or placed on the trajectory.
#include "generate/box_faces.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

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

void check(const RandomFamily& f) {
    if (f.dim != 2 && f.dim != 3) throw std::invalid_argument("the dimension must be 2 or 3");
    if (f.mirrors < 0 || f.mirrors > 1'000'000)
        throw std::invalid_argument("the number of mirrors must be in [0, 10^6]");
    if (f.absorbers < 0 || f.absorbers > 1 || f.absorbers.get_den() > (1 << 20))
        throw std::invalid_argument(
            "the absorber fraction must be in [0, 1], with a denominator up to 2^20");
    if (f.denominator < 1 || f.denominator > (std::int64_t{1} << 20))
        throw std::invalid_argument("the denominator bound must be in [1, 2^20]");
    // Numerators k in [0, range * q] must fit in 64 bits: ranges of 10^18
    // with integer coordinates are fine (the induction engine's benchmark).
    if (f.range < 2 || f.range > (std::int64_t{1} << 62) / f.denominator)
        throw std::invalid_argument(
            "the coordinate range must be in [2, 2^62 / the denominator bound]");
    if (f.direction_size < 1 || f.direction_size > (std::int64_t{1} << 40))
        throw std::invalid_argument("the direction size must be in [1, 2^40]");
    if (f.target_after && (*f.target_after < 0 || *f.target_after > 1'000'000))
        throw std::invalid_argument("the target's segment must be in [0, 10^6]");
    // The reference tracer scans every element at every reflection.
    if (f.target_after && (*f.target_after + 1) * (f.mirrors + 6) > 1'000'000'000)
        throw std::invalid_argument("tracing K reflections among this many mirrors would take "
                                    "too long: (K + 1) * mirrors must stay below 10^9");
}

} // namespace

GeneratedScene generate_random(const RandomFamily& f) {
    check(f);
    std::mt19937_64 rng(f.seed);
    GeneratedScene out;
    Scene& scene = out.scene;
    scene.dim = f.dim;
    if (f.box) generate::add_box_faces(scene, std::vector<Rational>(3, Rational(f.range)));

    // Mirrors about as long as the gaps between them: side s = range /
    // floor(n^(1/dim)), lengths in [s/2, s], so crossings stay rare.
    const std::int64_t side = std::max<std::int64_t>(
        2, f.range / integer_root(std::max<std::int64_t>(1, f.mirrors), f.dim));
    const Integer absorb_num = f.absorbers.get_num(), absorb_den = f.absorbers.get_den();
    for (std::int64_t i = 0; i < f.mirrors; ++i) {
        const int axis = static_cast<int>(uniform(rng, 0, f.dim - 1));
        const Rational offset = random_number(rng, f, 0, f.range);
        std::vector<std::pair<Rational, Rational>> extent;
        for (int j = 0; j < f.dim; ++j) {
            if (j == axis) continue;
            Rational length = random_number(rng, f, side / 2, side);
            if (length == 0) length = 1;
            if (length > f.range) length = f.range;
            const Rational room = f.range - length;
            Integer floor_room;
            mpz_fdiv_q(floor_room.get_mpz_t(), room.get_num_mpz_t(), room.get_den_mpz_t());
            const Rational lo = random_number(rng, f, 0, floor_room.get_si());
            extent.emplace_back(lo, lo + length);
        }
        const bool absorber =
            Integer(static_cast<long>(uniform(rng, 0, absorb_den.get_si() - 1))) < absorb_num;
        scene.add(absorber ? ElementKind::absorber : ElementKind::mirror, axis, offset, extent);
    }
    for (int j = 0; j < f.dim; ++j) scene.ray().start[j] = random_number(rng, f, 0, f.range);
    for (int j = 0; j < f.dim; ++j) {
        std::int64_t d = uniform(rng, 1, f.direction_size);
        if (uniform(rng, 0, 1) == 0) d = -d;
        scene.ray().direction[j] = Rational(Integer(static_cast<long>(d)));
    }
    out.notes.push_back(
        "random: " + std::to_string(f.mirrors) + " elements" +
        (f.box ? " inside the mirror box [0, " + std::to_string(f.range) + "]" : ""));

    if (!f.target_after) {
        for (int j = 0; j < f.dim; ++j) scene.target()[j] = random_number(rng, f, 0, f.range);
        out.notes.push_back("target: a random point (answer not known in advance)");
        return out;
    }

    // The trajectory's first k + 1 reflections, from the reference tracer
    // (independent of the default engine the expectation is tested against).
    PathRecorder path;
    SolveOptions options;
    options.engine = Engine::reference;
    options.max_steps = static_cast<std::uint64_t>(*f.target_after) + 1;
    options.path = &path;
    Scene probe = scene;
    probe.target() = Vector{Rational(-1, 3) - f.range, Rational(-1, 7) - f.range, 0};
    const Answer traced = solve(probe, options);
    // Segment i runs from points[i] to points[i + 1]; after an escape the last
    // one is the final ray. Take segment k, or the last there is.
    const bool escaped = traced.reason == Reason::escape;
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
