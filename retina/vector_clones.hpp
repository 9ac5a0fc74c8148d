// Loops compiled for AVX-512 and AVX2 beside the baseline and chosen when
// the program starts (GCC's function multi-versioning). No version fuses a
// multiply and an add (the build passes -ffp-contract=off: AVX-512 brings
// FMA, which GCC would otherwise use), so every version gives the same
// bytes; the wider ones handle more values per instruction. Elsewhere the
// attribute is empty. glare/vector_clones.hpp is the glare library's copy
// (tests/vector_clones_test.cpp holds them equal).
#pragma once

#ifndef EYESTREAM_VECTOR_CLONES
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define EYESTREAM_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define EYESTREAM_VECTOR_CLONES
#endif
#endif
