// What this build of the library is made of: its own version and those of
// the libraries and compiler it was built with, for bug reports and for
// `orthoray version --json`.
#pragma once

#include <string>

namespace orthoray {

struct BuildInfo {
    std::string orthoray; // "MAJOR.MINOR.PATCH"
    // The git commit built ("a78e605c1d2e", "-dirty" appended when tracked
    // files had changes), or "unknown" when not built from a git checkout.
    std::string commit;
    std::string gmp;      // the GMP linked at run time (gmp_version)
    std::string boost;    // the Boost headers compiled against ("1.74")
    std::string compiler; // "GCC 12.2.0", "Clang 14.0.6"
    std::string build_type;
};

BuildInfo build_info();

} // namespace orthoray
