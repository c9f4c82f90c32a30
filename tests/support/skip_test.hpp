// A test case that cannot run on this machine (the public puzzle files are
// not beside the source tree, or mounting a file system is not allowed)
// says so with skip_test() and returns before its first check. Its line
// carries ORTHORAY_SKIP_MARKER, and tests/CMakeLists.txt tells ctest that a
// test case whose output holds it was skipped: ctest then lists it as
// "Skipped", not as passed, so a test that checked nothing never counts as
// a pass.
#pragma once

#include <catch2/catch.hpp>

#include <string>

namespace orthoray::test {

// The marker comes from tests/CMakeLists.txt, which also gives it to ctest.
inline void skip_test(const std::string& why) {
    WARN(ORTHORAY_SKIP_MARKER " " << why);
}

} // namespace orthoray::test
