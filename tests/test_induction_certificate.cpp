// Induction certificates (docs/induction-certificates.md): hand-derived
// certificates for tiny scenes verify, and each tampering is rejected for
// the reason it introduces (the message is matched, so a check that never
// fires fails the test).
#include "support/certificate_outcome.hpp"
#include "support/portable_random.hpp"
#include "support/random_scene.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

using orthoray::Rational;
using orthoray::Scene;

using orthoray::test::expect_invalid;
using orthoray::test::expect_valid;
using orthoray::test::Outcome;
using orthoray::test::verify;

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    REQUIRE(text.find(from, at + 1) == std::string::npos); // the tampering is unambiguous
    text.replace(at, from.size(), to);
    return text;
}

void expect_malformed(const Scene& scene, const std::string& text, const std::string& reason) {
    const Outcome outcome = verify(scene, text);
    INFO("certificate:\n" << text << "verify said: " << outcome.message);
    CHECK_FALSE(outcome.valid);
    CHECK(outcome.input_error);
    CHECK(outcome.message.find(reason) != std::string::npos);
}

// ------------------------------------------------------------ hallway --
//
// Two mirrors y = 0 and y = 1 for x in [0, 6]; the ray starts at (0, 0)
// along (1, 1). It zigzags (1, 1), (2, 0), (3, 1), (4, 0), (5, 1), (6, 0)
// (the end of y = 0 reflects) and leaves along (1, 1): escape after 6.
//
// Lattice: scale 1 1 (all integral, direction already diagonal). The first
// state x is (1, 1) leaving along (1, -1): w(x) = -1 * 1 - 1 * 1 = -2.
// Reflections on y = 0 leave w alone and on y = 1 change it by +-2, so the
// modulus is 2: the states have even w.
//   transversal 0: the line Y = 1 with direction (1, -1), u = X in [0, 6]:
//     w = -1 - u even, so u = 1, 3, 5; w grows as u falls, so the states are
//     (5, 1), (3, 1), (1, 1): raw 0, 1, 2.
//   transversal 1: the line Y = 0 with direction (1, 1): w = -u even, u = 0,
//     2, 4, 6; in order of w: (6, 0), (4, 0), (2, 0), (0, 0): raw 3 to 6.
// x is state 2 of transversal 0, raw 2, so rotated = (raw - 2) mod 7:
//   (1,1) 0, (6,0) 1, (4,0) 2, (2,0) 3, (0,0) 4, (5,1) 5, (3,1) 6.
// The map: 0 -> 3 -> 6 -> 2 -> 5 -> 1 -> escape, 4 (the start point (0, 0),
// no predecessor) -> 0. The escaping state 1 is sent to the one state
// without a predecessor, 4. Rotated 2, 3 (raw 4, 5: transversal 1) go to 5,
// 6 (raw 0, 1: transversal 0), and 5, 6 to 1, 2: two pieces of length 2.
//
// The induction, (d, i, l, r, event) for each piece, L = 7:
//   P0 (0,3,1,1) P1 (1,4,1,1,escape@0) P2 (2,5,2,1) P3 (4,0,1,1) P4 (5,1,2,1)
//   D = P4 (domain ends at 7), R = P2 (image ends at 7), equal lengths:
//   equal 2 4: P2 (2,1,2,2); L = 5. D = P3, R = P1: equal 1 3: P1
//   (1,0,1,2,escape@0); L = 4. D = P2 (l 2), R = P0 (l 1): top 2 0: P0
//   image 1 + 2 - 1 = 2, r 3; P2 l 1; L = 3. D = P2, R = P0: equal 0 2: P0
//   (0,1,1,5); L = 2. D = P1, R = P0: equal 0 1: P0 gets P1's escape at
//   offset 0 + 5: escape after 6 reflections, as walked above.

Scene hallway() {
    return orthoray::read_scene("dim 2\n"
                                "mirror y 0 x 0 6\n"
                                "mirror y 1 x 0 6\n"
                                "ray 0 0 1 1\n"
                                "target 3 0\n");
}

const std::string hallway_certificate = "orthoray-certificate 1\n"
                                        "dim 2\n"
                                        "point 0 0\n"
                                        "point 1 1\n"
                                        "method induction\n"
                                        "direction 1 -1\n"
                                        "scale 1 1\n"
                                        "modulus 2\n"
                                        "transversal 1 1 0 6 1 -1\n"
                                        "transversal 1 0 0 6 1 1\n"
                                        "first 0 2\n"
                                        "piece 0 1 reflect 3\n"
                                        "piece 1 1 escape 4\n"
                                        "piece 2 2 reflect 5\n"
                                        "piece 4 1 reflect 0\n"
                                        "piece 5 2 reflect 1\n"
                                        "step equal 2 4\n"
                                        "step equal 1 3\n"
                                        "step top 2 0\n"
                                        "step equal 0 2\n"
                                        "step equal 0 1\n"
                                        "answer no\n"
                                        "reason escape\n"
                                        "reflections 6\n"
                                        "end\n";

// The same hallway with the target (5, 1), the fifth reflection point: the
// segments from (4, 0) (rotated 2) and from (5, 1) itself (rotated 5) hold
// it, so both are pieces of their own flagged hit. L = 7:
//   P0 (0,3) P1 (1,4,escape) P2 (2,5,hit) P3 (3,6) P4 (4,0) P5 (5,1,hit) P6 (6,2)
//   equal 3 6: P3 (3,2,r 2); L 6. equal 2 5: P2 (2,1,r 2,hit@0); L 5.
//   equal 1 4: P1 (1,0,r 2,escape@0); L 4. equal 0 3: P0 (0,2,r 3); L 3.
//   equal 0 2: P0 (0,1,r 5,hit@3); L 2. equal 0 1: P0 keeps hit@3; L 1.
// Hit at offset 3: 4 reflections, on the segment (4, 0) to (5, 1).
Scene hallway_hit() {
    Scene s = hallway();
    s.target() = {5, 1, 0};
    return s;
}

const std::string hallway_hit_certificate = "orthoray-certificate 1\n"
                                            "dim 2\n"
                                            "point 0 0\n"
                                            "point 1 1\n"
                                            "method induction\n"
                                            "direction 1 -1\n"
                                            "scale 1 1\n"
                                            "modulus 2\n"
                                            "transversal 1 1 0 6 1 -1\n"
                                            "transversal 1 0 0 6 1 1\n"
                                            "first 0 2\n"
                                            "piece 0 1 reflect 3\n"
                                            "piece 1 1 escape 4\n"
                                            "piece 2 1 reflect 5 hit\n"
                                            "piece 3 1 reflect 6\n"
                                            "piece 4 1 reflect 0\n"
                                            "piece 5 1 reflect 1 hit\n"
                                            "piece 6 1 reflect 2\n"
                                            "step equal 3 6\n"
                                            "step equal 2 5\n"
                                            "step equal 1 4\n"
                                            "step equal 0 3\n"
                                            "step equal 0 2\n"
                                            "step equal 0 1\n"
                                            "answer yes\n"
                                            "reason hit\n"
                                            "reflections 4\n"
                                            "end\n";

// The hallway with an absorber across its open end at x = 7: the ray from
// (6, 0) is absorbed at (7, 1). Same exchange, piece 1 absorbed.
Scene hallway_absorbed() {
    Scene s = hallway();
    s.add_absorber(0, 7, {{0, 1}});
    return s;
}

