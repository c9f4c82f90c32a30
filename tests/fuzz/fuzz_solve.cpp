// libFuzzer target: solve and verify small parsed scenes. The default engine,
// the piece tables, the induction engine and the reference tracer, all
// capped at 300 reflections, must agree; the default engine's certificate
// must verify exactly when it answered.
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>

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
    // way the command line does: the same answer again.
    struct Watcher : orthoray::RunMonitor {
        std::optional<orthoray::Limit> poll(std::uint64_t) override { return std::nullopt; }
    } watcher;
    orthoray::SolveOptions tables;
    tables.max_steps = 300;
    tables.shooter = orthoray::Shooter::pieces;
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
