// How many random cases a property test runs: all of them in the plain
// build, a quarter under sanitizers, where each case costs five to ten times
// more and what is sought is memory and undefined-behaviour errors, which a
// quarter of the cases exercises as well. The plain build (the README's test
// command) always runs the full counts.
#pragma once

namespace orthoray::test {

constexpr int case_count(int full) {
#ifdef ORTHORAY_SANITIZE
    return full / 4;
#else
    return full;
#endif
}

} // namespace orthoray::test