// ---------------------------------------------------------------- box --
//
// The box [0, 2] x [0, 1] of mirrors, the ray from the corner (0, 0) along
// (1, 1): (1, 1) along (1, -1), the corner (2, 0) (both components negate)
// along (-1, 1), (1, 1) along (-1, -1), the corner (0, 0) along (1, 1), and
// back to (1, 1) along (1, -1): a cycle of period 4. Each of the four
// states is a transversal of one state (w = -2, 2, 0, 0: all even, modulus
// 2), x is raw 0, and the exchange is the rotation 0 -> 1 -> 2 -> 3 -> 0.
// equal 2 3 (L 3), equal 1 2 (L 2), equal 0 1 (L 1): r = 4, no event.

Scene box() {
    return orthoray::read_scene("dim 2\n"
                                "mirror x 0 y 0 1\n"
                                "mirror x 2 y 0 1\n"
                                "mirror y 0 x 0 2\n"
                                "mirror y 1 x 0 2\n"
                                "ray 0 0 1 1\n"
                                "target 1 0\n");
}

const std::string box_certificate = "orthoray-certificate 1\n"
                                    "dim 2\n"
                                    "point 0 0\n"
                                    "point 1 1\n"
                                    "method induction\n"
                                    "direction 1 -1\n"
                                    "scale 1 1\n"
                                    "modulus 2\n"
                                    "transversal 1 1 1 1 1 -1\n"
                                    "transversal 1 0 2 2 -1 1\n"
                                    "transversal 1 1 1 1 -1 -1\n"
                                    "transversal 1 0 0 0 1 1\n"
                                    "first 0 0\n"
                                    "piece 0 1 reflect 1\n"
                                    "piece 1 1 reflect 2\n"
                                    "piece 2 1 reflect 3\n"
                                    "piece 3 1 reflect 0\n"
                                    "step equal 2 3\n"
                                    "step equal 1 2\n"
                                    "step equal 0 1\n"
                                    "answer no\n"
                                    "reason cycle\n"
                                    "reflections 4\n"
                                    "period 4\n"
                                    "end\n";

// ------------------------------------------ a brute-force certificate writer --
//
// Test-only, and deliberately naive: for a small 2D scene it lists every
// lattice state on a mirror (one transversal a merged mirror interval and
// direction), finds each state's next state by a plain scan, closes the holes,
// cuts the exchange into maximal pieces and runs Rauzy induction on explicit
// positions, with cycle steps at random. It writes certificates the checker
// must accept, whose verdict the tests compare with the reference tracer,
// independently of the induction engine.

using orthoray::Integer;
using orthoray::Vector;

