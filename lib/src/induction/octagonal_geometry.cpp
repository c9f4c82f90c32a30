#include "induction/octagonal_geometry.hpp"

#include "engine/event_rule.hpp"

#include <stdexcept>

namespace orthoray::induction::octagonal {

using lattice::from_integer;
using lattice::int128_t;
using lattice::to_integer;

const std::array<Symmetry, 8>& symmetries() {
    // The four sign changes, then the same after swapping the axes.
    static const std::array<Symmetry, 8> all = {{
        {{{1, 0}, {0, 1}}},
        {{{-1, 0}, {0, 1}}},
        {{{1, 0}, {0, -1}}},
        {{{-1, 0}, {0, -1}}},
        {{{0, 1}, {1, 0}}},
        {{{0, -1}, {1, 0}}},
        {{{0, 1}, {-1, 0}}},
        {{{0, -1}, {-1, 0}}},
    }};
    return all;
}

namespace {

int index_of(const int (&m)[2][2]) {
    const auto& all = symmetries();
    for (int i = 0; i < 8; ++i) {
        bool same = true;
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c) same = same && all[i].m[r][c] == m[r][c];
        if (same) return i;
    }
    throw std::logic_error("not a symmetry of the square");
}

template <class Int>
Int cross(const Point<Int>& d, const Point<Int>& p) {
    return Int(d[0] * p[1] - d[1] * p[0]);
}

template <class Int>
Point<Int> apply(int g, const Point<Int>& p) {
    const auto& m = symmetries()[static_cast<std::size_t>(g)].m;
    return {Int(m[0][0] * p[0] + m[0][1] * p[1]), Int(m[1][0] * p[0] + m[1][1] * p[1])};
}

Integer lcm_of_denominators(const Scene& scene) {
    Integer d = 1;
    auto take = [&](const Rational& x) { d = lcm(d, Integer(x.get_den())); };
    for (const Element& e : scene.elements)
        for (int j = 0; j < 2; ++j) {
            take(e.lo[j]);
            take(e.hi[j]);
        }
    for (int j = 0; j < 2; ++j) {
        take(scene.ray().start[j]);
        take(scene.target()[j]);
    }
    return d;
}

// The start direction as a primitive integer vector.
std::array<Integer, 2> primitive_direction(const Scene& scene) {
    const Vector& v = scene.ray().direction;
    const Integer den = lcm(Integer(v[0].get_den()), Integer(v[1].get_den()));
    std::array<Integer, 2> p;
    for (int j = 0; j < 2; ++j) p[j] = Integer(v[j] * den);
    const Integer g = gcd(p[0], p[1]);
    for (int j = 0; j < 2; ++j) p[j] /= g;
    return p;
}

Integer scale_of(const Scene& scene) {
    const auto v = primitive_direction(scene);
    Integer k = 1;
    for (const Integer& kappa :
         std::array<Integer, 4>{abs(v[0]), abs(v[1]), abs(v[0] - v[1]), abs(v[0] + v[1])})
        if (kappa != 0) k = lcm(k, kappa);
    return 2 * lcm_of_denominators(scene) * k;
}

} // namespace

