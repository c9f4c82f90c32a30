// libFuzzer target: the certificate reader and verifier, on two fixed
// scenes: the 3 x 5 mirror box (a single trajectory) and a splitter scene
// (the illumination question). Any bytes give a verdict or an InputError;
// a verdict of valid must be for the true answer: for the box, yes after 6
// reflections; for the splitter scene, targets 1 and 2 lit (the second
// after 1 reflection) and target 3 unlit. A third scene carries
// intensities (docs/intensity.md): a valid certificate for it must give the
// answer the search gives, at the certificate's threshold if it has one.
// A fourth, where two states step to one, has a walk certificate
// (docs/induction-certificates.md, "The walk").
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

void check(const orthoray::Scene& scene, const std::string& bytes, const char* truth) {
    std::istringstream in(bytes);
    try {
        const orthoray::Verdict verdict = orthoray::verify_certificate(scene, in, "fuzz");
        if (verdict.valid && verdict.message.find(truth) == std::string::npos)
            std::abort(); // a certificate proved something false
    } catch (const orthoray::InputError& e) {
        if (e.line() < 1 || e.column() < 1) std::abort();
    }
}

// A valid verdict must be the search's reason and reflections: "valid:
// REASON above intensity EPS, K reflections, ..." those of the intensity
// search at that EPS, and a plain "valid: REASON, K reflections, ..." (an
// illumination certificate, which this scene can have too) those of the
// illumination search.
void check_intensity(const orthoray::Scene& scene, const std::string& bytes) {
    std::istringstream in(bytes);
    try {
        const orthoray::Verdict verdict = orthoray::verify_certificate(scene, in, "fuzz");
        if (!verdict.valid) return;
        orthoray::SolveOptions options;
        std::string above;
        const std::string::size_type at = verdict.message.find(" above intensity ");
        if (at != std::string::npos) {
            const std::string::size_type from = at + 17;
            above = verdict.message.substr(from, verdict.message.find(',', from) - from);
            options.min_intensity = orthoray::Integer(above);
            above = " above intensity " + above;
        }
        const orthoray::Answer truth = orthoray::solve(scene, options);
        const std::string expected = std::string("valid: ") + orthoray::to_string(truth.reason) +
                                     above + ", " + truth.reflections.get_str() + " reflections,";
        if (verdict.message.compare(0, expected.size(), expected) != 0) std::abort();
    } catch (const orthoray::InputError& e) {
        if (e.line() < 1 || e.column() < 1) std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const orthoray::Scene box = orthoray::read_scene("dim 2\n"
                                                            "mirror x 0 y 0 5\n"
                                                            "mirror x 3 y 0 5\n"
                                                            "mirror y 0 x 0 3\n"
                                                            "mirror y 5 x 0 3\n"
                                                            "ray 0 0 1 1\n"
                                                            "target 3 5\n");
    static const orthoray::Scene split = orthoray::read_scene("dim 2\n"
                                                              "splitter x 2 y -1 1\n"
                                                              "ray 0 0 1 0\n"
                                                              "target 5 0\n"
                                                              "target -3 0\n"
                                                              "target 2 -3\n");
    static const orthoray::Scene corridor =
        orthoray::read_scene("dim 2\n"
                             "mirror x 4 y -1 1 reflectance 2/3\n"
                             "mirror x -4 y -1 1 reflectance 2/3\n"
                             "splitter x 2 y -1 1 reflectance 1/2 transmittance 1/3\n"
                             "ray 0 0 1 0 intensity 1000\n"
                             "target 3 0\n"
                             "target -2 0\n"
                             "target 0 5\n");
    // Two states step to one here (a ray slides along the '/' into the
    // wall): its induction certificate is a walk, and the cycle has a tail.
    static const orthoray::Scene slide = orthoray::read_scene("dim 2\n"
                                                              "mirror / 3 0 4 1\n"
                                                              "mirror x 0 y 0 7\n"
                                                              "mirror x 11 y 0 7\n"
                                                              "mirror y 0 x 0 11\n"
                                                              "mirror y 7 x 0 11\n"
                                                              "ray 5 2 1 1\n"
                                                              "target 22 0\n");
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    check(box, bytes, "hit, 6 reflections");
    check(slide, bytes, "cycle, 13 reflections");
    check(split, bytes, "unlit, 1 reflections,");
    check_intensity(corridor, bytes);
    return 0;
}
