#include "support/degenerate_check.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

namespace orthoray::test {
namespace {

using orthoray::Answer;
using orthoray::Arithmetic;
using orthoray::CycleDetector;
using orthoray::Engine;
using orthoray::Reason;

struct Config {
    const char* name;
    Engine engine;
    Arithmetic arithmetic;
    CycleDetector detector;
};

// Every engine with every option that may change how it gets there.
const Config configs[] = {
    {"lattice/automatic/first-state", Engine::lattice, Arithmetic::automatic,
     CycleDetector::first_state},
    {"lattice/automatic/brent", Engine::lattice, Arithmetic::automatic, CycleDetector::brent},
    {"lattice/wide/first-state", Engine::lattice, Arithmetic::wide, CycleDetector::first_state},
    {"lattice/wide/brent", Engine::lattice, Arithmetic::wide, CycleDetector::brent},
    {"reference/first-state", Engine::reference, Arithmetic::automatic, CycleDetector::first_state},
    {"reference/brent", Engine::reference, Arithmetic::automatic, CycleDetector::brent},
    {"graph/first-state", Engine::graph, Arithmetic::automatic, CycleDetector::first_state},
    {"graph/brent", Engine::graph, Arithmetic::automatic, CycleDetector::brent},
};

// Solves the scene with every configuration and demands its answer. A step
// cap far above every answer here turns an engine that never stops into a
// failure instead of a hang. The certificates of the simulation engines must
// verify, so the independent checker agrees with the rule the scene isolates.
} // namespace

void expect(const Degenerate& degenerate) {
    const auto [text, reason, reflections, graph_fits] = degenerate;
    const orthoray::Scene scene = orthoray::read_scene(text, "<degenerate>");
    const std::string want_reason = orthoray::to_string(reason);
    const std::string want_reflections = std::to_string(reflections);
    INFO("scene:\n" << text);
    for (const Config& config : configs) {
        orthoray::SolveOptions options;
        options.engine = config.engine;
        options.arithmetic = config.arithmetic;
        options.cycle_detector = config.detector;
        options.max_steps = 10'000;
        const Answer answer = orthoray::solve(scene, options);
        INFO("configuration " << config.name);
        if (config.engine == Engine::graph && !graph_fits) {
            CHECK(answer.reason == Reason::limit);
            continue;
        }
        CHECK(std::string(orthoray::to_string(answer.reason)) == want_reason);
        CHECK(answer.reflections.get_str() == want_reflections);
        CHECK(std::string(orthoray::answer_word(answer)) == (reason == Reason::hit ? "yes" : "no"));
    }
    for (Engine engine : {Engine::lattice, Engine::reference}) {
        std::stringstream certificate;
        orthoray::CertificateWriter writer(certificate, scene);
        orthoray::SolveOptions options;
        options.engine = engine;
        writer.attach(options);
        writer.finish(orthoray::solve(scene, options));
        const orthoray::Verdict verdict = orthoray::verify_certificate(scene, certificate);
        INFO("certificate of the " << (engine == Engine::lattice ? "lattice" : "reference")
                                   << " engine:\n"
                                   << certificate.str() << "verify said: " << verdict.message);
        CHECK(verdict.valid);
    }
    // The step map of every scene here is injective (spec: reflection is
    // reversible), and the state graph must say so.
    const auto report = orthoray::explore_state_graph(scene, 2'000'000);
    if (!graph_fits) {
        CHECK_FALSE(report.has_value());
        return;
    }
    REQUIRE(report.has_value());
    CHECK(report->injective);
}

} // namespace orthoray::test