int compose(int r, int g) {
    const auto& a = symmetries()[static_cast<std::size_t>(r)].m;
    const auto& b = symmetries()[static_cast<std::size_t>(g)].m;
    int m[2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
    return index_of(m);
}

int inverse(int g) {
    const auto& a = symmetries()[static_cast<std::size_t>(g)].m;
    const int m[2][2] = {{a[0][0], a[1][0]}, {a[0][1], a[1][1]}}; // orthogonal: the transpose
    return index_of(m);
}

int reflection_of(Orientation o) {
    switch (o) {
    case Orientation::vertical:
        return 1; // (x, y) -> (-x, y)
    case Orientation::horizontal:
        return 2; // (x, y) -> (x, -y)
    case Orientation::rising:
        return 4; // (x, y) -> (y, x)
    case Orientation::falling:
        return 7; // (x, y) -> (-y, -x)
    }
    return 0;
}

Integer octagonal_magnitude(const Scene& scene) {
    const Integer f = scale_of(scene);
    Integer m = 0;
    auto take = [&](const Rational& x) {
        const Integer y = abs(Integer(x * f));
        if (y > m) m = y;
    };
    for (const Element& e : scene.elements)
        for (int j = 0; j < 2; ++j) {
            take(e.lo[j]);
            take(e.hi[j]);
        }
    for (int j = 0; j < 2; ++j) {
        take(scene.ray().start[j]);
        take(scene.target()[j]);
    }
    const auto v = primitive_direction(scene);
    return m * (abs(v[0]) + abs(v[1]) + 1) * (abs(v[0]) + abs(v[1]) + 1);
}

template <class Int>
OctagonalScene<Int> make_octagonal(const Scene& scene) {
    OctagonalScene<Int> s;
    s.scale = scale_of(scene);
    auto scaled = [&](const Rational& x) { return from_integer<Int>(Integer(x * s.scale)); };
    const auto v = primitive_direction(scene);
    s.a = from_integer<Int>(v[0]);
    s.b = from_integer<Int>(v[1]);
    for (int j = 0; j < 2; ++j) {
        s.start[j] = scaled(scene.ray().start[j]);
        s.target[j] = scaled(scene.target()[j]);
    }
    for (const Element& e : scene.elements) {
        Segment<Int> seg;
        seg.absorber = e.kind == ElementKind::absorber;
        seg.element = &e;
        if (e.is_diagonal()) {
            seg.orientation =
                e.diagonal == Diagonal::rising ? Orientation::rising : Orientation::falling;
            const Vector from = e.from();
            const Point<Int> p{scaled(from[0]), scaled(from[1])};
            seg.c = line_constant(seg.orientation, p);
            seg.lo = scaled(e.lo[0]);
            seg.hi = scaled(e.hi[0]);
        } else {
            seg.orientation = e.axis == 0 ? Orientation::vertical : Orientation::horizontal;
            seg.c = scaled(e.lo[e.axis]);
            seg.lo = scaled(e.lo[1 - e.axis]);
            seg.hi = scaled(e.hi[1 - e.axis]);
        }
        s.segments.push_back(seg);
    }
    for (int g = 0; g < 8; ++g) {
        s.direction[static_cast<std::size_t>(g)] = apply<Int>(g, {s.a, s.b});
        const Vector d = s.direction_vector(g);
        auto& acts = s.acting[static_cast<std::size_t>(g)];
        for (const Element& e : scene.elements) acts.push_back(engine::acts_on(e, d) ? 1 : 0);
        const Point<Int>& dir = s.direction[static_cast<std::size_t>(g)];
        std::vector<typename IntervalStabbing<Int>::Interval> ranges;
        for (std::size_t i = 0; i < s.segments.size(); ++i) {
            if (!acts[i]) continue;
            const Segment<Int>& seg = s.segments[i];
            Int lo = cross(dir, point_on(seg.orientation, seg.c, seg.lo));
            Int hi = cross(dir, point_on(seg.orientation, seg.c, seg.hi));
            if (hi < lo) std::swap(lo, hi);
            ranges.push_back({lo, hi, static_cast<std::uint32_t>(i)});
        }
        s.crossing_lines[static_cast<std::size_t>(g)] = IntervalStabbing<Int>(ranges);
    }
    s.magnitude = octagonal_magnitude(scene);
    return s;
}

template <class Int>
Vector OctagonalScene<Int>::direction_vector(int g) const {
    const Point<Int>& d = direction[static_cast<std::size_t>(g)];
    return {Rational(to_integer(d[0])), Rational(to_integer(d[1])), Rational(0)};
}

template <class Int>
Int OctagonalScene<Int>::w(const Point<Int>& q, int g) const {
    const Point<Int> p = apply<Int>(inverse(g), q);
    return Int(a * p[1] - b * p[0]);
}

template <class Int>
int OctagonalScene<Int>::sheet_of(const Point<Int>& d) const {
    for (int g = 0; g < 8; ++g)
        if (direction[static_cast<std::size_t>(g)] == d) return g;
    throw std::logic_error("a direction the ray cannot take");
}

template <class Int>
Point<Int> OctagonalScene<Int>::advance(const Point<Int>& q, int g, const Shot<Int>& shot,
                                        bool backwards) const {
    const Point<Int>& d = direction[static_cast<std::size_t>(g)];
    Point<Int> r;
    for (int j = 0; j < 2; ++j) {
        const Int step = Int(shot.num * d[j]);
        if (step % shot.den != 0) throw std::logic_error("an event point off the lattice");
        r[j] = backwards ? Int(q[j] - step / shot.den) : Int(q[j] + step / shot.den);
    }
    return r;
}

template <class Int>
Shot<Int> OctagonalScene<Int>::shoot(const Point<Int>& q, int g, bool backwards) const {
    Point<Int> d = direction[static_cast<std::size_t>(g)];
    if (backwards) d = {Int(-d[0]), Int(-d[1])};
    Shot<Int> best;
    const Int line = cross(direction[static_cast<std::size_t>(g)], q);
    crossing_lines[static_cast<std::size_t>(g)].stab(line, [&](std::uint32_t i) {
        const Segment<Int>& s = segments[i];
        // t = num / den where the ray meets the line; the position there,
        // times den, is base * den + num * along.
        Int num = 0, den = 0, base = 0, along = 0;
        switch (s.orientation) {
        case Orientation::vertical:
            num = s.c - q[0], den = d[0], base = q[1], along = d[1];
            break;
        case Orientation::horizontal:
            num = s.c - q[1], den = d[1], base = q[0], along = d[0];
            break;
        case Orientation::rising:
            num = s.c - (q[1] - q[0]), den = d[1] - d[0], base = q[0], along = d[0];
            break;
        case Orientation::falling:
            num = s.c - (q[1] + q[0]), den = d[1] + d[0], base = q[0], along = d[0];
            break;
        }
        if (den == 0) return;
        if (den < 0) num = -num, den = -den;
        if (!(num > 0)) return;
        const Int at = Int(base * den + num * along);
        if (at < Int(s.lo * den) || Int(s.hi * den) < at) return;
        if (best.found && !(Int(num * best.den) < Int(best.num * den))) return;
        best.found = true;
        best.num = num;
        best.den = den;
        best.segment = i;
    });
    return best;
}

template <class Int>
std::vector<const Segment<Int>*> OctagonalScene<Int>::acting_at(const Point<Int>& q, int g) const {
    std::vector<const Segment<Int>*> out;
    const Int line = cross(direction[static_cast<std::size_t>(g)], q);
    crossing_lines[static_cast<std::size_t>(g)].stab(line, [&](std::uint32_t i) {
        const Segment<Int>& s = segments[i];
        if (line_constant(s.orientation, q) != s.c) return;
        const Int& u = position(s.orientation, q);
        if (s.lo <= u && u <= s.hi) out.push_back(&s);
    });
    // In scene order, as a scan would give them.
    std::sort(out.begin(), out.end());
    return out;
}

template <class Int>
Outcome<Int> outcome_at(const OctagonalScene<Int>& scene,
                        const std::vector<const Segment<Int>*>& acting, int g) {
    std::vector<const Element*> elements;
    bool one_orientation = true;
    for (const Segment<Int>* s : acting) {
        elements.push_back(s->element);
        one_orientation = one_orientation && s->orientation == acting.front()->orientation;
    }
    const engine::EventOutcome event =
        engine::event_outcome(2, elements, scene.direction_vector(g));
    Outcome<Int> out;
    if (event.absorbed) {
        out.absorbed = true;
        return out;
    }
    const Vector& leaving = event.outgoing.front().direction;
    const Point<Int> d{from_integer<Int>(Integer(leaving[0])),
                       from_integer<Int>(Integer(leaving[1]))};
    const Point<Int>& incoming = scene.direction[static_cast<std::size_t>(g)];
    auto fits = [&](int r) { return apply<Int>(r, incoming) == d; };
    int r = one_orientation ? reflection_of(acting.front()->orientation) : -1;
    if (r < 0 || !fits(r)) {
        if (one_orientation)
            throw std::logic_error("a line reflects otherwise than its reflection");
        for (r = 0; r < 8 && !fits(r); ++r) {
        }
    }
    out.sheet = compose(r, g);
    return out;
}

template struct OctagonalScene<int128_t>;
template struct OctagonalScene<Integer>;
template OctagonalScene<int128_t> make_octagonal<int128_t>(const Scene&);
template OctagonalScene<Integer> make_octagonal<Integer>(const Scene&);
template Outcome<int128_t> outcome_at(const OctagonalScene<int128_t>&,
                                      const std::vector<const Segment<int128_t>*>&, int);
template Outcome<Integer> outcome_at(const OctagonalScene<Integer>&,
                                     const std::vector<const Segment<Integer>*>&, int);

} // namespace orthoray::induction::octagonal
