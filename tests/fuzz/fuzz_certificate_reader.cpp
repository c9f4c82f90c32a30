// libFuzzer target: the certificate reader and verifier, on a fixed scene
// (the 3 x 5 mirror box). Any bytes give a verdict or an InputError; a
// verdict of valid must be for the true answer (yes, 6 reflections).
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const orthoray::Scene scene = orthoray::read_scene("dim 2\n"
                                                              "mirror x 0 y 0 5\n"
                                                              "mirror x 3 y 0 5\n"
                                                              "mirror y 0 x 0 3\n"
                                                              "mirror y 5 x 0 3\n"
                                                              "ray 0 0 1 1\n"
                                                              "target 3 5\n");
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const orthoray::Verdict verdict = orthoray::verify_certificate(scene, in, "fuzz");
        if (verdict.valid && verdict.message.find("hit, 6 reflections") == std::string::npos)
            std::abort(); // a certificate proved something false
    } catch (const orthoray::InputError& e) {
        if (e.line() < 1 || e.column() < 1) std::abort();
    }
    return 0;
}
