#include "orthoray/allocator_policy.hpp"

#include <cstdlib>
#include <cstring>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace orthoray {

bool keep_freed_memory() {
#if defined(__GLIBC__)
    if (const char* tunables = std::getenv("GLIBC_TUNABLES");
        tunables != nullptr && std::strstr(tunables, "glibc.malloc.") != nullptr)
        return false;
    // Blocks up to 32 MB, glibc's largest threshold (half its 64-bit heap
    // size), come from the heap; larger ones are few and keep their own
    // mappings. And the heap's top is not given back while under 1 GB.
    // mallopt returns 1 on success; a sanitizer's allocator does not honour
    // it.
    constexpr int mapped_from = 32 << 20, trimmed_from = 1 << 30;
    return mallopt(M_MMAP_THRESHOLD, mapped_from) == 1 &&
           mallopt(M_TRIM_THRESHOLD, trimmed_from) == 1;
#else
    return false;
#endif
}

} // namespace orthoray
