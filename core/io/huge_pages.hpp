#pragma once
// Memory a process touches for the first time costs the kernel a page fault
// per 4 KiB page: on the KVM machines this project is measured on, about
// 9 us each (19 MB first touched: 44 ms), half of a Newton solve of the
// 128 x 128 net and most of building a 1M-particle model. glibc's malloc
// backs its memory with transparent huge pages (2 MiB a fault) when the
// process starts with the tunable glibc.malloc.hugetlb=1 (glibc 2.35 and
// later; older ones ignore it). Tunables are read only at start-up, so
// tendril's programs start themselves again with it, once, first thing.
namespace tendril {

inline constexpr const char* kHugePagesTunable = "glibc.malloc.hugetlb=1";

// Executes /proc/self/exe again with argv and GLIBC_TUNABLES extended by
// kHugePagesTunable, unless GLIBC_TUNABLES already names glibc.malloc.hugetlb
// (the user's choice, or this is the second start), TENDRIL_HUGE_PAGES=0
// asks not to, or valgrind runs the program (it would not follow the exec).
// Returns only when it does not restart, or the exec failed (then with the
// environment as it was).
void restart_with_huge_pages(char** argv);

// Whether this process started with kHugePagesTunable.
bool started_with_huge_pages();

}  // namespace tendril
