#include "support/brute_induction_certificate.hpp"

#include "support/portable_random.hpp"

#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

namespace orthoray::test {
namespace {

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

} // namespace

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
    shuffle(transversals, rng);
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
                      !pieces.back().hit && image[z] == image[z - 1] + 1 && chance(rng, 95);
        if (extend && kind[z] == reflect) extend = same_transversal(z) && same_image_transversal(z);
        if (extend && kind[z] != reflect) extend = same_transversal(z) || chance(rng, 50);
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
        const bool cycle = chance(rng, 50);
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

} // namespace orthoray::test
