#pragma once
// PROJSURF_CLONES before a function compiles it twice on x86-64 Linux, for AVX2 and for the
// baseline, and the loader picks the one the CPU runs (GCC / Clang function multi-versioning).
// For the straight-line per-point loops: AVX2 brings 8-wide floats, blends and 32-bit integer
// multiplies that SSE2 lacks (the gain is measured by bench/bench_stages). Only .cpp files
// include this header; the library itself stays built for generic x86-64.
#if defined(__x86_64__) && defined(__linux__) && (defined(__GNUC__) || defined(__clang__))
#define PROJSURF_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PROJSURF_CLONES
#endif
