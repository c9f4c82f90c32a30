#include "induction/octagonal_induction.hpp"

#include "engine/cycle_detector.hpp"

#include "engine/reference_tracer.hpp"
#include "induction/induction_engine.hpp"
#include "induction/octagonal_exchange.hpp"
#include "induction/rauzy_induction.hpp"
#include "induction/rho_walk.hpp"

#include <chrono>

namespace orthoray::induction {
namespace {

using namespace octagonal;
using lattice::int128_t;
using lattice::to_integer;

// The integers the geometry needs: every product it forms is at most the
// scene's magnitude times (|a| + |b| + 1)^2 (octagonal_magnitude) times a
// small constant.
bool fits_int128(const Scene& scene) {
    return octagonal_magnitude(scene) < (Integer(1) << 118);
}

// The first segment of the ray: an answer when it decides before reflection
// 1; the lifted state x after reflection 1 when there is one.
template <class Int>
struct FirstSegment {
    std::optional<Answer> answer;
    bool reflects = false;
    Point<Int> x;
    int sheet = 0;
};

template <class Int>
FirstSegment<Int> first_segment(const OctagonalScene<Int>& s) {
    FirstSegment<Int> out;
    auto decide = [&](Reason reason) {
        if (out.answer) return;
        Answer a;
        a.reason = reason;
        a.reflections = 0;
        out.answer = a;
    };
    const Shot<Int> shot = s.shoot(s.start, 0);
    // Is the target on [start, x] (on the whole ray when it escapes)?
    const Int dx = Int(s.target[0] - s.start[0]), dy = Int(s.target[1] - s.start[1]);
    const Int along = Int(s.a * dx + s.b * dy), norm = Int(s.a * s.a + s.b * s.b);
    if (dx == 0 && dy == 0) decide(Reason::hit);
    // target = start + (along / norm) v, the event at t = num / den.
    if (Int(s.a * dy - s.b * dx) == 0 && along > 0 &&
        (!shot.found || !(Int(shot.num * norm) < Int(along * shot.den))))
        decide(Reason::hit);
    if (!shot.found) {
        decide(Reason::escape);
        return out;
    }
    out.x = s.advance(s.start, 0, shot, false);
    const Outcome<Int> event = outcome_at(s, s.acting_at(out.x, 0), 0);
    if (event.absorbed) {
        decide(Reason::absorbed);
        return out;
    }
    out.reflects = true;
    out.sheet = event.sheet;
    return out;
}

// The scene's own direction g v (v as the scene writes it, not primitive),
// as a path certificate lists it.
Vector scene_direction(const Scene& scene, int g) {
    const auto& m = symmetries()[static_cast<std::size_t>(g)].m;
    const Vector& v = scene.ray().direction;
    return {m[0][0] * v[0] + m[0][1] * v[1], m[1][0] * v[0] + m[1][1] * v[1], Rational(0)};
}

// The exchange of the twin search: `exchange` with the piece holding x's
// twin (rotated coordinate `twin`) cut so the twin is a piece of its own,
// the only one with the hit mark (docs/induction-certificates.md).
IntervalExchange with_twin_alone(IntervalExchange exchange, const Integer& twin) {
    std::vector<ExchangePiece> cut;
    cut.reserve(exchange.pieces.size() + 2);
    for (ExchangePiece& p : exchange.pieces) {
        p.hit = false;
        if (twin < p.start || p.start + p.length <= twin) {
            cut.push_back(std::move(p));
            continue;
        }
        const Integer head = twin - p.start;
        const Integer tail = p.length - head - 1;
        if (head > 0) cut.push_back({p.start, head, p.image, p.kind, false});
        cut.push_back({twin, 1, p.image + head, p.kind, true});
        if (tail > 0) cut.push_back({twin + 1, tail, p.image + head + 1, p.kind, false});
    }
    exchange.pieces = std::move(cut);
    return exchange;
}

// What a certificate (and exchange_of) tells about the states: the lattice
// scale and the lifted transversals as lattice points, x and its twin.
void add_lattice_states(IntervalExchange& exchange, const OctagonalLayout& layout,
                        const Integer& scale) {
    exchange.scale[0] = exchange.scale[1] = scale;
    exchange.lifted = layout.transversals;
    exchange.first_transversal = layout.first_slot;
    exchange.first_index = layout.first_index;
    if (layout.twin) {
        exchange.twin_transversal = layout.twin_slot;
        exchange.twin_index = layout.twin_index;
    }
}

// The most pieces the exchange may have (as for the axis-parallel engine).
std::size_t cap_of(const Scene& scene) {
    return piece_cap(scene.elements.size());
}

// Applies --max-steps as a simulation would: on diagonal scenes every
// simulation runs Brent's detector (engine::may_have_tail), which notices a
// cycle of period p entered at state mu at reflection 2^k + p (2^k >= mu,
// p), as the graph engine reports it too; past 2^62 that is beyond any cap
// anyway. False when a certificate is wanted and the cap cuts the answer:
// the tracer then walks up to the cap and writes the path so far.
bool capped(Answer& answer, const SolveOptions& options) {
    if (!options.max_steps) return true;
    Integer needed = answer.reflections;
    if (answer.reason == Reason::cycle)
        needed = answer.reflections < (Integer(1) << 62)
                     ? Integer(static_cast<unsigned long>(engine::brent_detection(
                           answer.tail.get_ui() + 1, answer.period().get_ui())))
                     : Integer(answer.reflections * 2);
    const Integer cap(static_cast<unsigned long>(*options.max_steps));
    if (needed <= cap) return true;
    if (options.path || options.induction_observer) return false;
    answer.reason = Reason::limit;
    answer.limit = Limit::steps;
    answer.reflections = cap;
    answer.tail = 0;
    return true;
}

Answer finished(Answer& answer, std::chrono::steady_clock::time_point begin) {
    answer.stats.induction.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return answer;
}

// The step map of a layout with collisions in E's listed coordinates
// (rho_walk.hpp): the collisions cut, x = 0, the target's states flagged.
RhoMap rho_map(const OctagonalLayout& layout) {
    std::vector<RawPiece> pieces = layout.pieces;
    cut_collisions(pieces, layout.collisions);
    RhoMap map;
    map.listed = finish_exchange_on(layout.size, layout.modulus, {}, std::move(pieces),
                                    layout.first, layout.hits);
    auto rotated = [&](const Integer& raw) {
        return Integer(lattice::floor_mod(Integer(raw - layout.first), layout.size));
    };
    for (const Collision& c : layout.collisions)
        map.cuts.emplace_back(rotated(c.state), rotated(c.join));
    std::vector<std::pair<Integer, Integer>> twins = layout.twins;
    if (layout.twin) twins.emplace_back(layout.first, *layout.twin);
    for (const auto& [state, twin] : twins) { // both ways
        map.twins.emplace_back(rotated(state), rotated(twin));
        map.twins.emplace_back(rotated(twin), rotated(state));
    }
    for (auto* list : {&map.cuts, &map.twins}) {
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    return map;
}

// The answer the walk gives (rho_walk.hpp).
void set_walk_outcome(Answer& answer, const RhoMap& map, const RhoOrbit& rho) {
    answer.stats.induction.pieces = map.listed.pieces.size();
    answer.stats.induction.states = map.listed.size;
    answer.stats.induction.steps = rho.steps;
    answer.stats.induction.rounds = rho.rounds;
    InducedOrbit orbit;
    orbit.event = rho.event;
    orbit.offset = rho.offset;
    orbit.period = rho.period;
    set_outcome(answer, orbit);
    if (rho.event == ExchangeEvent::none) {
        answer.tail = rho.tail;
        answer.reflections = rho.tail + rho.period;
    }
}

// The walk's certificate: E as listed, then every search of the proof with
// its steps (docs/induction-certificates.md, "The walk"); false when `stop`
// ended it.
bool stream_walk(const RhoMap& map, const RhoOrbit& rho, const OctagonalLayout& layout,
                 const Integer& scale, InductionObserver& observer,
                 const std::function<bool(std::uint64_t)>& stop) {
    IntervalExchange listed = to_public(map.listed);
    add_lattice_states(listed, layout, scale);
    listed.cuts = map.cuts;
    if (!observer.begin(listed, [&] { return stop(0); })) return false;
    for (const RhoSearch& search : rho.proof) {
        observer.walk_search(search.from, search.only);
        if (!induce(to_public(search_exchange(map, search)), &observer, stop)) return false;
    }
    return true;
}

// nullopt when there is no exchange to induce on (see induce_octagonal).
template <class Int>
std::optional<Answer> solve_on(const Scene& scene, const SolveOptions& options) {
    using Clock = std::chrono::steady_clock;
    const auto begin = Clock::now();
    const OctagonalScene<Int> s = make_octagonal<Int>(scene);
    const FirstSegment<Int> first = first_segment(s);
    // A certificate needs the path p0, p1 before the exchange; an answer
    // before reflection 1 is left to the tracer's path certificate.
    const bool certify = options.path || options.induction_observer;
    if (first.answer && certify) return std::nullopt;
    bool visited = false;
    auto visit_prefix = [&] {
        if (!options.path || visited) return;
        visited = true;
        Vector p1 = {Rational(to_integer(first.x[0]), s.scale),
                     Rational(to_integer(first.x[1]), s.scale), Rational(0)};
        p1[0].canonicalize();
        p1[1].canonicalize();
        options.path->visit(scene.ray().start, scene.ray().direction);
        options.path->visit(p1, scene_direction(scene, first.sheet));
    };
    if (first.answer) {
        Answer answer = *first.answer;
        answer.engine = EngineUsed::induction;
        answer.arithmetic = lattice::arithmetic_used(Int{});
        return answer;
    }
    std::optional<Limit> limit;
    auto stop = [&](std::uint64_t) {
        if (!options.monitor) return false;
        limit = options.monitor->poll(1);
        return limit.has_value();
    };
    Answer answer;
    answer.engine = EngineUsed::induction;
    answer.arithmetic = lattice::arithmetic_used(Int{});
    auto limited = [&](Limit which) {
        answer.reason = Reason::limit;
        answer.limit = which;
        answer.reflections = 1; // the first reflection was taken by a shot
        visit_prefix();         // a partial certificate: the path up to it
        return answer;
    };
    BuildFailure failure;
    const std::optional<OctagonalLayout> layout = build_layout(
        s, first.x, first.sheet, cap_of(scene), failure, nullptr, [&] { return stop(0); });
    if (failure == BuildFailure::stopped) return limited(*limit);
    if (!layout) return std::nullopt;
    if (stop(0)) return limited(*limit);
    if (!layout->collisions.empty()) {
        // Two states step to one: the walk between special states
        // (rho_walk.hpp), certified search by search.
        const RhoMap map = rho_map(*layout);
        const std::optional<RhoOrbit> rho = walk_rho(map, stop);
        if (!rho) return limited(*limit);
        set_walk_outcome(answer, map, *rho);
        if (!capped(answer, options)) return std::nullopt;
        if (certify) {
            visit_prefix();
            if (InductionObserver* observer = options.induction_observer)
                if (!stream_walk(map, *rho, *layout, s.scale, *observer, stop))
                    return limited(*limit);
        }
        return finished(answer, begin);
    }
    IntervalExchange exchange = finish_exchange(layout->size, layout->modulus, {}, layout->pieces,
                                                layout->first, layout->hits);
    const std::optional<InducedOrbit> orbit = induce(exchange, nullptr, stop);
    if (!orbit) return limited(*limit);
    answer.stats.induction.pieces = exchange.pieces.size();
    answer.stats.induction.states = exchange.size;
    answer.stats.induction.steps = orbit->steps;
    answer.stats.induction.rounds = orbit->rounds;
    set_outcome(answer, *orbit);
    const bool twin_search = orbit->event == ExchangeEvent::none && layout->twin;
    const Integer twin_rotated =
        layout->twin ? Integer(lattice::floor_mod(*layout->twin - layout->first, layout->size))
                     : Integer(0);
    if (twin_search) {
        // On the double cover the lifted orbit closes after the physical
        // period p or after 2p, when T^p(x) is x's twin: mark the twin alone.
        const IntervalExchange twin = with_twin_alone(exchange, twin_rotated);
        const std::optional<InducedOrbit> half = induce(twin, nullptr, stop);
        if (!half) return limited(*limit);
        answer.stats.induction.steps += half->steps;
        answer.stats.induction.rounds += half->rounds;
        if (half->event == ExchangeEvent::hit) answer.reflections = half->offset;
    }
    if (!capped(answer, options)) return std::nullopt; // the tracer writes the path to the cap
    if (certify) {
        // Run again, streaming: the certificate gets the steps only once the
        // answer is known to stand.
        visit_prefix();
        if (InductionObserver* observer = options.induction_observer) {
            add_lattice_states(exchange, *layout, s.scale);
            if (!observer->begin(exchange, [&] { return stop(0); })) return limited(*limit);
            if (!induce(exchange, observer, stop)) return limited(*limit);
            if (twin_search) {
                observer->twin_search();
                if (!induce(with_twin_alone(exchange, twin_rotated), observer, stop))
                    return limited(*limit);
            }
        }
    }
    return finished(answer, begin);
}

template <class Int>
std::optional<std::size_t> dump_on(const Scene& scene, std::ostream& out) {
    const OctagonalScene<Int> s = make_octagonal<Int>(scene);
    const FirstSegment<Int> first = first_segment(s);
    if (!first.reflects) return std::nullopt;
    BuildFailure failure;
    const auto layout = build_layout(s, first.x, first.sheet, ~std::size_t{0}, failure, &out);
    if (!layout) return std::nullopt;
    return layout->pieces.size();
}

template <class Int>
std::optional<IntervalExchange> exchange_on(const Scene& scene) {
    const OctagonalScene<Int> s = make_octagonal<Int>(scene);
    const FirstSegment<Int> first = first_segment(s);
    if (!first.reflects) return std::nullopt;
    BuildFailure failure;
    auto layout = build_layout(s, first.x, first.sheet, cap_of(scene), failure);
    if (!layout || !layout->collisions.empty()) return std::nullopt; // no bijection
    IntervalExchange exchange = finish_exchange(
        layout->size, layout->modulus, {}, std::move(layout->pieces), layout->first, layout->hits);
    add_lattice_states(exchange, *layout, s.scale);
    return exchange;
}

} // namespace

std::optional<Answer> induce_octagonal(const Scene& scene, const SolveOptions& options) {
    // A one-way mirror lets two states step to one: no bijection to induce
    // on, and the orbit may enter its cycle after a tail (docs/optics.md).
    if (scene.has_one_sided()) return std::nullopt;
    // The geometry runs on 128-bit integers when they cannot overflow (there
    // is no 64-bit path: the scale factor alone often passes 2^63);
    // Arithmetic::wide asks for GMP.
    return options.arithmetic != Arithmetic::wide && fits_int128(scene)
               ? solve_on<int128_t>(scene, options)
               : solve_on<Integer>(scene, options);
}

Answer solve_octagonal_by_induction(const Scene& scene, const SolveOptions& options) {
    if (std::optional<Answer> induced = induce_octagonal(scene, options)) return *induced;
    return engine::solve_by_reference(scene, options);
}

std::optional<IntervalExchange> octagonal_exchange_of(const Scene& scene) {
    if (scene.has_one_sided()) return std::nullopt; // no bijection: two states may step to one
    return fits_int128(scene) ? exchange_on<int128_t>(scene) : exchange_on<Integer>(scene);
}

std::optional<std::size_t> write_octagonal_pieces(const Scene& scene, std::ostream& out) {
    if (scene.has_one_sided()) return std::nullopt;
    return fits_int128(scene) ? dump_on<int128_t>(scene, out) : dump_on<Integer>(scene, out);
}

} // namespace orthoray::induction
