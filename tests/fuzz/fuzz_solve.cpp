// libFuzzer target: solve and verify small parsed scenes. The default engine,
// the piece tables, the induction engine and the reference tracer, all
// capped at 300 reflections, must agree; the default engine's certificate
// must verify exactly when it answered. Optics scenes (splitters, one-sided
// elements, several rays or targets) and octagonal ones (diagonals) are held
// to the explicit state graph instead (check_optics, and
// check_octagonal_trajectory with the reference tracer's certificate).
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>

namespace {

// Small caps: the default illumination search steps at most this many
// events, and the graph engine refuses scenes with more reachable states.
constexpr std::uint64_t optics_states = 2000;

bool same_target(const orthoray::TargetAnswer& a, const orthoray::TargetAnswer& b) {
    return a.status == b.status && (a.status != orthoray::TargetAnswer::Status::lit ||
                                    (a.reflections == b.reflections && a.ray == b.ray));
}

// The illumination question, by the default engine (Dijkstra over states
// found by the reference scan) and by --engine graph (Boost's BFS and
// Dijkstra on the explicit graph): every target's status, reflections and
// ray must agree when both decide. When only the graph decides, every
// target the capped search lit is final (Dijkstra settles in order) and
// must match too. A single trajectory among one-sided elements is asked
// with its target listed twice, which makes it an illumination question
// with one branch: its answer must then be the trajectory's (hit after k
// reflections <=> lit after k by ray 1, any other answer <=> unlit).
void check_optics(const orthoray::Scene& scene) {
    orthoray::Scene question = scene;
    if (question.single_trajectory()) question.targets.push_back(question.target());
    orthoray::SolveOptions search;
    search.max_steps = optics_states;
    const orthoray::Answer found = orthoray::solve(question, search);
    orthoray::SolveOptions graph;
    graph.engine = orthoray::Engine::graph;
    graph.max_graph_states = optics_states;
    const orthoray::Answer built = orthoray::solve(question, graph);
    if (found.targets.size() != question.targets.size() ||
        built.targets.size() != question.targets.size())
        std::abort();
    if (built.decided()) {
        for (std::size_t t = 0; t < question.targets.size(); ++t) {
            const orthoray::TargetAnswer& a = found.targets[t];
            if ((found.decided() || a.status == orthoray::TargetAnswer::Status::lit) &&
                !same_target(a, built.targets[t]))
                std::abort();
        }
        if (found.decided() &&
            (found.reason != built.reason || found.reflections != built.reflections))
            std::abort();
    }
    if (!scene.single_trajectory()) return;
    orthoray::SolveOptions alone;
    alone.max_steps = 300;
    // Of the single-trajectory engines, the reference tracer follows
    // diagonals (docs/octagonal.md).
    if (scene.has_diagonal()) alone.engine = orthoray::Engine::reference;
    const orthoray::Answer trajectory = orthoray::solve(scene, alone);
    if (!trajectory.decided() || !found.decided()) return;
    const orthoray::TargetAnswer& a = found.targets.front();
    if ((trajectory.reason == orthoray::Reason::hit) !=
        (a.status == orthoray::TargetAnswer::Status::lit))
        std::abort();
    if (a.status == orthoray::TargetAnswer::Status::lit &&
        (a.reflections != trajectory.reflections || a.ray != 1))
        std::abort();
}

// A single trajectory among diagonals (docs/octagonal.md): the reference
// tracer, which writes the certificate, and the state graph of the states
// reached must agree when both decide within their caps, and the
// certificate must verify exactly when the tracer answered.
void check_octagonal_trajectory(const orthoray::Scene& scene) {
    orthoray::SolveOptions reference;
    reference.max_steps = 300;
    reference.engine = orthoray::Engine::reference;
    std::ostringstream certificate;
    orthoray::CertificateWriter writer(certificate, scene);
    writer.attach(reference);
    const orthoray::Answer traced = orthoray::solve(scene, reference);
    writer.finish(traced);

    orthoray::SolveOptions graph;
    graph.max_steps = 300;
    graph.engine = orthoray::Engine::graph;
    graph.max_graph_states = optics_states;
    const orthoray::Answer built = orthoray::solve(scene, graph);
    if (traced.decided() && built.decided() &&
        (traced.reason != built.reason || traced.reflections != built.reflections ||
         traced.tail != built.tail))
        std::abort();

    std::istringstream in(certificate.str());
    const orthoray::Verdict verdict = orthoray::verify_certificate(scene, in, "fuzz");
    if (verdict.valid != traced.decided()) std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Small scenes only: the reference tracer is quadratic in the elements,
    // and a 1000-digit number says nothing a 100-digit one does not.
    if (size > 600) return 0;
    orthoray::Scene scene;
    try {
        scene = orthoray::read_scene(std::string_view(reinterpret_cast<const char*>(data), size),
                                     "fuzz");
    } catch (const orthoray::InputError&) {
        return 0;
    }
    // The engines cross-checked below decide single trajectories among
    // two-sided axis-aligned elements; the optics scenes are held to the
    // state graph, and so are diagonal ones, whose trajectories only the
    // reference tracer and the graph follow.
    if (!scene.single_trajectory() || scene.has_one_sided() || scene.has_diagonal()) {
        check_optics(scene);
        if (scene.single_trajectory() && scene.has_diagonal()) check_octagonal_trajectory(scene);
        return 0;
    }
    orthoray::SolveOptions options;
    options.max_steps = 300;
    std::ostringstream certificate;
    orthoray::CertificateWriter writer(certificate, scene);
    writer.attach(options);
    const orthoray::Answer fast = orthoray::solve(scene, options);
    writer.finish(fast);

    orthoray::SolveOptions reference;
    reference.max_steps = 300;
    reference.engine = orthoray::Engine::reference;
    const orthoray::Answer slow = orthoray::solve(scene, reference);
    if (fast.reason != slow.reason || fast.reflections != slow.reflections) std::abort();

    // The 2D piece tables from the first reflection, stepped in chunks the
    // way the command line does: the same answer again. (3D refuses them;
    // there the default shooter takes their place.)
    struct Watcher : orthoray::RunMonitor {
        std::optional<orthoray::Limit> poll(std::uint64_t) override { return std::nullopt; }
    } watcher;
    orthoray::SolveOptions tables;
    tables.max_steps = 300;
    tables.shooter = scene.dim == 2 ? orthoray::Shooter::pieces : orthoray::Shooter::automatic;
    tables.monitor = &watcher;
    const orthoray::Answer stepped = orthoray::solve(scene, tables);
    if (stepped.reason != slow.reason || stepped.reflections != slow.reflections) std::abort();

    // The induction engine, with the same cap (it reports a limit when the
    // answer needs more reflections): the same answer once more.
    orthoray::SolveOptions induction;
    induction.max_steps = 300;
    induction.engine = orthoray::Engine::induction;
    const orthoray::Answer induced = orthoray::solve(scene, induction);
    if (induced.reason != slow.reason || induced.reflections != slow.reflections) std::abort();

    std::istringstream in(certificate.str());
    const orthoray::Verdict verdict = orthoray::verify_certificate(scene, in, "fuzz");
    if (verdict.valid != fast.decided()) std::abort();
    return 0;
}
