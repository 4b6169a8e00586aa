#pragma once
// Marks a hot loop function for an AVX2 clone next to the baseline x86-64 one; the loader picks
// the clone the CPU supports. The build itself targets plain x86-64 (no -march), so the same
// binary runs everywhere. AVX2 alone, without FMA: both clones then round the same way.

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define FACET_NORMALS_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define FACET_NORMALS_VECTOR_CLONES
#endif
