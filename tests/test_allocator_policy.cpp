// keep_freed_memory: freed blocks stay in the process and serve the next
// allocations (orthoray/allocator_policy.hpp).
#include "orthoray/allocator_policy.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__GLIBC__) && !defined(ORTHORAY_SANITIZE) // sanitizers keep their own allocator
TEST_CASE("keep_freed_memory: an 8 MB block comes from the heap and is reused", "[allocator]") {
    if (const char* tunables = std::getenv("GLIBC_TUNABLES");
        tunables != nullptr && std::strstr(tunables, "glibc.malloc.") != nullptr) {
        CHECK_FALSE(orthoray::keep_freed_memory()); // the environment's choice stands
        return;
    }
    REQUIRE(orthoray::keep_freed_memory());
    constexpr std::size_t size = std::size_t{8} << 20;
    const std::size_t mapped = mallinfo2().hblkhd;
    char* block = static_cast<char*>(std::malloc(size));
    REQUIRE(block != nullptr);
    std::memset(block, 1, size);
    // Not a mapping of its own (glibc's default maps every block over 128 kB).
    CHECK(mallinfo2().hblkhd == mapped);
    std::free(block);
    // Still in the process: the heap did not shrink below it.
    const struct mallinfo2 kept = mallinfo2();
    CHECK(kept.arena >= size);
    CHECK(kept.fordblks >= size);
    // And the next block of that size is served from it, without growing the heap.
    char* again = static_cast<char*>(std::malloc(size));
    REQUIRE(again != nullptr);
    CHECK(mallinfo2().arena == kept.arena);
    std::free(again);
}
#endif
