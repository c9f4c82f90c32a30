// Instance families (docs/generate.md): scenes built from a few parameters,
// byte-for-byte the same on every machine, most with their answer known in
// closed form so that a test can hold the solver to it.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace orthoray {

// A uniform integer in [lo, hi] (lo <= hi) from std::mt19937_64, whose
// output sequence the C++ standard fixes, by rejection sampling with integer
// arithmetic only. (std::uniform_int_distribution is not used: each standard
// library picks its own algorithm, so one seed would give other scenes
// elsewhere.)
std::int64_t uniform(std::mt19937_64& rng, std::int64_t lo, std::int64_t hi);

// floor(n^(1/dim)) for dim in {1, 2, 3} and n >= 1, in integers.
std::int64_t integer_root(std::int64_t n, int dim);

// The answer a family knows from its construction or a closed form.
struct Expectation {
    Reason reason = Reason::hit; // hit, escape, absorbed or cycle
    Integer reflections;         // for cycle: the period
};

struct GeneratedScene {
    Scene scene;
    std::optional<Expectation> expect;
    std::vector<std::string> notes; // one-line comments: how it was built, why the answer holds
};

// `random`: mirrors with random normal axes, offsets and extents; with
// splitters, one-sided elements, several rays or several targets as asked
// (docs/generate.md). Left at their defaults, those draw nothing, so a seed
// gives the same scene it gave before they existed.
struct RandomFamily {
    // The bounds generate_random checks, and the command line's options
    // carry: the number of elements, of rays and of targets, the
    // denominator bound q (and of a chance), the direction size and the
    // target's segment. The coordinate range is at most 2^62 / q, so that
    // every numerator fits 64 bits.
    static constexpr std::int64_t max_mirrors = 1'000'000;
    static constexpr std::int64_t max_rays = 1000, max_targets = 1000;
    static constexpr std::int64_t max_denominator = std::int64_t{1} << 20;
    static constexpr std::int64_t max_range = std::int64_t{1} << 62;
    static constexpr std::int64_t max_direction_size = std::int64_t{1} << 40;
    static constexpr std::int64_t max_target_after = 1'000'000;

    int dim = 2;
    std::int64_t mirrors = 20;
    Rational absorbers = 0;       // the chance that an element absorbs, in [0, 1]
    Rational splitters = 0;       // the chance that an element that does not absorb splits
    Rational one_sided = 0;       // the chance that an element is one-sided (+ or - alike)
    Rational diagonals = 0;       // 2D: the chance that an element lies on a diagonal
    std::int64_t rays = 1;        // rays, each with a random start and direction
    std::int64_t targets = 1;     // targets, random points (with target_after: rays = targets = 1)
    std::int64_t range = 1000;    // coordinates lie in [0, range]
    std::int64_t denominator = 1; // each number is k / q with q drawn from 1..denominator
    bool box = false;             // also the closed mirror box [0, range]^dim
    // The target: the midpoint of segment k of the trajectory (after k
    // reflections; fewer if the ray escapes, is absorbed or cycles sooner), or,
    // without k, a random point.
    std::optional<std::int64_t> target_after;
    std::int64_t direction_size = 10; // direction components: nonzero integers in [-d, d]
    std::uint64_t seed = 1;
};
GeneratedScene generate_random(const RandomFamily& family);

// `box`: the closed mirror box [0, a] x [0, b] (x [0, c]).
struct BoxFamily {
    std::vector<Integer> sides = {3, 5}; // 2 or 3 positive sides
    // Default: from the corner 0 along (1, ..., 1), where the answer is known.
    std::optional<Vector> start, direction;
    enum class Target {
        reached, // the corner the 45-degree ray from 0 reaches (the default)
        far,     // the corner opposite 0
        generic, // (1/2, 1/3, 1/5): on no line x +- y = integer, never reached
        point,   // `target_point`
    } target = Target::reached;
    Vector target_point;
};
GeneratedScene generate_box(const BoxFamily& family);

// `square`: the unit mirror square, direction (p, q), a start that keeps the
// ray off every corner, and a target off the trajectory: a cycle of period
// 2 (p + q) / gcd(p, q).
GeneratedScene generate_square(const Integer& p, const Integer& q);

// `hallway`: the mirrors y = 0 and y = 1 for x in [0, length], the ray from
// (0, 1/2) with slope `slope` > 0, the target on its final ray past the end:
// floor(1/2 + slope * length) reflections.
GeneratedScene generate_hallway(const Rational& length, const Rational& slope);

// `coprime-box`: the box (2^k + 1) x 2^k from a corner at 45 degrees;
// `coprime-cuboid`: (2^k + 1) x 2^k x (2^k - 1). Four or six mirrors and
// O(k) input bits, about 2^(k+1) or 3 * 2^k reflections.
GeneratedScene generate_coprime_box(unsigned k, BoxFamily::Target target);
GeneratedScene generate_coprime_cuboid(unsigned k, BoxFamily::Target target);

// The .scene text: the `header` lines and notes as comments, the
// expectation as `# expect: yes hit 6` (or `no cycle 16`, `no escape 3`,
// `no absorbed 2`), then the scene.
std::string write_generated(const GeneratedScene& generated,
                            const std::vector<std::string>& header = {});

// The expectation written in a .scene text, if there is one.
std::optional<Expectation> read_expectation(std::string_view scene_text);

} // namespace orthoray
