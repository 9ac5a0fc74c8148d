// Loops compiled for AVX-512 and AVX2 beside the baseline, chosen when the
// program starts (GCC's function multi-versioning). The AVX-512 version is
// x86-64-v4 (AVX-512 F, BW, CD, DQ and VL over AVX2), so that a 64-bit
// multiply, as in the dither's hashes, is one instruction instead of three
// 32-bit multiplies with shifts and adds; GCC before 12, which does not
// know the x86-64-vN levels in target_clones, gets AVX-512 F alone. No version fuses a multiply and an
// add (the build passes -ffp-contract=off: AVX-512 brings FMA, which GCC
// would otherwise use), so every version gives the same bytes; the wider
// ones handle more values per instruction. Elsewhere the attribute is
// empty. glare/ and io/vector_clones.hpp are the other libraries' copies
// (tests/vector_clones_test.cpp holds them equal).
#pragma once

#ifndef EYESTREAM_VECTOR_CLONES
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define EYESTREAM_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#elif defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)  // (x86-64-v4 in target_clones: GCC 12 on)
#define EYESTREAM_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define EYESTREAM_VECTOR_CLONES
#endif
#endif