Integer lcm_of(const Integer& a, const Integer& b) {
    Integer r;
    mpz_lcm(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return r;
}

Integer gcd_of(const Integer& a, const Integer& b) {
    Integer r;
    mpz_gcd(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return r;
}

Integer mod_of(const Integer& a, const Integer& m) {
    Integer r;
    mpz_fdiv_r(r.get_mpz_t(), a.get_mpz_t(), m.get_mpz_t());
    return r;
}

struct BruteElement {
    int axis;
    Integer c, lo, hi;
    bool absorber;
};

struct BruteState {
    Integer x, y;
    int dx, dy;
    bool operator<(const BruteState& o) const {
        return std::tie(x, y, dx, dy) < std::tie(o.x, o.y, o.dx, o.dy);
    }
};

struct BruteTransversal {
    int a;
    Integer c, lo, hi;
    int dx, dy;
    std::vector<BruteState> states; // by increasing w
};

struct Brute {
    std::string text;
    std::string verdict; // "valid: <reason>, <n> reflections"
    int steps = 0, cycle_steps = 0;
};

std::optional<Brute> brute_certificate(const Scene& scene, std::mt19937_64& rng,
                                       std::size_t max_states) {
    if (scene.dim != 2 || scene.ray().direction[0] == 0 || scene.ray().direction[1] == 0)
        return std::nullopt;
    orthoray::PathRecorder path;
    {
        orthoray::SolveOptions o;
        o.engine = orthoray::Engine::reference;
        o.max_steps = 1;
        o.path = &path;
        Scene probe = scene;
        probe.target() = Vector{Rational(1, 3) << 200, 0, 0};
        orthoray::solve(probe, o);
    }
    if (path.points.size() < 2) return std::nullopt; // escapes at once
    const Vector p1 = path.points[1], v1 = path.directions[1];
    for (const orthoray::Element& e : scene.elements) // absorbed at p1
        if (e.kind == orthoray::ElementKind::absorber && e.lo[0] <= p1[0] && p1[0] <= e.hi[0] &&
            e.lo[1] <= p1[1] && p1[1] <= e.hi[1])
            return std::nullopt;
    // The scale: |v_x| * SX = |v_y| * SY, then everything integral.
    Rational sx = abs(scene.ray().direction[1]), sy = abs(scene.ray().direction[0]);
    Integer k = 1;
    auto need = [&](const Rational& value, const Rational& s) {
        const Rational q = value * s;
        k = lcm_of(k, q.get_den());
    };
    for (const orthoray::Element& e : scene.elements)
        for (int j = 0; j < 2; ++j) {
            need(e.lo[j], j == 0 ? sx : sy);
            need(e.hi[j], j == 0 ? sx : sy);
        }
    for (const Vector* v : {&scene.ray().start, &p1, &scene.target()})
        for (int j = 0; j < 2; ++j) need((*v)[j], j == 0 ? sx : sy);
    sx *= k;
    sy *= k;
    auto lat = [](const Rational& v, const Rational& s) {
        const Rational q = v * s;
        return Integer(q.get_num());
    };
    std::vector<BruteElement> elements;
    for (const orthoray::Element& e : scene.elements) {
        const int other = 1 - e.axis;
        const Rational& so = e.axis == 0 ? sx : sy;
        const Rational& sa = other == 0 ? sx : sy;
        elements.push_back({e.axis, lat(e.offset(), so), lat(e.lo[other], sa), lat(e.hi[other], sa),
                            e.kind == orthoray::ElementKind::absorber});
    }
    const Integer px = lat(p1[0], sx), py = lat(p1[1], sy);
    const Integer tx = lat(scene.target()[0], sx), ty = lat(scene.target()[1], sy);
    const int dx1 = sgn(v1[0]), dy1 = sgn(v1[1]);
    const Integer wx = dy1 * py - dx1 * px;
    Integer g = 0;
    for (const BruteElement& e : elements)
        if (!e.absorber) g = gcd_of(g, Integer(2 * e.c));
    auto in_class = [&](const Integer& w) { return g == 0 ? w == wx : mod_of(w - wx, g) == 0; };

    // Transversals: merged mirror intervals on each mirror line, for each
    // direction; points of a horizontal line that lie on a vertical mirror
    // belong to the vertical line's transversal.
    auto on_vertical = [&](const Integer& x, const Integer& y) {
        for (const BruteElement& e : elements)
            if (!e.absorber && e.axis == 0 && e.c == x && e.lo <= y && y <= e.hi) return true;
        return false;
    };
    std::vector<BruteTransversal> transversals;
    for (int a = 0; a < 2; ++a) {
        std::vector<Integer> lines;
        for (const BruteElement& e : elements)
            if (!e.absorber && e.axis == a) lines.push_back(e.c);
        std::sort(lines.begin(), lines.end());
        lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
        for (const Integer& c : lines) {
            std::vector<std::pair<Integer, Integer>> spans;
            for (const BruteElement& e : elements)
                if (!e.absorber && e.axis == a && e.c == c) spans.push_back({e.lo, e.hi});
            std::sort(spans.begin(), spans.end());
            std::vector<std::pair<Integer, Integer>> merged;
            for (const auto& sp : spans) {
                if (!merged.empty() && sp.first <= merged.back().second + 1)
                    merged.back().second = std::max(merged.back().second, sp.second);
                else
                    merged.push_back(sp);
            }
            for (int dir = 0; dir < 4; ++dir) {
                const int dx = dir & 1 ? -1 : 1, dy = dir & 2 ? -1 : 1;
                for (const auto& [lo, hi] : merged) {
                    BruteTransversal t{a, c, lo, lo, dx, dy, {}};
                    bool open = false;
                    auto close = [&]() {
                        if (open && !t.states.empty()) transversals.push_back(t);
                        open = false;
                    };
                    for (Integer u = lo; u <= hi; ++u) {
                        const Integer x = a == 0 ? c : u, y = a == 0 ? u : c;
                        if (a == 1 && on_vertical(x, y)) {
                            close();
                            continue;
                        }
                        if (!open) {
                            t = BruteTransversal{a, c, u, u, dx, dy, {}};
                            open = true;
                        }
                        t.hi = u;
                        if (in_class(dy * y - dx * x)) t.states.push_back({x, y, dx, dy});
                    }
                    close();
                }
            }
        }
    }
    orthoray::test::shuffle(transversals, rng);
    std::map<BruteState, std::size_t> raw_of;
    std::vector<BruteState> raw_states;
    std::vector<std::size_t> transversal_of;
    for (std::size_t k2 = 0; k2 < transversals.size(); ++k2) {
        BruteTransversal& t = transversals[k2];
        std::sort(t.states.begin(), t.states.end(), [](const BruteState& p, const BruteState& q) {
            return p.dy * p.y - p.dx * p.x < q.dy * q.y - q.dx * q.x;
        });
        for (const BruteState& st : t.states) {
            raw_of[st] = raw_states.size();
            raw_states.push_back(st);
            transversal_of.push_back(k2);
        }
        if (raw_states.size() > max_states) return std::nullopt;
    }
    const std::size_t n = raw_states.size();
    const auto x_it = raw_of.find({px, py, dx1, dy1});
    INFO("scene:\n"
         << orthoray::write_scene(scene) << "x " << px << " " << py << " " << dx1 << " " << dy1
         << " scale " << sx << " " << sy);
    REQUIRE(x_it != raw_of.end());
    const std::size_t raw_x = x_it->second;

    // The map, by a plain scan from every state.
    enum Kind { reflect, escape, absorbed };
    std::vector<long long> image(n, -1);
    std::vector<Kind> kind(n, reflect);
    std::vector<bool> hit(n, false);
    auto rot = [&](std::size_t raw) { return (raw + n - raw_x) % n; };
    for (std::size_t raw = 0; raw < n; ++raw) {
        const BruteState& st = raw_states[raw];
        std::optional<Integer> best;
        bool absorber = false;
        bool flip[2] = {false, false};
        for (const BruteElement& e : elements) {
            const Integer t = e.axis == 0 ? st.dx * (e.c - st.x) : st.dy * (e.c - st.y);
            if (t <= 0 || (best && t > *best)) continue;
            const Integer along = e.axis == 0 ? st.y + t * st.dy : st.x + t * st.dx;
            if (along < e.lo || along > e.hi) continue;
            if (!best || t < *best) {
                best = t;
                absorber = false;
                flip[0] = flip[1] = false;
            }
            if (e.absorber)
                absorber = true;
            else
                flip[e.axis] = true;
        }
        const std::size_t z = rot(raw);
        // The target on the segment: target = state + tau * (dx, dy).
        const Integer tau = st.dx * (tx - st.x);
        hit[z] = tau >= 0 && st.dy * (ty - st.y) == tau && (!best || tau <= *best);
        if (!best) {
            kind[z] = escape;
        } else if (absorber) {
            kind[z] = absorbed;
        } else {
            const BruteState next{st.x + *best * st.dx, st.y + *best * st.dy,
                                  flip[0] ? -st.dx : st.dx, flip[1] ? -st.dy : st.dy};
            const auto it = raw_of.find(next);
            REQUIRE(it != raw_of.end());
            image[z] = static_cast<long long>(rot(it->second));
        }
    }
    // Close the holes: the states without a successor onto those without a
    // predecessor, in order.
    {
        std::vector<bool> has_pred(n, false);
        for (std::size_t z = 0; z < n; ++z)
            if (image[z] >= 0) has_pred[static_cast<std::size_t>(image[z])] = true;
        std::vector<std::size_t> sources;
        for (std::size_t z = 0; z < n; ++z)
            if (!has_pred[z]) sources.push_back(z);
        std::size_t next = 0;
        for (std::size_t z = 0; z < n; ++z)
            if (image[z] < 0) {
                REQUIRE(next < sources.size());
                image[z] = static_cast<long long>(sources[next++]);
            }
        REQUIRE(next == sources.size());
    }
    auto raw_of_rot = [&](std::size_t z) { return (z + raw_x) % n; };
    auto same_transversal = [&](std::size_t z) { // z - 1 and z, as raw states
        const std::size_t a = raw_of_rot(z - 1), b = raw_of_rot(z);
        return b == a + 1 && transversal_of[a] == transversal_of[b];
    };
    auto same_image_transversal = [&](std::size_t z) {
        const std::size_t a = raw_of_rot(static_cast<std::size_t>(image[z - 1]));
        const std::size_t b = raw_of_rot(static_cast<std::size_t>(image[z]));
        return b == a + 1 && transversal_of[a] == transversal_of[b];
    };

    // Pieces: maximal runs of one translation and one kind, hit states alone.
    struct Piece {
        long long d, i, l, r;
        Kind kind;
        bool hit;
        int event = 0; // 0 none, 1 hit, 2 escape, 3 absorbed
        long long e = 0;
        bool alive = true;
    };
    std::vector<Piece> pieces;
    for (std::size_t z = 0; z < n; ++z) {
        bool extend = z >= 2 && !pieces.empty() && pieces.back().kind == kind[z] && !hit[z] &&
                      !pieces.back().hit && image[z] == image[z - 1] + 1 &&
                      orthoray::test::chance(rng, 95);
        if (extend && kind[z] == reflect) extend = same_transversal(z) && same_image_transversal(z);
        if (extend && kind[z] != reflect)
            extend = same_transversal(z) || orthoray::test::chance(rng, 50);
        if (extend && raw_of_rot(z) == 0) extend = kind[z] != reflect; // a wrap
        if (extend) {
            ++pieces.back().l;
            continue;
        }
        Piece p{static_cast<long long>(z), image[z], 1, 1, kind[z], hit[z]};
        p.event = hit[z] ? 1 : kind[z] == escape ? 2 : kind[z] == absorbed ? 3 : 0;
        pieces.push_back(p);
    }
    std::ostringstream out;
    out << "orthoray-certificate 1\ndim 2\n";
    out << "point " << orthoray::to_string(scene.ray().start[0]) << " "
        << orthoray::to_string(scene.ray().start[1]) << "\n";
    out << "point " << orthoray::to_string(p1[0]) << " " << orthoray::to_string(p1[1]) << "\n";
    out << "method induction\n";
    out << "direction " << orthoray::to_string(v1[0]) << " " << orthoray::to_string(v1[1]) << "\n";
    out << "scale " << orthoray::to_string(sx) << " " << orthoray::to_string(sy) << "\n";
    out << "modulus " << g << "\n";
    for (const BruteTransversal& t : transversals)
        out << "transversal " << t.a << " " << t.c << " " << t.lo << " " << t.hi << " " << t.dx
            << " " << t.dy << "\n";
    {
        const std::size_t tx1 = transversal_of[raw_x];
        std::size_t index = 0;
        while (raw_x - index > 0 && transversal_of[raw_x - index - 1] == tx1) ++index;
        out << "first " << tx1 << " " << index << "\n";
    }
    for (const Piece& p : pieces)
        out << "piece " << p.d << " " << p.l << " "
            << (p.kind == reflect  ? "reflect"
                : p.kind == escape ? "escape"
                                   : "absorbed")
            << " " << p.i << (p.hit ? " hit" : "") << "\n";

    // The induction, on explicit positions.
    Brute result;
    auto then = [](const Piece& a, const Piece& b, int& event, long long& e) {
        if (a.event) {
            event = a.event;
            e = a.e;
        } else if (b.event) {
            event = b.event;
            e = b.e + a.r;
        } else {
            event = 0;
        }
    };
    long long L = static_cast<long long>(n);
    while (L > 1) {
        std::size_t di = pieces.size(), ri = pieces.size();
        for (std::size_t j = 0; j < pieces.size(); ++j) {
            if (!pieces[j].alive) continue;
            if (pieces[j].d + pieces[j].l == L) di = j;
            if (pieces[j].i + pieces[j].l == L) ri = j;
        }
        REQUIRE(di < pieces.size());
        REQUIRE(ri < pieces.size());
        Piece& D = pieces[di];
        Piece& R = pieces[ri];
        const bool cycle = orthoray::test::chance(rng, 50);
        ++result.steps;
        if (di == ri) {
            out << "step invariant " << di << "\n";
            D.alive = false;
            L -= D.l;
        } else if (D.l > R.l) {
            const long long S = L - (D.i + D.l);
            const long long M = (D.l - 1) / S;
            if (cycle && M >= 1) {
                ++result.cycle_steps;
                out << "step top-cycle " << di << " " << M << "\n";
                for (Piece& P : pieces) {
                    if (!P.alive || &P == &D || P.i < D.i + D.l) continue;
                    if (!P.event && D.event) {
                        P.event = D.event;
                        P.e = P.r + D.e;
                    }
                    P.r += M * D.r;
                    P.i -= M * S;
                }
                D.l -= M * S;
                L -= M * S;
            } else {
                out << "step top " << di << " " << ri << "\n";
                then(R, D, R.event, R.e);
                R.r += D.r;
                R.i = D.i + D.l - R.l;
                D.l -= R.l;
                L -= R.l;
            }
        } else if (R.l > D.l) {
            const long long S = L - (R.d + R.l);
            const long long M = (R.l - 1) / S;
            if (cycle && M >= 1) {
                ++result.cycle_steps;
                out << "step bottom-cycle " << ri << " " << M << "\n";
                for (Piece& P : pieces) {
                    if (!P.alive || &P == &R || P.d < R.d + R.l) continue;
                    if (R.event) {
                        P.event = R.event;
                        P.e = R.e;
                    } else if (P.event) {
                        P.e += M * R.r;
                    }
                    P.r += M * R.r;
                    P.d -= M * S;
                }
                R.l -= M * S;
                L -= M * S;
            } else {
                out << "step bottom " << ri << " " << di << "\n";
                int event;
                long long e = 0;
                then(R, D, event, e);
                D.event = event;
                D.e = e;
                D.r += R.r;
                D.d = R.d + R.l - D.l;
                R.l -= D.l;
                L -= D.l;
            }
        } else {
            out << "step equal " << ri << " " << di << "\n";
            then(R, D, R.event, R.e);
            R.r += D.r;
            R.i = D.i;
            D.alive = false;
            L -= D.l;
        }
    }
    const Piece& x = pieces[0];
    REQUIRE(x.alive);
    if (x.event == 0) {
        out << "answer no\nreason cycle\nreflections " << x.r << "\nperiod " << x.r << "\n";
        result.verdict = "valid: cycle, " + std::to_string(x.r) + " reflections";
    } else {
        const char* reason = x.event == 1 ? "hit" : x.event == 2 ? "escape" : "absorbed";
        out << "answer " << (x.event == 1 ? "yes" : "no") << "\nreason " << reason
            << "\nreflections " << x.e + 1 << "\n";
        result.verdict =
            std::string("valid: ") + reason + ", " + std::to_string(x.e + 1) + " reflections";
    }
    out << "end\n";
    result.text = out.str();
    return result;
}
} // namespace

// ------------------------------------------------------------------ valid --

TEST_CASE("hand-derived induction certificates verify", "[induction-certificate]") {
    expect_valid(hallway(), hallway_certificate, "valid: escape, 6 reflections");
    expect_valid(hallway_hit(), hallway_hit_certificate, "valid: hit, 4 reflections");
    expect_valid(hallway_absorbed(),
                 replace(replace(hallway_certificate, "piece 1 1 escape 4", "piece 1 1 absorbed 4"),
                         "reason escape", "reason absorbed"),
                 "valid: absorbed, 6 reflections");
    expect_valid(box(), box_certificate, "valid: cycle, 4 reflections");
    // A top step is a top-cycle with M = 1 (S = 4 - (1 + 2) = 1 < l_D = 2).
    expect_valid(hallway(), replace(hallway_certificate, "step top 2 0", "step top-cycle 2 1"),
                 "valid: escape, 6 reflections");
    // Comments and blank lines are allowed, as in path certificates.
    expect_valid(hallway(), replace(hallway_certificate, "modulus 2\n", "modulus 2 # G\n\n"),
                 "valid: escape, 6 reflections");
}

TEST_CASE("the same numbers at a scale", "[induction-certificate]") {
    // The hallway with every coordinate halved: scale 2 2 brings it back.
    Scene half = orthoray::read_scene("dim 2\n"
                                      "mirror y 0 x 0 3\n"
                                      "mirror y 1/2 x 0 3\n"
                                      "ray 0 0 1 1\n"
                                      "target 3/2 0\n");
    std::string text = replace(hallway_certificate, "point 1 1\n", "point 1/2 1/2\n");
    text = replace(text, "scale 1 1", "scale 2 2");
    expect_valid(half, text, "valid: escape, 6 reflections");
    // A direction (2, 1) is diagonal at scale 1 2: the same lattice.
    Scene wide = orthoray::read_scene("dim 2\n"
                                      "mirror y 0 x 0 6\n"
                                      "mirror y 1/2 x 0 6\n"
                                      "ray 0 0 2 1\n"
                                      "target 3 0\n");
    text = replace(hallway_certificate, "point 1 1\n", "point 1 1/2\n");
    text = replace(text, "direction 1 -1", "direction 2 -1");
    text = replace(text, "scale 1 1", "scale 1 2");
    expect_valid(wide, text, "valid: escape, 6 reflections");
}

// --------------------------------------------------------------- tampered --

TEST_CASE("tampered induction certificates are rejected for their reason",
          "[induction-certificate]") {
    const Scene h = hallway();
    const std::string& c = hallway_certificate;

    SECTION("header") {
        expect_invalid(h, replace(c, "point 0 0", "point 0 1"), "not the start point");
        expect_invalid(h, replace(c, "point 1 1", "point 2 2"), "first meets an element at (1, 1)");
        expect_invalid(h, replace(c, "direction 1 -1", "direction 1 1"),
                       "is not the direction (1, -1)");
        Scene early = h;
        early.target() = {Rational(1, 2), Rational(1, 2), 0};
        expect_invalid(early, c, "step 1: the target lies on the segment from point 0 to point 1");
    }
    SECTION("path prefix") {
        const std::string two = "point 0 0\npoint 1 1\n";
        expect_valid(h, replace(c, two, two + "point 2 0\npoint 3 1\n"),
                     "valid: escape, 6 reflections");
        expect_invalid(h, replace(c, two, two + "point 2 0\npoint 3 0\n"),
                       "step 3: point 3 is (3, 0), but the ray from point 2 first meets an "
                       "element at (3, 1)");
        expect_invalid(hallway_hit(),
                       replace(hallway_hit_certificate, two,
                               two + "point 2 0\npoint 3 1\npoint 4 0\npoint 5 1\n"),
                       "step 5: the target lies on the segment from point 4 to point 5");
        expect_invalid(hallway_absorbed(),
                       replace(c, two,
                               two + "point 2 0\npoint 3 1\npoint 4 0\npoint 5 1\npoint 6 "
                                     "0\npoint 7 1\n"),
                       "header: the ray is absorbed at point 7 of the path prefix");
        expect_invalid(h, replace(c, two, "point 0 0\n"),
                       "header: the path prefix has only point 0");
    }
    SECTION("scale not integral, direction not diagonal") {
        expect_invalid(h, replace(c, "scale 1 1", "scale 1/2 1/2"), "not an integer");
        expect_invalid(h, replace(c, "scale 1 1", "scale 1 2"), "is not diagonal");
        expect_invalid(h, replace(c, "scale 1 1", "scale -1 -1"), "is not positive");
    }
    SECTION("transversals") {
        // Overlapping ranges on one line with one direction.
        expect_invalid(h, replace(c, "first 0 2", "transversal 1 0 4 6 1 1\nfirst 0 2"),
                       "transversal 2: shares the state u = 4 on its line with transversal 1");
        // A vertical and a horizontal transversal crossing at a common state.
        expect_invalid(box(),
                       replace(box_certificate, "first 0 0", "transversal 0 2 0 0 -1 1\nfirst 0 0"),
                       "transversal 4: shares the state at the lattice point (2, 0) with "
                       "transversal 1");
        expect_invalid(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 0 6 0 1 1"),
                       "LO 6 > HI 0");
        // u = 1 on Y = 0 with direction (1, 1) has w = -1: odd, no state.
        expect_invalid(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 0 1 1 1 1"),
                       "so it has no state");
        // Y = 2 is on no mirror.
        expect_invalid(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 2 0 6 1 1"),
                       "transversal 1: its state at the lattice point (0, 2) is on no mirror");
        expect_invalid(h, replace(c, "first 0 2", "first 0 1"),
                       "is the lattice point (3, 1) with direction (1, -1), not point 1");
        expect_invalid(h, replace(c, "first 0 2", "first 0 3"), "has 3 states, no state 3");
    }
    SECTION("tiling") {
        expect_invalid(h, replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 4"),
                       "images must tile");
        expect_invalid(h, replace(c, "piece 4 1 reflect 0", "piece 4 2 reflect 0"),
                       "piece 4: it starts at 5, but the pieces before it end at 6");
        expect_invalid(h,
                       replace(c, "piece 0 1 reflect 3\npiece 1 1 escape 4", "piece 0 2 reflect 3"),
                       "piece 0: it is [0, 2), not [0, 1)");
    }
    SECTION("a piece's image off by one") {
        // Images 4 for piece 0 and 3 for piece 1 still tile, but x = (1, 1)
        // is not mapped to its next state (2, 0).
        std::string t = replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 4");
        t = replace(t, "piece 1 1 escape 4", "piece 1 1 escape 3");
        expect_invalid(h, t,
                       "piece 0: its state at rotated coordinate 0 (lattice point (1, 1), "
                       "direction (1, -1)) is mapped to the lattice point (0, 0), which is not "
                       "ahead of it on its ray");
        // Images [4, 6) for piece 2: raw 6 and 0, across two transversals.
        t = replace(c, "piece 1 1 escape 4", "piece 1 1 escape 6");
        t = replace(t, "piece 2 2 reflect 5", "piece 2 2 reflect 4");
        expect_invalid(h, t,
                       "piece 2: a reflect piece's image must lie in one transversal, but it "
                       "spans transversals 1 and 0");
        // Swapping the images of pieces 0 and 3: x is mapped to itself.
        t = replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 0");
        t = replace(t, "piece 4 1 reflect 0", "piece 4 1 reflect 3");
        expect_invalid(h, t, "piece 0: its state at rotated coordinate 0");
    }
    SECTION("wrong kind") {
        expect_invalid(h, replace(c, "piece 2 2 reflect 5", "piece 2 2 escape 5"),
                       "piece 2: its state at rotated coordinate 2 (lattice point (4, 0), "
                       "direction (1, 1)) meets the mirror y = 1");
        expect_invalid(h, replace(c, "piece 2 2 reflect 5", "piece 2 2 absorbed 5"),
                       "first meets a mirror and no absorber, yet the piece is absorbed");
        expect_invalid(h, replace(c, "piece 1 1 escape 4", "piece 1 1 absorbed 4"),
                       "piece 1: its state at rotated coordinate 1 (lattice point (6, 0), "
                       "direction (1, 1)) meets no element, yet the piece is absorbed");
        expect_invalid(h, replace(c, "piece 1 1 escape 4", "piece 1 1 reflect 4"),
                       "piece 1: its state at rotated coordinate 1 (lattice point (6, 0), "
                       "direction (1, 1)) is mapped to the lattice point (0, 0)");
        // With the absorber, escape is wrong.
        expect_invalid(hallway_absorbed(), c, "meets the absorber x = 7");
    }
    SECTION("hit flags") {
        const Scene hit = hallway_hit();
        const std::string& ch = hallway_hit_certificate;
        expect_invalid(hit, replace(ch, "piece 2 1 reflect 5 hit", "piece 2 1 reflect 5"),
                       "piece 2: the target lies on the segment from its state at rotated "
                       "coordinate 2 (lattice point (4, 0), direction (1, 1)), but the piece is "
                       "not flagged hit");
        expect_invalid(hit, replace(ch, "piece 3 1 reflect 6", "piece 3 1 reflect 6 hit"),
                       "piece 3: it is flagged hit, but the target is not on the segment from "
                       "its state at rotated coordinate 3");
        // The escape certificate's pieces 2 (two states) flagged hit.
        expect_invalid(h, replace(c, "piece 2 2 reflect 5", "piece 2 2 reflect 5 hit"),
                       "piece 2: it is flagged hit");
    }
    SECTION("geometry fails for one state of a piece") {
        // A mirror x = 3 for y in [0, 1] is met by the state (2, 0) of piece
        // 2 at its claimed next point (3, 1), negating x, but not by (4, 0).
        Scene blocked = h;
        blocked.add_mirror(0, 3, {{0, 1}});
        expect_invalid(blocked, c,
                       "piece 2: its state at rotated coordinate 3 (lattice point (2, 0), "
                       "direction (1, 1)) meets the mirror x = 3");
        // With a gap in y = 1 around x = 3, the state (3, 1) of transversal
        // 0 is on no mirror.
        Scene gap = orthoray::read_scene("dim 2\n"
                                         "mirror y 0 x 0 6\n"
                                         "mirror y 1 x 0 2\n"
                                         "mirror y 1 x 4 6\n"
                                         "ray 0 0 1 1\n"
                                         "target 3 0\n");
        expect_invalid(gap, c,
                       "transversal 0: its state at the lattice point (3, 1) is on no mirror");
    }
    SECTION("steps") {
        expect_invalid(h, replace(c, "step equal 2 4", "step equal 4 2"),
                       "step 1 (step equal 4 2): piece 4's image [1, 3) does not end at L = 7");
        expect_invalid(h, replace(c, "step top 2 0", "step bottom 0 2"),
                       "step 3 (step bottom 0 2): needs l_R > l_D, but l(0) = 1 <= l(2) = 2");
        expect_invalid(h, replace(c, "step top 2 0", "step top-cycle 2 2"),
                       "needs M * S < l_D, but M * S = 2 * 1 = 2 >= l_D = 2");
        expect_invalid(h, replace(c, "step equal 0 1\n", ""), "after the last step L = 2, not 1");
        expect_invalid(h, replace(c, "step equal 0 1\n", "step equal 0 1\nstep invariant 0\n"),
                       "step 6 (step invariant 0): the induction has ended (L = 1)");
        expect_invalid(h, replace(c, "step equal 1 3", "step equal 1 7"), "there is no piece 7");
        expect_invalid(h, replace(c, "step equal 1 3", "step equal 1 4"),
                       "piece 4 was removed earlier");
        expect_invalid(h, replace(c, "step equal 2 4", "step invariant 4"),
                       "piece 4's image [1, 3) does not end at L = 7");
    }
    SECTION("verdict") {
        expect_invalid(h, replace(c, "reflections 6", "reflections 7"),
                       "verdict: reflections 7, but the induction gives 6");
        expect_invalid(h, replace(c, "reason escape", "reason absorbed"),
                       "reason absorbed, but the induction gives escape");
        expect_invalid(h, replace(c, "answer no", "answer yes"),
                       "answer yes does not go with reason escape");
        expect_invalid(box(), replace(box_certificate, "period 4", "period 3"),
                       "period 3, but the induction gives 4");
        expect_invalid(box(), replace(box_certificate, "reflections 4", "reflections 3"),
                       "reflections 3, but the induction gives 4");
    }
    SECTION("partial") {
        // A run stopped by a limit while writing the steps.
        std::string cut = c.substr(0, c.find("step equal 0 2"));
        const Outcome partial =
            verify(h, cut + "answer unknown\nreason limit\nreflections 0\npartial\nend\n");
        CHECK_FALSE(partial.valid);
        CHECK(partial.message ==
              "partial certificate: the exchange and 3 induction steps checked, no answer proven");
        expect_invalid(h,
                       replace(cut, "step top 2 0", "step top 0 2") +
                           "answer unknown\nreason limit\nreflections 0\npartial\nend\n",
                       "step 3 (step top 0 2)");
        expect_invalid(h, cut + "answer no\nreason limit\nreflections 0\npartial\nend\n",
                       "answer no does not go with reason limit");
        expect_malformed(h, cut + "answer unknown\nreason limit\nreflections 0\nend\n",
                         "found 'end', expected 'partial'");
    }
    SECTION("truncated and malformed") {
        expect_invalid(h, replace(c, "end\n", ""), "incomplete certificate");
        expect_invalid(h, c.substr(0, c.find("step equal 0 2")), "incomplete certificate");
        expect_malformed(
            h, replace(c, "piece 1 1 escape 4", "piece 1 1 escaped 4"),
            "<test>:13:11: found 'escaped', expected reflect, escape, absorbed or cut");
        expect_malformed(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 0 0 6 1 2"),
                         "<test>:10:23: found '2', expected 1 or -1");
        expect_malformed(h, replace(c, "step top 2 0", "step top 2"),
                         "expected a non-negative integer");
        expect_malformed(h, replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 3 hot"),
                         "found 'hot', expected 'hit' or end of line");
        expect_malformed(h, replace(c, "method induction", "method magic"),
                         "found 'magic', expected 'induction'");
        expect_malformed(h, replace(c, "reflections 6\n", "reflections 6\nperiod 6\n"),
                         "expected 'end'");
    }
}

// ----------------------------------------------------------------- random --

TEST_CASE("brute-force induction certificates of random scenes verify",
          "[induction-certificate][slow]") {
    std::mt19937_64 rng(20261122);
    orthoray::test::RandomSceneShape shape;
    shape.max_elements = 10;
    shape.range = 4;
    shape.max_denominator = 2;
    shape.max_direction = 2;
    int verified = 0, cycle_steps = 0, tampered = 0, rejected = 0;
    int by_reason[4] = {};
    for (int round = 0; round < 4000 && verified < 400; ++round) {
        Scene scene = orthoray::test::random_scene(rng, shape);
        scene.target() = orthoray::test::random_target(rng, scene, shape);
        orthoray::SolveOptions o;
        o.engine = orthoray::Engine::reference;
        o.max_steps = 100000;
        const orthoray::Answer truth = orthoray::solve(scene, o);
        if (!truth.decided()) continue;
        const std::optional<Brute> brute = brute_certificate(scene, rng, 3000);
        if (!brute) continue;
        // A hit on the first segment is a path certificate's business.
        if (truth.reason == orthoray::Reason::hit && truth.reflections == 0) continue;
        INFO("scene:\n" << orthoray::write_scene(scene));
        const std::string expected = std::string("valid: ") + orthoray::to_string(truth.reason) +
                                     ", " + truth.reflections.get_str() + " reflections";
        REQUIRE(brute->verdict == expected);
        const Outcome outcome = verify(scene, brute->text);
        INFO("certificate:\n" << brute->text << "verify said: " << outcome.message);
        REQUIRE(outcome.valid);
        REQUIRE(outcome.message == expected);
        ++verified;
        ++by_reason[static_cast<int>(truth.reason)];
        cycle_steps += brute->cycle_steps;

        // One number changed by one: rejected, or still the true verdict.
        std::vector<std::string> lines;
        {
            std::istringstream in(brute->text);
            for (std::string line; std::getline(in, line);) lines.push_back(line);
        }
        for (int attempt = 0; attempt < 3; ++attempt) {
            const std::size_t at = orthoray::test::pick_index(rng, 2, lines.size() - 2);
            std::istringstream words(lines[at]);
            std::vector<std::string> t;
            for (std::string w; words >> w;) t.push_back(w);
            std::vector<std::size_t> numeric;
            for (std::size_t j = 1; j < t.size(); ++j)
                if (orthoray::read_number(t[j]).status == orthoray::NumberToken::Status::ok)
                    numeric.push_back(j);
            if (numeric.empty()) continue;
            const std::size_t j = numeric[orthoray::test::pick_index(rng, 0, numeric.size() - 1)];
            const Rational v = orthoray::read_number(t[j]).value;
            const Rational changed = v + (orthoray::test::chance(rng, 50) ? 1 : -1);
            t[j] = orthoray::to_string(changed);
            std::vector<std::string> copy = lines;
            copy[at].clear();
            for (std::size_t w = 0; w < t.size(); ++w) copy[at] += (w ? " " : "") + t[w];
            std::string text;
            for (const std::string& line : copy) text += line + "\n";
            const Outcome tamper = verify(scene, text);
            INFO("tampered line " << at + 1 << ": " << copy[at]
                                  << "\nverify said: " << tamper.message);
            ++tampered;
            if (tamper.valid)
                CHECK(tamper.message == expected);
            else
                ++rejected;
        }
    }
    INFO("verified " << verified << " (hit/escape/absorbed/cycle " << by_reason[0] << "/"
                     << by_reason[1] << "/" << by_reason[2] << "/" << by_reason[3]
                     << "), cycle steps " << cycle_steps << ", tampered " << tampered
                     << ", rejected " << rejected);
    CHECK(verified >= 300);
    for (int count : by_reason) CHECK(count >= 10);
    CHECK(cycle_steps >= 100);
    CHECK(rejected * 10 >= tampered * 8);
    WARN("verified " << verified << " (hit/escape/absorbed/cycle " << by_reason[0] << "/"
                     << by_reason[1] << "/" << by_reason[2] << "/" << by_reason[3]
                     << "), cycle steps " << cycle_steps << ", tampered " << tampered
                     << ", rejected " << rejected);
}

// -------------------------------------------------------------------- cli --

TEST_CASE("orthoray verify reads induction certificates", "[induction-certificate][cli]") {
    using orthoray::test::quote;
    using orthoray::test::run_cli;
    orthoray::test::TempDir dir;
    const std::string scene = dir.write("hallway.scene", orthoray::write_scene(hallway()));
    const std::string good = dir.write("good.cert", hallway_certificate);
    orthoray::test::CliResult r = run_cli("verify " + quote(scene) + " " + quote(good));
    CHECK(r.status == 0);
    CHECK(r.out == "valid: escape, 6 reflections\n");
    const std::string bad =
        dir.write("bad.cert", replace(hallway_certificate, "reflections 6", "reflections 5"));
    r = run_cli("verify " + quote(scene) + " " + quote(bad));
    CHECK(r.status == 1);
    CHECK(r.out == "invalid: verdict: reflections 5, but the induction gives 6 (x's first event "
                   "is escape at offset 5)\n");
    const std::string malformed =
        dir.write("malformed.cert", replace(hallway_certificate, "step top 2 0", "step top 2 x"));
    r = run_cli("verify " + quote(scene) + " " + quote(malformed));
    CHECK(r.status == 2);
    CHECK(r.err.find("malformed.cert:19:12: found 'x', expected a non-negative integer") !=
          std::string::npos);
}

// ------------------------------------------------------------------ large --
//
// The hallway of length 2m (mirrors y = 0 and y = 1 for x in [0, 2m]) for
// m = 10^30: 2m reflections, then escape. The same derivation as for m = 3
// (N = 2m + 1, x is raw m - 1): rotated 0 is (1, 1), 1 .. m + 1 are (2m, 0),
// (2m - 2, 0), ..., (0, 0), and m + 2 .. 2m are (2m - 1, 1), ..., (3, 1).
// Pieces: [0] -> m, [1] escape -> m + 1, [2, m + 1) -> m + 2, [m + 1] -> 0,
// [m + 2, 2m + 1) -> 1. Steps: equal 2 4 (L m + 2), equal 1 3 (L m + 1),
// then D = piece 2 (length m - 1) beats R = piece 0 (length 1) m - 2 times
// over S = 1: top-cycle 2 (m - 2) leaves piece 0 with r = 1 + 2 (m - 2) and
// L = 3; equal 0 2 (r 2m - 1), equal 0 1: escape at offset 2m - 1.

TEST_CASE("a hallway of length 2 * 10^30", "[induction-certificate]") {
    const Integer m("1000000000000000000000000000000");
    auto n = [](const Integer& v) { return v.get_str(); };
    const Scene scene =
        orthoray::read_scene("dim 2\nmirror y 0 x 0 " + n(2 * m) + "\nmirror y 1 x 0 " + n(2 * m) +
                             "\nray 0 0 1 1\ntarget 3 0\n");
    const std::string text =
        "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 1 1\nmethod induction\n"
        "direction 1 -1\nscale 1 1\nmodulus 2\n"
        "transversal 1 1 0 " +
        n(2 * m) +
        " 1 -1\n"
        "transversal 1 0 0 " +
        n(2 * m) +
        " 1 1\n"
        "first 0 " +
        n(m - 1) +
        "\n"
        "piece 0 1 reflect " +
        n(m) +
        "\n"
        "piece 1 1 escape " +
        n(m + 1) +
        "\n"
        "piece 2 " +
        n(m - 1) + " reflect " + n(m + 2) +
        "\n"
        "piece " +
        n(m + 1) +
        " 1 reflect 0\n"
        "piece " +
        n(m + 2) + " " + n(m - 1) +
        " reflect 1\n"
        "step equal 2 4\nstep equal 1 3\n"
        "step top-cycle 2 " +
        n(m - 2) +
        "\n"
        "step equal 0 2\nstep equal 0 1\n"
        "answer no\nreason escape\nreflections " +
        n(2 * m) + "\nend\n";
    expect_valid(scene, text, "valid: escape, " + n(2 * m) + " reflections");
    expect_invalid(scene, replace(text, "top-cycle 2 " + n(m - 2), "top-cycle 2 " + n(m - 1)),
                   "needs M * S < l_D, but M * S = " + n(m - 1) + " * 1 = " + n(m - 1) +
                       " >= l_D = " + n(m - 1));
    expect_invalid(scene, replace(text, "reflections " + n(2 * m), "reflections " + n(2 * m - 1)),
                   "reflections " + n(2 * m - 1) + ", but the induction gives " + n(2 * m));
    // One state too many in the middle piece: the tiling breaks.
    expect_invalid(scene, replace(text, "piece 2 " + n(m - 1), "piece 2 " + n(m)),
                   "piece 3: it starts at " + n(m + 1) + ", but the pieces before it end at " +
                       n(m + 2));
    // A mirror across the hallway far away is met by one state of piece 2.
    Scene blocked = scene;
    blocked.add_mirror(0, Rational(m + 1), {{0, 1}});
    expect_invalid(blocked, text, "meets the mirror x = " + n(m + 1));
}

// ------------------------------------------------------ the engine's own --

namespace {

// Another word of the same statement slot, so a tamper stays well formed.
std::string other_word(const std::string& word, std::mt19937_64& rng) {
    const std::vector<std::vector<std::string>> families = {
        {"reflect", "escape", "absorbed"},
        {"top", "bottom", "equal", "invariant", "top-cycle", "bottom-cycle"},
        {"yes", "no"},
        {"hit", "escape", "absorbed", "cycle"}};
    for (const auto& family : families)
        for (const std::string& w : family)
            if (w == word) {
                std::string pick = word;
                while (pick == word)
                    pick = family[orthoray::test::pick_index(rng, 0, family.size() - 1)];
                return pick;
            }
    return word;
}

// One token of one statement changed: a number moved by one to three, a
// word swapped for another of its kind, or a trailing `hit` dropped.
std::string tamper_once(const std::string& text, std::mt19937_64& rng, std::string& what) {
    std::vector<std::string> lines;
    {
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
    }
    for (;;) {
        const std::size_t at = orthoray::test::pick_index(rng, 2, lines.size() - 2);
        std::vector<std::string> t;
        {
            std::istringstream words(lines[at]);
            for (std::string w; words >> w;) t.push_back(w);
        }
        if (t.size() < 2) continue;
        const std::size_t j = orthoray::test::pick_index(rng, 1, t.size() - 1);
        const orthoray::NumberToken n = orthoray::read_number(t[j]);
        std::string changed;
        if (n.status == orthoray::NumberToken::Status::ok) {
            const int delta = orthoray::test::pick(rng, 1, 3);
            changed =
                orthoray::to_string(n.value + (orthoray::test::chance(rng, 50) ? delta : -delta));
        } else if (t[j] == "hit" && j + 1 == t.size() && t[0] == "piece") {
            changed = "";
        } else {
            changed = other_word(t[j], rng);
            if (changed == t[j]) continue;
        }
        what = "line " + std::to_string(at + 1) + ": '" + lines[at] + "' token " +
               std::to_string(j) + " -> '" + changed + "'";
        t[j] = changed;
        lines[at].clear();
        for (const std::string& w : t)
            if (!w.empty()) lines[at] += (lines[at].empty() ? "" : " ") + w;
        std::string result;
        for (const std::string& line : lines) result += line + "\n";
        return result;
    }
}

} // namespace

TEST_CASE("the induction engine's certificates of random scenes verify, tampered ones do not",
          "[induction-certificate][engine][slow]") {
    std::mt19937_64 rng(8101);
    struct Family {
        orthoray::test::RandomSceneShape shape;
        int goal;
    };
    std::vector<Family> families(3);
    families[0].shape = {2, 12, 6, 3, 3};
    families[0].goal = 150;
    families[1].shape = {2, 12, 6, 1, 2};
    families[1].goal = 100;
    families[2].shape = {2, 30, 10, 2, 5};
    families[2].goal = 100;
    int induced = 0, tampered = 0, rejected = 0, neutral = 0, jsonl = 0;
    int by_reason[4] = {};
    for (Family& family : families) {
        family.shape.box_percent = 90;
        int got = 0;
        for (int attempt = 0; got < family.goal && attempt < 20 * family.goal; ++attempt) {
            Scene scene = orthoray::test::random_scene(rng, family.shape);
            scene.target() = orthoray::test::random_target(rng, scene, family.shape);
            const bool json = orthoray::test::chance(rng, 25);
            std::stringstream out;
            orthoray::CertificateWriter writer(out, scene,
                                               json ? orthoray::CertificateFormat::jsonl
                                                    : orthoray::CertificateFormat::text);
            orthoray::SolveOptions o;
            o.engine = orthoray::Engine::induction;
            writer.attach(o);
            const orthoray::Answer answer = orthoray::solve(scene, o);
            writer.finish(answer);
            if (answer.engine != orthoray::EngineUsed::induction)
                continue; // answered on the first segments
            const std::string text = out.str();
            INFO("scene:\n" << orthoray::write_scene(scene) << "certificate:\n" << text);
            REQUIRE(text.find("induction") != std::string::npos);
            const Outcome outcome = verify(scene, text);
            INFO("verify said: " << outcome.message);
            const std::string expected = std::string("valid: ") +
                                         orthoray::to_string(answer.reason) + ", " +
                                         answer.reflections.get_str() + " reflections";
            REQUIRE(outcome.valid);
            REQUIRE(outcome.message == expected);
            ++got;
            ++induced;
            jsonl += json;
            ++by_reason[static_cast<int>(answer.reason)];
            if (json) continue; // the tampering below edits the text format
            for (int k = 0; k < 4; ++k) {
                std::string what;
                const std::string bad = tamper_once(text, rng, what);
                const Outcome t = verify(scene, bad);
                INFO("tampered " << what << "\nverify said: " << t.message);
                ++tampered;
                if (t.valid) {
                    // Some edits change nothing that matters (a transversal's
                    // LO or HI moved past its last state): the verdict stays true.
                    CHECK(t.message == expected);
                    ++neutral;
                } else {
                    CHECK((t.input_error || t.message.rfind("invalid: ", 0) == 0));
                    ++rejected;
                }
            }
        }
        CHECK(got == family.goal);
    }
    WARN("induced " << induced << " (hit/escape/absorbed/cycle " << by_reason[0] << "/"
                    << by_reason[1] << "/" << by_reason[2] << "/" << by_reason[3] << ", " << jsonl
                    << " as JSON Lines), tampered " << tampered << ": rejected " << rejected
                    << ", neutral " << neutral);
    for (int count : by_reason) CHECK(count >= 10);
    CHECK(rejected * 10 >= tampered * 9);
}

TEST_CASE("the engines' certificates of huge family instances verify",
          "[induction-certificate][engine][slow]") {
    using orthoray::BoxFamily;
    std::vector<orthoray::GeneratedScene> scenes;
    const Integer big_a = (Integer(1) << 61) - 1, big_b("1000000000000000000");
    for (BoxFamily::Target target :
         {BoxFamily::Target::reached, BoxFamily::Target::far, BoxFamily::Target::generic}) {
        BoxFamily box;
        box.sides = {big_a, big_b};
        box.target = target;
        scenes.push_back(orthoray::generate_box(box));
        scenes.push_back(orthoray::generate_coprime_box(30, target));
    }
    scenes.push_back(orthoray::generate_hallway(
        Rational(Integer("1000000000000000000000000000000")), Rational(1, 3)));
    scenes.push_back(orthoray::generate_square(Integer("123456789012345678901"),
                                               Integer("98765432109876543210")));
    orthoray::RandomFamily maze;
    maze.mirrors = 200;
    maze.box = true;
    maze.range = std::int64_t(1) << 40;
    maze.seed = 11;
    scenes.push_back(orthoray::generate_random(maze));
    int induced = 0;
    for (const orthoray::GeneratedScene& g : scenes) {
        for (orthoray::Engine engine : {orthoray::Engine::induction, orthoray::Engine::automatic}) {
            // The default engine streams its whole simulated prefix (for the
            // maze about 300,000 points, 12 s to check): the maze is checked
            // through --engine induction only.
            if (engine == orthoray::Engine::automatic && &g == &scenes.back()) continue;
            INFO("scene:\n" << orthoray::write_generated(g));
            std::stringstream out;
            orthoray::CertificateWriter writer(out, g.scene);
            orthoray::SolveOptions o;
            o.engine = engine;
            writer.attach(o);
            const orthoray::Answer answer = orthoray::solve(g.scene, o);
            writer.finish(answer);
            REQUIRE(answer.decided());
            if (g.expect) {
                CHECK(answer.reason == g.expect->reason);
                CHECK(answer.reflections == g.expect->reflections);
            }
            induced += answer.engine == orthoray::EngineUsed::induction;
            const Outcome outcome = verify(g.scene, out.str());
            INFO("verify said: " << outcome.message);
            CHECK(outcome.message == std::string("valid: ") + orthoray::to_string(answer.reason) +
                                         ", " + answer.reflections.get_str() + " reflections");
        }
    }
    CHECK(induced >= 15);
}
