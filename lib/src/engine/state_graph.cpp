#include "orthoray/state_graph.hpp"

#include "engine/reference_step.hpp"
#include "lattice/lattice_scene.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/strong_components.hpp>

#include <map>
#include <stdexcept>
#include <vector>

namespace orthoray {
namespace {

using lattice::Coords;
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS>;
using Key = std::pair<std::vector<Integer>, unsigned>;

enum : std::size_t { start_vertex = 0, escape_vertex = 1, absorbed_vertex = 2, first_state = 3 };

// The answer from the graph alone: the first state (by breadth-first
// distance from the start) whose segment passes the target, else escape or
// absorption if reachable, else the cycle the walk ends in (its length from
// the strong components).
void decide(const Graph& g, const std::vector<bool>& passes, StateGraphReport& report) {
    const std::size_t n = boost::num_vertices(g);
    const std::size_t unreached = n;
    std::vector<std::size_t> distance(n, unreached);
    distance[start_vertex] = 0;
    boost::breadth_first_search(g, boost::vertex(start_vertex, g),
                                boost::visitor(boost::make_bfs_visitor(boost::record_distances(
                                    distance.data(), boost::on_tree_edge()))));

    Answer& answer = report.answer;
    answer.engine = EngineUsed::graph;
    answer.arithmetic = ArithmeticUsed::rational;
    std::size_t first_pass = unreached, farthest = start_vertex;
    for (std::size_t u = 0; u < n; ++u) {
        if (distance[u] == unreached) continue;
        if (u >= first_state) ++report.reachable;
        if (passes[u] && (first_pass == unreached || distance[u] < distance[first_pass]))
            first_pass = u;
        if (distance[u] > distance[farthest]) farthest = u;
    }
    auto as_integer = [](std::size_t x) { return Integer(static_cast<unsigned long>(x)); };
    if (first_pass != unreached) {
        answer.reason = Reason::hit;
        answer.reflections = as_integer(distance[first_pass]);
    } else if (distance[escape_vertex] != unreached) {
        answer.reason = Reason::escape;
        answer.reflections = as_integer(distance[escape_vertex] - 1);
    } else if (distance[absorbed_vertex] != unreached) {
        answer.reason = Reason::absorbed;
        answer.reflections = as_integer(distance[absorbed_vertex] - 1);
    } else {
        // The walk from the start ends in a cycle, and its farthest vertex
        // lies on it: the size of that vertex's component is the period.
        // Every state reached is on the tail or the cycle, each once, so the
        // tail is the rest (0 for an injective step map, docs/optics.md).
        std::vector<std::size_t> component(n);
        boost::strong_components(g, component.data());
        std::size_t size = 0;
        for (std::size_t u = 0; u < n; ++u) size += component[u] == component[farthest];
        answer.reason = Reason::cycle;
        answer.reflections = as_integer(report.reachable);
        answer.tail = as_integer(report.reachable - size);
    }
}

// A scene with diagonals (docs/octagonal.md): its vertices are the states
// reachable from the start, found by stepping each once, since its lattice
// of event points (denominators up to lcm(a, b, a - b, a + b) for a
// direction (a, b)) is far larger than what one ray reaches. The answer
// still comes from breadth-first search and strong components, not from a
// cycle detector.
std::optional<StateGraphReport> explore_reachable(const Scene& scene, std::uint64_t max_states,
                                                  RunMonitor* monitor) {
    std::map<std::pair<Vector, Vector>, std::size_t> id;
    std::vector<std::pair<Vector, Vector>> key_of;
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    std::vector<bool> passes(first_state, false);
    std::vector<std::size_t> in_degree(first_state, 0);
    auto step = [&](std::size_t u, const Vector& p, const Vector& v) {
        const engine::ReferenceEvent e = engine::reference_step(scene, p, v);
        passes[u] = engine::reference_passes(scene, scene.target(), p, v, e);
        std::size_t w = e.escape ? escape_vertex : absorbed_vertex;
        if (!e.escape && !e.absorbed) {
            auto [it, added] =
                id.emplace(std::pair{e.point, e.direction}, first_state + key_of.size());
            if (added) {
                key_of.push_back(it->first);
                passes.push_back(false);
                in_degree.push_back(0);
            }
            w = it->second;
            if (u != start_vertex) ++in_degree[w];
        }
        edges.emplace_back(u, w);
    };
    step(start_vertex, scene.ray().start, scene.ray().direction);
    for (std::size_t k = 0; k < key_of.size(); ++k) {
        if (key_of.size() > max_states) return std::nullopt;
        if (monitor && k % 1024 == 0) {
            if (const std::optional<Limit> limit = monitor->poll(0)) {
                StateGraphReport stopped;
                stopped.answer.engine = EngineUsed::graph;
                stopped.answer.arithmetic = ArithmeticUsed::rational;
                stopped.answer.limit = *limit;
                return stopped;
            }
        }
        const std::pair<Vector, Vector> state = key_of[k];
        step(first_state + k, state.first, state.second);
    }
    Graph g(first_state + key_of.size());
    for (const auto& [u, w] : edges) boost::add_edge(u, w, g);
    StateGraphReport report;
    report.states = key_of.size();
    for (std::size_t u = first_state; u < in_degree.size(); ++u)
        report.injective = report.injective && in_degree[u] <= 1;
    decide(g, passes, report);
    return report;
}

} // namespace

std::optional<StateGraphReport> explore_state_graph(const Scene& scene, std::uint64_t max_states,
                                                    RunMonitor* monitor) {
    if (scene.has_diagonal()) return explore_reachable(scene, max_states, monitor);
    const lattice::LatticeScene ls = lattice::make_lattice(scene);
    const unsigned directions = 1u << ls.dim;

    // Count first, so that a huge scene is refused before anything is built.
    Integer count = 0;
    for (const auto& e : ls.elements) {
        if (e.absorber) continue;
        Integer points = directions;
        for (int j = 0; j < ls.dim; ++j) points *= e.hi[j] - e.lo[j] + 1;
        count += points;
    }
    if (count > Integer(static_cast<unsigned long>(max_states))) return std::nullopt;

    // Vertices: the three special ones, then every (lattice point on a mirror,
    // direction); overlapping mirrors share their points.
    std::map<Key, std::size_t> id;
    std::vector<Key> key_of;
    for (const auto& e : ls.elements) {
        if (e.absorber) continue;
        std::vector<Integer> x(e.lo.begin(), e.lo.begin() + ls.dim);
        while (true) {
            for (unsigned d = 0; d < directions; ++d)
                if (id.emplace(Key{x, d}, first_state + key_of.size()).second)
                    key_of.push_back(Key{x, d});
            int j = 0;
            while (j < ls.dim && x[j] == e.hi[j]) x[j] = e.lo[j], ++j;
            if (j == ls.dim) break;
            ++x[j];
        }
    }
    const std::size_t n = first_state + key_of.size();

    // One step from every vertex with the reference rule; mark the vertices
    // whose outgoing segment passes the target.
    Graph g(n);
    std::vector<bool> passes(n, false);
    std::vector<std::size_t> in_degree(n, 0);
    auto step = [&](std::size_t u, const Vector& p, const Vector& v) {
        engine::ReferenceEvent e = engine::reference_step(scene, p, v);
        passes[u] = engine::reference_passes(scene, scene.target(), p, v, e);
        std::size_t w;
        if (e.escape) {
            w = escape_vertex;
        } else if (e.absorbed) {
            w = absorbed_vertex;
        } else {
            Coords c;
            if (!ls.to_lattice(e.point, c))
                throw std::logic_error("state graph: a reflection point is off the lattice");
            unsigned mask = 0;
            for (int j = 0; j < ls.dim; ++j)
                if (e.direction[ls.active[j]] < 0) mask |= 1u << j;
            auto it = id.find(Key{std::vector<Integer>(c.begin(), c.begin() + ls.dim), mask});
            if (it == id.end())
                throw std::logic_error("state graph: a reflection point is on no mirror");
            w = it->second;
            if (u != start_vertex) ++in_degree[w];
        }
        boost::add_edge(u, w, g);
    };
    step(start_vertex, scene.ray().start, scene.ray().direction);
    for (std::size_t k = 0; k < key_of.size(); ++k) {
        if (monitor && k % 1024 == 0) {
            if (const std::optional<Limit> limit = monitor->poll(0)) {
                StateGraphReport stopped;
                stopped.answer.engine = EngineUsed::graph;
                stopped.answer.arithmetic = ArithmeticUsed::rational;
                stopped.answer.limit = *limit;
                return stopped;
            }
        }
        Coords c;
        for (int j = 0; j < ls.dim; ++j) c[j] = key_of[k].first[j];
        step(first_state + k, ls.point(c), ls.direction(key_of[k].second));
    }

    StateGraphReport report;
    report.states = key_of.size();
    for (std::size_t u = first_state; u < n; ++u)
        report.injective = report.injective && in_degree[u] <= 1;
    decide(g, passes, report);
    return report;
}

} // namespace orthoray
