#include "malloc_policy.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <unistd.h>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace hrsr::app {

namespace {

// Sanitizers replace malloc: glibc's tunable would change nothing there.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define HRSR_MALLOC_REPLACED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                         \
    __has_feature(memory_sanitizer)
#define HRSR_MALLOC_REPLACED 1
#endif
#endif

// The kernel's mode is `madvise`: huge pages only where asked for. With `always` malloc's
// blocks get them anyway, with `never` not at all.
[[maybe_unused]] bool huge_pages_on_request() {
    std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    return std::getline(mode, line) && line.find("[madvise]") != std::string::npos;
}

} // namespace

void ask_for_huge_pages(char** argv) {
#if defined(__GLIBC__) && defined(__GLIBC_PREREQ) && !defined(HRSR_MALLOC_REPLACED)
#if __GLIBC_PREREQ(2, 35)
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) return;
    if (!huge_pages_on_request()) return;
    const std::string given = tunables ? tunables : "";
    const std::string asked =
        given.empty() ? "glibc.malloc.hugetlb=1" : given + ":glibc.malloc.hugetlb=1";
    if (setenv("GLIBC_TUNABLES", asked.c_str(), 1) != 0) return;
    execv("/proc/self/exe", argv);
    // Still here: the exec failed (no /proc, say). Go on as started.
    if (tunables)
        setenv("GLIBC_TUNABLES", given.c_str(), 1);
    else
        unsetenv("GLIBC_TUNABLES");
#endif
#endif
    (void)argv;
}

void release_large_blocks_eagerly() {
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, 1 << 20); // a fixed threshold: no more dynamic raising
#endif
}

} // namespace hrsr::app
