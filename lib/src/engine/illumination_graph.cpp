// The illumination question on an explicit state graph (Boost.Graph): the
// states reachable from the rays are the vertices, each event gives a state
// one out-edge per outgoing direction, weighted 1 for a reflection and 0 for
// a pass-through. Lit or unlit is breadth-first reachability from all rays at
// once; the least reflections come from Boost's Dijkstra, run from each ray
// in turn, so ties go to the least-numbered ray by construction. It shares
// the first-event scan with the reference engine but none of its search.
#include "orthoray/state_graph.hpp"

#include "engine/reference_step.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <limits>
#include <map>
#include <new>
#include <stdexcept>
#include <vector>

namespace orthoray {
namespace {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property,
                                    boost::property<boost::edge_weight_t, std::uint64_t>>;
using Key = std::pair<Vector, Vector>;

enum : std::size_t { all_rays_vertex = 0 };

} // namespace

Answer explore_illumination_graph(const Scene& scene, std::uint64_t max_states, RunMonitor* monitor,
                                  std::optional<std::uint64_t> max_expanded) {
    Answer answer;
    answer.engine = EngineUsed::graph;
    answer.arithmetic = ArithmeticUsed::rational;
    answer.targets.assign(scene.targets.size(), TargetAnswer{});

    // Discover the reachable states, numbering them from 1 (0 is the
    // vertex that feeds every ray), and record the edges and which targets
    // each state's segment passes. States are expanded in the order found
    // (breadth-first in hops), until every one is or a limit stops the walk.
    std::map<Key, std::size_t> id;
    std::vector<Key> key_of{Key{}};
    struct Edge {
        std::size_t from, to;
        std::uint64_t weight;
    };
    std::vector<Edge> edges;
    std::vector<std::size_t> ray_vertex;
    auto vertex = [&](const Key& k) {
        auto [it, added] = id.emplace(k, key_of.size());
        if (added) key_of.push_back(k);
        return it->second;
    };
    for (const Ray& r : scene.rays) {
        ray_vertex.push_back(vertex({r.start, r.direction}));
        edges.push_back({all_rays_vertex, ray_vertex.back(), 0});
    }
    std::vector<std::vector<std::size_t>> passes{{}};
    std::optional<Limit> stopped;
    std::size_t u = 1;
    for (; u < key_of.size(); ++u) {
        if (key_of.size() > max_states + 1) {
            stopped = Limit::memory;
            break;
        }
        if (max_expanded && u - 1 == *max_expanded) {
            stopped = Limit::steps;
            break;
        }
        if (monitor && u % 1024 == 0) {
            stopped = monitor->poll(0);
            if (stopped) break;
        }
        const Key k = key_of[u];
        const engine::ReferenceEvent e = engine::reference_step(scene, k.first, k.second);
        passes.emplace_back();
        for (std::size_t t = 0; t < scene.targets.size(); ++t)
            if (engine::reference_passes(scene, scene.targets[t], k.first, k.second, e))
                passes.back().push_back(t);
        for (const engine::Outgoing& out : e.outgoing)
            edges.push_back({u, vertex({e.point, out.direction}), out.reflection ? 1u : 0u});
    }
    // A state found but not expanded passes at least the targets at its own
    // point. Only a ray's start needs this: any other such state was found
    // from an expanded one whose segment ends at that point, which passes
    // those targets with no more reflections (the edge's weight counts the
    // reflection at the point, made after passing it).
    for (; u < key_of.size(); ++u) {
        passes.emplace_back();
        for (std::size_t t = 0; t < scene.targets.size(); ++t)
            if (scene.targets[t] == key_of[u].first) passes.back().push_back(t);
    }
    const std::size_t n = key_of.size();
    Graph g(n);
    for (const Edge& e : edges) boost::add_edge(e.from, e.to, e.weight, g);

    // Lit or not: reachable from the rays at all.
    const std::size_t unreached = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> hops(n, unreached);
    hops[all_rays_vertex] = 0;
    boost::breadth_first_search(g, boost::vertex(all_rays_vertex, g),
                                boost::visitor(boost::make_bfs_visitor(
                                    boost::record_distances(hops.data(), boost::on_tree_edge()))));
    std::vector<bool> lit(scene.targets.size(), false);
    for (std::size_t v = 1; v < n; ++v)
        if (hops[v] != unreached)
            for (std::size_t t : passes[v]) lit[t] = true;

    // The least reflections: Dijkstra from each ray; a strictly smaller
    // count from a later ray replaces an earlier one, an equal one does not.
    const std::uint64_t infinite = std::numeric_limits<std::uint64_t>::max();
    for (std::size_t r = 0; r < scene.rays.size(); ++r) {
        std::vector<std::uint64_t> distance(n, infinite);
        boost::dijkstra_shortest_paths(g, boost::vertex(ray_vertex[r], g),
                                       boost::distance_map(distance.data()));
        for (std::size_t v = 1; v < n; ++v) {
            if (distance[v] == infinite) continue;
            const Integer d = Integer(static_cast<unsigned long>(distance[v]));
            for (std::size_t t : passes[v]) {
                TargetAnswer& target = answer.targets[t];
                if (target.status == TargetAnswer::Status::lit && target.reflections <= d) continue;
                target = {TargetAnswer::Status::lit, d, r + 1, std::nullopt};
            }
        }
    }
    bool all = true;
    for (std::size_t t = 0; t < scene.targets.size(); ++t) {
        TargetAnswer& target = answer.targets[t];
        // BFS and Dijkstra must agree on which targets are lit.
        if (lit[t] != (target.status == TargetAnswer::Status::lit))
            throw std::logic_error("illumination graph: BFS and Dijkstra disagree");
        // Cut short, the graph may lack a cheaper path to the target; none
        // beats 0 reflections from ray 1.
        if (stopped && lit[t]) target.best_proven = target.reflections == 0 && target.ray == 1;
        if (!lit[t] && !stopped) target.status = TargetAnswer::Status::unlit;
        if (lit[t] && target.reflections > answer.reflections)
            answer.reflections = target.reflections;
        all = all && lit[t] && target.best_proven;
    }
    answer.states = Integer(static_cast<unsigned long>(n - 1));
    answer.states_lower_bound = stopped.has_value();
    // Every target lit with a proven count answers the question whatever
    // the limit left unexplored.
    if (stopped && !all) {
        answer.reason = Reason::limit;
        answer.limit = *stopped;
    } else {
        answer.reason = all ? Reason::lit : Reason::unlit;
    }
    return answer;
}

} // namespace orthoray
