// Loops compiled for AVX-512 (x86-64-v4: AVX-512 F, BW, DQ and VL, so that
// 64-bit multiplies, as in the dither's hashes, are one instruction rather
// than three; F alone left them emulated) and AVX2 beside the baseline,
// chosen when the program starts (GCC's function multi-versioning). No version fuses a
// multiply and an add (the build passes -ffp-contract=off: AVX-512 brings
// FMA, which GCC would otherwise use), so every version gives the same
// bytes; the wider ones handle more values per instruction. Elsewhere the
// attribute is empty. glare/vector_clones.hpp is the glare library's copy
// (tests/vector_clones_test.cpp holds them equal).
#pragma once

#ifndef EYESTREAM_VECTOR_CLONES
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define EYESTREAM_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define EYESTREAM_VECTOR_CLONES
#endif
#endif
