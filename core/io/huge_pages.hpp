#pragma once
// Memory a process touches for the first time costs the kernel a page fault
// per 4 KiB page: on the KVM machines this project is measured on, about
// 9 us each (19 MB first touched: 44 ms), half of a Newton solve of the
// 128 x 128 net and most of building a 1M-particle model. glibc's malloc
// backs its memory with transparent huge pages (2 MiB a fault) when the
// process starts with the tunable glibc.malloc.hugetlb=1 (glibc 2.35 and
// later; older ones ignore it).
// Memory freed goes back to the kernel, which clears it again when it is
// taken again: glibc maps blocks of 32 MiB and more on their own and trims
// its heap's free top beyond 128 KiB. A Newton solve builds its multigrid
// hierarchies anew every few iterations: at 1M particles 3.2 s of its
// 13.9 s were the kernel clearing pages. glibc.malloc.mmap_max=0 takes
// every block from the heap, and trim_threshold keeps up to 256 MiB of free
// heap for the next allocation: 0.7 s of 11.1 s (docs/performance.md, stop
// 46). Tunables are read only at start-up, so tendril's programs start
// themselves again with them, once, first thing.
namespace tendril {

inline constexpr const char* kMemoryTunables =
    "glibc.malloc.hugetlb=1:glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=268435456";

// Executes /proc/self/exe again with argv and GLIBC_TUNABLES extended by
// kMemoryTunables, unless GLIBC_TUNABLES already names glibc.malloc.hugetlb
// (the user's choice, or this is the second start), TENDRIL_HUGE_PAGES=0
// asks not to, or valgrind runs the program (it would not follow the exec).
// Returns only when it does not restart, or the exec failed (then with the
// environment as it was).
void restart_with_huge_pages(char** argv);

// Whether this process started with kMemoryTunables.
bool started_with_huge_pages();

}  // namespace tendril
