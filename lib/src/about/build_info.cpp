#include "orthoray/build_info.hpp"

#include "about/build_commit.hpp"
#include "orthoray/version.hpp"

#include <boost/version.hpp>
#include <gmp.h>

namespace orthoray {

BuildInfo build_info() {
    BuildInfo info;
    info.orthoray = version;
    info.commit = ORTHORAY_COMMIT;
    // The run-time library's own string: a program may run against a newer
    // GMP than the one it was compiled with.
    info.gmp = gmp_version;
    info.boost = std::to_string(BOOST_VERSION / 100000) + '.' +
                 std::to_string(BOOST_VERSION / 100 % 1000) + '.' +
                 std::to_string(BOOST_VERSION % 100);
#if defined(__clang__)
    info.compiler = "Clang " __clang_version__;
#elif defined(__GNUC__)
    info.compiler = "GCC " __VERSION__;
#else
    info.compiler = "unknown";
#endif
    info.build_type = ORTHORAY_BUILD_TYPE;
    return info;
}

} // namespace orthoray
