// How the command-line tool's malloc takes memory from the system and gives it back. Both settings
// are process-wide, so only the command-line tool makes them, first thing in main(); never the
// library or the MeshLab plugin.
#pragma once

namespace hrsr::app {

/// Where the kernel gives transparent huge pages only to memory that asks for them (its mode
/// `madvise`, the usual default) and glibc can ask (2.35 and later), runs this program again,
/// once, with GLIBC_TUNABLES=glibc.malloc.hugetlb=1 added, so that malloc's large blocks and
/// heaps are backed by 2 MB pages: the run spends far less time in page faults (bunny scans,
/// two threads, alternated: 204k–220k faults → 63k–78k, 6.4–8.5 s → 5.1–6.5 s, the same bytes,
/// peak within 3 %; docs/BENCHMARKS.md, session 55). glibc reads its tunables only when a program
/// starts, hence the new start. Returns (and nothing changes) when it does not apply, when the exec
/// fails, or when GLIBC_TUNABLES already names glibc.malloc.hugetlb:
/// `GLIBC_TUNABLES=glibc.malloc.hugetlb=0` keeps a run in one process (for a debugger or valgrind).
void ask_for_huge_pages(char** argv);

/// Makes large blocks go back to the system as soon as they are freed. glibc otherwise raises
/// its mmap threshold after each large free, and later blocks of that size stay in the heap
/// after they are freed: the phases' big temporary arrays then add up in the resident set
/// (measured on the bunny scans: 185 MB peak instead of 149 MB).
void release_large_blocks_eagerly();

} // namespace hrsr::app
