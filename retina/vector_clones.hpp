// Loops compiled for AVX2 beside the baseline and chosen when the program
// starts (GCC's function multi-versioning). No FMA is enabled, so both
// versions give the same bytes; the AVX2 one handles twice as many values
// per instruction. Elsewhere the attribute is empty.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define EYESTREAM_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define EYESTREAM_VECTOR_CLONES
#endif
