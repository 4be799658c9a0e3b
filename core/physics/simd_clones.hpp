#pragma once
// The element loops written for the vectoriser (forces.cpp, cst_forces.cpp)
// are compiled, with GCC on x86-64, three times: for AVX-512, AVX2 and the
// portable SSE2, and the CPU picks one when the program starts
// (target_clones): 8 or 4 elements per instruction instead of 2, the same
// binary on every x86-64. Each lane rounds as the scalar code does (no fused
// multiply-adds: -ffp-contract=off for those files, core/CMakeLists.txt), so
// every copy gives the same numbers bit for bit. Clang (the sanitizer build)
// and native builds compile one copy. The scalar passes around those loops
// (the fused step's gathers, scatters and kick) have copies too: the same
// arithmetic, with VEX's three-operand forms and 4-lane loads and stores of
// the sums.
// GCC's AVX-512 copies use 256-bit vectors: 512-bit ones
// (-mprefer-vector-width=512) measured no faster in the step.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__)
#define TENDRIL_SIMD_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define TENDRIL_SIMD_CLONES
#endif

// Inlines a lambda of a scatter loop that the compiler would call.
#if defined(__GNUC__)
#define TENDRIL_INLINE __attribute__((always_inline))
#else
#define TENDRIL_INLINE
#endif
