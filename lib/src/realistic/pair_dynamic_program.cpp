// The dynamic program of Isobe et al. (docs/realistic-scenes.md) on
// Boost.Graph. A vertex is a pair (previous object, current object): the
// last leg of a path. An edge (a, b) -> (b, c) is a triple, and following it
// applies b's transfer to the intensity that reached b. A start vertex feeds
// `emitted` into every first leg (source, x).
//
// Why Dijkstra's order is right here: with "more intensity is better" as the
// order, a transfer never raises the intensity (f(i) <= i), so the vertex
// with the most intensity left in the queue cannot be improved by any path
// through the vertices not yet taken; and since every transfer is monotone,
// the most intensity at a pair is the best to pass on, so one value per pair
// is enough. A path through the same pair twice is never needed.
#include "orthoray/realistic.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <functional>
#include <map>
#include <utility>

namespace orthoray {
namespace {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property,
                                    boost::property<boost::edge_weight_t, std::size_t>>;
using Vertex = boost::graph_traits<Graph>::vertex_descriptor;

// The weight of an edge names its transfer; `identity` (the start's edges)
// passes the intensity on unchanged.
constexpr std::size_t identity = static_cast<std::size_t>(-1);

} // namespace

RealisticAnswer solve_realistic(const RealisticModel& model) {
    std::map<std::pair<std::size_t, std::size_t>, Vertex> vertex_of;
    std::vector<std::pair<std::size_t, std::size_t>> pair_of{{model.source, model.source}};
    Graph graph(1); // vertex 0: the start
    auto vertex = [&](std::size_t previous, std::size_t current) {
        const auto [it, added] = vertex_of.emplace(std::pair{previous, current}, 0);
        if (added) {
            it->second = boost::add_vertex(graph);
            pair_of.emplace_back(previous, current);
        }
        return it->second;
    };
    for (const std::size_t leg : model.first_legs)
        boost::add_edge(0, vertex(model.source, leg), identity, graph);
    for (std::size_t k = 0; k < model.triples.size(); ++k) {
        const Triple& t = model.triples[k];
        boost::add_edge(vertex(t.from, t.via), vertex(t.via, t.to), k, graph);
    }

    const std::size_t n = boost::num_vertices(graph);
    std::vector<Integer> intensity(n);
    std::vector<Vertex> predecessor(n);
    // "Shortest" means most intensity: compare by >, combine by the
    // transfer, -1 (no light at all) as the unreached value.
    const auto more = std::greater<Integer>();
    const auto pass = [&](const Integer& in, std::size_t transfer) {
        return transfer == identity ? in : model.triples[transfer].transfer(in);
    };
    boost::dijkstra_shortest_paths(
        graph, Vertex{0},
        boost::make_iterator_property_map(predecessor.begin(),
                                          boost::get(boost::vertex_index, graph)),
        boost::make_iterator_property_map(intensity.begin(),
                                          boost::get(boost::vertex_index, graph)),
        boost::get(boost::edge_weight, graph), boost::get(boost::vertex_index, graph), more, pass,
        Integer(-1), model.emitted, boost::default_dijkstra_visitor());

    RealisticAnswer answer;
    Vertex best = 0;
    for (Vertex v = 1; v < n; ++v) {
        if (intensity[v] < 0) continue;
        answer.bounds.push_back({pair_of[v].first, pair_of[v].second, intensity[v]});
        if (pair_of[v].second == model.receiver && intensity[v] > answer.best) {
            answer.best = intensity[v];
            best = v;
        }
    }
    answer.yes = answer.best > model.eps;
    if (best != 0) {
        std::vector<Vertex> chain;
        for (Vertex v = best; v != 0; v = predecessor[v]) chain.push_back(v);
        answer.path.push_back(model.source);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            answer.path.push_back(pair_of[*it].second);
            answer.intensities.push_back(intensity[*it]);
        }
    }
    return answer;
}

} // namespace orthoray
